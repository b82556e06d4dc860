// b2a_viewer: the sample table.
#include "SampleRegistry.h"

#include "samples/Samples.h"

#include <cctype>

namespace b2a::viewer
{

const std::vector<SampleEntry>& Samples()
{
	static const std::vector<SampleEntry> table = {
		{"Granular", "Hopper discharge", MakeHopperSample},
		{"Granular", "Packing", MakePackingSample},
		{"Granular", "Beverloo channel", MakeBeverlooSample},
		{"Pairs", "Contact cases", MakeContactCasesSample},
		{"Pairs", "Collision cases", MakeCollisionCasesSample},
		{"Stacking", "Superellipse stack", MakeSuperellipseStackSample},
		{"Stacking", "Ellipses on a slope", MakeEllipseSlopeSample},
		{"Stacking", "Mixed with Box2D shapes", MakeMixedSample},
		{"Sandbox", "Shape editor", MakeSandboxSample},
		{"3D", "Figure 17 superellipsoids", MakeFigure17Sample},
	};
	return table;
}

std::string SampleKey(const SampleEntry& entry)
{
	std::string key;
	for (const char* c = entry.name; *c; ++c)
		key += *c == ' ' ? '-' : char(std::tolower(static_cast<unsigned char>(*c)));
	return key;
}

int FindSample(const std::string& key)
{
	const auto& table = Samples();
	for (size_t i = 0; i < table.size(); ++i)
		if (SampleKey(table[i]) == key)
			return int(i);
	return -1;
}

} // namespace b2a::viewer

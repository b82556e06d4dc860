// b2analytic benchmarks: the pair benchmark's picture of time against error.
#include "PairsPlot.h"

#include "common/Plot.h"
#include "common/Svg.h"

#include <cmath>

namespace b2a::bench
{

namespace
{
struct MethodStyle
{
	const char* prefix; // the method names it covers, by their start
	const char* colour;
	demo::Marker markers[5]; // by variant, in the order of `variants`
	const char* variants[5];
};

// The kinds of methods and their variants (an unknown method is drawn black, as a circle).
const MethodStyle kStyles[] = {
	{"newton_", demo::palette::blue, {demo::Marker::circle, demo::Marker::square}, {"cold", "warm"}},
	{"auto", demo::palette::vermillion, {demo::Marker::circle, demo::Marker::square}, {"auto", "auto_warm"}},
	{"grid_refined", demo::palette::orange, {demo::Marker::diamond}, {"grid_refined"}},
	{"grid_", demo::palette::green, {demo::Marker::circle, demo::Marker::square, demo::Marker::triangle, demo::Marker::diamond},
	 {"64", "256", "1024", "4096"}},
	{"box2d_gjk", demo::palette::skyBlue, {demo::Marker::circle, demo::Marker::square, demo::Marker::triangle, demo::Marker::diamond},
	 {"8", "16", "32", "64"}},
	{"bullet_gjk_epa", demo::palette::skyBlue,
	 {demo::Marker::circle, demo::Marker::square, demo::Marker::triangle, demo::Marker::diamond, demo::Marker::triangleDown},
	 {"32", "64", "128", "256", "512"}},
	{"box2d_", demo::palette::purple, {demo::Marker::circle, demo::Marker::square, demo::Marker::triangle}, {"polygon8", "obb", "circle"}},
};

void Style(const std::string& method, demo::Series& s)
{
	s.colour = demo::palette::black;
	s.marker = demo::Marker::circle;
	for (const MethodStyle& style : kStyles)
	{
		const std::string prefix = style.prefix;
		if (method.compare(0, prefix.size(), prefix) != 0)
			continue;
		s.colour = style.colour;
		for (int v = 0; v < 5 && style.variants[v]; ++v)
		{
			const std::string variant = style.variants[v];
			if (method.size() >= variant.size() && method.compare(method.size() - variant.size(), variant.size(), variant) == 0)
				s.marker = style.markers[v];
		}
		return;
	}
}
} // namespace

std::string PairsPlot(const std::string& family, const std::vector<PairsPlotPoint>& points)
{
	std::vector<demo::Series> series;
	for (const PairsPlotPoint& p : points)
	{
		demo::Series s;
		s.name = p.method;
		s.points = true;
		Style(p.method, s);
		s.x = {p.nsPerQuery};
		s.y = {std::fmax(p.pointError, 1e-17)};
		series.push_back(s);
	}
	return demo::LinePlot(series, family + ": time against contact point error", "time per query (ns)",
	                      "largest point error (units of the particle size)", true, true);
}

} // namespace b2a::bench

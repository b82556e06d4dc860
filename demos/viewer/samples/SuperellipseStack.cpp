// b2a_viewer: blocky superellipses (n = m = 8) stacked in a column and a pyramid, the test of a
// contact's flat patch: each face-to-face contact needs two manifold points to stand.
#include "samples/Samples.h"

#include "b2analytic/SuperellipseShape.h"

namespace b2a::viewer
{
namespace
{
class SuperellipseStack : public Sample
{
public:
	SuperellipseStack()
	{
		MakeWorld(b2Vec2(0.0f, -10.0f));
		AddGroundEdge(b2Vec2(-40.0f, 0.0f), b2Vec2(40.0f, 0.0f));

		// A column of flat blocks (a = 1, b = 0.4) and a pyramid of square ones (a = b = 0.5).
		const ShapePtr slab = MakeSuperellipse(1.0, 0.4, 8.0, 8.0), block = MakeSuperellipse(0.5, 0.5, 8.0, 8.0);
		for (int i = 0; i < 12; ++i)
			AddParticle(slab, b2Vec2(-12.0f, 0.4f + 0.82f * float(i)), 0.0f);
		const int rows = 12;
		for (int row = 0; row < rows; ++row)
			for (int k = 0; k < rows - row; ++k)
				AddParticle(block, b2Vec2(2.0f + 1.02f * (float(k) + 0.5f * float(row)), 0.5f + 1.01f * float(row)), 0.0f);
	}

	SampleDefaults Defaults() const override
	{
		return MetreScene(b2Vec2(-16.0f, -1.0f), b2Vec2(16.0f, 14.0f));
	}
};
} // namespace

std::unique_ptr<Sample> MakeSuperellipseStackSample()
{
	return std::make_unique<SuperellipseStack>();
}

} // namespace b2a::viewer

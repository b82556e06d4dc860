// b2a_viewer: ellipses rolling down a slope and rocking on the flat. An ellipse rests on a slope
// of angle θ only where its surface normal leans θ away from the line to its centre, and the
// largest such lean of an ellipse of aspect r is atan((r − 1/r)/2): on this 30° slope those of
// aspect above 1.78 rock to rest, the rounder ones (and the circle) roll down, unevenly, their
// centres rising and falling. On the flat, tipped ellipses rock about their flat sides.
#include "samples/Samples.h"

#include "b2analytic/SuperellipseShape.h"

#include <cmath>

namespace b2a::viewer
{
namespace
{
class EllipseSlope : public Sample
{
public:
	EllipseSlope()
	{
		MakeWorld(b2Vec2(0.0f, -10.0f));
		// A slope of 30 degrees down to a flat floor, closed by a wall on the right.
		const b2Vec2 top(-24.0f, 15.0f), foot(-24.0f + 15.0f * std::sqrt(3.0f), 0.0f);
		AddGroundEdge(top, foot, 0.9f);
		AddGroundEdge(foot, b2Vec2(40.0f, 0.0f), 0.9f);
		AddGroundEdge(b2Vec2(40.0f, 0.0f), b2Vec2(40.0f, 10.0f), 0.9f);

		// On the slope, lying on their flat sides: the roundest lowest, so that what rolls does
		// not run into what stays.
		const b2Vec2 down = foot - top;
		const float angle = std::atan2(down.y, down.x);
		const b2Vec2 along(std::cos(angle), std::sin(angle)), normal(-std::sin(angle), std::cos(angle));
		const double aspects[] = {3.0, 2.0, 1.6, 1.3, 1.0};
		for (int i = 0; i < 5; ++i)
		{
			const double b = 0.6, a = b * aspects[i];
			const b2Vec2 at = top + (3.0f + 4.5f * float(i)) * along + float(b + 0.02) * normal;
			AddParticle(MakeEllipse(a, b), at, angle, 1.0f, 0.9f);
		}
		// On the flat: ellipses tipped onto their ends, to rock about their flat side.
		for (int i = 0; i < 3; ++i)
		{
			const double a = 1.2 + 0.4 * i, b = 0.5;
			const float tilt = 0.5f + 0.3f * float(i);
			AddParticle(MakeEllipse(a, b), b2Vec2(16.0f + 7.0f * float(i), float(a) + 0.3f), tilt, 1.0f, 0.9f);
		}
	}

	SampleDefaults Defaults() const override
	{
		return MetreScene(b2Vec2(-26.0f, -2.0f), b2Vec2(42.0f, 17.0f));
	}
};
} // namespace

std::unique_ptr<Sample> MakeEllipseSlopeSample()
{
	return std::make_unique<EllipseSlope>();
}

} // namespace b2a::viewer

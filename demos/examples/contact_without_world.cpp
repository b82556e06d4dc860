// b2analytic example: the geometry and contact solvers without a Box2D world (the README's
// "without a world" lines, as a whole program). It needs only b2analytic::core (no Box2D).
#include <b2analytic/b2analytic.h>

#include <cstdio>

int main()
{
	auto a = b2a::MakeSuperellipse(2.0, 4.0, 6.0, 8.0);   // |x/2|^6 + |y/4|^8 <= 1
	b2a::LevelResult l = b2a::SolveCommonLevel(*a, b2a::Pose({0, 0}, 0.3), *a, b2a::Pose({9, 2}, 1.0));
	b2a::ContactResult c = b2a::ComputeContact(*a, b2a::Pose({0, 0}, 0.3), *b2a::MakeHeart(1.0), b2a::Pose({2.5, 1}, 0.0));

	// Level above 1: the two superellipses are apart, and touch when both are rescaled to it.
	std::printf("common level %.6f at (%.6f, %.6f), %s\n", l.level, l.point.x, l.point.y, b2a::StatusName(l.status));
	// Negative separation: the superellipse and the heart overlap by that much along the normal.
	std::printf("contact: separation %.6f, normal (%.6f, %.6f), %s by %s\n", c.separation, c.normal.x, c.normal.y,
	            b2a::StatusName(c.status), b2a::MethodName(c.method));
	return l.Ok() && c.Ok() ? 0 : 1;
}

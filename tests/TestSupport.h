// b2analytic tests: small helpers shared by the test folders.
#pragma once

#include "ReferenceRandom.h" // Random, shared with the reference library
#include "b2analytic/Math.h"

#include <algorithm>
#include <cmath>

namespace b2a::test
{

/// |a − b| / max(|b|, floor).
inline double RelativeError(double a, double b, double floor = 1e-300)
{
	return std::fabs(a - b) / std::max(std::fabs(b), floor);
}

/// The pose at `position` turned by the rotation with exactly this cosine and sine: a pose
/// written out in hexadecimal doubles, as the benchmarks held it (Pose(p, angle) would take the
/// cosine and sine anew, to libm's rounding).
inline Pose PoseOf(Vec2 position, double c, double s)
{
	Rot q;
	q.c = c;
	q.s = s;
	return Pose(position, q);
}

} // namespace b2a::test

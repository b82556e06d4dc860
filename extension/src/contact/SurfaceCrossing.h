// b2analytic: the first surface crossing along a line, given what the caller knows (internal).
#pragma once

#include "b2analytic/Shape.h"

namespace b2a
{

/// FirstSurfaceCrossing given f0 = λ(X) − own level (which the caller has computed) and the
/// slope of λ along dir at X (NaN when not known): with the slope, a non-convex shape's march
/// heads for where the level is estimated to reach the own level instead of doubling its way
/// there.
double FirstSurfaceCrossingFrom(const Shape& shape, const Pose& pose, Vec2 X, Vec2 dir, double sMax, double f0, double slope0);

} // namespace b2a

// b2analytic: the first surface crossing along a line, given what the caller knows (internal).
#pragma once

#include "b2analytic/Shape.h"

namespace b2a
{

/// FirstSurfaceCrossing given f0 = λ(X) − own level (which the caller has computed) and the
/// slope of λ along dir at X (NaN when not known). Both must be the true ones: heading for the
/// surface, where the shape bounds its curvature over the stretch ahead and the level is convex
/// there, the parabolas through (0, f0) with that slope bracket the crossing, found then by
/// Halley's steps, with no march; elsewhere the slope steers a non-convex shape's march toward
/// where the level is estimated to reach the own level instead of doubling its way there.
double FirstSurfaceCrossingFrom(const Shape& shape, const Pose& pose, Vec2 X, Vec2 dir, double sMax, double f0, double slope0);

} // namespace b2a

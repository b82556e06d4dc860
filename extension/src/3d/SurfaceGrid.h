// b2analytic: spreading the nodes of a surface parameter grid (internal).
#pragma once

#include "b2analytic/3d/Shape3.h"

#include <functional>
#include <vector>

namespace b2a
{

/// `count` parameter values in [lo, hi] spread so that both arc length and turning of the given
/// curves are resolved: half of the budget follows arc length, half the turning of the tangent
/// (as the 2D samples), averaged over the curves (each a function of the parameter, sampled
/// densely). `cyclic`: the values are lo + the k/count points of the cumulative weight, k = 0 …
/// count − 1 (hi is lo again); else the (k + 1)/(count + 1) points, the ends excluded.
std::vector<double> SpreadParameters(const std::vector<std::function<Vec3(double)>>& curves, double lo, double hi, int count,
                                     bool cyclic);

/// The samples of a star-shaped, centrally symmetric shape on the latitude–longitude grid of
/// SurfaceSamples3, for about `count` points: `point(η, ω)` gives the surface point of the
/// grid's direction. Longitudes follow the equator (η = 0), latitudes the meridians through
/// ω = 0 and ω = π/2; perRing is a multiple of 4 and rings = perRing/2 − 1 (odd: the equator is
/// a ring).
SurfaceSamples3 BuildLatitudeLongitudeSamples(const std::function<Vec3(double, double)>& point, int count);

} // namespace b2a

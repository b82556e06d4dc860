// b2analytic: contact between an analytic shape and a convex polygon or segment.
#pragma once

#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"

namespace b2a
{

/// Contact between an analytic shape A and a convex polygon B given by its vertices in B's body
/// frame, counter-clockwise (count ≥ 3), or a segment (count = 2). These are the walls and
/// floors of a Box2D scene: polygons, edges and chain links, taken without their skin radius.
///
/// For convex sets the signed distance is D = max over unit n of [min_j vⱼ·n − h_A(n)], with h_A
/// A's support function: the distance when apart, minus the penetration depth when overlapping
/// (separating-axis theorem). The maximiser is found among the polygon's face normals, the
/// directions to its vertices, 16 even directions and `guessNormal` (a previous answer), then
/// refined by Brent's method. The normal points from A to B; pointA is A's support point along
/// it, pointB = pointA + D·normal lies on B, separation = D. For a non-convex A (a heart) the
/// support is that of its convex hull, which only errs where a polygon corner enters a notch.
ContactResult ComputePolygonContact(const Shape& a, const Pose& pa, const Vec2* vertices, int count, const Pose& pb,
                                    const Vec2* guessNormal = nullptr);

} // namespace b2a

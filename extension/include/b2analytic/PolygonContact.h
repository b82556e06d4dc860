// b2analytic: contact between an analytic shape and a convex polygon or segment.
#pragma once

#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"
#include "b2analytic/ShapeKind.h"

namespace b2a
{

/// A function of the dispatch table's polygon column: the contact of a shape A with a convex
/// polygon B given by its vertices in B's body frame, counter-clockwise (count ≥ 3), or a segment
/// (count = 2); `guessNormal` (or null) is a previous answer's normal.
using PolygonContactFunction = ContactResult (*)(const Shape& a, const Pose& pa, const Vec2* vertices, int count,
                                                 const Pose& pb, const Vec2* guessNormal);

/// Contact between an analytic shape A and a convex polygon or segment B (see
/// PolygonContactFunction). These are the walls and floors of a Box2D scene: polygons, edges and
/// chain links, taken without their skin radius. The dispatch table's polygon column decides by
/// A's kind: SeparatingAxisContact for every built-in kind and, until one is registered, for a
/// registered kind.
ContactResult ComputePolygonContact(const Shape& a, const Pose& pa, const Vec2* vertices, int count, const Pose& pb,
                                    const Vec2* guessNormal = nullptr);

/// Register `function` as the contact of shapes of the 2D kind `kind` with polygons and segments
/// (ComputePolygonContact). Set-up only, as RegisterContactFunction; throws InvalidParameter
/// naming 'kind' for a kind that is not a registered 2D kind, 'function' for a null function.
void RegisterPolygonContactFunction(ShapeKind kind, PolygonContactFunction function);

/// The polygon column's function for `kind` (throws as RegisterPolygonContactFunction).
PolygonContactFunction GetPolygonContactFunction(ShapeKind kind);

/// The separating-axis contact of A with a convex polygon or segment B.
///
/// For convex sets the signed distance is D = max over unit n of [min_j vⱼ·n − h_A(n)], with h_A
/// A's support function: the distance when apart, minus the penetration depth when overlapping
/// (separating-axis theorem). The maximiser is found among the polygon's face normals, the
/// directions to its vertices, 16 even directions and `guessNormal` (a previous answer), then
/// refined by Brent's method. The normal points from A to B; pointA is A's support point along
/// it, pointB = pointA + D·normal lies on B, separation = D. For a non-convex A (a heart) the
/// support is that of its convex hull, which only errs where a polygon corner enters a notch.
ContactResult SeparatingAxisContact(const Shape& a, const Pose& pa, const Vec2* vertices, int count, const Pose& pb,
                                    const Vec2* guessNormal = nullptr);

} // namespace b2a

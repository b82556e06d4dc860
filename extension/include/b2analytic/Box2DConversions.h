// b2analytic: Box2D's vectors, rotations and transforms as the library's, and back; and the
// Box2D polygon that stands in for an analytic shape.
#pragma once

#include "b2analytic/Math.h"
#include "b2analytic/Shape.h"

#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <cmath>

namespace b2a
{

/// A Box2D vector in double precision (exact).
inline Vec2 ToVec2(const b2Vec2& v) { return Vec2(v.x, v.y); }

/// A vector as Box2D's float vector (each component rounded to the nearest float).
inline b2Vec2 ToB2Vec2(Vec2 v) { return b2Vec2(float(v.x), float(v.y)); }

/// A Box2D rotation as a rotation in double precision, scaled to unit length. Box2D's b2Rot
/// holds float sine and cosine (b2Rot::Set rounds sinf and cosf), whose squares sum to 1 within
/// about 1e-7, so it also scales what it rotates by that much; the library's queries need a
/// rigid motion (a point test and a ray cast must see the same particle, and a particle must lie
/// inside its bounding circle), so the pair is divided by its length.
inline Rot ToRot(const b2Rot& q)
{
	Rot r;
	const double c = q.c, s = q.s, length = std::sqrt(c * c + s * s);
	if (length > 0.0 && std::isfinite(length))
	{
		r.c = c / length;
		r.s = s / length;
	}
	return r;
}

/// A rotation as Box2D's (cosine and sine rounded to float).
inline b2Rot ToB2Rot(Rot q)
{
	b2Rot r;
	r.c = float(q.c);
	r.s = float(q.s);
	return r;
}

/// A Box2D transform (a body's, b2Body::GetTransform) as a pose: the position exactly, the
/// rotation as ToRot gives it.
inline Pose ToPose(const b2Transform& xf) { return Pose(ToVec2(xf.p), ToRot(xf.q)); }

/// A pose as Box2D's transform (rounded to float).
inline b2Transform ToB2Transform(const Pose& pose) { return b2Transform(ToB2Vec2(pose.p), ToB2Rot(pose.q)); }

/// The Box2D polygon a user would otherwise give a body for `shape`: `count` vertices (3 to
/// b2_maxPolygonVertices) on the shape's own surface, at the polar directions of an affine
/// image of the regular count-gon on the shape's extents along its body axes (for an ellipse,
/// the inscribed polygon of largest area; for a superellipse of exponent 4, the 8-gon takes its
/// four corners), in the shape's body frame; for a non-convex shape (a heart), their convex
/// hull, as b2PolygonShape::Set makes it. Box2D adds its usual skin (b2_polygonRadius). So the
/// same scene of Box2D's own shapes is one line away. Throws InvalidParameter for a count out of
/// range, or a shape too small for Box2D's polygon (vertices closer than its weld distance,
/// half of b2_linearSlop, or on one line).
b2PolygonShape MakeInscribedPolygon(const Shape& shape, int count);

} // namespace b2a

// b2analytic contact tests: small helpers shared by the contact test files (no references here,
// see ContactReference.h for those).
#pragma once

#include "b2analytic/b2analytic.h"

#include <cmath>
#include <string>

namespace b2a::test
{

/// Every number in a level result is finite.
inline bool AllFinite(const LevelResult& r)
{
	return std::isfinite(r.level) && IsFinite(r.point) && IsFinite(r.normal) && std::isfinite(r.multiplier) &&
	       r.failure != nullptr;
}

/// Every number in a contact result is finite.
inline bool AllFinite(const ContactResult& c)
{
	return std::isfinite(c.level) && IsFinite(c.point) && IsFinite(c.normal) && IsFinite(c.pointA) && IsFinite(c.pointB) &&
	       std::isfinite(c.separation) && c.failure != nullptr;
}

/// Level of a world point in a posed shape's body frame, relative to the shape's own level.
inline double RelativeLevel(const Shape& s, const Pose& p, Vec2 X)
{
	return s.Level(ToBody(p, X)) / s.SurfaceLevel();
}

/// Largest component-wise distance between two vectors.
inline double MaxDiff(Vec2 a, Vec2 b) { return std::fmax(std::fabs(a.x - b.x), std::fabs(a.y - b.y)); }

/// Apply a rigid motion (rotation by phi about the origin, then translation t) to a pose.
inline Pose Moved(const Pose& p, double phi, Vec2 t)
{
	const Rot r(phi);
	return Pose(Rotate(r, p.p) + t, p.q.Angle() + phi);
}
/// The same rigid motion applied to a point and to a direction.
inline Vec2 MovedPoint(Vec2 X, double phi, Vec2 t) { return Rotate(Rot(phi), X) + t; }
inline Vec2 MovedVector(Vec2 v, double phi) { return Rotate(Rot(phi), v); }

/// A circle of radius r as a user shape (kind smooth_convex): the same geometry as MakeCircle,
/// but the dispatch table sends it through the general smooth-convex path (Newton) instead of
/// the circle closed form.
inline ShapePtr MakeUserCircle(double r)
{
	UserShapeDef def;
	def.name = "user circle";
	def.function = [r](Vec2 x, double L) { return (x.x * x.x + x.y * x.y) / (r * r) - L; };
	def.levelOf = [r](Vec2 x) { return (x.x * x.x + x.y * x.y) / (r * r); };
	def.gradient = [r](Vec2 x, double) { return Vec2(2.0 * x.x / (r * r), 2.0 * x.y / (r * r)); };
	def.hessian = [r](Vec2, double) { return Sym22{2.0 / (r * r), 0.0, 2.0 / (r * r)}; };
	def.level = 1.0;
	def.convex = true;
	def.smooth = true;
	def.lengthScale = r;
	return MakeUserShape(def);
}

/// An ellipse x²/a² + y²/b² ≤ 1 as a user shape (kind smooth_convex).
inline ShapePtr MakeUserEllipse(double a, double b)
{
	UserShapeDef def;
	def.name = "user ellipse";
	def.function = [a, b](Vec2 x, double L) { return x.x * x.x / (a * a) + x.y * x.y / (b * b) - L; };
	def.levelOf = [a, b](Vec2 x) { return x.x * x.x / (a * a) + x.y * x.y / (b * b); };
	def.gradient = [a, b](Vec2 x, double) { return Vec2(2.0 * x.x / (a * a), 2.0 * x.y / (b * b)); };
	def.hessian = [a, b](Vec2, double) { return Sym22{2.0 / (a * a), 0.0, 2.0 / (b * b)}; };
	def.level = 1.0;
	def.convex = true;
	def.smooth = true;
	def.lengthScale = std::fmax(a, b);
	return MakeUserShape(def);
}

} // namespace b2a::test

// b2analytic: analytic-shape particles for Box2D.
// Plain double-precision 2D math for the geometry core (no Box2D here).
#pragma once

#include <cmath>

namespace b2a
{

/// A 2D vector (or point) in double precision.
struct Vec2
{
	double x = 0.0; ///< first component
	double y = 0.0; ///< second component

	/// Zero vector.
	constexpr Vec2() = default;
	/// Vector from components.
	constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}
};

/// Component-wise sum.
constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
/// Component-wise difference.
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
/// Negation.
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
/// Scaling by a number.
constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
/// Scaling by a number.
constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
/// Division by a number.
constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
/// In-place sum.
inline Vec2& operator+=(Vec2& a, Vec2 b) { a.x += b.x; a.y += b.y; return a; }
/// In-place difference.
inline Vec2& operator-=(Vec2& a, Vec2 b) { a.x -= b.x; a.y -= b.y; return a; }

/// Dot product.
constexpr double Dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// 2D cross product (z component of the 3D cross product).
constexpr double Cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// Counter-clockwise perpendicular: Perp((1,0)) = (0,1).
constexpr Vec2 Perp(Vec2 a) { return {-a.y, a.x}; }
/// Euclidean length.
inline double Length(Vec2 a)
{
	// sqrt of the sum of squares where that neither overflows nor underflows (several times
	// faster than hypot, which the hot paths call for every normal); hypot elsewhere.
	const double s = a.x * a.x + a.y * a.y;
	return (s > 1e-290 && s < 1e290) ? std::sqrt(s) : std::hypot(a.x, a.y);
}
/// Squared length.
constexpr double LengthSquared(Vec2 a) { return a.x * a.x + a.y * a.y; }
/// Distance between two points.
inline double Distance(Vec2 a, Vec2 b) { return Length(a - b); }
/// True when both components are finite.
inline bool IsFinite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }

/// Unit vector along a; returns (0,0) when a is zero or not finite.
inline Vec2 Normalize(Vec2 a)
{
	const double len = Length(a);
	if (!(len > 0.0) || !std::isfinite(len))
		return {};
	return a / len;
}

/// Unit vector at polar angle theta, exactly on an axis where theta is the double nearest a
/// multiple of π/2 (cos(π/2) in double is 6e-17, not 0: a shape whose level grows like
/// |x|^{2/3} across an axis, the heart at its tip and notch, turns that into 1e-11 of its size).
/// Components below 2e-16 (the rounding of such an angle) are taken as 0.
inline Vec2 PolarDirection(double theta)
{
	double c = std::cos(theta), s = std::sin(theta);
	if (std::fabs(c) < 2e-16)
		c = 0.0, s = s > 0.0 ? 1.0 : -1.0;
	else if (std::fabs(s) < 2e-16)
		s = 0.0, c = c > 0.0 ? 1.0 : -1.0;
	return {c, s};
}

/// Distance from the point p to the segment [a, b].
inline double DistanceToSegment(Vec2 p, Vec2 a, Vec2 b)
{
	const Vec2 ab = b - a;
	const double len2 = LengthSquared(ab);
	double t = len2 > 0.0 ? Dot(p - a, ab) / len2 : 0.0;
	t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
	return Distance(p, a + t * ab);
}

/// A symmetric 2x2 matrix, used for Hessians.
struct Sym22
{
	double xx = 0.0; ///< entry (0,0)
	double xy = 0.0; ///< entries (0,1) and (1,0)
	double yy = 0.0; ///< entry (1,1)
};

/// Sum of symmetric matrices.
constexpr Sym22 operator+(Sym22 a, Sym22 b) { return {a.xx + b.xx, a.xy + b.xy, a.yy + b.yy}; }
/// Scaling of a symmetric matrix.
constexpr Sym22 operator*(double s, Sym22 a) { return {s * a.xx, s * a.xy, s * a.yy}; }
/// Matrix-vector product.
constexpr Vec2 operator*(Sym22 m, Vec2 v) { return {m.xx * v.x + m.xy * v.y, m.xy * v.x + m.yy * v.y}; }
/// Outer product v vᵀ.
constexpr Sym22 Outer(Vec2 v) { return {v.x * v.x, v.x * v.y, v.y * v.y}; }
/// Symmetrised outer product (a bᵀ + b aᵀ) / 2.
constexpr Sym22 OuterSym(Vec2 a, Vec2 b) { return {a.x * b.x, 0.5 * (a.x * b.y + a.y * b.x), a.y * b.y}; }

/// A rotation by an angle, stored as its cosine and sine.
/// Applied to a body vector it rotates counter-clockwise (body → world).
struct Rot
{
	double c = 1.0; ///< cosine of the angle
	double s = 0.0; ///< sine of the angle

	/// Identity rotation.
	constexpr Rot() = default;
	/// Rotation by an angle in radians.
	explicit Rot(double angle) : c(std::cos(angle)), s(std::sin(angle)) {}
	/// The angle in radians, in (-π, π].
	double Angle() const { return std::atan2(s, c); }
};

/// Rotate v by q (body → world).
constexpr Vec2 Rotate(Rot q, Vec2 v) { return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y}; }
/// Rotate v by the inverse of q (world → body).
constexpr Vec2 InvRotate(Rot q, Vec2 v) { return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y}; }
/// Composition a·b (apply b first, then a).
constexpr Rot Mul(Rot a, Rot b)
{
	Rot r;
	r.c = a.c * b.c - a.s * b.s;
	r.s = a.s * b.c + a.c * b.s;
	return r;
}
/// Composition aᵀ·b (the rotation of b relative to a).
constexpr Rot InvMul(Rot a, Rot b)
{
	Rot r;
	r.c = a.c * b.c + a.s * b.s;
	r.s = a.c * b.s - a.s * b.c;
	return r;
}

/// Rotate a symmetric matrix into the world: R H Rᵀ.
constexpr Sym22 Rotate(Rot q, Sym22 h)
{
	// R H Rᵀ written out for R = [c -s; s c].
	const double c = q.c, s = q.s;
	const double xx = c * c * h.xx - 2.0 * c * s * h.xy + s * s * h.yy;
	const double yy = s * s * h.xx + 2.0 * c * s * h.xy + c * c * h.yy;
	const double xy = c * s * (h.xx - h.yy) + (c * c - s * s) * h.xy;
	return {xx, xy, yy};
}

/// The pose of a particle: centroid position and orientation.
/// Body coordinates of a world point X are x = Rᵀ(X − p).
struct Pose
{
	Vec2 p; ///< position of the body origin in the world
	Rot q;  ///< orientation (body → world, counter-clockwise)

	/// Identity pose.
	Pose() = default;
	/// Pose from a position and a rotation.
	Pose(Vec2 position, Rot rotation) : p(position), q(rotation) {}
	/// Pose from a position and an angle in radians.
	Pose(Vec2 position, double angle) : p(position), q(angle) {}
};

/// Body point → world point.
constexpr Vec2 ToWorld(const Pose& t, Vec2 x) { return Rotate(t.q, x) + t.p; }
/// World point → body point.
constexpr Vec2 ToBody(const Pose& t, Vec2 X) { return InvRotate(t.q, X - t.p); }
/// Pose of b expressed in a's body frame: ToWorld(Relative(a,b), x) maps b's body to a's body.
constexpr Pose Relative(const Pose& a, const Pose& b)
{
	Pose r;
	r.p = InvRotate(a.q, b.p - a.p);
	r.q = InvMul(a.q, b.q);
	return r;
}

/// An axis-aligned box.
struct Box
{
	Vec2 lower; ///< lower-left corner
	Vec2 upper; ///< upper-right corner
};

/// A rectangle of any orientation: `axis` (a unit vector) along its length, halfLength along
/// it and halfWidth across it about `centre`. The grid method's runs of samples each lie in one
/// aligned with their chord, a thin box where their disc is round.
struct OrientedBox
{
	Vec2 centre;            ///< centre
	Vec2 axis{1.0, 0.0};    ///< unit vector along the length
	double halfLength = 0.0; ///< half the extent along `axis`
	double halfWidth = 0.0;  ///< half the extent across it
};

/// π to double precision.
inline constexpr double kPi = 3.14159265358979323846264338327950288;

} // namespace b2a

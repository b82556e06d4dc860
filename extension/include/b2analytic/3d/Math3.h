// b2analytic: plain double-precision 3D math for the 3D geometry core (vectors, symmetric
// matrices, rotations as unit quaternions, poses, boxes, z-x-z Euler angles).
#pragma once

#include <cmath>

namespace b2a
{

/// A 3D vector (or point) in double precision.
struct Vec3
{
	double x = 0.0; ///< first component
	double y = 0.0; ///< second component
	double z = 0.0; ///< third component

	/// Zero vector.
	constexpr Vec3() = default;
	/// Vector from components.
	constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
	/// Component i (0, 1 or 2).
	constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
	/// Component i (0, 1 or 2), writable.
	double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

/// Component-wise sum.
constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
/// Component-wise difference.
constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
/// Negation.
constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
/// Scaling by a number.
constexpr Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
/// Scaling by a number.
constexpr Vec3 operator*(Vec3 a, double s) { return {s * a.x, s * a.y, s * a.z}; }
/// Division by a number.
constexpr Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
/// In-place sum.
inline Vec3& operator+=(Vec3& a, Vec3 b) { a.x += b.x; a.y += b.y; a.z += b.z; return a; }
/// In-place difference.
inline Vec3& operator-=(Vec3& a, Vec3 b) { a.x -= b.x; a.y -= b.y; a.z -= b.z; return a; }

/// Dot product.
constexpr double Dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// Cross product.
constexpr Vec3 Cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
/// Squared length.
constexpr double LengthSquared(Vec3 a) { return a.x * a.x + a.y * a.y + a.z * a.z; }
/// Euclidean length (without overflow or underflow for any finite vector).
inline double Length(Vec3 a)
{
	const double s = LengthSquared(a);
	if (s > 1e-290 && s < 1e290)
		return std::sqrt(s);
	return std::hypot(std::hypot(a.x, a.y), a.z);
}
/// Distance between two points.
inline double Distance(Vec3 a, Vec3 b) { return Length(a - b); }
/// True when every component is finite.
inline bool IsFinite(Vec3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
/// Unit vector along a; (0,0,0) when a is zero or not finite.
inline Vec3 Normalize(Vec3 a)
{
	const double len = Length(a);
	if (!(len > 0.0) || !std::isfinite(len))
		return {};
	return a / len;
}
/// Largest absolute component.
inline double MaxAbs(Vec3 a) { return std::fmax(std::fabs(a.x), std::fmax(std::fabs(a.y), std::fabs(a.z))); }

/// A symmetric 3×3 matrix (Hessians, inertia tensors).
struct Sym33
{
	double xx = 0.0; ///< entry (0,0)
	double xy = 0.0; ///< entries (0,1) and (1,0)
	double xz = 0.0; ///< entries (0,2) and (2,0)
	double yy = 0.0; ///< entry (1,1)
	double yz = 0.0; ///< entries (1,2) and (2,1)
	double zz = 0.0; ///< entry (2,2)
};
/// Sum of symmetric matrices.
constexpr Sym33 operator+(const Sym33& a, const Sym33& b)
{
	return {a.xx + b.xx, a.xy + b.xy, a.xz + b.xz, a.yy + b.yy, a.yz + b.yz, a.zz + b.zz};
}
/// Scaling of a symmetric matrix.
constexpr Sym33 operator*(double s, const Sym33& a) { return {s * a.xx, s * a.xy, s * a.xz, s * a.yy, s * a.yz, s * a.zz}; }
/// Matrix-vector product.
constexpr Vec3 operator*(const Sym33& m, Vec3 v)
{
	return {m.xx * v.x + m.xy * v.y + m.xz * v.z, m.xy * v.x + m.yy * v.y + m.yz * v.z, m.xz * v.x + m.yz * v.y + m.zz * v.z};
}
/// Outer product v vᵀ.
constexpr Sym33 Outer(Vec3 v) { return {v.x * v.x, v.x * v.y, v.x * v.z, v.y * v.y, v.y * v.z, v.z * v.z}; }

/// A 3×3 matrix, row-major: m[i][j] is row i, column j.
struct Mat33
{
	double m[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}; ///< entries (identity by default)

	/// Column j.
	constexpr Vec3 Column(int j) const { return {m[0][j], m[1][j], m[2][j]}; }
	/// Row i.
	constexpr Vec3 Row(int i) const { return {m[i][0], m[i][1], m[i][2]}; }
};
/// M·v.
constexpr Vec3 operator*(const Mat33& M, Vec3 v)
{
	return {M.m[0][0] * v.x + M.m[0][1] * v.y + M.m[0][2] * v.z, M.m[1][0] * v.x + M.m[1][1] * v.y + M.m[1][2] * v.z,
	        M.m[2][0] * v.x + M.m[2][1] * v.y + M.m[2][2] * v.z};
}
/// Mᵀ·v.
constexpr Vec3 MulT(const Mat33& M, Vec3 v)
{
	return {M.m[0][0] * v.x + M.m[1][0] * v.y + M.m[2][0] * v.z, M.m[0][1] * v.x + M.m[1][1] * v.y + M.m[2][1] * v.z,
	        M.m[0][2] * v.x + M.m[1][2] * v.y + M.m[2][2] * v.z};
}
/// Product A·B.
Mat33 operator*(const Mat33& A, const Mat33& B);
/// Rotate a symmetric matrix into the world: R H Rᵀ.
Sym33 Rotate(const Mat33& R, const Sym33& H);
/// R D Rᵀ for a diagonal D = diag(d): a body Hessian of the superellipsoid family in the world.
Sym33 RotateDiagonal(const Mat33& R, Vec3 d);

/// A rotation as a unit quaternion w + xi + yj + zk (body → world).
struct Quat
{
	double w = 1.0; ///< scalar part
	double x = 0.0; ///< i component
	double y = 0.0; ///< j component
	double z = 0.0; ///< k component

	/// Identity rotation.
	constexpr Quat() = default;
	/// Quaternion from components (not normalised here).
	constexpr Quat(double w_, double x_, double y_, double z_) : w(w_), x(x_), y(y_), z(z_) {}
};
/// Hamilton product a·b (apply b first, then a).
constexpr Quat operator*(Quat a, Quat b)
{
	return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
	        a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
/// The inverse rotation (conjugate of a unit quaternion).
constexpr Quat Conjugate(Quat q) { return {q.w, -q.x, -q.y, -q.z}; }
/// Norm of the quaternion.
inline double Norm(Quat q) { return std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z); }
/// Unit quaternion along q; the identity when q is zero or not finite.
Quat Normalize(Quat q);
/// Rotation by `angle` radians about the unit axis `axis` (right-handed).
Quat AxisAngle(Vec3 axis, double angle);
/// Rotation by the vector φ: about φ/|φ| by |φ| radians (the exponential map; identity for 0).
Quat RotationVector(Vec3 phi);
/// The rotation matrix of a unit quaternion (body → world).
Mat33 ToMatrix(Quat q);
/// Rotate v by q (body → world).
Vec3 Rotate(Quat q, Vec3 v);
/// Rotate v by the inverse of q (world → body).
Vec3 InvRotate(Quat q, Vec3 v);

/// The rotation R = Rz(ψ)·Rx(θ)·Rz(φ) (z-x-z Euler angles, body → world, each right-handed):
/// the body is turned by φ about z, then by θ about x, then by ψ about z, all about the world's
/// fixed axes (equivalently ψ, θ, φ about the moving axes z, x', z'').
Quat EulerZXZ(double psi, double theta, double phi);
/// The z-x-z Euler angles (ψ, θ, φ) of a rotation, θ in [0, π] (ψ = φ's sum or difference is
/// split as ψ = atan2 and φ = 0 where θ is 0 or π).
Vec3 ToEulerZXZ(Quat q);

/// The pose of a 3D particle: centre and orientation (body → world).
/// Body coordinates of a world point X are x = Rᵀ(X − p).
struct Pose3
{
	Vec3 p; ///< position of the body origin in the world
	Quat q; ///< orientation, a unit quaternion (body → world)

	/// Identity pose.
	Pose3() = default;
	/// Pose from a position and a rotation.
	Pose3(Vec3 position, Quat rotation) : p(position), q(rotation) {}
};
/// Body point → world point.
inline Vec3 ToWorld(const Pose3& t, Vec3 x) { return Rotate(t.q, x) + t.p; }
/// World point → body point.
inline Vec3 ToBody(const Pose3& t, Vec3 X) { return InvRotate(t.q, X - t.p); }
/// True when the position is finite and the rotation is a finite unit quaternion (to 1e-9).
bool IsValidPose(const Pose3& t);

/// An axis-aligned box in 3D.
struct Box3
{
	Vec3 lower; ///< lowest corner
	Vec3 upper; ///< highest corner
};

} // namespace b2a

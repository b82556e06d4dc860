// b2analytic: 3D rotations (quaternions, matrices, z-x-z Euler angles).
#include "b2analytic/3d/Math3.h"

namespace b2a
{

Mat33 operator*(const Mat33& A, const Mat33& B)
{
	Mat33 C;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			C.m[i][j] = A.m[i][0] * B.m[0][j] + A.m[i][1] * B.m[1][j] + A.m[i][2] * B.m[2][j];
	return C;
}

Sym33 Rotate(const Mat33& R, const Sym33& H)
{
	// R H Rᵀ: first M = R H (row i of R times H), then M Rᵀ (its symmetric half).
	const double h[3][3] = {{H.xx, H.xy, H.xz}, {H.xy, H.yy, H.yz}, {H.xz, H.yz, H.zz}};
	double M[3][3];
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			M[i][j] = R.m[i][0] * h[0][j] + R.m[i][1] * h[1][j] + R.m[i][2] * h[2][j];
	auto entry = [&](int i, int j) { return M[i][0] * R.m[j][0] + M[i][1] * R.m[j][1] + M[i][2] * R.m[j][2]; };
	return {entry(0, 0), entry(0, 1), entry(0, 2), entry(1, 1), entry(1, 2), entry(2, 2)};
}

Sym33 RotateDiagonal(const Mat33& R, Vec3 d)
{
	// (R D Rᵀ)ᵢⱼ = Σₖ Rᵢₖ dₖ Rⱼₖ.
	auto entry = [&](int i, int j) { return R.m[i][0] * d.x * R.m[j][0] + R.m[i][1] * d.y * R.m[j][1] + R.m[i][2] * d.z * R.m[j][2]; };
	return {entry(0, 0), entry(0, 1), entry(0, 2), entry(1, 1), entry(1, 2), entry(2, 2)};
}

Quat Normalize(Quat q)
{
	const double n = Norm(q);
	if (!(n > 0.0) || !std::isfinite(n))
		return Quat();
	return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Quat AxisAngle(Vec3 axis, double angle)
{
	const Vec3 u = Normalize(axis);
	const double s = std::sin(0.5 * angle);
	return Normalize(Quat(std::cos(0.5 * angle), s * u.x, s * u.y, s * u.z));
}

Quat RotationVector(Vec3 phi)
{
	const double angle = Length(phi);
	if (!(angle > 0.0))
		return Quat();
	return AxisAngle(phi / angle, angle);
}

Mat33 ToMatrix(Quat q)
{
	const double w = q.w, x = q.x, y = q.y, z = q.z;
	Mat33 R;
	R.m[0][0] = 1.0 - 2.0 * (y * y + z * z);
	R.m[0][1] = 2.0 * (x * y - w * z);
	R.m[0][2] = 2.0 * (x * z + w * y);
	R.m[1][0] = 2.0 * (x * y + w * z);
	R.m[1][1] = 1.0 - 2.0 * (x * x + z * z);
	R.m[1][2] = 2.0 * (y * z - w * x);
	R.m[2][0] = 2.0 * (x * z - w * y);
	R.m[2][1] = 2.0 * (y * z + w * x);
	R.m[2][2] = 1.0 - 2.0 * (x * x + y * y);
	return R;
}

Vec3 Rotate(Quat q, Vec3 v)
{
	// v + 2w (u × v) + 2 u × (u × v), u the vector part: the sandwich q v q* for a unit q.
	const Vec3 u(q.x, q.y, q.z);
	const Vec3 t = 2.0 * Cross(u, v);
	return v + q.w * t + Cross(u, t);
}

Vec3 InvRotate(Quat q, Vec3 v) { return Rotate(Conjugate(q), v); }

Quat EulerZXZ(double psi, double theta, double phi)
{
	const Quat zPsi(std::cos(0.5 * psi), 0.0, 0.0, std::sin(0.5 * psi));
	const Quat xTheta(std::cos(0.5 * theta), std::sin(0.5 * theta), 0.0, 0.0);
	const Quat zPhi(std::cos(0.5 * phi), 0.0, 0.0, std::sin(0.5 * phi));
	return Normalize(zPsi * xTheta * zPhi);
}

Vec3 ToEulerZXZ(Quat q)
{
	// R = Rz(ψ)Rx(θ)Rz(φ) has R₂₂ = cos θ, (R₀₂, R₁₂) = sin θ (sin ψ, −cos ψ) and
	// (R₂₀, R₂₁) = sin θ (sin φ, cos φ).
	const Mat33 R = ToMatrix(Normalize(q));
	const double s = std::hypot(R.m[0][2], R.m[1][2]);
	const double theta = std::atan2(s, R.m[2][2]);
	if (s > 1e-12)
		return {std::atan2(R.m[0][2], -R.m[1][2]), theta, std::atan2(R.m[2][0], R.m[2][1])};
	// θ = 0 or π: only ψ ± φ is defined; R's upper 2×2 block is Rz(ψ ± φ).
	return {std::atan2(R.m[1][0], R.m[0][0]), theta, 0.0};
}

bool IsValidPose(const Pose3& t)
{
	const double n = Norm(t.q);
	return IsFinite(t.p) && std::isfinite(n) && std::fabs(n - 1.0) <= 1e-9;
}

} // namespace b2a

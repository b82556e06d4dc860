// b2analytic: a 4×4 linear solve with its exact condition number (internal).
#pragma once

#include <Eigen/Dense>

#include <cmath>

namespace b2a
{

/// Solution of J·x = r for a 4×4 matrix, and rcond = 1 / (‖J‖₁ ‖J⁻¹‖₁), the reciprocal of the
/// exact 1-norm condition number (0 when J is singular or not finite): Solve3's contract one
/// size up, for the 3D Newton steps on (X, μ).
struct Solve4Result
{
	double x[4] = {0.0, 0.0, 0.0, 0.0}; ///< the solution (zeros when singular)
	double rcond = 0.0;                 ///< reciprocal condition number
};

/// Solve through the inverse (Eigen's cofactor formula for 4×4, no pivoting to choose), whose
/// 1-norm gives the exact condition number the solvers test before trusting a step.
inline Solve4Result Solve4(const double J[4][4], const double r[4])
{
	Solve4Result out;
	Eigen::Matrix4d M;
	for (int i = 0; i < 4; ++i)
		for (int j = 0; j < 4; ++j)
			M(i, j) = J[i][j];
	Eigen::Matrix4d inverse;
	bool invertible = false;
	M.computeInverseWithCheck(inverse, invertible, 0.0);
	if (!invertible || !inverse.allFinite())
		return out;
	const double normJ = M.cwiseAbs().colwise().sum().maxCoeff();
	const double normInverse = inverse.cwiseAbs().colwise().sum().maxCoeff();
	const double rcond = 1.0 / (normJ * normInverse);
	if (!std::isfinite(rcond))
		return out;
	const Eigen::Vector4d x = inverse * Eigen::Vector4d(r[0], r[1], r[2], r[3]);
	for (int i = 0; i < 4; ++i)
		out.x[i] = x(i);
	out.rcond = rcond;
	return out;
}

} // namespace b2a

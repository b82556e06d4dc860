// b2analytic: a 3×3 linear solve with its exact condition number (internal).
#pragma once

#include <cmath>

namespace b2a
{

/// Solution of J·x = r for a 3×3 matrix, and rcond = 1 / (‖J‖₁ ‖J⁻¹‖₁), the reciprocal of the
/// exact 1-norm condition number (0 when J is singular or not finite).
struct Solve3Result
{
	double x[3] = {0.0, 0.0, 0.0}; ///< the solution (zeros when singular)
	double rcond = 0.0;            ///< reciprocal condition number
};

/// Solve through the adjugate: J⁻¹ = adj(J)/det(J), the cofactors computed once. For the Newton
/// steps of the contact solvers (3×3, solved every iteration) this is several times cheaper than
/// a pivoted LU with a condition estimate, and it gives the exact condition number, which the
/// solvers test before trusting a step (they stop below 1e-14; above that the adjugate's
/// rounding, ~eps·cond, is far below what the line search tolerates).
inline Solve3Result Solve3(const double J[3][3], const double r[3])
{
	Solve3Result out;
	double C[3][3]; // C[i][j] = cofactor of J[j][i] (the adjugate)
	C[0][0] = J[1][1] * J[2][2] - J[1][2] * J[2][1];
	C[0][1] = J[0][2] * J[2][1] - J[0][1] * J[2][2];
	C[0][2] = J[0][1] * J[1][2] - J[0][2] * J[1][1];
	C[1][0] = J[1][2] * J[2][0] - J[1][0] * J[2][2];
	C[1][1] = J[0][0] * J[2][2] - J[0][2] * J[2][0];
	C[1][2] = J[0][2] * J[1][0] - J[0][0] * J[1][2];
	C[2][0] = J[1][0] * J[2][1] - J[1][1] * J[2][0];
	C[2][1] = J[0][1] * J[2][0] - J[0][0] * J[2][1];
	C[2][2] = J[0][0] * J[1][1] - J[0][1] * J[1][0];
	const double det = J[0][0] * C[0][0] + J[0][1] * C[1][0] + J[0][2] * C[2][0];
	if (!(std::fabs(det) > 0.0) || !std::isfinite(det))
		return out;
	// 1-norms: largest column sums. (Comparisons, not std::fmax, which is a library call here;
	// a finite det leaves no NaN for fmax's rule to matter.)
	double normJ = 0.0, normC = 0.0;
	for (int j = 0; j < 3; ++j)
	{
		const double sumJ = std::fabs(J[0][j]) + std::fabs(J[1][j]) + std::fabs(J[2][j]);
		const double sumC = std::fabs(C[0][j]) + std::fabs(C[1][j]) + std::fabs(C[2][j]);
		normJ = sumJ > normJ ? sumJ : normJ;
		normC = sumC > normC ? sumC : normC;
	}
	const double inv = 1.0 / det;
	const double rcond = std::fabs(det) / (normJ * normC); // 1 / (‖J‖ · ‖adj J‖ / |det|)
	if (!std::isfinite(rcond) || !std::isfinite(inv))
		return out;
	out.rcond = rcond;
	for (int i = 0; i < 3; ++i)
		out.x[i] = (C[i][0] * r[0] + C[i][1] * r[1] + C[i][2] * r[2]) * inv;
	return out;
}

} // namespace b2a

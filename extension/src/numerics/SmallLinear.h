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

/// Solve3 for the bordered symmetric matrix J = [[h11, h12, g1], [h12, h22, g2], [d1, d2, 0]] of
/// the Newton steps on the common level (a 2×2 Hessian, the multiplier's column g and the
/// level-equality row d): the same adjugate, solution and exact rcond, with the zero and the
/// symmetry written out (about half the operations).
inline Solve3Result SolveBordered(double h11, double h12, double h22, double g1, double g2, double d1, double d2,
                                  const double r[3])
{
	Solve3Result out;
	// Cofactors of J (C[i][j] = cofactor of J[j][i], the adjugate), J[2][2] = 0 and J[1][0] = J[0][1].
	const double c00 = -g2 * d2, c01 = g1 * d2, c02 = h12 * g2 - g1 * h22;
	const double c10 = g2 * d1, c11 = -g1 * d1, c12 = g1 * h12 - h11 * g2;
	const double c20 = h12 * d2 - h22 * d1, c21 = h12 * d1 - h11 * d2, c22 = h11 * h22 - h12 * h12;
	const double det = h11 * c00 + h12 * c10 + g1 * c20;
	if (!(std::fabs(det) > 0.0) || !std::isfinite(det))
		return out;
	const double j0 = std::fabs(h11) + std::fabs(h12) + std::fabs(d1), j1 = std::fabs(h12) + std::fabs(h22) + std::fabs(d2),
	             j2 = std::fabs(g1) + std::fabs(g2);
	const double k0 = std::fabs(c00) + std::fabs(c10) + std::fabs(c20), k1 = std::fabs(c01) + std::fabs(c11) + std::fabs(c21),
	             k2 = std::fabs(c02) + std::fabs(c12) + std::fabs(c22);
	const double normJ = j0 > j1 ? (j0 > j2 ? j0 : j2) : (j1 > j2 ? j1 : j2);
	const double normC = k0 > k1 ? (k0 > k2 ? k0 : k2) : (k1 > k2 ? k1 : k2);
	const double inv = 1.0 / det;
	const double rcond = std::fabs(det) / (normJ * normC);
	if (!std::isfinite(rcond) || !std::isfinite(inv))
		return out;
	out.rcond = rcond;
	out.x[0] = (c00 * r[0] + c01 * r[1] + c02 * r[2]) * inv;
	out.x[1] = (c10 * r[0] + c11 * r[1] + c12 * r[2]) * inv;
	out.x[2] = (c20 * r[0] + c21 * r[1] + c22 * r[2]) * inv;
	return out;
}

} // namespace b2a

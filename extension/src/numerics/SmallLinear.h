// b2analytic: a 3×3 linear solve with its exact condition number (internal).
#pragma once

#include <cmath>
#include <limits>

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

/// The adjugate of the bordered symmetric matrix J = [[h11, h12, g1], [h12, h22, g2], [d1, d2, 0]]
/// of the Newton steps on the common level (a 2×2 Hessian, the multiplier's column g and the
/// level-equality row d), c[i][j] the cofactor of J[j][i], with the zero and the symmetry written
/// out, and det J.
struct BorderedAdjugate
{
	double c[3][3]; ///< adj(J)
	double det;     ///< det(J)
};

/// BorderedAdjugate of J.
inline BorderedAdjugate AdjugateOfBordered(double h11, double h12, double h22, double g1, double g2, double d1, double d2)
{
	BorderedAdjugate a;
	a.c[0][0] = -g2 * d2;
	a.c[0][1] = g1 * d2;
	a.c[0][2] = h12 * g2 - g1 * h22;
	a.c[1][0] = g2 * d1;
	a.c[1][1] = -g1 * d1;
	a.c[1][2] = g1 * h12 - h11 * g2;
	a.c[2][0] = h12 * d2 - h22 * d1;
	a.c[2][1] = h12 * d1 - h11 * d2;
	a.c[2][2] = h11 * h22 - h12 * h12;
	a.det = h11 * a.c[0][0] + h12 * a.c[1][0] + g1 * a.c[2][0];
	return a;
}

/// x = adj(J)·r / det(J).
inline void ApplyAdjugate(const BorderedAdjugate& a, const double r[3], double x[3])
{
	const double inv = 1.0 / a.det;
	for (int i = 0; i < 3; ++i)
		x[i] = (a.c[i][0] * r[0] + a.c[i][1] * r[1] + a.c[i][2] * r[2]) * inv;
}

/// SolveBordered's exact reciprocal condition number of the bordered matrix (its entries as
/// SolveBordered takes them) whose adjugate is `a`; NaN where SolveBordered fails (det J zero or
/// not finite, the condition number or 1/det not finite).
inline double BorderedRcond(const BorderedAdjugate& a, double h11, double h12, double h22, double g1, double g2, double d1,
                            double d2)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	if (!(std::fabs(a.det) > 0.0) || !std::isfinite(a.det))
		return nan;
	const double j0 = std::fabs(h11) + std::fabs(h12) + std::fabs(d1), j1 = std::fabs(h12) + std::fabs(h22) + std::fabs(d2),
	             j2 = std::fabs(g1) + std::fabs(g2);
	double k[3];
	for (int j = 0; j < 3; ++j)
		k[j] = std::fabs(a.c[0][j]) + std::fabs(a.c[1][j]) + std::fabs(a.c[2][j]);
	const double normJ = j0 > j1 ? (j0 > j2 ? j0 : j2) : (j1 > j2 ? j1 : j2);
	const double normC = k[0] > k[1] ? (k[0] > k[2] ? k[0] : k[2]) : (k[1] > k[2] ? k[1] : k[2]);
	const double rcond = std::fabs(a.det) / (normJ * normC); // 1 / (‖J‖ · ‖adj J‖ / |det|)
	if (!std::isfinite(rcond) || !std::isfinite(1.0 / a.det))
		return nan;
	return rcond;
}

/// Whether ApplyAdjugate may divide by a's determinant: nonzero, and its reciprocal finite
/// (SolveBorderedSolution's test; SolveBordered asks for BorderedRcond as well).
inline bool AdjugateInvertible(const BorderedAdjugate& a) { return std::fabs(a.det) > 0.0 && std::isfinite(1.0 / a.det); }

/// Solve3 for the bordered symmetric matrix of BorderedAdjugate: the same adjugate, solution and
/// exact rcond, with the zero and the symmetry written out (about half the operations).
inline Solve3Result SolveBordered(double h11, double h12, double h22, double g1, double g2, double d1, double d2,
                                  const double r[3])
{
	Solve3Result out;
	const BorderedAdjugate a = AdjugateOfBordered(h11, h12, h22, g1, g2, d1, d2);
	const double rcond = BorderedRcond(a, h11, h12, h22, g1, g2, d1, d2);
	if (std::isnan(rcond))
		return out;
	out.rcond = rcond;
	ApplyAdjugate(a, r, out.x);
	return out;
}

/// SolveBordered's solution alone, without the condition number: for a Jacobian within a small
/// Newton step of one whose condition SolveBordered checked. False, x untouched, where det J is
/// zero, not finite, or its inverse overflows.
inline bool SolveBorderedSolution(double h11, double h12, double h22, double g1, double g2, double d1, double d2,
                                  const double r[3], double x[3])
{
	const BorderedAdjugate a = AdjugateOfBordered(h11, h12, h22, g1, g2, d1, d2);
	if (!AdjugateInvertible(a))
		return false;
	ApplyAdjugate(a, r, x);
	return true;
}

} // namespace b2a

// b2analytic: the min–max (Perram–Wertheim) characterisation of the 3D common level: the fallback.
#include "3d/Solvers3.h"

#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>

namespace b2a
{

namespace
{
// Cholesky factor of a symmetric 3×3 matrix; false unless it is positive definite (relative to
// `scale`).
bool Cholesky3(const Sym33& H, double scale, double L[3][3])
{
	const double floor = 1e-14 * scale;
	L[0][0] = H.xx > floor ? std::sqrt(H.xx) : 0.0;
	if (!(L[0][0] > 0.0))
		return false;
	L[1][0] = H.xy / L[0][0];
	L[2][0] = H.xz / L[0][0];
	const double d1 = H.yy - L[1][0] * L[1][0];
	if (!(d1 > floor))
		return false;
	L[1][1] = std::sqrt(d1);
	L[2][1] = (H.yz - L[2][0] * L[1][0]) / L[1][1];
	const double d2 = H.zz - L[2][0] * L[2][0] - L[2][1] * L[2][1];
	if (!(d2 > floor))
		return false;
	L[2][2] = std::sqrt(d2);
	return true;
}

Vec3 CholeskySolve(const double L[3][3], Vec3 b)
{
	// L y = b, then Lᵀ x = y.
	const double y0 = b.x / L[0][0];
	const double y1 = (b.y - L[1][0] * y0) / L[1][1];
	const double y2 = (b.z - L[2][0] * y0 - L[2][1] * y1) / L[2][2];
	const double x2 = y2 / L[2][2];
	const double x1 = (y1 - L[2][1] * x2) / L[1][1];
	const double x0 = (y0 - L[1][0] * x1 - L[2][0] * x2) / L[0][0];
	return {x0, x1, x2};
}

// X(ν) = argmin ψA + e^ν ψB by damped Newton from xi (updated in place), with a Levenberg shift
// where the Hessian is only semi-definite (flat faces, points far from both shapes). Both ψ are
// convex, so the direction descends and the backtracking search converges. Returns ψA − ψB there.
double InnerMinimum(const PairFrame3& f, double nu, Vec3& xi, int& evaluations)
{
	const double trust = std::max(0.5, 0.5 * Length(f.Xi(f.b.pose.p) - f.Xi(f.a.pose.p)));
	const double mu = std::exp(nu);
	for (int it = 0; it < 100; ++it)
	{
		const GaugeValue3 A = f.Eval(f.a, xi, true), B = f.Eval(f.b, xi, true);
		++evaluations;
		const Vec3 g = A.grad + mu * B.grad;
		Sym33 H = A.hess + mu * B.hess;
		const double phi = A.psi + mu * B.psi;
		const double scale = std::fabs(H.xx) + std::fabs(H.yy) + std::fabs(H.zz) +
		                     2.0 * (std::fabs(H.xy) + std::fabs(H.xz) + std::fabs(H.yz));
		if (!(scale > 0.0) || !std::isfinite(scale))
			break; // a Hessian that vanishes gives no scale for the shift
		double L[3][3];
		double shift = 1e-12 * scale;
		bool factored = Cholesky3(H, scale, L);
		// The shifts exceed the scale by the 14th try, where the shifted matrix is diagonally
		// dominant: the cap is never reached.
		for (int k = 0; k < 30 && !factored; ++k)
		{
			H.xx += shift;
			H.yy += shift;
			H.zz += shift;
			shift *= 10.0;
			factored = Cholesky3(H, scale, L);
		}
		if (!factored)
			break;
		Vec3 step = -CholeskySolve(L, g);
		const double len = MaxAbs(step);
		if (!(len > 0.0) || !std::isfinite(len))
			break;
		if (len > trust)
			step = (trust / len) * step;
		const double slope = Dot(g, step);
		double alpha = 1.0;
		bool accepted = false;
		for (int k = 0; k < 50; ++k, alpha *= 0.5)
		{
			const Vec3 trial = xi + alpha * step;
			if (f.Psi(f.a, trial) + mu * f.Psi(f.b, trial) <= phi + 1e-4 * alpha * slope)
			{
				xi = trial;
				accepted = true;
				break;
			}
		}
		if (!accepted || alpha * len < 1e-15)
			break;
	}
	return f.Psi(f.a, xi) - f.Psi(f.b, xi);
}
} // namespace

LevelResult3 SolveCommonLevelMinMax(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                                    const SolverOptions& options)
{
	LevelResult3 result;
	result.method = SolveMethod::minMax;
	if (!a.IsSmoothConvex() || !b.IsSmoothConvex())
	{
		result.failure = "the min-max solver needs smooth, strictly convex shapes";
		return result;
	}
	const PairFrame3 f(a, pa, b, pb);
	Vec3 xi0;
	double mu0 = 1.0;
	if (!GeometricStart3(f, xi0, mu0))
	{
		result.failure = "coincident centres: no common-level point between them";
		return result;
	}
	int evaluations = 0;
	// g(ν) = ψA(X(ν)) − ψB(X(ν)) increases with ν: weight on B pulls X towards B's centre.
	Vec3 xiLo = xi0, xiHi = xi0;
	double lo = std::log(mu0), hi = lo;
	double glo = InnerMinimum(f, lo, xiLo, evaluations), ghi = glo;
	xiHi = xiLo;
	double step = 1.0;
	for (int k = 0; k < 80 && glo > 0.0; ++k, step *= 2.0)
	{
		hi = lo;
		ghi = glo;
		xiHi = xiLo;
		lo -= step;
		glo = InnerMinimum(f, lo, xiLo, evaluations);
	}
	step = 1.0;
	for (int k = 0; k < 80 && ghi < 0.0; ++k, step *= 2.0)
	{
		lo = hi;
		glo = ghi;
		xiLo = xiHi;
		hi += step;
		ghi = InnerMinimum(f, hi, xiHi, evaluations);
	}
	if (!(glo <= 0.0 && ghi >= 0.0))
	{
		result.failure = "min-max: the multiplier could not be bracketed";
		result.iterations = evaluations;
		return result;
	}
	Vec3 xi = 0.5 * (xiLo + xiHi);
	auto g = [&](double nu) { return InnerMinimum(f, nu, xi, evaluations); };
	const ScalarResult root = FindRootBrent(g, lo, hi, glo, ghi, 1e-15, 200);
	g(root.x); // leave xi at the minimiser of the final ν
	result.iterations = root.iterations;

	// Polish with Newton from here (inside its basin now): its answer is taken where it stayed
	// within 1e-3 of the pair's size or its level is at most max(λA, λB) at the min–max point,
	// which bounds the common level from above (the 2D solver's rule).
	const GaugeValue3 A = f.Eval(f.a, xi, false);
	LevelResult3 polished = RunNewton3(f, xi, root.x, options);
	const double bound = A.finite ? std::max(A.lambda, f.Eval(f.b, xi, false).lambda) : std::nan("");
	if (polished.Ok() && (Length(f.Xi(polished.point) - xi) < 1e-3 || polished.level <= bound * (1.0 + 1e-3)))
	{
		polished.method = SolveMethod::minMax;
		polished.iterations += result.iterations;
		return polished;
	}
	if (!A.finite)
	{
		result.failure = "min-max: non-finite level at the answer";
		return result;
	}
	result.status = SolveStatus::converged;
	result.level = A.lambda;
	result.point = f.World(xi);
	result.normal = Normalize(A.grad);
	result.multiplier = std::exp(root.x);
	return result;
}

} // namespace b2a

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

// X(ν) = argmin ψA + e^ν ψB by Newton with a Levenberg–Marquardt shift from xi (updated in
// place). Both ψ are convex, so the shifted direction descends; the shift grows where a step
// needs cutting back (flat faces of high exponents, whose Hessian nearly vanishes along them and
// whose Newton steps run far along the face) and shrinks where full steps are taken, so that the
// direction across the faces, which sets ψA − ψB, converges however flat they are. Stops where
// the step's predicted decrease is at the rounding of the sum. Returns ψA − ψB there.
double InnerMinimum(const PairFrame3& f, double nu, Vec3& xi, int& evaluations)
{
	const double trust = std::max(0.5, 0.5 * Length(f.Xi(f.b.pose.p) - f.Xi(f.a.pose.p)));
	const double mu = std::exp(nu);
	double damping = 1e-12; // relative to the Hessian's size
	for (int it = 0; it < 200; ++it)
	{
		const GaugeValue3 A = f.Eval(f.a, xi, true), B = f.Eval(f.b, xi, true);
		++evaluations;
		const Vec3 g = A.grad + mu * B.grad;
		const Sym33 H0 = A.hess + mu * B.hess;
		const double phi = A.psi + mu * B.psi;
		const double scale = std::fabs(H0.xx) + std::fabs(H0.yy) + std::fabs(H0.zz) +
		                     2.0 * (std::fabs(H0.xy) + std::fabs(H0.xz) + std::fabs(H0.yz));
		if (!(scale > 0.0) || !std::isfinite(scale) || !std::isfinite(phi))
			break; // a Hessian that vanishes gives no scale for the shift
		bool moved = false;
		for (int attempt = 0; attempt < 40 && !moved && damping < 1e12; ++attempt)
		{
			Sym33 H = H0;
			double L[3][3];
			bool factored = false;
			for (int k = 0; k < 30 && !factored; ++k, damping *= 10.0)
			{
				H = H0;
				H.xx += damping * scale;
				H.yy += damping * scale;
				H.zz += damping * scale;
				factored = Cholesky3(H, scale, L);
				if (factored)
					break;
			}
			if (!factored)
				return f.Psi(f.a, xi) - f.Psi(f.b, xi);
			Vec3 step = -CholeskySolve(L, g);
			const double len = MaxAbs(step);
			if (!(len > 0.0) || !std::isfinite(len))
				return f.Psi(f.a, xi) - f.Psi(f.b, xi);
			if (len > trust)
				step = (trust / len) * step;
			const double slope = Dot(g, step);
			if (!(-slope > 1e-30 * std::fabs(phi)))
				return f.Psi(f.a, xi) - f.Psi(f.b, xi); // converged: nothing left to gain
			double alpha = 1.0;
			for (int k = 0; k < 6; ++k, alpha *= 0.5)
			{
				const Vec3 trial = xi + alpha * step;
				if (f.Psi(f.a, trial) + mu * f.Psi(f.b, trial) <= phi + 1e-4 * alpha * slope)
				{
					xi = trial;
					moved = true;
					break;
				}
			}
			// Full steps: trust the quadratic model more; cut-back or rejected ones: less.
			if (moved && alpha == 1.0)
				damping = std::max(1e-12, 0.1 * damping);
			else
				damping *= moved ? 4.0 : 100.0;
		}
		if (!moved)
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
	// Brent's steps capped at four per Newton iteration allowed (200 by default): a small cap in
	// the options stops the min-max early too, and its answer is then held to the same test.
	const int brentCap = std::min(200, 4 * std::max(1, options.maxIterations));
	const ScalarResult root = FindRootBrent(g, lo, hi, glo, ghi, 1e-15, brentCap);
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
	// Unpolished, its own point is the answer only where it solves the conditions to the standard
	// of any converged answer (the inner minimum or the multiplier's root may have stopped short).
	if (!ConditionsHold3(f, xi))
	{
		result.failure = root.converged ? "min-max: stopped short of a solution (its levels or normals disagree beyond rounding)"
		                                : "min-max: the multiplier's root did not converge within the cap";
		result.iterations = evaluations;
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

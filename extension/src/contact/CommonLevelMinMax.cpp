// b2analytic: the min–max (Perram–Wertheim) characterisation of the common level: the fallback.
#include "b2analytic/CommonLevel.h"

#include "contact/SolverCore.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

namespace
{
// X(ν) = argmin ψA + e^ν ψB by damped Newton from xi (updated in place). Both ψ are convex, so
// the Newton direction (with a small Levenberg shift when the Hessian is only semi-definite)
// descends and a backtracking search converges. Returns ψA − ψB at the minimiser.
double InnerMinimum(const PairFrame& f, double nu, Vec2& xi, int& evaluations)
{
	// Steps may cover half the pair's size or half the distance between the centres.
	const double trust = std::max(0.5, 0.5 * Length(f.Xi(f.b.pose.p) - f.Xi(f.a.pose.p)));
	const double mu = std::exp(nu);
	for (int it = 0; it < 100; ++it)
	{
		const GaugeValue A = f.Eval(f.a, xi, true), B = f.Eval(f.b, xi, true);
		++evaluations;
		const Vec2 g = A.grad + mu * B.grad;
		Sym22 H = A.hess + mu * B.hess;
		const double phi = A.psi + mu * B.psi;
		// A Hessian that vanishes (or overflows) gives no scale for the shift, which would never
		// grow from zero. Far from both shapes the gauges are that flat; stop there.
		const double scale = std::fabs(H.xx) + std::fabs(H.yy) + 2.0 * std::fabs(H.xy);
		if (!(scale > 0.0) || !std::isfinite(scale))
			break;
		double det = H.xx * H.yy - H.xy * H.xy;
		double shift = 1e-12 * scale;
		// The shifts add up to more than 2 · scale by the 14th try; past that both diagonal
		// entries exceed 2|H.xy| and det ≥ 3/4 · scale². 30 tries is a cap that is never reached.
		for (int k = 0; k < 30 && !(det > 1e-14 * scale * scale && H.xx > 0.0 && H.yy > 0.0); ++k)
		{
			H.xx += shift;
			H.yy += shift;
			det = H.xx * H.yy - H.xy * H.xy;
			shift *= 10.0;
		}
		Vec2 step(-(H.yy * g.x - H.xy * g.y) / det, -(H.xx * g.y - H.xy * g.x) / det);
		const double len = std::max(std::fabs(step.x), std::fabs(step.y));
		if (!(len > 0.0) || !std::isfinite(len))
			break;
		if (len > trust)
			step = (trust / len) * step;
		const double slope = Dot(g, step);
		double alpha = 1.0;
		bool accepted = false;
		double value = phi;
		for (int k = 0; k < 50; ++k, alpha *= 0.5)
		{
			const Vec2 trial = xi + alpha * step;
			value = f.Psi(f.a, trial) + mu * f.Psi(f.b, trial);
			if (value <= phi + 1e-4 * alpha * slope)
			{
				xi = trial;
				accepted = true;
				break;
			}
		}
		if (!accepted || alpha * len < 1e-15)
			break;
		// Far from the minimiser the sum grows like a power of high degree k (ψ of a needle with
		// exponent 20 in the gauge of another's exponent 2: k ≈ 10), where Newton's step covers
		// 1/(k − 1) of the way: from a start at ψ ~ 1e46 a hundred full steps did not reach the
		// minimiser, and its wrong sign of ψA − ψB closed the outer bracket on a false root.
		// Where the full step more than halved the sum, longer ones are tried while they lower
		// it further (within the trust region).
		if (alpha == 1.0 && value < 0.5 * phi)
			for (double longer = 2.0; longer * len <= trust; longer *= 2.0)
			{
				const Vec2 trial = xi + (longer - alpha) * step;
				const double further = f.Psi(f.a, trial) + mu * f.Psi(f.b, trial);
				if (!(further < value))
					break;
				xi = trial;
				value = further;
				alpha = longer;
			}
	}
	return f.Psi(f.a, xi) - f.Psi(f.b, xi);
}
} // namespace

LevelResult SolveCommonLevelMinMax(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options)
{
	LevelResult result;
	result.method = SolveMethod::minMax;
	if (!a.IsSmoothConvex() || !b.IsSmoothConvex())
	{
		result.failure = "the min-max solver needs smooth, strictly convex shapes";
		return result;
	}
	const PairFrame f(a, pa, b, pb);
	Vec2 xi0;
	double mu0 = 1.0;
	if (!GeometricStart(f, xi0, mu0))
	{
		result.failure = "coincident centres: no common-level point between them";
		return result;
	}
	int evaluations = 0;
	// g(ν) = ψA(X(ν)) − ψB(X(ν)) increases with ν: weight on B pulls X towards B's centre.
	Vec2 xiLo = xi0, xiHi = xi0;
	double lo = std::log(mu0), hi = lo;
	double glo = InnerMinimum(f, lo, xiLo, evaluations), ghi = glo;
	xiHi = xiLo;
	double step = 1.0;
	for (int k = 0; k < 80 && glo > 0.0; ++k, step *= 2.0)
	{
		hi = lo; ghi = glo; xiHi = xiLo;
		lo -= step;
		glo = InnerMinimum(f, lo, xiLo, evaluations);
	}
	step = 1.0;
	for (int k = 0; k < 80 && ghi < 0.0; ++k, step *= 2.0)
	{
		lo = hi; glo = ghi; xiLo = xiHi;
		hi += step;
		ghi = InnerMinimum(f, hi, xiHi, evaluations);
	}
	if (!(glo <= 0.0 && ghi >= 0.0))
	{
		result.failure = "min-max: the multiplier could not be bracketed";
		result.iterations = evaluations;
		return result;
	}
	Vec2 xi = 0.5 * (xiLo + xiHi);
	auto g = [&](double nu) { return InnerMinimum(f, nu, xi, evaluations); };
	const ScalarResult root = FindRootBrent(g, lo, hi, glo, ghi, 1e-15, 200);
	g(root.x); // leave xi at the minimiser of the final ν
	result.iterations = root.iterations;

	return PolishCommonLevel(f, xi, root.x, options, result, "min-max: non-finite level at the answer",
	                         "min-max: stopped short of a solution (its levels or normals disagree beyond rounding)");
}

} // namespace b2a

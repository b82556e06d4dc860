// b2analytic: a fallback's common-level answer polished by Newton, or held to the conditions.
#include "contact/SolverCore.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

LevelResult PolishCommonLevel(const PairFrame& f, Vec2 xi, double nu, const SolverOptions& options, LevelResult result,
                              const char* nonFinite, const char* stoppedShort)
{
	// Newton from the candidate: it is inside Newton's basin now. Newton's answer is taken where
	// it stayed within 1e-3 of the pair's size, or where its level is at most max(λA, λB) at the
	// candidate (with 1e-3 for the rounding of levels like 1e12). Any point's larger level bounds
	// the common level from above, and Newton's converged point (equal levels, opposed gradients)
	// is the common level's point itself, unique for convex shapes. Where the min–max bracket
	// closed on a flat inner minimum (a needle 1e6 of its size from a giant: the point 6e5 sizes
	// off, in b2a_stress), the bound holds and the distance does not.
	const GaugeValue A = f.Eval(f.a, xi, false);
	LevelResult polished = RunNewton(f, xi, nu, options);
	const double bound = A.finite ? std::max(A.lambda, f.Eval(f.b, xi, false).lambda) : std::nan(""); // NaN: no bound
	if (polished.Ok() && (Length(f.Xi(polished.point) - xi) < 1e-3 || polished.level <= bound * (1.0 + 1e-3)))
	{
		polished.method = result.method;
		polished.iterations += result.iterations;
		return polished;
	}
	if (!A.finite)
	{
		result.failure = nonFinite;
		return result;
	}
	// Newton's polish failed: the candidate itself is the answer only where it solves the
	// conditions to the same standard (ConditionsHold; the min–max inner minimisation and Brent's
	// bracket, and the grid's samples and bracket, each stop at their own tolerances, which a
	// needle's levels do not see).
	const GaugeValue a2 = f.Eval(f.a, xi, true), b2 = f.Eval(f.b, xi, true);
	const double reach = std::max({Length(f.World(xi)), Length(f.a.pose.p), Length(f.b.pose.p)});
	if (!ConditionsHold(a2.psi, b2.psi, a2.grad, b2.grad, a2.hess, b2.hess, std::numeric_limits<double>::epsilon() * reach / f.scale,
	                    f.power))
	{
		result.status = SolveStatus::failed;
		result.failure = stoppedShort;
		return result;
	}
	result.status = SolveStatus::converged;
	result.level = A.lambda;
	result.point = f.World(xi);
	result.normal = Normalize(A.grad);
	result.multiplier = std::exp(nu);
	return result;
}

LevelResult CheckGridCommonLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                                 const LevelResult& grid)
{
	if (!grid.Ok())
		return grid;
	const PairFrame f(a, pa, b, pb);
	const Vec2 xi = f.Xi(grid.point);
	// μ balancing the gauges' gradients at the grid's point (∇ψA + μ∇ψB = 0 at a solution).
	const GaugeValue A = f.Eval(f.a, xi, false), B = f.Eval(f.b, xi, false);
	const double ratio = Length(A.grad) / Length(B.grad);
	const double nu = ratio > 0.0 && std::isfinite(ratio) ? std::log(ratio) : 0.0;
	LevelResult candidate;
	candidate.method = grid.method;
	candidate.iterations = grid.iterations;
	return PolishCommonLevel(f, xi, nu, options, candidate, "grid: non-finite level at the answer",
	                         "grid: stopped short of a solution (its levels or normals disagree beyond rounding)");
}

} // namespace b2a

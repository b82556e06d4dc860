// b2analytic: Newton's method for the one-sided scale (A rescaled onto B's surface).
#include "b2analytic/CommonLevel.h"

#include "contact/SolverCore.h"
#include "contact/PairFrame.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
// The smallest level of A on B's surface is a critical point of λA on the curve ψB = 1, where
// the two gradients are parallel (either way round: antiparallel when A's centre is outside B,
// parallel when inside). So solve, for X alone,
//   F1 = n̂A × n̂B = 0,   F2 = ψB − 1 = 0,
// with unit normals n̂ = ∇ψ/|∇ψ|. Both equations are dimensionless or in B's level units, which
// keeps the system well scaled however different the two sizes are (a multiplier would carry
// their ratio). Differentiating the unit normals, dn̂ = t (t·H dX)/|∇ψ| with t = Perp(n̂):
//   ∇F1 = (t_A × n̂B) H_A t_A / |∇ψA| + (n̂A × t_B) H_B t_B / |∇ψB|,   ∇F2 = ∇ψB.
struct Point
{
	Vec2 xi;
	GaugeValue A, B;
	Vec2 na, nb;
	double F1 = 0.0, F2 = 0.0;
	bool finite = false;
};

Point Evaluate(const PairFrame& f, Vec2 xi, double psiB0)
{
	Point p;
	p.xi = xi;
	p.A = f.Eval(f.a, xi, true);
	p.B = f.Eval(f.b, xi, true);
	p.na = Normalize(p.A.grad);
	p.nb = Normalize(p.B.grad);
	p.F1 = Cross(p.na, p.nb);
	p.F2 = p.B.psi - psiB0;
	p.finite = p.A.finite && p.B.finite && LengthSquared(p.na) > 0.0 && LengthSquared(p.nb) > 0.0;
	return p;
}

// Whether a point solves the one-sided conditions to what double precision allows, on the
// conditions themselves (ConditionsResidual's standard): B's gauge within 1e-11 of its own level
// and the unit normals parallel to 1e-10 rad, or each within ten times what the rounding of the
// point's coordinates leaves. (The merit's own units, an angle and a length in ξ, cannot see a
// needle's thickness: a length of 1e-10 of the pair's size is a level off by 1e-4 across a needle
// of 1e-6.)
bool ScaleSolved(const PairFrame& f, const Point& p, double psiB0)
{
	const double eps = std::numeric_limits<double>::epsilon();
	const double reach = std::max({Length(f.World(p.xi)), Length(f.a.pose.p), Length(f.b.pose.p)});
	const double delta = eps * reach / f.scale;
	const double ga = Length(p.A.grad), gb = Length(p.B.grad);
	const Vec2 t = Perp(p.na);
	ConditionsResidual r;
	r.level = std::fabs(p.F2) / psiB0;
	r.levelFloor = gb * delta / psiB0 + 4.0 * eps;
	r.angle = std::fabs(p.F1);
	r.angleFloor = (std::fabs(Dot(t, p.A.hess * t)) / ga + std::fabs(Dot(t, p.B.hess * t)) / gb) * delta + 4.0 * eps;
	r.valid = std::isfinite(r.level + r.levelFloor + r.angle + r.angleFloor);
	return r.Within(1e-11, 1e-10, f.power);
}

LevelResult RunScaleNewton(const PairFrame& f, Vec2 xi, double trust, const SolverOptions& options)
{
	LevelResult result;
	result.method = SolveMethod::newton;
	const double psiB0 = f.PsiOfLevel(1.0);
	Point p = Evaluate(f, xi, psiB0);
	for (int it = 1; it <= std::max(1, options.maxIterations); ++it)
	{
		result.iterations = it;
		if (!p.finite)
		{
			result.failure = "non-finite level value or derivative during Newton iteration";
			return result;
		}
		const Vec2 ta = Perp(p.na), tb = Perp(p.nb);
		const double ga = Length(p.A.grad), gb = Length(p.B.grad);
		const Vec2 row1 = (Cross(ta, p.nb) / ga) * (p.A.hess * ta) + (Cross(p.na, tb) / gb) * (p.B.hess * tb);
		Eigen::Matrix2d J;
		J << row1.x, row1.y, p.B.grad.x, p.B.grad.y;
		const Eigen::FullPivLU<Eigen::Matrix2d> lu(J);
		if (!(lu.rcond() > 1e-14))
		{
			result.failure = "singular or ill-conditioned Jacobian";
			return result;
		}
		Eigen::Vector2d delta = lu.solve(Eigen::Vector2d(-p.F1, -p.F2));
		const double step = std::max(std::fabs(delta[0]), std::fabs(delta[1]));
		double limit = step > trust ? trust / step : 1.0;
		delta *= limit;
		// Line search on F1² + (F2/|∇ψB|)², both in comparable units (an angle and a length in ξ).
		const double w2 = 1.0 / (gb * gb);
		auto merit = [&](const Point& q) { return q.F1 * q.F1 + w2 * q.F2 * q.F2; };
		const double m0 = merit(p);
		double alpha = 1.0;
		Point next;
		bool accepted = false;
		for (int k = 0; k < 40; ++k, alpha *= 0.5)
		{
			next = Evaluate(f, p.xi + alpha * Vec2(delta[0], delta[1]), psiB0);
			if (next.finite && merit(next) <= (1.0 - 1e-4 * alpha) * m0)
			{
				accepted = true;
				break;
			}
		}
		if (!accepted)
		{
			if (ScaleSolved(f, p, psiB0))
				break; // rounding floor
			result.failure = "line search stalled (no step lowers the residual)";
			return result;
		}
		p = next;
		// A step below the tolerance ends the solve only at a solution.
		if ((limit == 1.0 && alpha == 1.0 && alpha * step <= options.stepTolerance && ScaleSolved(f, p, psiB0)) ||
		    merit(p) == 0.0)
			break;
		if (it == options.maxIterations)
		{
			result.failure = "iteration cap reached";
			return result;
		}
	}
	result.status = SolveStatus::converged;
	result.failure = "";
	result.level = p.A.lambda / f.a.unit; // A's level in its own units, as the grid reports
	result.point = f.World(p.xi);
	result.normal = p.na;
	result.multiplier = -Dot(p.A.grad, p.B.grad) / LengthSquared(p.B.grad);
	return result;
}
} // namespace

LevelResult SolveScaleANewton(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options)
{
	LevelResult result;
	if (!NewtonApplies(a, b, result))
		return result;
	const PairFrame f(a, pa, b, pb);
	// λA on B's surface has a minimum and a maximum (more when A's centre is inside B) and Newton
	// finds whichever critical point is near. Start near the lowest local minima of A's level over
	// B's surface samples (as many as the grid method uses), lowest first, with steps no longer
	// than half the distance to the neighbouring trial points (the basin of the minimum lies
	// between them; near a thin tip the maximum is not much farther), and keep the lowest answer
	// that is a minimum along the surface (its neighbours at ±1e-4 rad of B's polar angle are
	// not lower). Where none is, the result says so.
	const SurfaceSamples* samples = &b.SamplesRef(std::max(8, options.gridSamples));
	const int n = samples->Count();
	const Pose bInA = Relative(pa, pb);
	std::vector<double> level(n);
	for (int k = 0; k < n; ++k)
		level[k] = a.Level(ToWorld(bInA, samples->point[k]));
	std::vector<int> starts;
	for (int k = 0; k < n; ++k)
		if (level[k] <= level[(k + n - 1) % n] && level[k] < level[(k + 1) % n])
			starts.push_back(k);
	std::sort(starts.begin(), starts.end(), [&](int i, int j) { return level[i] < level[j]; });
	const double unit = a.SurfaceLevel() > 0.0 ? a.SurfaceLevel() : 1.0;
	LevelResult best;
	best.method = SolveMethod::newton;
	best.failure = "no sample of B's surface to start from";
	int spent = 0;
	for (size_t s = 0; s < starts.size() && s < 3; ++s)
	{
		// Narrow the start between the neighbouring samples, twice by eight: a thin particle's
		// tip against another's side has a basin much narrower than the samples' spacing.
		const int k = starts[s];
		double lo, hi, mid = samples->angle[k];
		samples->NeighbourAngles(k, lo, hi);
		double bestLevel = level[k];
		for (int round = 0; round < 2; ++round)
		{
			const double step = (hi - lo) / 8.0;
			for (int j = 1; j < 8; ++j)
			{
				const double t = lo + j * step;
				const double l = a.Level(ToWorld(bInA, b.SurfacePoint(t)));
				if (l < bestLevel)
				{
					bestLevel = l;
					mid = t;
				}
			}
			lo = mid - step;
			hi = mid + step;
		}
		const Vec2 p = b.SurfacePoint(mid);
		const double gap = std::min(Distance(p, b.SurfacePoint(lo)), Distance(p, b.SurfacePoint(hi)));
		const double trust = std::max(0.5 * gap / f.scale, 1e-12);
		LevelResult r = RunScaleNewton(f, f.Xi(ToWorld(pb, p)), trust, options);
		spent += r.iterations;
		if (!r.Ok())
		{
			if (!best.Ok())
				best = r;
			continue;
		}
		const Vec2 x = ToBody(pb, r.point);
		const double theta = std::atan2(x.y, x.x);
		bool minimum = true;
		for (double d : {-1e-4, 1e-4})
			if (a.Level(ToWorld(bInA, b.SurfacePoint(theta + d))) < r.level - 1e-12 * std::max(std::fabs(r.level), unit))
				minimum = false;
		if (!minimum)
		{
			r.status = SolveStatus::failed;
			r.failure = "Newton converged to a critical point of A's level on B's surface that is not its minimum";
			if (!best.Ok())
				best = r;
			continue;
		}
		if (!best.Ok() || r.level < best.level)
			best = r; // the lowest of the minima found
	}
	best.iterations = spent;
	return best;
}

} // namespace b2a

// b2analytic: the grid method in 3D (paper section 3): B's surface samples on its parameter
// grid, the lowest local minima of A's level refined to the exact minimum, and the grid's
// common level as a fixed point.
#include "3d/Solvers3.h"

#include "numerics/NelderMead.h"
#include "numerics/RootFinding.h"
#include "numerics/Solve4.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
// A's level (own units) over B's level-L surface, and what the refinements need of the pair.
struct SurfaceScan
{
	const PairFrame3& f;
	double levelB;  // B's level L (λB's own units, 1 = its surface)
	double spacing; // the samples' largest spacing at level 1 (world length)

	Vec3 OnB(Vec3 bodyDirection) const
	{
		return f.b.shape->PointOnRay(bodyDirection, levelB * f.b.shape->SurfaceLevel());
	}
	double LevelA(Vec3 world) const { return f.a.unit * f.a.shape->Level(f.a.Body(world)); }
	Vec3 World(Vec3 bodyB) const { return f.b.pose.p + f.b.R * bodyB; }
};

struct Found
{
	Vec3 bodyB;   // the point in B's body frame
	double level; // A's level there (own units)
	int iterations = 0;
	bool ok = false;
};

// Newton on ∇ψA + μ∇ψB = 0, ψB = ψ(L) in (ξ, μ) from a sample: J = [[H_A + μH_B, ∇ψB], [∇ψBᵀ, 0]]
// (symmetric), steps limited to four sample spacings and damped by backtracking on the residual.
// μ is free in sign: where A's centre lies inside B's level surface the gradients are parallel.
Found RefineByNewton(const SurfaceScan& s, const Vec3 startBodyB, double startLevel)
{
	const PairFrame3& f = s.f;
	const double target = f.PsiOfLevel(s.levelB);
	// Steps of a tenth of the level surface's size along the ray through the start.
	const double trust = 0.1 * Length(startBodyB) / f.scale;
	Vec3 xi = f.Xi(s.World(startBodyB));
	Found out;
	auto residual = [&](const GaugeValue3& A, const GaugeValue3& B, double mu, double r[4]) {
		const Vec3 g = A.grad + mu * B.grad;
		r[0] = g.x;
		r[1] = g.y;
		r[2] = g.z;
		r[3] = B.psi - target;
		return LengthSquared(g) / (LengthSquared(A.grad) + 1e-300) + r[3] * r[3] / (target * target + 1e-300);
	};
	GaugeValue3 A = f.Eval(f.a, xi, true), B = f.Eval(f.b, xi, true);
	double mu = -Dot(A.grad, B.grad) / (LengthSquared(B.grad) + 1e-300);
	double r[4];
	double merit = residual(A, B, mu, r);
	for (int it = 1; it <= 50; ++it)
	{
		out.iterations = it;
		if (!(A.finite && B.finite && std::isfinite(merit)))
			return out;
		const Sym33 H = A.hess + mu * B.hess;
		const double J[4][4] = {{H.xx, H.xy, H.xz, B.grad.x},
		                        {H.xy, H.yy, H.yz, B.grad.y},
		                        {H.xz, H.yz, H.zz, B.grad.z},
		                        {B.grad.x, B.grad.y, B.grad.z, 0.0}};
		const double minusR[4] = {-r[0], -r[1], -r[2], -r[3]};
		const Solve4Result step = Solve4(J, minusR);
		if (!(step.rcond > 1e-14))
		{
			if (merit < 1e-24)
				break;
			return out;
		}
		Vec3 d(step.x[0], step.x[1], step.x[2]);
		double dmu = step.x[3];
		const double len = MaxAbs(d);
		double limit = len > trust ? trust / len : 1.0;
		d = limit * d;
		dmu *= limit;
		double alpha = 1.0;
		bool accepted = false;
		for (int k = 0; k < 30; ++k, alpha *= 0.5)
		{
			const Vec3 x2 = xi + alpha * d;
			const GaugeValue3 A2 = f.Eval(f.a, x2, true), B2 = f.Eval(f.b, x2, true);
			double r2[4];
			const double m2 = residual(A2, B2, mu + alpha * dmu, r2);
			if (A2.finite && B2.finite && m2 <= (1.0 - 1e-4 * alpha) * merit)
			{
				xi = x2;
				A = A2;
				B = B2;
				mu += alpha * dmu;
				merit = m2;
				std::copy(r2, r2 + 4, r);
				accepted = true;
				break;
			}
		}
		if (!accepted)
		{
			if (merit < 1e-24)
				break;
			return out;
		}
		const double moved = alpha * limit * len;
		if ((limit == 1.0 && alpha == 1.0 && moved <= 1e-14) || merit < 1e-30)
			break;
	}
	// A minimum of A's level on B's surface, not a saddle or maximum: no higher than its sample.
	out.bodyB = f.b.Body(f.World(xi));
	out.level = A.lambda;
	out.ok = merit < 1e-20 && A.lambda <= startLevel * (1.0 + 1e-9) + 1e-300;
	return out;
}

// Nelder–Mead over the directions around the sample's (B's body frame): where the level has
// kinks (exponents below 2) or Newton does not settle. The point is on B's level surface by
// construction; its accuracy is that of a derivative-free minimum (the level to rounding, the
// point to about the square root of it on smooth stretches, exact at a kink).
Found RefineByNelderMead(const SurfaceScan& s, const Vec3 startBodyB)
{
	const Vec3 d0 = startBodyB;
	const double len = Length(d0);
	// Two directions across d0, of its length.
	const Vec3 helper = std::fabs(d0.x) <= std::fabs(d0.y) && std::fabs(d0.x) <= std::fabs(d0.z) ? Vec3(1, 0, 0)
	                    : std::fabs(d0.y) <= std::fabs(d0.z)                                     ? Vec3(0, 1, 0)
	                                                                                              : Vec3(0, 0, 1);
	const Vec3 e1 = len * Normalize(Cross(d0, helper));
	const Vec3 e2 = Normalize(Cross(d0, e1)) * len;
	auto at = [&](double u, double v) { return s.OnB(d0 + u * e1 + v * e2); };
	auto level = [&](double u, double v) { return s.LevelA(s.World(at(u, v))); };
	const double step = std::max(s.spacing / std::max(len, 1e-300), 1e-6);
	// Restarted from where it stopped, with a fresh simplex, until a restart gains nothing: a
	// simplex that collapsed across a narrow valley of the level stalls short of its minimum.
	Minimum2 m = MinimizeNelderMead(level, 0.0, 0.0, 0.5 * step, 1e-14, 600);
	int evaluations = m.evaluations;
	for (int restart = 0; restart < 8; ++restart)
	{
		const Minimum2 again = MinimizeNelderMead(level, m.x[0], m.x[1], 0.05 * step, 1e-14, 600);
		evaluations += again.evaluations;
		const bool gainedEnough = again.fx < m.fx * (1.0 - 1e-14);
		if (again.fx < m.fx)
			m = again;
		if (!gainedEnough)
			break;
	}
	Found out;
	out.bodyB = at(m.x[0], m.x[1]);
	out.level = m.fx;
	out.iterations = evaluations;
	out.ok = std::isfinite(m.fx);
	return out;
}

// Newton where it settles on a minimum, else Nelder–Mead.
Found Refine(const SurfaceScan& s, Vec3 startBodyB, double startLevel)
{
	const Found n = RefineByNewton(s, startBodyB, startLevel);
	if (n.ok)
		return n;
	Found m = RefineByNelderMead(s, startBodyB);
	m.iterations += n.iterations;
	return m;
}

// The grid: A's level at every sample of B's level-L surface, its lowest local minima refined
// (or, without refinement, the lowest sample).
LevelResult3 GridScale(const PairFrame3& f, const SolverOptions& options, double levelB)
{
	LevelResult3 result;
	result.method = SolveMethod::grid;
	if (!(levelB > 0.0) || !std::isfinite(levelB))
	{
		result.failure = "the level of B must be finite and > 0";
		return result;
	}
	const SurfaceSamples3& samples = f.b.shape->Samples(options.gridSamples);
	const SurfaceScan s{f, levelB, samples.maxSpacing};
	Found best;
	best.level = std::numeric_limits<double>::infinity();
	const int n = samples.Count();
	std::vector<Vec3> onB(n);
	std::vector<double> value(n);
	for (int i = 0; i < n; ++i)
	{
		onB[i] = levelB == 1.0 ? samples.point[i] : s.OnB(samples.point[i]);
		value[i] = s.LevelA(s.World(onB[i]));
	}
	std::vector<int> minima, nb;
	for (int i = 0; i < n; ++i)
	{
		samples.Neighbours(i, nb);
		bool lowest = std::isfinite(value[i]);
		for (int j : nb)
			lowest = lowest && value[i] <= value[j];
		if (lowest)
			minima.push_back(i);
	}
	if (minima.empty())
	{
		result.failure = "grid: no finite level on the samples";
		return result;
	}
	std::sort(minima.begin(), minima.end(), [&](int i, int j) { return value[i] < value[j]; });
	const int candidates = options.gridRefine ? std::max(1, std::min(options.gridCandidates, int(minima.size()))) : 1;
	int iterations = 0;
	for (int c = 0; c < candidates; ++c)
	{
		const int i = minima[c];
		Found found{onB[i], value[i], 0, true};
		if (options.gridRefine)
		{
			const Found refined = Refine(s, onB[i], value[i]);
			iterations += refined.iterations;
			if (refined.ok && refined.level <= value[i])
			{
				found.bodyB = refined.bodyB;
				found.level = refined.level;
			}
		}
		if (found.level < best.level)
			best = found;
	}
	best.iterations = iterations;
	if (!best.ok || !std::isfinite(best.level))
	{
		result.failure = "grid: the refinement failed";
		return result;
	}
	const Vec3 X = s.World(best.bodyB);
	const Vec3 xi = f.Xi(X);
	const GaugeValue3 A = f.Eval(f.a, xi, false), B = f.Eval(f.b, xi, false);
	result.status = SolveStatus::converged;
	result.iterations = std::max(best.iterations, 1);
	result.level = best.level;
	result.point = X;
	result.normal = Normalize(A.grad);
	result.multiplier = -Dot(A.grad, B.grad) / (LengthSquared(B.grad) + 1e-300);
	return result;
}
} // namespace

LevelResult3 SolveGridScale(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                            double levelB)
{
	const PairFrame3 f(a, pa, b, pb);
	return GridScale(f, options, std::isnan(levelB) ? 1.0 : levelB / b.SurfaceLevel());
}

LevelResult3 SolveScaleA(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, MethodChoice method,
                         const SolverOptions& options)
{
	(void)method; // every choice is the refined grid in 3D (its Newton is the refinement)
	SolverOptions o = options;
	o.gridRefine = true;
	return SolveGridScale(a, pa, b, pb, o);
}

LevelResult3 SolveCommonLevelGrid(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options)
{
	LevelResult3 result;
	result.method = SolveMethod::grid;
	if (!a.IsConvex() || !b.IsConvex())
	{
		result.failure = "the grid's common level needs convex shapes (use SolveScaleA)";
		return result;
	}
	if (CentresCoincide(a, pa, b, pb))
	{
		result.failure = "coincident centres: no common-level point between them";
		return result;
	}
	const PairFrame3 f(a, pa, b, pb);
	// C = min over X of max(λA, λB) is the fixed point of g̃(C), the least level of A over B's
	// level-C set: A's centre's level (0) where that set holds it, else the least over its
	// surface (g, the grid). g̃ does not increase with C, so h(C) = g̃(C) − C decreases, and the
	// root lies below λB(A's centre), where h = −C < 0. From any C with h(C) < 0 and g̃(C) > 0,
	// C' = g̃(C) has h(C') ≥ 0 (and the other way round): two evaluations bracket the root.
	const double centreInB = f.b.unit * b.Level(f.b.Body(pa.p));
	int iterations = 0;
	LevelResult3 last;
	// Every evaluation scans B's samples afresh: a refinement from the last answer alone can stay
	// in a local minimum that is not the least, and the bracket would break.
	auto gTilde = [&](double C) {
		if (C >= centreInB)
			return 0.0;
		LevelResult3 r = GridScale(f, options, C);
		iterations += r.iterations;
		if (!r.Ok())
			return std::numeric_limits<double>::quiet_NaN();
		last = r;
		return r.level;
	};
	double c0 = std::min(1.0, 0.5 * centreInB);
	double g0 = gTilde(c0);
	if (!std::isfinite(g0))
		return last;
	double c1 = g0, g1 = gTilde(c1);
	for (int k = 0; k < 60 && g1 == 0.0 && g0 < c0; ++k)
		g1 = gTilde(c1 *= 0.5); // A's centre inside B's level-g̃ set: come down until it is not
	if (!std::isfinite(g1))
		return last;
	double lo = std::min(c0, c1), hi = std::max(c0, c1);
	double hLo = (lo == c0 ? g0 : g1) - lo, hHi = (hi == c0 ? g0 : g1) - hi;
	if (!(hLo >= 0.0 && hHi <= 0.0))
	{
		result.failure = "grid: the fixed point C = g(C) could not be bracketed";
		result.iterations = iterations;
		return result;
	}
	const ScalarResult root = FindRootBrent([&](double C) { return gTilde(C) - C; }, lo, hi, hLo, hHi, 0.0, 200);
	if (!(root.converged || std::fabs(root.fx) <= 1e-12 * hi))
	{
		result.failure = "grid: the fixed point C = g(C) did not converge";
		result.iterations = iterations;
		return result;
	}
	// The answer at the root itself (Brent's last evaluation may be the bracket's other end).
	if (!(std::fabs(last.level - root.x) <= 1e-12 * root.x))
		gTilde(root.x);
	last.iterations = iterations;
	last.method = SolveMethod::grid;
	// The root's bracket closes to rounding in C, but the point moves with C faster than C does
	// where the surfaces are flat (1e-9 of the size): where both shapes are smooth, a polish by
	// Newton on the common level's equations from here, inside its quadratic regime. Where it
	// does not take, the grid's point is the answer only where it solves the conditions to the
	// same standard (ConditionsHold3). (With kinks, exponents below 2, the conditions do not hold
	// at a kink and the grid's minimum is the answer as it stands.)
	if (!options.gridRefine)
		return last;
	if (a.IsSmoothConvex() && b.IsSmoothConvex() && last.multiplier > 0.0)
	{
		SolverOptions polish = options;
		polish.maxIterations = 8;
		const LevelResult3 n = RunNewton3(f, f.Xi(last.point), std::log(last.multiplier), polish);
		if (n.Ok() && Distance(n.point, last.point) <= 1e-6 * f.scale)
		{
			last.level = n.level;
			last.point = n.point;
			last.normal = n.normal;
			last.multiplier = n.multiplier;
			last.iterations += n.iterations;
			return last;
		}
	}
	if (a.IsSmoothConvex() && b.IsSmoothConvex() && !ConditionsHold3(f, f.Xi(last.point)))
	{
		last.status = SolveStatus::failed;
		last.failure = "grid: stopped short of a solution (its levels or normals disagree beyond rounding)";
	}
	return last;
}

} // namespace b2a

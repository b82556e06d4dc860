// b2analytic: Newton–Raphson on the common level (paper eqs. 6–17), with step control.
#include "b2analytic/CommonLevel.h"

#include "contact/SolverCore.h"
#include "contact/WarmSlide.h"
#include "numerics/RootFinding.h"
#include "numerics/SmallLinear.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
struct NewtonPoint
{
	Vec2 xi;
	double m = 0.0;
	double mu = 1.0; // e^m, kept with m
	GaugeValue A, B;
	double r[3] = {0.0, 0.0, 0.0};
	double relative = 0.0; // residual relative to the size of its terms
	bool finite = false;
};

// The residual at a point whose shapes are evaluated, for multiplier μ (it enters only here, so
// trying another multiplier at the same point costs no shape evaluation): fills r and returns
// its size relative to the size of its terms.
double Residual(const NewtonPoint& p, double mu, double r[3])
{
	const Vec2 r12 = p.A.grad + mu * p.B.grad;
	const double r3 = p.A.psi - p.B.psi;
	r[0] = r12.x;
	r[1] = r12.y;
	r[2] = r3;
	const double gradScale = LengthSquared(p.A.grad) + mu * mu * LengthSquared(p.B.grad) + 1e-300;
	const double levelScale = p.A.psi * p.A.psi + p.B.psi * p.B.psi + 1e-300;
	return std::sqrt(LengthSquared(r12) / gradScale + r3 * r3 / levelScale);
}

// Sets the multiplier m = log μ of an evaluated point and its residual. In place: a NewtonPoint
// holds two gauges with Hessians, and copying it was a visible part of a warm solve.
void SetMultiplier(NewtonPoint& p, double m, double mu)
{
	p.m = m;
	p.mu = mu;
	p.relative = Residual(p, mu, p.r);
	p.finite = p.A.finite && p.B.finite && std::isfinite(mu) && std::isfinite(p.relative);
}

void Evaluate(const PairFrame& f, Vec2 xi, double m, NewtonPoint& p)
{
	p.xi = xi;
	p.A = f.Eval(f.a, xi, true);
	p.B = f.Eval(f.b, xi, true);
	SetMultiplier(p, m, std::exp(m));
}

// The least-squares multiplier for the point, μ = −∇ψA·∇ψB / |∇ψB|², where it lowers the
// residual: the multiplier is only as good as the point it was found at, and a stale one makes
// Newton crawl.
void TakeLeastSquaresMultiplier(NewtonPoint& p)
{
	const double gb2 = LengthSquared(p.B.grad);
	const double muLs = gb2 > 0.0 ? -Dot(p.A.grad, p.B.grad) / gb2 : 0.0;
	const double mLs = muLs > 0.0 ? std::log(muLs) : p.m;
	if (mLs != p.m && std::isfinite(mLs))
	{
		double r[3];
		const double relative = Residual(p, muLs, r);
		if (std::isfinite(relative) && relative < p.relative)
			SetMultiplier(p, mLs, muLs);
	}
}

// The step that would confirm convergence, taken to first order without evaluating the shapes
// again: ξ and m move by δ, and ψA and its gradient follow from the derivatives already at hand
// (ψ + ∇ψ·δ, ∇ψ + ∇²ψ·δ), exact to O(|δ|²) ~ 1e-26.
void TakeUnevaluatedStep(const PairFrame& f, NewtonPoint& p, const double delta[3])
{
	const Vec2 d(delta[0], delta[1]);
	p.xi = p.xi + d;
	p.m += delta[2];
	p.mu = std::exp(p.m);
	// λ = ψ^q, so dλ = q·λ·dψ/ψ.
	const double dpsi = Dot(p.A.grad, d);
	if (p.A.psi > 0.0)
		p.A.lambda += f.power * p.A.lambda * dpsi / p.A.psi;
	p.A.psi += dpsi;
	p.A.grad = p.A.grad + p.A.hess * d;
}

// Backtracking line search along δ on the residual, with row weights frozen at p (for any fixed
// positive weights the Newton direction descends): the first of α = 1, ½, ¼, … whose point
// lowers the merit enough, evaluated into `next`. At the rounding floor (a residual that the
// stall test accepts) a step that does not lower the merit at once or after two halvings will
// not at all: forty halvings there cost forty evaluations for nothing. False where none does.
bool LineSearch(const PairFrame& f, const NewtonPoint& p, const double delta[3], NewtonPoint& next, double& alpha)
{
	const double w12 = 1.0 / (LengthSquared(p.A.grad) + p.mu * p.mu * LengthSquared(p.B.grad) + 1e-300);
	const double w3 = 1.0 / (p.A.psi * p.A.psi + p.B.psi * p.B.psi + 1e-300);
	auto merit = [&](const NewtonPoint& q) { return w12 * (q.r[0] * q.r[0] + q.r[1] * q.r[1]) + w3 * q.r[2] * q.r[2]; };
	const double merit0 = merit(p);
	const int halvings = p.relative < 1e-9 ? 3 : 40;
	alpha = 1.0;
	for (int k = 0; k < halvings; ++k, alpha *= 0.5)
	{
		Evaluate(f, p.xi + alpha * Vec2(delta[0], delta[1]), p.m + alpha * delta[2], next);
		if (next.finite && merit(next) <= (1.0 - 1e-4 * alpha) * merit0)
			return true;
	}
	return false;
}

// How far an evaluated point is from solving the conditions (ResidualOfConditions): its
// coordinates are rounded to a part in 1e16 of the largest world coordinate in play, the
// point's or a centre's.
ConditionsResidual ResidualAt(const PairFrame& f, const NewtonPoint& p)
{
	const double reach = std::max({Length(f.World(p.xi)), Length(f.a.pose.p), Length(f.b.pose.p)});
	const double delta = std::numeric_limits<double>::epsilon() * reach / f.scale;
	return ResidualOfConditions(p.A.psi, p.B.psi, p.A.grad, p.B.grad, p.A.hess, p.B.hess, delta);
}

// Whether an evaluated point solves the conditions to what double precision allows
// (ConditionsHold's standard).
bool Solved(const PairFrame& f, const NewtonPoint& p)
{
	if (ConditionsWithin(p.A.psi, p.B.psi, p.A.grad, p.B.grad, 1e-11, 1e-11))
		return true; // (the common case, before the roots of the reach)
	return ResidualAt(f, p).Within(1e-11, 1e-10, f.power);
}

// The answer at the solved point: a solution has opposed gradients (a point where both gradients
// are tiny, deep inside both particles, can satisfy the residual test with parallel ones).
LevelResult Answer(const PairFrame& f, const NewtonPoint& p, LevelResult result, LevelSlide* slide)
{
	if (!(Dot(Normalize(p.A.grad), Normalize(p.B.grad)) < -1.0 + 1e-6))
	{
		result.failure = "converged to a point where the gradients are not opposed";
		return result;
	}
	result.status = SolveStatus::converged;
	result.failure = "";
	// Common levels are reported relative to the own levels (C ≤ 1 ⇔ touching).
	result.level = p.A.lambda;
	result.point = f.World(p.xi);
	result.normal = Normalize(p.A.grad);
	result.multiplier = p.mu;
	if (slide) // ξ has the world's axes in units of the frame's scale
		ComputeSlide(p.A.grad, p.A.hess, p.B.hess, result.normal, p.mu, f.scale, Rot(), *slide);
	return result;
}
} // namespace

LevelResult RunNewton(const PairFrame& f, Vec2 xi, double m, const SolverOptions& options, LevelSlide* slide)
{
	if (slide)
		slide->valid = false;
	LevelResult result;
	result.method = SolveMethod::newton;
	const double trust = std::max(0.5, 0.5 * Length(f.Xi(f.b.pose.p) - f.Xi(f.a.pose.p)));
	// Two points, the current one and the trial, swapped when a trial is accepted.
	NewtonPoint points[2];
	NewtonPoint* current = &points[0];
	NewtonPoint* trial = &points[1];
	Evaluate(f, xi, m, *current);
	const int cap = std::max(1, options.maxIterations);
	double previousMoved = 0.0; // the last full step's length in ξ (0: none yet)
	bool lastStep = false;      // converged to within the tolerance: one more step, unevaluated
	int forced = 0;             // full steps taken where the line search stalled
	for (int it = 1; it <= cap; ++it)
	{
		NewtonPoint& p = *current;
		result.iterations = it;
		if (!p.finite)
		{
			result.failure = "non-finite level value or derivative during Newton iteration";
			return result;
		}
		TakeLeastSquaresMultiplier(p);
		const double mu = p.mu;
		// Jacobian of (∇ψA + μ∇ψB, third equation) with respect to (ξ, m).
		const Sym22 H = p.A.hess + mu * p.B.hess;
		const Vec2 dmu = mu * p.B.grad;
		const Vec2 row3 = p.A.grad - p.B.grad;
		// J = [[H, μ∇ψB], [(∇ψA − ∇ψB)ᵀ, 0]]: bordered, solved with its zero and symmetry written out
		// (the same cofactors, solution and rcond as Solve3's, in about half the operations).
		const double minusR[3] = {-p.r[0], -p.r[1], -p.r[2]};
		const Solve3Result step = SolveBordered(H.xx, H.xy, H.yy, dmu.x, dmu.y, row3.x, row3.y, minusR);
		if (!BorderedStepUsable(step.rcond, H.xx, H.xy, H.yy, dmu.x, dmu.y, row3.x, row3.y))
		{
			if (Solved(f, p))
				break; // already solved: the Jacobian is singular only at the answer's rounding level
			result.failure = "singular or ill-conditioned Jacobian";
			return result;
		}
		double delta[3] = {step.x[0], step.x[1], step.x[2]};
		if (lastStep)
		{
			TakeUnevaluatedStep(f, p, delta);
			break;
		}
		// Trust region: at most half the pair's size or of the distance between the centres
		// (whichever is larger) in ξ, and a factor e² in μ.
		double limit = 1.0;
		const double stepXi = std::max(std::fabs(delta[0]), std::fabs(delta[1]));
		if (stepXi > trust) limit = std::min(limit, trust / stepXi);
		const double mLimit = 2.0;
		if (std::fabs(delta[2]) > mLimit) limit = std::min(limit, mLimit / std::fabs(delta[2]));
		for (double& d : delta)
			d *= limit;
		double alpha = 1.0;
		if (!LineSearch(f, p, delta, *trial, alpha))
		{
			if (Solved(f, p))
				break; // rounding floor: no step can lower the residual any more
			// Near the solution (levels and normals to 1e-4, or the normals within ten times
			// their rounding) the full step is right even where rounding hides its gain from the
			// line search: a needle's gradient grows like 1/thickness and so does the rounding
			// of its length, and at a sharp tip the normals' rounding may swamp the residual
			// while the levels still differ. Taken twice at most, and the point then tested as
			// any other.
			if (!(forced < 2 && ResidualAt(f, p).Within(1e-4, 1e-4, f.power)))
			{
				result.failure = "line search stalled (no step lowers the residual)";
				return result;
			}
			++forced;
			alpha = 1.0;
			Evaluate(f, p.xi + Vec2(delta[0], delta[1]), p.m + delta[2], *trial);
		}
		const double moved = alpha * std::max(std::fabs(delta[0]), std::fabs(delta[1]));
		std::swap(current, trial); // p is the previous point from here on
		const bool full = limit == 1.0 && alpha == 1.0;
		// A step below the tolerance ends the solve only at a solution: a needle's point moves
		// by a part in 1e13 of the pair's size where its levels still differ by a factor 1.1.
		if ((full && moved <= options.stepTolerance && Solved(f, *current)) || current->relative < 1e-15)
			break;
		// Quadratic convergence: two full steps δ₁, δ₂ in a row give K ≈ |δ₂|/|δ₁|², and the
		// error left at the new point is about K·|δ₂|². Where that is below the step tolerance
		// (with a factor 10 of margin) the step that would confirm it is taken without its
		// evaluation: a warm start then takes two evaluations after the first instead of three.
		// The estimate needs a contraction (|δ₂| < |δ₁|/4), so a slow or erratic approach is
		// never cut short, and the relative residual already 1e-6 (the contraction alone can
		// mislead: between a needle and a larger particle the steps contract by 1e4 where the
		// levels still differ by a factor 2).
		if (full && previousMoved > 0.0 && moved < 0.25 * previousMoved && current->relative <= 1e-6)
		{
			const double K = moved / (previousMoved * previousMoved);
			lastStep = 10.0 * K * moved * moved <= options.stepTolerance;
		}
		previousMoved = full ? moved : 0.0;
		if (it == cap)
		{
			result.failure = "iteration cap reached";
			return result;
		}
	}
	return Answer(f, *current, result, slide);
}

bool GeometricStart(const PairFrame& f, Vec2& xi, double& mu)
{
	if (CentresCoincide(*f.a.shape, f.a.pose, *f.b.shape, f.b.pose))
		return false;
	const Vec2 ca = f.Xi(f.a.pose.p), cb = f.Xi(f.b.pose.p);
	// ψA − ψB goes from −ψB(cA) < 0 to ψA(cB) > 0 along the segment: one root.
	auto phi = [&](double t) {
		const Vec2 x = ca + t * (cb - ca);
		return f.Psi(f.a, x) - f.Psi(f.b, x);
	};
	// A guess from the surfaces' radii along the centre line, rA towards B and rB towards A: where
	// both ψ are homogeneous of one degree k (superellipses with equal exponents, of one family or
	// ζ-normalised), ψA = (s/rA)^k and ψB = ((D − s)/rB)^k at distance s from A's centre, so the
	// root is exactly t = rA/(rA + rB). Otherwise it is a close start and Brent's method only needs
	// the half of the segment on the far side of the guess.
	const Vec2 dir = Normalize(f.b.pose.p - f.a.pose.p);
	const double rA = f.a.shape->RadiusAt(InvRotate(f.a.pose.q, dir), f.a.shape->SurfaceLevel());
	const double rB = f.b.shape->RadiusAt(InvRotate(f.b.pose.q, -dir), f.b.shape->SurfaceLevel());
	double t = 0.5;
	if (rA > 0.0 && rB > 0.0 && std::isfinite(rA + rB))
		t = rA / (rA + rB);
	const Vec2 xt = ca + t * (cb - ca);
	const double psiA = f.Psi(f.a, xt), psiB = f.Psi(f.b, xt);
	const double phiT = psiA - psiB;
	if (!(std::fabs(phiT) <= 1e-9 * (psiA + psiB)))
	{
		// The tolerance is absolute in t and must stay far below a small particle's share of the
		// segment (size ratios of 1e5 put the root at t ~ 1e-5).
		const ScalarResult r = phiT > 0.0 ? FindRootBrent(phi, 0.0, t, phi(0.0), phiT, 1e-10, 100)
		                                  : FindRootBrent(phi, t, 1.0, phiT, phi(1.0), 1e-10, 100);
		t = r.x;
	}
	xi = ca + t * (cb - ca);
	const double ga = Length(f.Eval(f.a, xi, false).grad), gb = Length(f.Eval(f.b, xi, false).grad);
	mu = (ga > 0.0 && gb > 0.0 && std::isfinite(ga / gb)) ? ga / gb : 1.0;
	return true;
}

LevelResult SolveCommonLevelNewton(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                   const SolverOptions& options, const WarmStart* warm)
{
	return SolveCommonLevelNewton(a, pa, b, pb, options, warm, nullptr);
}

LevelResult SolveCommonLevelNewton(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                                   const WarmStart* warm, LevelSlide* slide)
{
	if (slide)
		slide->valid = false;
	LevelResult result;
	if (!NewtonApplies(a, b, result))
		return result;
	const PairFrame f(a, pa, b, pb);
	Vec2 xi;
	double mu = 1.0;
	if (warm && warm->valid && warm->multiplier > 0.0 && IsFinite(warm->localPoint))
	{
		// Where the point went with both bodies' motions and the slide along the surfaces.
		xi = f.Xi(ToWorld(pa, WarmStartPoint(*warm, pa, pb, f.scale)));
		mu = warm->multiplier;
	}
	else if (!GeometricStart(f, xi, mu))
	{
		result.failure = "coincident centres: no common-level point between them";
		return result;
	}
	return RunNewton(f, xi, std::log(mu), options, slide);
}

} // namespace b2a

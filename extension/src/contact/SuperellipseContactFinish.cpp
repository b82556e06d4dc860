// b2analytic: the last Newton steps of two smooth superellipses (exponents ≥ 2, integer or
// real), on the raw levels f (no gauge roots), and their contact points by Halley steps.
#include "b2analytic/Contact.h"
#include "contact/ResultChecks.h"
#include "contact/SolverCore.h"
#include "contact/WarmSlide.h"

#include "b2analytic/SuperellipseShape.h"
#include "geometry/SuperellipseTerms.h"
#include "numerics/CodeLayout.h"
#include "numerics/SmallLinear.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

namespace
{
// Both shapes at x (A's body frame, world lengths): f, ∇f and ∇²f of each in A's frame, and x in
// B's body frame. B's derivatives are turned by r (B's axes in A's frame): ∇f ↦ R∇f and
// diag(hx, hy) ↦ R diag(hx, hy) Rᵀ.
// `Real`: some exponent is not an integer, and each axis takes its power |X|^{n−2} from one
// std::pow (SmoothSuperellipseDerivatives, the level and its derivatives all from that value);
// pairs of integer exponents keep the multiplications alone (IntegerSuperellipseDerivatives,
// the same values without PowAbs's choice between pow and products).
struct PairDerivatives
{
	double fA, fB;
	Vec2 gA, gB;
	Sym22 hA, hB;
	Vec2 xB;
};

// Whether ∇²f is Lipschitz continuous: each exponent an integer ≥ 2 or a real ≥ 3.
inline bool LipschitzHessian(const SuperellipseTerms& t)
{
	return (t.nInt >= 2 || t.n >= 3.0) && (t.mInt >= 2 || t.m >= 3.0);
}

template <bool Real>
inline AxisDerivatives AxisDerivativesOf(const SuperellipseTerms& t, Vec2 x)
{
	if (Real)
		return SmoothSuperellipseDerivatives(t, x.x, x.y);
	return t.nInt == t.mInt ? IntegerSuperellipseDerivativesEqual(t, x.x, x.y) : IntegerSuperellipseDerivatives(t, x.x, x.y);
}

// Out of line, one copy for the start and the steps: a warm contact runs it two or three times
// among much other code, where each inlined copy would take instruction cache lines of its own.
template <bool Real>
B2A_NOINLINE void EvaluatePair(const SuperellipseTerms& ta, const SuperellipseTerms& tb, const Pose& rel, Vec2 x, PairDerivatives& e)
{
	const AxisDerivatives da = AxisDerivativesOf<Real>(ta, x);
	e.fA = da.f;
	e.gA = Vec2(da.gx, da.gy);
	e.hA = Sym22{da.hx, 0.0, da.hy};
	e.xB = InvRotate(rel.q, x - rel.p);
	const AxisDerivatives db = AxisDerivativesOf<Real>(tb, e.xB);
	const double c = rel.q.c, s = rel.q.s;
	e.fB = db.f;
	e.gB = Rotate(rel.q, Vec2(db.gx, db.gy));
	e.hB = Sym22{c * c * db.hx + s * s * db.hy, c * s * (db.hx - db.hy), s * s * db.hx + c * c * db.hy};
}

// RawConditionsHold's test beyond ConditionsWithin (ConditionsHold's residual and floors), rarely
// reached: out of line.
B2A_COLD bool RawConditionsHoldBeyond(const PairDerivatives& e, double reach2)
{
	const double eps = std::numeric_limits<double>::epsilon();
	return ConditionsHold(e.fA, e.fB, e.gA, e.gB, e.hA, e.hB, eps * std::sqrt(reach2), 1.0);
}

// Whether the raw levels at x solve the conditions (ConditionsHold: their mismatch and the
// normals' alignment, to what the rounding of x allows). Every exit of the steps tests it, the
// last step taken unevaluated too (its values are exact to O(|δ|²)): NearSolution's 1e-5 rad
// before that step does not bound the normals after it.
// And the point's rounding must keep the normals (RoundingKeepsNormals), or agreement in
// double shows nothing.
bool RawConditionsHold(const PairDerivatives& e, Vec2 x, const Pose& rel, const Pose& pa, const Pose& pb)
{
	const double eps = std::numeric_limits<double>::epsilon();
	const double reach2 = std::max({LengthSquared(x), LengthSquared(rel.p), LengthSquared(pa.p), LengthSquared(pb.p)});
	if (!RoundingKeepsNormals(e.gA, e.gB, e.hA, e.hB, eps * eps * reach2))
		return false;
	return ConditionsWithin(e.fA, e.fB, e.gA, e.gB, 1e-11, 1e-11) || RawConditionsHoldBeyond(e, reach2);
}

// Newton on the raw levels from (x, μ) with the pair evaluated there in e: plain steps, with no
// line search, trust region or fallback of their own. A step larger than 5 % of the size, one
// that does not contract by 4 as Newton does in its quadratic regime, a singular Jacobian or 4
// steps without settling return false. On success x, μ and e are the answer, and `iterations`
// the steps taken.
// `linearLast` (read for Real only: integer exponents always may): whether the last step may be
// taken unevaluated. Its values f + ∇f·δ and
// ∇f + ∇²f·δ are exact to O(|δ|²) where ∇²f is Lipschitz: every exponent an integer ≥ 2 or a
// real ≥ 3 (|X|^{n−2} with n − 2 ≥ 1). For a real n in (2, 3), ∇²f ∝ |X|^{n−2} is only Hölder
// continuous at the axis X = 0, of order n − 2 < 1, and the gradient's model errs by up to
// (n/a)|δx/a|^{n−1}: against |∇f| ≈ m/b on the face that crosses the axis, a normal turned by
// |δx/a|^{n−1}, 1e-9 rad for a last step of 1e-6 of the size and n = 2.5 (NewtonSettled allows
// steps that large). There the settled step is evaluated, and the exit's RawConditionsHold
// sees the true values.
template <bool Real>
bool NewtonOnRawLevels(const SuperellipseTerms& ta, const SuperellipseTerms& tb, const Pose& pa, const Pose& pb, const Pose& rel,
                       const SolverOptions& options, double size, bool linearLast, Vec2& x, double& mu, PairDerivatives& e,
                       int& iterations)
{
	const double tolerance = options.stepTolerance * size; // on the point, in world lengths
	double previous = 0.0, previousMu = 0.0;                // the last step in x and in μ (0: none yet)
	for (int it = 1;; ++it)
	{
		if (it > 4)
			return false;
		iterations = it;
		// Jacobian of (∇fA + μ∇fB, fA − fB) in (x, μ): [[HA + μHB, ∇fB], [(∇fA − ∇fB)ᵀ, 0]]. Its
		// condition gets the full solver's test at the start only: the later Jacobians lie within
		// contracting steps (the first at most 5 % of the size) of it.
		const double minusR[3] = {-(e.gA.x + mu * e.gB.x), -(e.gA.y + mu * e.gB.y), e.fB - e.fA};
		const double hxx = e.hA.xx + mu * e.hB.xx, hxy = e.hA.xy + mu * e.hB.xy, hyy = e.hA.yy + mu * e.hB.yy;
		const double dxA = e.gA.x - e.gB.x, dyA = e.gA.y - e.gB.y;
		// (One adjugate for both cases, SolveBordered's at the first step and SolveBorderedSolution's
		// after: the same values, in one copy of the code.)
		const BorderedAdjugate adjugate = AdjugateOfBordered(hxx, hxy, hyy, e.gB.x, e.gB.y, dxA, dyA);
		if (it == 1 ? !BorderedStepUsable(BorderedRcond(adjugate, hxx, hxy, hyy, e.gB.x, e.gB.y, dxA, dyA), hxx, hxy, hyy, e.gB.x,
		                                  e.gB.y, dxA, dyA)
		            : !AdjugateInvertible(adjugate))
			return false;
		double delta[3];
		ApplyAdjugate(adjugate, minusR, delta);
		const Vec2 dx(delta[0], delta[1]);
		const double dmu = delta[2];
		// The steps in x (world lengths) and in μ; the bounds on μ's step are relative, so they
		// are multiplied by μ (no division).
		const double stepX = std::max(std::fabs(dx.x), std::fabs(dx.y)), stepMu = std::fabs(dmu);
		if (!(stepX <= 0.05 * size) || !(stepMu <= 0.5 * mu))
			return false; // not near the answer (or not finite)
		if (previous > 0.0 && !(stepX <= 0.25 * previous || stepX <= tolerance))
			return false; // not contracting: not in Newton's quadratic regime
		// The last step may be taken unevaluated where the steps show the quadratic regime and
		// the point is near the solution (NearSolution: the contraction alone can mislead).
		const bool settled = previous > 0.0 && previous <= 1e-2 * size && NewtonSettled(stepX, previous, tolerance) &&
		                     NewtonSettled(stepMu, previousMu, options.stepTolerance * mu) && NearSolution(e.fA, e.fB, e.gA, e.gB);
		if (settled && (!Real || linearLast))
		{
			// The last step, taken without evaluating the shapes: f + ∇f·δ and ∇f + ∇²f·δ, exact to
			// O(|δ|²), far below the tolerance here.
			e.fA += Dot(e.gA, dx);
			e.fB += Dot(e.gB, dx);
			e.gA = e.gA + e.hA * dx;
			e.gB = e.gB + e.hB * dx;
			x = x + dx;
			mu += dmu;
			e.xB = InvRotate(rel.q, x - rel.p);
			return mu > 0.0 && RawConditionsHold(e, x, rel, pa, pb);
		}
		x = x + dx;
		mu += dmu;
		EvaluatePair<Real>(ta, tb, rel, x, e);
		// A step below the tolerance ends the steps only at a solution (ConditionsHold on the raw
		// levels: their mismatch and the normals' alignment, to what the rounding of x allows); so
		// may a settled step taken evaluated (not linearLast).
		if (((Real && settled) || stepX <= tolerance) && RawConditionsHold(e, x, rel, pa, pb))
			return mu > 0.0;
		previous = stepX;
		previousMu = stepMu;
	}
}

// The far crossing by SuperellipseFarCrossing where the Halley steps declined, and the contact by
// ContactFromLevel where a line misses a particle: rare, and kept out of line (cold), so that the
// common path's code stays in fewer instruction cache lines.
B2A_COLD bool FallbackFarCrossing(const SuperellipseTerms& t, Vec2 x, Vec2 d, double& at)
{
	return SuperellipseFarCrossing(t, x, d, at);
}
B2A_COLD void FallbackContact(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb, Vec2 x,
                              double mu, Vec2 normal, double level, int iterations, ContactResult& contact)
{
	LevelResult solved;
	solved.status = SolveStatus::converged;
	solved.method = SolveMethod::newton;
	solved.iterations = iterations;
	solved.level = level;
	solved.point = ToWorld(pa, x);
	solved.normal = normal;
	solved.multiplier = mu;
	contact = ContactFromLevel(a, pa, b, pb, solved, level <= 1.0);
}

// The contact at the solved point x (A's frame) with its normal n there: where the line through
// x along n leaves A last and enters B first (ContactFromLevel's rule), x itself where it lies
// on the surface to 1e-10 of the level; where the line misses a particle, ContactFromLevel's
// search and radial point from the level solved here.
void ContactAt(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb, const Pose& rel,
               Vec2 x, double mu, Vec2 n, const PairDerivatives& e, int iterations, ContactResult& contact)
{
	const SuperellipseTerms &ta = a.Terms(), &tb = b.Terms();
	const Vec2 nB = InvRotate(rel.q, -n);
	const double knownA[3] = {e.fA, Dot(e.gA, n), Dot(n, e.hA * n)};
	const double knownB[3] = {e.fB, -Dot(e.gB, n), Dot(n, e.hB * n)};
	// (A point within 1e-10 of its surface is its own crossing: it starts found, at t = 0.)
	SmoothCrossing crossA(ta, x, n, knownA, std::min(a.A(), a.B())), crossB(tb, e.xB, nB, knownB, std::min(b.A(), b.B()));
	if (std::fabs(e.fA - 1.0) <= 1e-10)
		crossA.state = SmoothCrossing::State::found;
	if (std::fabs(e.fB - 1.0) <= 1e-10)
		crossB.state = SmoothCrossing::State::found;
	SmoothFarCrossings(crossA, crossB);
	double tA = crossA.t, tB = crossB.t;
	const bool onA = crossA.state == SmoothCrossing::State::found || FallbackFarCrossing(ta, x, n, tA);
	const bool onB = onA && (crossB.state == SmoothCrossing::State::found || FallbackFarCrossing(tb, e.xB, nB, tB));
	// The world normal is normalised after the turn, as ContactFromLevel's is: a pose built from
	// Box2D's float rotation is off unit length by up to 1e-7, and so would be Rotate(pa.q, n).
	const Vec2 normal = Normalize(Rotate(pa.q, n));
	if (onB)
	{
		contact.status = SolveStatus::converged;
		contact.method = SolveMethod::newton;
		contact.failure = "";
		contact.iterations = iterations;
		contact.level = e.fA;
		contact.point = ToWorld(pa, x);
		contact.normal = normal;
		contact.pointA = ToWorld(pa, x + tA * n);
		contact.pointB = ToWorld(pa, x - tB * n);
		SetSeparation(contact, e.fA <= 1.0);
		return;
	}
	FallbackContact(a, pa, b, pb, x, mu, normal, e.fA, iterations, contact);
}

} // namespace

bool FinishApplies(const SuperellipseShape& a, const SuperellipseShape& b)
{
	return SmoothExponents(a.Terms()) && SmoothExponents(b.Terms());
}

bool FinishSuperellipseContact(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                               const SolverOptions& options, Vec2 x, double mu, int priorIterations, WarmStart* warm,
                               ContactResult& contact)
{
	// The common level solves ∇fA + μ∇fB = 0, fA = fB: at a common level the gauge ψ = f^{1/q}
	// of the full solver (SolveSuperellipsePairLevel) has ψ'(fA) = ψ'(fB), so its equations have
	// the same root and the same μ, and their warm starts are interchangeable. The gauge buys
	// Newton a wide basin from a cold start; near the answer (a warm start: where the point went
	// with both bodies and along the surfaces; a cold solve handed over once its steps are small)
	// either form converges quadratically, and without the gauge an evaluation is a few products
	// per shape: no roots, no divisions. So plain Newton steps (NewtonOnRawLevels), and where
	// they decline the caller's full solver decides (nothing is written before success).
	const SuperellipseTerms &ta = a.Terms(), &tb = b.Terms();
	// Real exponents: one pow per axis and evaluation (two per shape), against the full solver's
	// the same pows, a root and a division for each gauge, and the line searches' evaluations.
	// (Integer pairs, the common case, pass the first test alone.)
	const bool real = !IntegerExponents(ta) || !IntegerExponents(tb);
	if ((real && !(SmoothExponents(ta) && SmoothExponents(tb))) || !IsFinite(x))
		return false;
	const bool linearLast = real && LipschitzHessian(ta) && LipschitzHessian(tb);
	const double size = 0.5 * (a.BoundingRadius() + b.BoundingRadius());
	const Pose rel = Relative(pa, pb);
	PairDerivatives e;
	if (real)
		EvaluatePair<true>(ta, tb, rel, x, e);
	else
		EvaluatePair<false>(ta, tb, rel, x, e);
	// The multiplier given (the warm start's, off by the motion since, or the gauge solve's, off
	// by its last step) starts Newton, which moves μ with the point. Only where it is unusable
	// the least-squares one at the start, −∇fA·∇fB/|∇fB|² (taken always, it was no better a
	// start, and its division lay between the first evaluation and the first step).
	if (!(mu > 0.0) || !std::isfinite(mu))
	{
		const double gb2 = LengthSquared(e.gB);
		mu = gb2 > 0.0 ? -Dot(e.gA, e.gB) / gb2 : 0.0;
	}
	if (!(mu > 0.0) || !std::isfinite(mu))
		return false;
	int iterations = 0;
	if (!(real ? NewtonOnRawLevels<true>(ta, tb, pa, pb, rel, options, size, linearLast, x, mu, e, iterations)
	           : NewtonOnRawLevels<false>(ta, tb, pa, pb, rel, options, size, false, x, mu, e, iterations)))
		return false;
	// The gradients opposed (the full solver's test: unit normals within 1e-6 of −1 in their dot
	// product), without the roots: ∇fA·∇fB < 0 and (∇fA·∇fB)² > (1 − 1e-6)²|∇fA|²|∇fB|².
	const double ab = Dot(e.gA, e.gB), aa = LengthSquared(e.gA), bb = LengthSquared(e.gB);
	if (!(ab < 0.0) || !(ab * ab > (1.0 - 2e-6) * aa * bb))
		return false;
	// The normal: A's outward and B's inward normals agree, ∇fA = −μ∇fB to rounding, and their
	// weighted mean ∇fA − μ∇fB flips exactly when A and B swap (μ ↦ 1/μ).
	const Vec2 sum = e.gA - mu * e.gB;
	const double length = std::sqrt(LengthSquared(sum));
	const Vec2 n = sum / length;
	if (!IsFinite(n) || !(length > 0.0))
		return false;
	ContactAt(a, pa, b, pb, rel, x, mu, n, e, priorIterations + iterations, contact);
	// The next warm start: the point in both frames, μ, and the slide (from f's derivatives: the
	// curvatures and twists of the level curves, and so the slide, are the gauge's), written with
	// the normal as it is, in A's frame, and turned to B's from the poses (kept in memory: the
	// crossing's B-frame direction, kept alive to here, made cold contacts, which take no slide,
	// dearer).
	if (warm)
	{
		RecordWarmStartLocal(*warm, pa, pb, x, e.xB, mu, nullptr);
		double coefficients[3];
		if (SlideCoefficients(e.hA, e.hB, n, mu, std::sqrt(LengthSquared(e.gA)), 1.0, coefficients))
			WriteSlide(*warm, n, InvRotate(pb.q, Rotate(pa.q, n)), coefficients);
	}
	return true;
}

} // namespace b2a

// b2analytic: solver pieces shared between the contact sources (internal).
#pragma once

#include "b2analytic/ContactResult.h"
#include "b2analytic/SuperellipseShape.h"
#include "contact/PairFrame.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <typeinfo>

namespace b2a
{

/// Newton's quadratic regime, as the full solvers test it: a step `now` that is at rounding (a
/// tenth of the tolerance), or that contracted by 4 from `before` and leaves an error K·now²
/// (K ≈ now/before²) ten times below the tolerance (multiplied out: no division). The step
/// after it would be below the tolerance, so it need not be computed.
inline bool NewtonSettled(double now, double before, double tolerance)
{
	return now <= 0.1 * tolerance ||
	       (before > 0.0 && now < 0.25 * before && 10.0 * now * now * now <= tolerance * before * before);
}

/// How far the bordered Newton Jacobian J = [[H, g], [dᵀ, 0]] (H symmetric) is from singular,
/// whatever the units of its rows and columns: det J = −(Rd)ᵀH(Rg) with R the quarter turn, so
/// |det J| / (|g||d|‖H‖∞) is H's curvature across the border's directions relative to its
/// largest. That is what the rounding of H's entries (parts in 1e16 of the largest) leaves of a
/// step: a relative error of about 1e-16 over it. J's own condition number also carries the
/// units: a needle's H grows like 1/thickness² across it and its gradient like 1/thickness, and
/// rcond falls with the thickness where the step is as good as any.
inline double BorderedCurvature(double h11, double h12, double h22, double g1, double g2, double d1, double d2)
{
	const double u1 = -d2, u2 = d1, v1 = -g2, v2 = g1; // Rd, Rg
	const double across = u1 * (h11 * v1 + h12 * v2) + u2 * (h12 * v1 + h22 * v2);
	const double rows = std::fabs(h12) + std::max(std::fabs(h11), std::fabs(h22));
	return std::fabs(across) / (std::sqrt((g1 * g1 + g2 * g2) * (d1 * d1 + d2 * d2)) * rows);
}

/// Whether a Newton step on the common-level conditions can be trusted: J's condition number
/// above 1e-14 (the solvers' own test), or, where the units make that fall (BorderedCurvature),
/// H's curvature across the gradients above 1e-12 of its largest (the step then good to 1e-4).
inline bool BorderedStepUsable(double rcond, double h11, double h12, double h22, double g1, double g2, double d1, double d2)
{
	return rcond > 1e-14 || (rcond > 0.0 && BorderedCurvature(h11, h12, h22, g1, g2, d1, d2) > 1e-12); // (0: no step solved)
}

/// Whether the levels agree to `level` of λA and the gradients are opposed to `angle` radians
/// (the sine of the angle between one and the other's reverse), tested on squares: no root, no
/// division. With 1e-11 for both it is a cheap sufficient form of ConditionsHold.
inline bool ConditionsWithin(double levelA, double levelB, Vec2 gradA, Vec2 gradB, double level, double angle)
{
	const double d = levelA - levelB, cross = Cross(gradA, gradB);
	return d * d <= level * level * levelA * levelA && cross * cross <= angle * angle * LengthSquared(gradA) * LengthSquared(gradB) &&
	       Dot(gradA, gradB) < 0.0;
}

/// Whether a point lies where Newton's steps may be trusted to converge quadratically, so that a
/// step which the previous steps' contraction shows to be the last may be taken unevaluated: the
/// levels within 1e-6 of each other and the normals within 1e-5 rad of opposed. Between a needle
/// and a larger particle the steps contract by 1e4 where the levels still differ by a factor 2
/// (the needle's gradient, ~1/thickness, makes every step small); a needle's normal turns fast
/// with the point (2e-6 rad at a step of 3e-11 of the size), so its test is looser.
inline bool NearSolution(double levelA, double levelB, Vec2 gradA, Vec2 gradB)
{
	return ConditionsWithin(levelA, levelB, gradA, gradB, 1e-6, 1e-5);
}

/// How far a point is from solving the common-level conditions, measured on the conditions
/// themselves, and how far the rounding of its coordinates alone would put it: the gauges'
/// mismatch |ψA − ψB| relative to their mean, and the angle between one unit gradient and the
/// other's reverse (|n̂A + n̂B|), the point known to `delta` in the gradients' units, which moves
/// each ψ by |∇ψ|·delta and turns each normal by its level curve's curvature times delta (plus a
/// few parts in 1e16 of evaluation). A needle's thinness enters through its gradient and its
/// curvature, which the pair's size does not show.
struct ConditionsResidual
{
	double level = 0.0, levelFloor = 0.0; ///< relative mismatch of the levels, and its rounding
	double angle = 0.0, angleFloor = 0.0; ///< misalignment of the normals (radians), and its rounding
	bool valid = false;                   ///< false: a gradient vanishes or is not finite
	/// Both parts within their tolerance, or within ten times their rounding, but never beyond
	/// the level a converged answer is held to (1e-9 of itself: the gauges to 1e-9/q, `power` =
	/// q), nor normals misaligned beyond 1e-4 rad: a candidate at a sharp tip would otherwise
	/// excuse itself by its own curvature. (Between 1e-6 and 1e-4 the rounding of one particle's
	/// normal at a needle's tip can exceed the standard while the other's, the level solve's
	/// normal, is exact.)
	bool Within(double levelTolerance, double angleTolerance, double power) const
	{
		return valid && level <= std::max(levelTolerance, std::min(10.0 * levelFloor, 1e-9 / power)) &&
		       angle <= std::max(angleTolerance, std::min(10.0 * angleFloor, 1e-4));
	}
};
/// With each particle's point known to its own rounding: `deltaA` for A's, `deltaB` for B's (a
/// solver in A's body frame evaluates A at its exact coordinates, B at coordinates rounded
/// against B's centre).
inline ConditionsResidual ResidualOfConditions(double psiA, double psiB, Vec2 gradA, Vec2 gradB, const Sym22& hessA,
                                               const Sym22& hessB, double deltaA, double deltaB)
{
	ConditionsResidual r;
	const double eps = std::numeric_limits<double>::epsilon();
	const double la = Length(gradA), lb = Length(gradB);
	const double mean = 0.5 * (std::fabs(psiA) + std::fabs(psiB));
	if (!(la > 0.0) || !(lb > 0.0) || !std::isfinite(la + lb) || !(mean > 0.0))
		return r;
	const Vec2 na = gradA / la, nb = gradB / lb;
	const Vec2 t = Perp(na);
	const double curvatureA = std::fabs(Dot(t, hessA * t)) / la, curvatureB = std::fabs(Dot(t, hessB * t)) / lb;
	r.level = std::fabs(psiA - psiB) / mean;
	r.angle = Length(na + nb);
	// (One rounding for both: the floors as one product each, as they always were.)
	if (deltaA == deltaB)
	{
		r.levelFloor = (la + lb) * deltaA / mean + 4.0 * eps;
		r.angleFloor = (curvatureA + curvatureB) * deltaA + 4.0 * eps;
	}
	else
	{
		r.levelFloor = (la * deltaA + lb * deltaB) / mean + 4.0 * eps;
		r.angleFloor = curvatureA * deltaA + curvatureB * deltaB + 4.0 * eps;
	}
	r.valid = std::isfinite(r.level + r.angle + r.levelFloor + r.angleFloor);
	return r;
}
inline ConditionsResidual ResidualOfConditions(double psiA, double psiB, Vec2 gradA, Vec2 gradB, const Sym22& hessA,
                                               const Sym22& hessB, double delta)
{
	return ResidualOfConditions(psiA, psiB, gradA, gradB, hessA, hessB, delta, delta);
}

/// Whether a point solves the common-level conditions to what double precision allows
/// (ResidualOfConditions): the levels within 1e-11 of each other (the level then within
/// q·1e-11 ≤ 2e-10 of the common level, for gauges ψ = λ^{1/q}, `power` = q) and the normals
/// opposed to 1e-10 rad, or each within ten times its rounding up to the standard (Within).
/// (ConditionsWithin 1e-11 decides the common case first, without roots or divisions.)
inline bool ConditionsHold(double psiA, double psiB, Vec2 gradA, Vec2 gradB, const Sym22& hessA, const Sym22& hessB,
                           double delta, double power)
{
	if (ConditionsWithin(psiA, psiB, gradA, gradB, 1e-11, 1e-11))
		return true;
	return ResidualOfConditions(psiA, psiB, gradA, gradB, hessA, hessB, delta).Within(1e-11, 1e-10, power);
}

/// Whether the rounding of a point alone (`deltaSquared`: the square of its coordinates'
/// rounding, in the gradients' units) turns the two normals by at most 1e-2 rad in all: each
/// level curve's curvature |tᵀHt|/|∇ψ| times the rounding at most half that (ResidualOfConditions'
/// angle floor, multiplied out and squared: no roots, no divisions). Beyond it the normals'
/// agreement in double shows nothing (needles crossing deep inside each other, at levels of
/// 1e-18: a floor of 1e3 rad and more, with the true normals 0.04 to 2.4 rad apart), and a
/// point that passes ConditionsHold is still no verified solution.
inline bool RoundingKeepsNormals(Vec2 gradA, Vec2 gradB, const Sym22& hessA, const Sym22& hessB, double deltaSquaredA,
                                 double deltaSquaredB)
{
	const Vec2 u = Perp(gradA); // the tangent, |∇ψA| long
	const double a2 = LengthSquared(gradA), b2 = LengthSquared(gradB);
	const double ta = Dot(u, hessA * u), tb = Dot(u, hessB * u); // |∇ψA|² tᵀHt
	const double half = 0.25 * 1e-2 * 1e-2;                     // (1e-2 / 2)²
	return ta * ta * deltaSquaredA <= half * a2 * a2 * a2 && tb * tb * deltaSquaredB <= half * a2 * a2 * b2;
}
/// The same with one rounding for both particles' points.
inline bool RoundingKeepsNormals(Vec2 gradA, Vec2 gradB, const Sym22& hessA, const Sym22& hessB, double deltaSquared)
{
	return RoundingKeepsNormals(gradA, gradB, hessA, hessB, deltaSquared, deltaSquared);
}

/// The largest absolute row sum of a symmetric 2×2 matrix (a bound on its eigenvalues).
inline double NormOf(const Sym22& h)
{
	return std::fabs(h.xy) + std::max(std::fabs(h.xx), std::fabs(h.yy));
}

/// True when both shapes suit Newton (smooth, strictly convex); else fills `failure` with why.
inline bool NewtonApplies(const Shape& a, const Shape& b, LevelResult& failure)
{
	failure.method = SolveMethod::newton;
	if (a.IsSmoothConvex() && b.IsSmoothConvex())
		return true;
	failure.failure = "Newton needs smooth, strictly convex shapes (superellipse exponents >= 2)";
	return false;
}

/// A common-level answer's slide (WarmStart::slide), where the solver computed one (computed
/// and used by WarmSlide.h).
struct LevelSlide
{
	Vec2 normal;                                ///< A's outward unit normal at the point (world)
	double coefficients[3] = {0.0, 0.0, 0.0};   ///< WarmStart::slide (world lengths)
	bool valid = false;                         ///< false: none (flat on flat, or not computed)
};
/// Writes a slide into a warm start, in float (a hint for the next start): A's outward normal in
/// A's and in B's body frame, and the coefficients (WarmStart::slide).
inline void WriteSlide(WarmStart& warm, Vec2 normalA, Vec2 normalB, const double coefficients[3])
{
	warm.normalA[0] = float(normalA.x);
	warm.normalA[1] = float(normalA.y);
	warm.normalB[0] = float(normalB.x);
	warm.normalB[1] = float(normalB.y);
	for (int i = 0; i < 3; ++i)
		warm.slide[i] = float(coefficients[i]);
	warm.hasSlide = std::isfinite(warm.slide[0] + warm.slide[1] + warm.slide[2]);
}
/// Writes a valid solve's slide into a warm start (RecordWarmStart's part for the slide).
void RecordSlide(WarmStart* warm, const Pose& pa, const Pose& pb, const LevelSlide& slide);

/// Records a solution as the next warm start from the point already in both bodies' frames
/// (inA, inB), its multiplier μ > 0, and the slide where the solver computed a valid one.
inline void RecordWarmStartLocal(WarmStart& warm, const Pose& pa, const Pose& pb, Vec2 inA, Vec2 inB, double multiplier,
                                 const LevelSlide* slide)
{
	warm.valid = true;
	warm.hasPointB = true;
	warm.hasSlide = false;
	warm.localPoint = inA;
	warm.localPointB = inB;
	warm.multiplier = multiplier;
	if (slide && slide->valid)
		RecordSlide(&warm, pa, pb, *slide);
}

/// Records a solved level as the next warm start (the point in both bodies' frames, the
/// multiplier, and the slide where the solver computed a valid one); a failed solve, or one
/// without a positive multiplier, invalidates it.
inline void RecordWarmStart(WarmStart* warm, const Pose& pa, const Pose& pb, const LevelResult& level,
                            const LevelSlide* slide = nullptr)
{
	if (!warm)
		return;
	if (!(level.Ok() && level.multiplier > 0.0))
	{
		warm->valid = warm->hasPointB = warm->hasSlide = false;
		return;
	}
	RecordWarmStartLocal(*warm, pa, pb, ToBody(pa, level.point), ToBody(pb, level.point), level.multiplier, slide);
}

/// The shape as a plain ellipse or circle (n = m = 2, level f or f^1), else null. (Inline, as
/// AsSmoothSuperellipse: two of them open every contact of their pairs.)
inline const SuperellipseShape* AsPlainEllipse(const Shape& s)
{
	if (s.Kind() != BuiltinKinds::ellipse && s.Kind() != BuiltinKinds::circle)
		return nullptr;
	// The class is final: comparing the dynamic type is exact and costs less than a dynamic_cast
	// (two per contact between ellipses). A superellipse is of these kinds exactly when
	// n = m = 2, with the level f itself (ζ = 0) or f^(1/1) (ζ = 1, the only ζ with n = 2ζ = 2);
	// another Shape subclass may claim the kind, hence the type test.
	return typeid(s) == typeid(SuperellipseShape) ? static_cast<const SuperellipseShape*>(&s) : nullptr;
}
/// A plain ellipse's point on the line through the world point X along `dir`, by ContactFromLevel's
/// rule for a convex shape: X itself when its level is within 1e-10 of 1, else the far crossing
/// (the larger root of the line's quadratic in the body frame), and where the line misses the
/// ellipse beyond rounding the radial point, the surface point on the ray from the centre through
/// X. False where none applies (a line grazing the ellipse to rounding): the caller searches.
bool EllipseLinePoint(const SuperellipseShape& s, const Pose& p, Vec2 X, Vec2 dir, Vec2& point);
/// The surface points of an ellipse pair on the line through the level point along the normal
/// (ContactFromLevel's pointA and pointB), where the level solve gives them at little cost.
struct EllipsePairPoints
{
	Vec2 a, b;          ///< on A's surface, on B's
	bool valid = false; ///< false: compute them as ContactFromLevel does
};
/// Common level of two plain ellipses by Halley's method on Perram–Wertheim's one-dimensional
/// form (EllipsePairLevel.cpp), warm-started from the previous multiplier; fills `points` when
/// given and the pair is solved in double (aspect ratios up to 4).
LevelResult SolveEllipsePairLevel(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                                  const WarmStart* warm, EllipsePairPoints* points = nullptr);

/// The shape as a superellipse that SolveSuperellipsePairLevel takes (smooth: n, m ≥ 2; the raw
/// level f, not the ζ-form), else null.
inline const SuperellipseShape* AsSmoothSuperellipse(const Shape& s)
{
	// The class is final, so the type test is exact (and cheaper than a dynamic_cast). The ζ-form's
	// level f^{1/ζ} is left to the generic solver.
	if (typeid(s) != typeid(SuperellipseShape) || !s.IsSmoothConvex())
		return nullptr;
	const SuperellipseShape* e = static_cast<const SuperellipseShape*>(&s);
	return e->IsNormalised() ? nullptr : e;
}
/// What the superellipse pair solver knows at its answer: the contact's normal and points
/// follow from it without evaluating the shapes again.
struct SuperellipsePairPoint
{
	Vec2 gradA;           ///< ∇λA at the point (world frame and units)
	Vec2 gradB;           ///< ∇λB there
	double levelA = 0.0;  ///< λA there
	double levelB = 0.0;  ///< λB there
	LevelSlide slide;     ///< the answer's slide (computed only where the caller keeps a warm start)
	bool valid = false;   ///< false: compute them as ContactFromLevel does
};
/// Where SolveSuperellipsePairLevel hands a cold solve over to FinishSuperellipseContact: once a
/// full Newton step on the gauges (not cut by the trust region) would move the point less than
/// `below` (in units of the pair's size), the solve stops, returns a failed result ("handed
/// over") and fills `point` and `multiplier` with the step's end, not evaluated.
struct SuperellipseHandOver
{
	double below = 5e-2;    ///< the step, in units of the pair's size, below which it hands over
	Vec2 point;             ///< the point then, in A's body frame (world lengths)
	double multiplier = 0.0; ///< μ then
	int iterations = 0;     ///< the Newton iterations it took
	bool taken = false;     ///< true: the solve stopped here
};

/// Common level of two smooth superellipses (AsSmoothSuperellipse) by the generic Newton's
/// equations and rules with the levels evaluated inline in A's frame (SuperellipsePairLevel.cpp);
/// warm starts and multipliers are interchangeable with SolveCommonLevelNewton's.
LevelResult SolveSuperellipsePairLevel(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                                       const SolverOptions& options, const WarmStart* warm,
                                       SuperellipsePairPoint* at = nullptr, SuperellipseHandOver* handOver = nullptr);

/// SolveSuperellipsePairLevel for the level chain's fallbacks: no contact's hand-over, every
/// step evaluated (the last one too, which the contact's solve takes to first order), and with
/// `logLevels` on the gauge ψ = log f: a level of 1e-30 as well scaled as one of 1e-3, and a
/// needle's term |x/a|² across it, flat at its axis in f, of slope 2/x in log f. Its multiplier
/// at the answer is the same (fA = fB there).
LevelResult SolveSuperellipsePairLevelChecked(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                                              const SolverOptions& options, const WarmStart* warm, bool logLevels);

/// Whether FinishSuperellipseContact takes the pair: exponents ≥ 2 throughout, integer or real.
bool FinishApplies(const SuperellipseShape& a, const SuperellipseShape& b);

/// The contact of two smooth superellipses with exponents ≥ 2 (FinishApplies) from a
/// point `x` (A's body frame, world lengths) and multiplier `mu` within Newton's quadratic regime
/// of the answer (a warm start's WarmStartPoint, or a cold solve's SuperellipseHandOver),
/// SuperellipseContactFinish.cpp: Newton on the raw levels f, the points by Halley steps, and
/// the next warm start recorded into `warm` where given. The same equations and answer as
/// SolveSuperellipsePairLevel and ContactFromLevel's rules, for a fraction of their cost;
/// `priorIterations` are added to the contact's count. False, with nothing written, where the
/// steps do not contract as Newton's do near a root or anything is out of the ordinary (the
/// caller takes the full solver). On success every field of `contact` is written.
bool FinishSuperellipseContact(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                               const SolverOptions& options, Vec2 x, double mu, int priorIterations, WarmStart* warm,
                               ContactResult& contact);

/// Newton–Raphson on the common level from (ξ, m = log μ) in a PairFrame; `level` is λA there.
LevelResult RunNewton(const PairFrame& frame, Vec2 xi, double m, const SolverOptions& options, LevelSlide* slide = nullptr);
/// A fallback's candidate point ξ (with m = log μ) polished by RunNewton, whose answer is taken
/// where it stays near the candidate or below the candidate's larger level; else the candidate
/// itself where it solves the conditions (ConditionsHold), else `result` failed with
/// `stoppedShort` (`nonFinite` where λA is not finite there). `result` carries the method
/// and the iterations spent before (CommonLevelPolish.cpp).
LevelResult PolishCommonLevel(const PairFrame& frame, Vec2 xi, double m, const SolverOptions& options, LevelResult result,
                              const char* nonFinite, const char* stoppedShort);
/// The grid's common level (SolveCommonLevelGrid), which stops at its samples' and bracket's
/// tolerances, polished or held to the conditions as PolishCommonLevel does: a converged answer
/// solves them, else it fails with its reason.
LevelResult CheckGridCommonLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                                 const LevelResult& grid);
/// SolveCommonLevelNewton, warm-started with WarmStartPoint and filling `slide` (when given) for
/// RecordSlide.
LevelResult SolveCommonLevelNewton(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                                   const WarmStart* warm, LevelSlide* slide);

/// The point between the centres where ψA = ψB, and μ balancing the gradients there.
/// Returns false when the centres coincide.
bool GeometricStart(const PairFrame& frame, Vec2& xi, double& mu);

/// One-sided scale of A on B's surface by Newton (ScaleANewton.cpp).
LevelResult SolveScaleANewton(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options);

/// Common level of two circles in closed form; fails when the centres coincide exactly.
LevelResult CircleLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb);

} // namespace b2a

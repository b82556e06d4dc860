// b2analytic: solver pieces shared between the contact sources (internal).
#pragma once

#include "b2analytic/ContactResult.h"
#include "b2analytic/SuperellipseShape.h"
#include "contact/PairFrame.h"

#include <cmath>
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

/// Whether FinishSuperellipseContact takes the pair: integer exponents ≥ 2 throughout.
bool FinishApplies(const SuperellipseShape& a, const SuperellipseShape& b);

/// The contact of two smooth superellipses with integer exponents ≥ 2 (FinishApplies) from a
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

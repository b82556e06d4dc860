// b2analytic benchmark: numerical stability of the contact solvers over a million random pairs.
//
// Every configuration is solved by the automatic path (ComputeContact, and SolveCommonLevel or
// the one-sided SolveScaleA both ways for hearts) and by Newton alone, and common-level
// configurations also warm-started along a few small motions (as the Box2D adapter solves them);
// every answer is checked in long double against the shapes' formulas (StressReference.h):
// against the exact answer the configuration was built from (StressConfig.h), and by one
// long-double Newton step on the optimality conditions from the answer itself (the cheap check,
// which also serves the random poses that were not built from an answer). A deterministic
// subset, and every worst case, is checked again against the dense references of the unit tests
// (CommonLevelRef, Perram–Wertheim, SurfaceMin), which validates both. The summary's headline
// holds the configurations in range to a standard (normals to 1e-6 rad, levels to 1e-9) and
// reports each kind beyond range apart.
#include "BenchCommon.h"
#include "common/CommandLine.h"
#include "StressConfig.h"

#include "b2analytic/b2analytic.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::stress;
using demo::Json;

namespace
{
const char* kHelp = R"(b2a_stress: numerical stability of the contact solvers on random pairs.

A million configurations (--quick: 40000) of superellipses (aspect ratio 1 to 1000, exponents
2 to 20, integer or not, n != m included, sizes 1e-3 to 1e3), built so that their common level
is a chosen value from 1e-3 to 1e3, plus near-tangent pairs (|C - 1| < 1e-9), deep overlaps
(one centre inside the other), identical shapes, coincident centres, random poses, and hearts
against hearts and superellipses (one-sided grid method). Each is solved by the automatic path
(ComputeContact and SolveCommonLevel, or SolveScaleA both ways for hearts) and by Newton alone,
and each common-level configuration again with a WarmStart after 3 small motions of both bodies
(as the Box2D adapter does); all checked in long double against the exact answer (at the moved
poses, long-double Newton from the last one) and by the optimality conditions at the answer;
every 500th configuration and every worst case also against the dense references of the unit
tests.

In range: size ratio below 1e4, level within 1e-30 to 1e30 of the own level, neither centre
inside the other. There every converged answer is held to a standard: its normal within 1e-6
rad, its level within 1e-9 of itself (or, where the rounding of the coordinates alone moves them
more than a hundredth of that, within 100 times that rounding, and the normal or level is
counted as ill-conditioned; normals that are not unique, a heart's tip against another's or a
one-sided scale's at the scaled heart's tip, are counted apart). Beyond range each kind is reported apart: coincident
centres, a centre inside the other, size ratios of 1e4 and more, levels beyond 1e+-30, and the
one-sided scale that a heart pair's contact does not use.

Writes DIR/summary.json (the in-range counts of failures, wrong verdicts, wrong normals and
levels and inaccurate answers, by configuration, and the worst errors of the well-posed answers;
the same for each kind beyond range; per category and result kind the details; worst cases with
full-precision configurations; machine, run time), DIR/worst_cases.json and one CSV per category
(DIR/<category>.csv: how many answers fall in each decade of error). Exits 1 when any result has
a non-finite field, or in range an automatic answer fails, a verdict is wrong or a converged
answer misses the standard, cold or warm-started, at any level and for every shape pair (needles crossing deep inside
each other and heart pairs' tips are also counted apart in the summary).

)";

// ---------------------------------------------------------------------------------------------
// One checked answer
// ---------------------------------------------------------------------------------------------

/// The library results a configuration produces.
enum class Kind : int { contact, level, newton, scaleAB, scaleBA, count };
const char* KindName(Kind k)
{
	static const char* names[] = {"contact_auto", "level_auto", "newton", "scale_ab_auto", "scale_ba_auto"};
	return names[int(k)];
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A normal off by more than this (radians) is wrong, and so is a level off by more than
/// kWrongLevel of itself: the standard every converged answer in range is held to.
constexpr double kWrongNormal = 1e-6, kWrongLevel = 1e-9;

/// What the checks found for one library result.
struct Check
{
	bool ran = false;              ///< the result exists for this configuration
	SolveStatus status = SolveStatus::failed;
	SolveMethod method = SolveMethod::none;
	const char* failure = "";
	bool finite = true;            ///< every field finite
	bool expectedFailure = false;  ///< no answer exists (coincident centres for a level solve)
	bool exact = false;            ///< errors are against the built answer (else the residual estimate)
	double point = kNaN;           ///< |X − X*| / size
	double level = kNaN;           ///< |C − C*| / C*
	double normal = kNaN;          ///< angle between the normals (radians)
	double estimate = kNaN;        ///< the cheap check's point error (one long-double Newton step) / size
	double separation = kNaN;      ///< |separation − reference| / size (contacts)
	double surface = kNaN;         ///< pointA, pointB off their reference points / size (contacts)
	double axisExcess = kNaN;      ///< coincident centres: overlap along the reported axis above the least / size
	double condition = kNaN;       ///< 1 / ((κA + κB)·size): the point is determined to ~eps times this
	double pointFloor = kNaN;      ///< the point error double rounding alone may cause (relative to size)
	double levelFloor = kNaN;      ///< the level error double rounding alone may cause (relative)
	double levelRounding = kNaN;   ///< levelFloor before the floor of a heart's tip (the rounding of the coordinates alone)
	double normalRounding = kNaN;  ///< the normal error (radians) the rounding of the coordinates alone may cause
	double reference = kNaN;       ///< the reference level (built answer, or the answer's own)
	bool grazing = false;          ///< the normal line nearly misses a particle: points ill-conditioned
	bool touchingWrong = false;    ///< `touching` disagrees with the reference level (beyond 1e-12)
	bool unusedSide = false;       ///< a heart pair's one-sided scale that its contact was not built from
	int iterations = 0;
	double seconds = 0.0;          ///< time in the library call
};

/// A result's numbers, whatever its type.
struct Answer
{
	SolveStatus status;
	SolveMethod method;
	const char* failure;
	int iterations;
	double level;
	Vec2 point, normal;
	bool finite;
};

Answer Of(const LevelResult& r)
{
	const bool finite = std::isfinite(r.level) && IsFinite(r.point) && IsFinite(r.normal) && std::isfinite(r.multiplier);
	return {r.status, r.method, r.failure, r.iterations, r.level, r.point, r.normal, finite};
}

Answer Of(const ContactResult& c)
{
	const bool finite = std::isfinite(c.level) && IsFinite(c.point) && IsFinite(c.normal) && IsFinite(c.pointA) &&
	                    IsFinite(c.pointB) && std::isfinite(c.separation);
	return {c.status, c.method, c.failure, c.iterations, c.level, c.point, c.normal, finite};
}

/// Angle between two directions.
double Angle(V a, V b)
{
	return double(std::atan2(std::fabs(ref::Cross(a, b)), ref::Dot(a, b)));
}

/// True when a world point is (numerically) a heart's tip or notch: the axis of a heart in its body frame.
bool OnHeartAxis(const Posed& p, V X, double size)
{
	return p.shape.kind == RefShape::Kind::heart && std::fabs(ref::ToBodyL(p.pose, X).x) < 1e-9L * size;
}

/// What double precision allows at a solution (X, L). The library works on world coordinates
/// up to `reach` = max(|X|, |cA|, |cB|), rounded to eps·reach: that moves a level by
/// eps·reach·|∇λ| and, along a contact whose level sets curve by κA + κB, the point by
/// eps/(κA + κB). At a heart's tip the level grows like |x|^{2/3} and the library's Brent search on
/// the kink stops at ~1e-9 of the size: floors of 1e-9 (point) and 1e-8 (level) there. The normal
/// at one heart's tip is the other particle's, which the tip's rounding (eps·reach, across that
/// particle's surface) turns by eps·reach·κ, κ its level curve's curvature (`tipCurvature`; 0
/// where no tip or both tips): beside a needle's end, κ·size ~ 1e5 to 1e6, that is ~1e-6 rad.
void SetFloors(const Config& c, const Posed& A, const Posed& B, V X, LD L, bool tip, LD tipCurvature, Check& k)
{
	const LD eps = std::numeric_limits<double>::epsilon();
	const LD reach = std::max({ref::Len(X), ref::Len(A.pose.p), ref::Len(B.pose.p)});
	const LD grad = std::max(ref::Len(WorldDeriv(A, X).grad), ref::Len(WorldDeriv(B, X).grad));
	const LD condition = k.condition == k.condition ? LD(k.condition) : 0.0L;
	k.pointFloor = double(eps * (reach / c.size + condition));
	k.levelFloor = k.levelRounding = double(eps * reach * grad / L);
	// A point moved by eps·reach along the contact turns the normals by (κA + κB) times that.
	k.normalRounding = condition > 0.0L ? double(eps * reach / (condition * c.size)) : 0.0;
	if (tip)
	{
		k.pointFloor = std::max(k.pointFloor, 1e-9);
		k.levelFloor = std::max(k.levelFloor, 1e-8);
		if (tipCurvature > 0.0L)
			k.normalRounding = double(eps * reach * tipCurvature);
	}
}

/// The curvature of p's level curve through X, |tᵀHt|/|∇λ| (t the unit tangent).
LD LevelCurveCurvature(const Posed& p, V X)
{
	const Deriv d = WorldDeriv(p, X);
	const LD g = ref::Len(d.grad);
	const V t = PerpL(d.grad);
	return std::fabs(ref::Dot(t, HessTimes(d, t))) / (g * g * g);
}

/// How far p's unit normal turns over the points within `radius` of X (the rounding of X): the
/// largest angle from the normal at X to the normals at 8 points on that circle. Where X is
/// within rounding of a needle's tip (a level set 1e-15 of its size thick, whose tip turns the
/// normal over 1e-24 of it) this is ~π, though the level curve through X itself is flat.
LD NormalSpread(const Posed& p, V X, LD radius)
{
	const V n = ref::Unit(WorldDeriv(p, X).grad);
	LD spread = 0.0L;
	for (int k = 0; k < 8; ++k)
	{
		const LD t = 0.25L * 3.14159265358979323846L * k;
		const V Y{X.x + radius * std::cos(t), X.y + radius * std::sin(t)};
		spread = std::max(spread, LD(Angle(n, ref::Unit(WorldDeriv(p, Y).grad))));
	}
	return spread;
}

/// At one heart's tip (A's or B's, not both), the other particle's level-curve curvature there
/// (SetFloors); else 0.
LD TipCurvature(const Config& c, const Posed& A, const Posed& B, V X)
{
	const bool tipA = OnHeartAxis(A, X, c.size), tipB = OnHeartAxis(B, X, c.size);
	if (tipA == tipB)
		return 0.0L;
	const LD kappa = LevelCurveCurvature(tipA ? B : A, X);
	return std::isfinite(kappa) ? kappa : 0.0L;
}

/// Check a level answer of `problem` between A and B (B → A for the swapped one-sided scale).
/// `contact`: the normal is a contact's (the mean of A's outward and B's inward normals, or B's
/// inward one where they point the same way), else a level solve's (A's gradient direction).
Check CheckAnswer(const Config& c, const Answer& r, const Posed& A, const Posed& B, Problem problem, bool useBuilt,
                  bool contact)
{
	Check k;
	k.ran = true;
	k.status = r.status;
	k.method = r.method;
	k.failure = r.failure;
	k.iterations = r.iterations;
	k.finite = r.finite;
	if (r.status == SolveStatus::failed || !r.finite)
		return k;
	const V X = ref::FromVec(r.point);
	const LD L = r.level;
	const V n = ref::FromVec(r.normal);
	// The cheap check: one Newton step on the conditions from (X, C), in long double. At a
	// heart's tip the conditions do not hold (no gradient); it is skipped there.
	const bool atTip = OnHeartAxis(A, X, c.size) || OnHeartAxis(B, X, c.size);
	NewtonStep step;
	if (!atTip && L > 0.0L)
	{
		step = LevelNewtonStep(A, B, problem, X, L, c.size);
		k.estimate = step.finite ? double(ref::Len(step.dX) / c.size) : std::numeric_limits<double>::infinity();
		k.condition = step.curvature > 0.0L ? double(1.0L / (step.curvature * c.size)) : std::numeric_limits<double>::infinity();
	}
	const bool built = useBuilt && c.constructed && c.answer.ok;
	if (built && c.answer.curvature > 0.0L)
		k.condition = double(1.0L / (c.answer.curvature * c.size));
	k.reference = double(built ? c.answer.level : L);
	if (L > 0.0L)
	{
		const V at = built ? c.answer.point : X;
		const bool tip = atTip || (built && c.corner);
		SetFloors(c, A, B, at, built ? c.answer.level : L, tip, tip ? TipCurvature(c, A, B, at) : 0.0L, k);
	}
	if (built)
	{
		k.exact = true;
		k.point = double(ref::Len(X - c.answer.point) / c.size);
		k.level = double(std::fabs(L - c.answer.level) / c.answer.level);
		k.normal = Angle(n, c.answer.normal);
		return k;
	}
	if (atTip || !step.finite)
		return k;
	// No built answer: the corrected point is the reference, to first order.
	const V Xc = X + step.dX;
	k.point = k.estimate;
	k.level = double(std::fabs(step.dL) / L);
	const V na = ref::Unit(WorldDeriv(A, Xc).grad), nb = ref::Unit(WorldDeriv(B, Xc).grad);
	V expected = !contact ? na : (ref::Dot(na, nb) < 0.0L ? ref::Unit(na - nb) : V{-nb.x, -nb.y});
	// At a solution A's normal is B's reversed. Where the rounding of the point (eps·reach, as
	// SetFloors) turns one particle's normal beyond a tenth of the standard, that one at Xc says
	// nothing of it at the solution (needles crossing deep inside each other: the point within
	// rounding of a needle's tip), and the reference is the other particle's.
	const LD rounding = std::numeric_limits<double>::epsilon() * std::max({ref::Len(Xc), ref::Len(A.pose.p), ref::Len(B.pose.p)});
	const LD spreadA = NormalSpread(A, Xc, rounding), spreadB = NormalSpread(B, Xc, rounding);
	if (problem == Problem::common && std::max(spreadA, spreadB) > 0.1L * kWrongNormal)
	{
		expected = spreadA <= spreadB ? na : V{-nb.x, -nb.y};
		// And the level and point from Newton in the thinner particle's frame (PolishInThinFrame),
		// where its level set, 1e-15 of its size thick at levels of 1e-30, is held exactly.
		const bool supers = A.shape.kind == RefShape::Kind::superellipse && B.shape.kind == RefShape::Kind::superellipse;
		const LevelSolution framed = supers ? PolishInThinFrame(A, B, X, L, c.size) : LevelSolution{};
		if (framed.ok)
		{
			k.point = double(ref::Len(X - framed.point) / c.size);
			k.level = double(std::fabs(L - framed.level) / framed.level);
			expected = framed.normal;
		}
	}
	k.normal = Angle(n, expected);
	return k;
}

/// The contact-specific checks of a common-level contact against the built answer: `touching`,
/// and (where `linePoints`) pointA, pointB and the separation from the reference point and normal.
void CheckContactPoints(const Config& c, const ContactResult& r, const Posed& A, const Posed& B, Check& k,
                        bool linePoints = true)
{
	if (!r.Ok() || !k.finite || !c.constructed || !c.answer.ok)
		return;
	// Within rounding of tangency either verdict is right. The library's world coordinates, up to
	// `reach`, are rounded to eps·reach, which moves a level by eps·reach·|∇λ| and the particles'
	// gap along the normal, about |C − 1|·(1/|∇λA| + 1/|∇λB|) (|L − L₀|/|∇λA| one-sided), by
	// eps·reach. A verdict is judged only where the gap exceeds 1e3 times both.
	const LD own = c.problem == Problem::common ? 1.0L : A.shape.Own();
	const V X = c.answer.point;
	const LD ga = ref::Len(WorldDeriv(A, X).grad), gb = ref::Len(WorldDeriv(B, X).grad);
	const LD gap = c.answer.level - own;
	const LD distance = std::fabs(gap) * (1.0L / ga + (c.problem == Problem::common ? 1.0L / gb : 0.0L));
	const LD rounding = 1e3L * std::numeric_limits<double>::epsilon() *
	                    std::max({ref::Len(X), ref::Len(A.pose.p), ref::Len(B.pose.p)});
	if (!c.corner && distance > rounding && std::fabs(gap) > rounding * std::max(ga, gb))
		k.touchingWrong = r.touching != (gap < 0.0L);
	if (c.problem != Problem::common || !linePoints)
		return; // hearts: the one-sided contact's points are checked through the scales
	const V n = c.answer.normal;
	const LinePoint pa = LineExtreme(A, X, n, c.shapeA->BoundingRadius());
	const LinePoint pb = LineExtreme(B, X, V{-n.x, -n.y}, c.shapeB->BoundingRadius());
	// Where the line nearly grazes a particle the crossing moves like the square root of any
	// error in X or n: those points are not compared.
	k.grazing = std::fabs(pa.grazing) < 1e-6L || std::fabs(pb.grazing) < 1e-6L;
	if (k.grazing)
		return;
	// Relative to the size, or to the distance along the line where that is larger: a normal
	// good to 1e-16 still moves a point 1e3 sizes away by 1e-13 sizes.
	const LD sep = ref::Dot(pb.point - pa.point, n);
	k.separation = double(std::fabs(LD(r.separation) - sep) / (c.size + std::fabs(sep)));
	k.surface = double(std::max(ref::Dist(r.pointA, pa.point) / (c.size + ref::Len(pa.point - X)),
	                            ref::Dist(r.pointB, pb.point) / (c.size + ref::Len(pb.point - X))));
}

/// Coincident centres: the overlap-axis contact against the smallest overlap depth over all
/// directions (long double), and the depth along the reported normal.
void CheckOverlapAxis(const Config& c, const ContactResult& r, const Posed& A, const Posed& B, Check& k)
{
	if (!r.Ok() || !k.finite)
		return;
	const auto best = OverlapDepth(A, B);
	const V n = ref::FromVec(r.normal);
	const LD along = Width(A, n) + Width(B, V{-n.x, -n.y});
	// Relative to the size, or to the depth where that is larger (as for separations).
	const LD scale = c.size + best.first;
	k.exact = true;
	k.separation = double(std::fabs(-LD(r.separation) - best.first) / scale);
	k.axisExcess = double((along - best.first) / scale);
	// pointA, pointB on their surfaces at the reported normal: their extent along it.
	const LD wa = ref::Dot(ref::FromVec(r.pointA) - A.pose.p, n), wb = -ref::Dot(ref::FromVec(r.pointB) - B.pose.p, n);
	k.surface = double(std::max(std::fabs(wa - Width(A, n)), std::fabs(wb - Width(B, V{-n.x, -n.y}))) / c.size);
	k.touchingWrong = !r.touching;
}

// ---------------------------------------------------------------------------------------------
// Dense references (CommonLevelRef, Perram–Wertheim, SurfaceMin)
// ---------------------------------------------------------------------------------------------

/// A dense reference answer and how it compares.
struct FullCheck
{
	bool done = false;
	const char* reference = "";
	LD level = 0.0L;
	V point;
	double builtLevel = kNaN, builtPoint = kNaN;     ///< built answer against it
	double libraryLevel = kNaN, libraryPoint = kNaN; ///< the automatic answer against it
	double estimate = kNaN;                          ///< the cheap check's estimate for that answer
	double automaticVsBuiltLevel = kNaN, automaticVsBuiltPoint = kNaN; ///< the automatic answer against the built one
};

FullCheck DenseReference(const Config& c, const Posed& A, const Posed& B, const Answer& automatic, const Check& checked)
{
	FullCheck f;
	if (c.category == Category::coincident)
		return f;
	if (c.problem == Problem::scaleA)
	{
		const ref::SurfaceMinResult m = ref::SurfaceMin(A.shape, A.pose, B.shape, B.pose, B.shape.Own(), 4096, 8);
		f.reference = "surface_min";
		f.level = m.value;
		f.point = m.point;
	}
	else if (c.a.n == 2.0 && c.a.m == 2.0 && c.b.n == 2.0 && c.b.m == 2.0)
	{
		const ref::PwResult p = ref::PerramWertheim(ref::QuadOf(c.a.a, c.a.b, A.pose), ref::QuadOf(c.b.a, c.b.b, B.pose));
		f.reference = "perram_wertheim";
		f.level = p.level;
		f.point = p.point;
	}
	else
	{
		const ref::CommonLevelResult r = ref::CommonLevelRef(A.shape, A.pose, B.shape, B.pose, 2048);
		f.reference = "common_level_ref";
		f.level = r.level;
		f.point = r.point;
	}
	f.done = true;
	if (c.constructed && c.answer.ok)
	{
		f.builtLevel = double(std::fabs(c.answer.level - f.level) / f.level);
		f.builtPoint = double(ref::Len(c.answer.point - f.point) / c.size);
	}
	if (automatic.status != SolveStatus::failed && automatic.finite)
	{
		f.libraryLevel = double(std::fabs(automatic.level - f.level) / f.level);
		f.libraryPoint = double(ref::Dist(automatic.point, f.point) / c.size);
		f.estimate = checked.estimate;
		if (checked.exact)
		{
			f.automaticVsBuiltLevel = checked.level;
			f.automaticVsBuiltPoint = checked.point;
		}
	}
	return f;
}

// ---------------------------------------------------------------------------------------------
// Running one configuration
// ---------------------------------------------------------------------------------------------

/// Where a configuration stands against the range a user meets: in range, or beyond it, by the
/// first of these that applies (a heart pair's one-sided scale that its contact does not use is
/// beyond range as a result, Check::unusedSide, whatever its configuration's range).
enum class Range : int
{
	inRange,      ///< size ratio below 1e4, level within 1e±30, neither centre inside the other
	coincident,   ///< the centres coincide: no level point, only the overlap axis
	centreInside, ///< one centre lies inside the other particle
	sizeRatio,    ///< the bounding radii differ by a factor 1e4 or more
	extremeLevel, ///< the level (in units of the own level) is below 1e-30 or above 1e30
	unusedSide,   ///< (results only) a one-sided scale the contact was not built from
	count
};
const char* RangeName(Range r)
{
	static const char* names[] = {"in_range", "coincident_centres", "centre_inside_other", "size_ratio_1e4_or_more",
	                              "level_beyond_1e30", "unused_one_sided_scale"};
	return names[int(r)];
}

/// Levels (in units of the own level) below this are "deep": needles crossing or overlapping deep
/// inside each other, where the summary counts failures and wrong answers apart.
constexpr double kDeepLevel = 1e-9;

/// The warm-started contacts each common-level configuration runs after its cold one.
constexpr int kWarmSteps = 3;

/// One warm-started contact of a configuration's sequence of motions, and its check.
struct WarmCheck
{
	Check check;
	ContactResult contact;
	Pose pa, pb;         ///< the poses it was solved at
	LevelSolution answer; ///< the long-double reference there
};

/// Everything one configuration produced.
struct Outcome
{
	std::array<Check, int(Kind::count)> check;
	ContactResult contact;
	LevelResult level, newton, scaleAB, scaleBA;
	FullCheck full;
	std::vector<WarmCheck> warm;      ///< the warm-started contacts (common-level configurations)
	int warmUnchecked = 0;            ///< warm steps whose reference did not converge (the sequence stops)
	bool nearTangentVerified = false; ///< |C* − 1| < 1e-9 for the exact answer
	Range range = Range::inRange;     ///< the configuration's range
	double referenceLevel = kNaN;     ///< the reference level in units of the own level (RangeOf's), NaN where unknown
	/// An automatic answer (contact, level or scale) failed.
	bool AutomaticFailed() const
	{
		for (Kind k : {Kind::contact, Kind::level, Kind::scaleAB, Kind::scaleBA})
			if (check[int(k)].ran && check[int(k)].status == SolveStatus::failed && !check[int(k)].expectedFailure)
				return true;
		return false;
	}
};

template <class F>
auto Timed(double& seconds, F&& f)
{
	const auto start = std::chrono::steady_clock::now();
	auto r = f();
	seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	return r;
}

/// The configuration's reference level in units of the own level: the built answer's, else the
/// dense reference's, else the automatic answer's own (corrected by the cheap check).
double ReferenceLevel(const Config& c, const Outcome& o)
{
	const LD own = c.problem == Problem::common ? 1.0L : c.a.Ref().Own();
	if (c.constructed && c.answer.ok)
		return double(c.answer.level / own);
	if (o.full.done)
		return double(o.full.level / own);
	return double(o.check[int(c.problem == Problem::common ? Kind::level : Kind::scaleAB)].reference / own);
}

/// The configuration's range (Range), from its reference level (Outcome::referenceLevel).
Range RangeOf(const Config& c, const Outcome& o)
{
	if (c.category == Category::coincident)
		return Range::coincident;
	if (c.centreInside)
		return Range::centreInside;
	const double ra = c.shapeA->BoundingRadius(), rb = c.shapeB->BoundingRadius();
	if (std::max(ra, rb) >= 1e4 * std::min(ra, rb))
		return Range::sizeRatio;
	if (o.referenceLevel == o.referenceLevel && !(o.referenceLevel >= 1e-30 && o.referenceLevel <= 1e30))
		return Range::extremeLevel;
	return Range::inRange;
}

/// A small rigid motion of a pose, as a body makes in one step: a move of size·10^u in a random
/// direction and a turn of ±10^u radians, u uniform in [−6, −2] (each drawn apart).
Pose SmallMotion(const Pose& p, double& angle, double size, test::Random& r)
{
	const double move = size * std::pow(10.0, r.Uniform(-6.0, -2.0)), direction = r.Angle();
	angle += (r.Uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, r.Uniform(-6.0, -2.0));
	return Pose(p.p + Vec2(move * std::cos(direction), move * std::sin(direction)), angle);
}

/// The warm path, as the Box2D adapter takes it: the configuration's contact solved once more
/// with a WarmStart to record, then kWarmSteps small motions of both bodies (SmallMotion), each
/// solved from the WarmStart the last one left. Each is checked against the long-double solution
/// at its poses (Polish from the last step's reference, else from the answer itself; a step
/// whose reference does not converge ends the sequence, counted). Common-level configurations
/// with a reference only: the grid method (heart pairs) keeps no warm start.
void RunWarm(const Config& c, Outcome& o)
{
	if (c.problem != Problem::common || c.category == Category::coincident)
		return;
	LevelSolution previous;
	if (c.constructed && c.answer.ok)
		previous = c.answer;
	else if (o.level.Ok())
	{
		const Posed A{c.a.Ref(), ref::Of(c.pa)}, B{c.b.Ref(), ref::Of(c.pb)};
		previous = Polish(A, B, Problem::common, ref::FromVec(o.level.point), o.level.level, c.size);
	}
	if (!previous.ok)
		return;
	test::Random r(Mix(c.seed * 0x9E3779B97F4A7C15ull + c.index) ^ 0x5741524D5354415Aull);
	WarmStart warm;
	Pose pa = c.pa, pb = c.pb;
	double angleA = c.angleA, angleB = c.angleB;
	bench::KeepAlive(ComputeContact(*c.shapeA, pa, *c.shapeB, pb, MethodChoice::automatic, SolverOptions(), &warm));
	for (int step = 0; step < kWarmSteps; ++step)
	{
		WarmCheck w;
		w.pa = pa = SmallMotion(pa, angleA, c.size, r);
		w.pb = pb = SmallMotion(pb, angleB, c.size, r);
		w.contact = ComputeContact(*c.shapeA, pa, *c.shapeB, pb, MethodChoice::automatic, SolverOptions(), &warm);
		Config moved = c;
		moved.pa = pa;
		moved.pb = pb;
		moved.constructed = true;
		const Posed A{c.a.Ref(), ref::Of(pa)}, B{c.b.Ref(), ref::Of(pb)};
		w.answer = Polish(A, B, Problem::common, previous.point, previous.level, c.size);
		if (!w.answer.ok && w.contact.Ok())
			w.answer = Polish(A, B, Problem::common, ref::FromVec(w.contact.point), w.contact.level, c.size);
		// Needles crossing deep inside each other (below level 1e-9): in the thinner particle's
		// frame (PolishInThinFrame), whose level set world coordinates may not hold.
		if (w.answer.ok && w.answer.level < kDeepLevel)
		{
			const LevelSolution framed = PolishInThinFrame(A, B, w.answer.point, w.answer.level, c.size);
			if (framed.ok)
				w.answer = framed;
		}
		if (!w.answer.ok)
		{
			++o.warmUnchecked;
			return;
		}
		moved.answer = previous = w.answer;
		w.check = CheckAnswer(moved, Of(w.contact), A, B, Problem::common, true, true);
		CheckContactPoints(moved, w.contact, A, B, w.check, false);
		o.warm.push_back(w);
	}
}

Outcome Run(const Config& c, bool dense)
{
	Outcome o;
	const Shape& a = *c.shapeA;
	const Shape& b = *c.shapeB;
	const Posed A{c.a.Ref(), ref::Of(c.pa)}, B{c.b.Ref(), ref::Of(c.pb)};
	auto& k = o.check;
	double t = 0.0;
	// A pool shape samples its surface on first use (the grid method's and the line searches'
	// samples), and that set-up would dominate a heart pair's time: the grid pairs are solved once
	// untimed, so that their times are the contacts' own (building the samples alone, untimed, is
	// not enough: the first solve after it still runs slower, at the same instruction count).
	if (c.category == Category::heartHeart || c.category == Category::heartSuperellipse)
		bench::KeepAlive(ComputeContact(a, c.pa, b, c.pb, MethodChoice::automatic));
	o.contact = Timed(t, [&] { return ComputeContact(a, c.pa, b, c.pb, MethodChoice::automatic); });
	const Answer contact = Of(o.contact);
	Check& kc = k[int(Kind::contact)];
	if (c.category == Category::coincident)
	{
		kc = CheckAnswer(c, contact, A, B, c.problem, false, true);
		kc.point = kc.estimate = kc.normal = kNaN; // no level point exists: only the overlap axis is checked
		CheckOverlapAxis(c, o.contact, A, B, kc);
	}
	kc.seconds = t;
	if (c.problem == Problem::common)
	{
		o.level = Timed(t, [&] { return SolveCommonLevel(a, c.pa, b, c.pb, MethodChoice::automatic); });
		k[int(Kind::level)] = CheckAnswer(c, Of(o.level), A, B, c.problem, true, false);
		k[int(Kind::level)].seconds = t;
		o.newton = Timed(t, [&] { return SolveCommonLevel(a, c.pa, b, c.pb, MethodChoice::newton); });
		k[int(Kind::newton)] = CheckAnswer(c, Of(o.newton), A, B, c.problem, true, false);
		k[int(Kind::newton)].seconds = t;
		if (c.category == Category::coincident)
		{
			// No common-level point lies between coincident centres: a failure with a reason is right.
			for (Kind kind : {Kind::level, Kind::newton})
				k[int(kind)].expectedFailure = k[int(kind)].status == SolveStatus::failed && k[int(kind)].failure[0] != '\0';
			k[int(Kind::level)].point = k[int(Kind::newton)].point = kNaN;
		}
		else if (o.contact.method == SolveMethod::overlapAxis)
		{
			// No level met the solvers' standard and the pair overlaps (needles crossing deep
			// inside each other): the contact is the axis of least overlap, checked as for
			// coincident centres.
			const double seconds = kc.seconds;
			kc = CheckAnswer(c, contact, A, B, c.problem, false, true);
			kc.point = kc.estimate = kc.normal = kc.level = kNaN;
			CheckOverlapAxis(c, o.contact, A, B, kc);
			kc.seconds = seconds;
		}
		else
		{
			kc = CheckAnswer(c, contact, A, B, c.problem, true, true);
			kc.seconds = k[int(Kind::contact)].seconds;
			CheckContactPoints(c, o.contact, A, B, kc);
		}
	}
	else if (c.category != Category::coincident)
	{
		o.scaleAB = Timed(t, [&] { return SolveScaleA(a, c.pa, b, c.pb, MethodChoice::automatic); });
		k[int(Kind::scaleAB)] = CheckAnswer(c, Of(o.scaleAB), A, B, Problem::scaleA, true, false);
		k[int(Kind::scaleAB)].seconds = t;
		o.scaleBA = Timed(t, [&] { return SolveScaleA(b, c.pb, a, c.pa, MethodChoice::automatic); });
		k[int(Kind::scaleBA)] = CheckAnswer(c, Of(o.scaleBA), B, A, Problem::scaleA, false, false);
		k[int(Kind::scaleBA)].seconds = t;
		// The contact is built from one of the two scales (GridContact): its level and point are
		// that scale's, so its errors are that scale's; its own normal is checked against ν.
		const double seconds = kc.seconds;
		const bool fromAB = o.contact.level == o.scaleAB.level && o.contact.point.x == o.scaleAB.point.x &&
		                    o.contact.point.y == o.scaleAB.point.y;
		kc = CheckAnswer(c, contact, fromAB ? A : B, fromAB ? B : A, Problem::scaleA, fromAB, true);
		if (!fromAB)
			kc.normal = kPi - kc.normal; // the B → A check measures against B's direction, the contact's normal is flipped
		k[int(fromAB ? Kind::scaleBA : Kind::scaleAB)].unusedSide = true;
		kc.seconds = seconds;
		CheckContactPoints(c, o.contact, A, B, kc);
	}
	if (c.category == Category::nearTangent)
		o.nearTangentVerified = c.answer.ok && std::fabs(c.answer.level - 1.0L) < 1e-9L;
	// A failure needs the true level to say whether it lies in range (RangeOf: random poses of
	// high exponents reach levels of 1e-25): the built answer, else the dense reference.
	if (dense || (o.AutomaticFailed() && !(c.constructed && c.answer.ok)))
	{
		const Kind main = c.problem == Problem::common ? Kind::level : Kind::scaleAB;
		const Answer automatic = main == Kind::level ? Of(o.level) : Of(o.scaleAB);
		o.full = DenseReference(c, A, B, automatic, k[int(main)]);
	}
	o.referenceLevel = ReferenceLevel(c, o);
	o.range = RangeOf(c, o);
	if (!dense)
		o.full = FullCheck(); // only the chosen subset enters the dense statistics
	RunWarm(c, o);
	return o;
}

// ---------------------------------------------------------------------------------------------
// Statistics
// ---------------------------------------------------------------------------------------------

/// Largest value seen and the configuration that produced it.
struct Max
{
	double value = 0.0;
	std::uint64_t index = 0;
	bool any = false;
	void Add(double v, std::uint64_t i)
	{
		if (!(v == v))
			return;
		if (!any || v > value) { value = v; index = i; }
		any = true;
	}
	Json ToJson() const { return any ? Json{{"value", value}, {"index", index}} : Json(nullptr); }
};

/// Counts of values per decade: bin 0 is exactly 0, bin k (1..21) is [1e(k−22), 1e(k−21)), the
/// last bin 1 and above.
struct Histogram
{
	static constexpr int kBins = 23;
	std::array<std::uint64_t, kBins> count{};
	void Add(double v)
	{
		if (!(v == v)) return;
		int bin = 0;
		if (v > 0.0) bin = std::clamp(int(std::floor(std::log10(v))) + 22, 1, kBins - 1);
		++count[bin];
	}
	static std::string Label(int bin)
	{
		if (bin == 0) return "0";
		if (bin == kBins - 1) return ">=1";
		char text[32];
		std::snprintf(text, sizeof text, "1e%d", bin - 22);
		return text;
	}
};

/// Statistics of one result kind (in one category or overall).
struct KindStats
{
	std::uint64_t runs = 0, converged = 0, fallback = 0, failed = 0, expectedFailures = 0, nonFinite = 0;
	std::uint64_t checked = 0, exact = 0, illConditioned = 0, grazing = 0, touchingWrong = 0;
	std::uint64_t estimateMisses = 0; ///< built-answer error above 10× the cheap estimate + 1e-14
	std::uint64_t inaccurate = 0;     ///< point or level error above 1e4 times its rounding floor
	std::map<std::string, std::uint64_t> methods, failures;
	Max point, pointWell, level, normal, estimate, separation, surface, axisExcess, pointExcess, levelExcess;
	Histogram hPoint, hLevel, hNormal, hSeparation;
	double seconds = 0.0;
	double iterations = 0.0;

	/// Points along a flat contact are determined only to ~eps/(κA + κB): above 1e6 of the size
	/// (an expected error above 2e-10) the point counts as ill-conditioned.
	static bool WellConditioned(const Check& k) { return !(k.condition > 1e6); }
	/// Error in units of its rounding floor (NaN when either is unknown).
	static double Excess(double error, double floor) { return error / floor; }
	/// More than 1e4 times what rounding explains, in the point or the level.
	static bool Inaccurate(const Check& k)
	{
		return Excess(k.point, k.pointFloor) > 1e4 || Excess(k.level, k.levelFloor) > 1e4;
	}

	void Add(const Check& k, std::uint64_t index)
	{
		if (!k.ran) return;
		++runs;
		seconds += k.seconds;
		iterations += k.iterations;
		if (!k.finite) ++nonFinite;
		if (k.expectedFailure) ++expectedFailures;
		else if (k.status == SolveStatus::converged) ++converged;
		else if (k.status == SolveStatus::convergedAfterFallback) ++fallback;
		else { ++failed; ++failures[k.failure]; }
		if (k.status != SolveStatus::failed) ++methods[MethodName(k.method)];
		if (k.touchingWrong) ++touchingWrong;
		if (k.grazing) ++grazing;
		if (!(k.point == k.point) && !(k.separation == k.separation))
			return;
		++checked;
		if (k.exact) ++exact;
		point.Add(k.point, index);
		if (WellConditioned(k)) pointWell.Add(k.point, index);
		else ++illConditioned;
		level.Add(k.level, index);
		normal.Add(k.normal, index);
		estimate.Add(k.estimate, index);
		separation.Add(k.separation, index);
		surface.Add(k.surface, index);
		axisExcess.Add(k.axisExcess, index);
		pointExcess.Add(Excess(k.point, k.pointFloor), index);
		levelExcess.Add(Excess(k.level, k.levelFloor), index);
		if (Inaccurate(k)) ++inaccurate;
		hPoint.Add(k.point);
		hLevel.Add(k.level);
		hNormal.Add(k.normal);
		hSeparation.Add(k.separation);
		if (k.exact && k.point == k.point && k.estimate == k.estimate && k.point > 10.0 * k.estimate + 1e-14)
			++estimateMisses;
	}

	Json ToJson() const
	{
		Json j;
		j["runs"] = runs;
		j["converged"] = converged;
		j["fallback"] = fallback;
		j["failed"] = failed;
		j["expected_failures"] = expectedFailures;
		j["non_finite"] = nonFinite;
		Json m = Json::object();
		for (const auto& [name, n] : methods) m[name] = n;
		j["methods"] = m;
		Json why = Json::object();
		for (const auto& [reason, n] : failures) why[reason] = n;
		j["failure_reasons"] = why;
		j["checked"] = checked;
		j["checked_against_built_answer"] = exact;
		j["max_point_error"] = point.ToJson();
		j["max_point_error_well_conditioned"] = pointWell.ToJson();
		j["ill_conditioned_points"] = illConditioned;
		j["max_level_error"] = level.ToJson();
		j["max_normal_angle_error"] = normal.ToJson();
		j["max_point_error_over_rounding_floor"] = pointExcess.ToJson();
		j["max_level_error_over_rounding_floor"] = levelExcess.ToJson();
		j["inaccurate"] = inaccurate;
		j["max_point_error_estimate"] = estimate.ToJson();
		j["estimate_misses"] = estimateMisses;
		j["max_separation_error"] = separation.ToJson();
		j["max_surface_point_error"] = surface.ToJson();
		if (axisExcess.any) j["max_overlap_axis_excess"] = axisExcess.ToJson();
		j["grazing_lines"] = grazing;
		j["touching_mismatches"] = touchingWrong;
	j["inaccurate"] = inaccurate;
		j["mean_iterations"] = runs ? iterations / double(runs) : 0.0;
		j["mean_microseconds"] = runs ? 1e6 * seconds / double(runs) : 0.0;
		return j;
	}
};

/// Dense-reference comparisons.
struct FullStats
{
	std::uint64_t checks = 0;
	std::map<std::string, std::uint64_t> references;
	Max builtLevel, builtPoint, libraryLevel, libraryPoint;
	std::uint64_t estimateMisses = 0; ///< library error against the dense reference above 10× the estimate + 1e-9
	/// Dense reference and built answer disagree (level beyond 1e-9 or point beyond 1e-6 of the
	/// size), and of those, how many have the automatic answer nearer the built one than the
	/// dense reference is (in level and point): there the dense reference is the one that is off.
	std::uint64_t disagreements = 0, automaticWithBuilt = 0;
	void Add(const FullCheck& f, std::uint64_t index)
	{
		if (!f.done) return;
		++checks;
		if (f.builtLevel > 1e-9 || f.builtPoint > 1e-6)
		{
			++disagreements;
			if (f.automaticVsBuiltLevel < f.builtLevel && f.automaticVsBuiltPoint < f.builtPoint)
				++automaticWithBuilt;
		}
		++references[f.reference];
		builtLevel.Add(f.builtLevel, index);
		builtPoint.Add(f.builtPoint, index);
		libraryLevel.Add(f.libraryLevel, index);
		libraryPoint.Add(f.libraryPoint, index);
		// The dense references place points to ~1e-10 (sampling and golden search), so the
		// estimate is validated to that floor.
		if (f.libraryPoint == f.libraryPoint && f.estimate == f.estimate && f.libraryPoint > 10.0 * f.estimate + 1e-9)
			++estimateMisses;
	}
	Json ToJson() const
	{
		Json j;
		j["checks"] = checks;
		Json r = Json::object();
		for (const auto& [name, n] : references) r[name] = n;
		j["references"] = r;
		j["max_built_answer_level_difference"] = builtLevel.ToJson();
		j["max_built_answer_point_difference"] = builtPoint.ToJson();
		j["max_automatic_level_difference"] = libraryLevel.ToJson();
		j["max_automatic_point_difference"] = libraryPoint.ToJson();
		j["estimate_misses"] = estimateMisses;
		j["disagreements_with_built_answer"] = disagreements;
		j["of_which_automatic_is_nearer_the_built_answer"] = automaticWithBuilt;
		return j;
	}
};

/// Statistics of one category.
struct CategoryStats
{
	std::uint64_t configurations = 0, unpolished = 0, nearTangentVerified = 0, centreInside = 0, corners = 0;
	Max referenceStep; ///< the built answer's last Newton correction / size
	std::array<KindStats, int(Kind::count)> kind;
	FullStats full;

	void Add(const Config& c, const Outcome& o)
	{
		++configurations;
		if (c.constructed && !c.answer.ok) ++unpolished;
		if (c.constructed && c.answer.ok) referenceStep.Add(double(c.answer.lastStep / c.size), c.index);
		if (o.nearTangentVerified) ++nearTangentVerified;
		if (c.centreInside) ++centreInside;
		if (c.corner) ++corners;
		for (int i = 0; i < int(Kind::count); ++i)
			kind[i].Add(o.check[i], c.index);
		full.Add(o.full, c.index);
	}
	Json ToJson() const
	{
		Json j;
		j["configurations"] = configurations;
		j["built_answers_not_converged"] = unpolished;
		j["max_built_answer_correction"] = referenceStep.ToJson();
		j["near_tangent_verified"] = nearTangentVerified;
		j["centre_inside_other"] = centreInside;
		j["heart_tip_contacts"] = corners;
		for (int i = 0; i < int(Kind::count); ++i)
			if (kind[i].runs) j[KindName(Kind(i))] = kind[i].ToJson();
		j["dense_reference"] = full.ToJson();
		return j;
	}
	/// Decade counts as CSV: one row per decade, columns per kind and error.
	std::string Csv() const
	{
		bench::Table t;
		t.columns = {"decade"};
		std::vector<const Histogram*> cols;
		for (int i = 0; i < int(Kind::count); ++i)
		{
			if (!kind[i].runs) continue;
			const KindStats& s = kind[i];
			const std::string name = KindName(Kind(i));
			for (auto [label, h] : {std::pair<const char*, const Histogram*>{"point", &s.hPoint}, {"level", &s.hLevel},
			                        {"normal", &s.hNormal}, {"separation", &s.hSeparation}})
			{
				t.columns.push_back(name + "_" + label);
				cols.push_back(h);
			}
		}
		for (int b = 0; b < Histogram::kBins; ++b)
		{
			std::vector<std::string> row{Histogram::Label(b)};
			for (const Histogram* h : cols) row.push_back(std::to_string(h->count[b]));
			t.rows.push_back(row);
		}
		return t.Csv();
	}
};

/// The configurations to write out in full: the largest errors per category and metric, and
/// every failure and non-finite answer (up to 20 of each per category).
struct WorstCases
{
	struct Entry { double value; std::uint64_t index; };
	std::map<std::string, std::vector<Entry>> top; // key "category/kind/metric"
	std::map<std::string, std::vector<std::uint64_t>> bad;

	void Offer(const std::string& key, double v, std::uint64_t index, size_t keep = 2)
	{
		if (!(v == v) || v <= 0.0) return;
		auto& list = top[key];
		list.push_back({v, index});
		std::sort(list.begin(), list.end(), [](const Entry& a, const Entry& b) { return a.value > b.value; });
		if (list.size() > keep) list.resize(keep);
	}
	void Flag(const std::string& key, std::uint64_t index, size_t keep = 20)
	{
		auto& list = bad[key];
		if (list.size() < keep) list.push_back(index);
	}
	void Add(const Config& c, const Outcome& o)
	{
		const std::string cat = CategoryName(c.category);
		for (int i = 0; i < int(Kind::count); ++i)
		{
			const Check& k = o.check[i];
			if (!k.ran) continue;
			const std::string key = cat + "/" + KindName(Kind(i));
			if (!k.finite) Flag(key + "/non_finite", c.index);
			if (k.status == SolveStatus::failed && !k.expectedFailure && Kind(i) != Kind::newton) Flag(key + "/failed", c.index);
			if (k.touchingWrong) Flag(key + "/touching_mismatch", c.index);
			Offer(key + (KindStats::WellConditioned(k) ? "/point" : "/point_ill_conditioned"), k.point, c.index);
			Offer(key + "/level", k.level, c.index, 1);
			Offer(key + "/normal", k.normal, c.index, 1);
			Offer(key + "/separation", k.separation, c.index, 1);
			Offer(key + "/overlap_axis_excess", k.axisExcess, c.index, 1);
			Offer(key + "/point_over_floor", KindStats::Excess(k.point, k.pointFloor), c.index, 1);
			Offer(key + "/level_over_floor", KindStats::Excess(k.level, k.levelFloor), c.index, 1);
		}
		Offer(cat + "/dense/library_point", o.full.libraryPoint, c.index, 1);
		Offer(cat + "/dense/built_point", o.full.builtPoint, c.index, 1);
	}
	std::set<std::uint64_t> Indices() const
	{
		std::set<std::uint64_t> s;
		for (const auto& [key, list] : top) for (const Entry& e : list) s.insert(e.index);
		for (const auto& [key, list] : bad) for (std::uint64_t i : list) s.insert(i);
		return s;
	}
	Json ToJson() const
	{
		Json j = Json::object();
		for (const auto& [key, list] : top)
		{
			Json a = Json::array();
			for (const Entry& e : list) a.push_back(Json{{"value", e.value}, {"index", e.index}});
			j[key] = a;
		}
		for (const auto& [key, list] : bad) j[key] = list;
		return j;
	}
};

/// What one checked answer shows against the standard (kWrongNormal, kWrongLevel).
struct Assessment
{
	bool failed = false, nonFinite = false, wrongVerdict = false, wrongNormal = false, wrongLevel = false, inaccurate = false;
	bool illNormal = false, illLevel = false; ///< double precision cannot fix the normal (level) to the standard there
	void Merge(const Assessment& o)
	{
		failed |= o.failed;
		nonFinite |= o.nonFinite;
		wrongVerdict |= o.wrongVerdict;
		wrongNormal |= o.wrongNormal;
		wrongLevel |= o.wrongLevel;
		inaccurate |= o.inaccurate;
		illNormal |= o.illNormal;
		illLevel |= o.illLevel;
	}
};

/// Where the rounding of the coordinates alone moves the normal (level) by more than a hundredth
/// of the standard, double precision cannot promise the standard: the normal (level) is
/// ill-conditioned there, and wrong only beyond a hundred times that rounding.
bool IllConditionedNormal(const Check& k) { return k.normalRounding > 1e-2 * kWrongNormal; }
bool IllConditionedLevel(const Check& k) { return k.levelRounding > 1e-2 * kWrongLevel; }

/// Whether a result's normal is unique: not at a heart's tip against another's, and not a
/// one-sided scale's normal (the scaled particle's gradient) at the scaled heart's own tip.
bool UniqueNormal(const Config& c, Kind kind)
{
	return !c.tipAgainstTip && !(kind == Kind::scaleAB && c.cornerA) && !(kind == Kind::scaleBA && c.cornerB);
}

/// A failure of an automatic answer (Newton alone may fail: the automatic path falls back), a
/// wrong verdict, and for a converged answer a normal or level off by more than the standard
/// (the normal where it is unique: not at a heart's tip against another's).
Assessment Assess(const Config& c, const Check& k, Kind kind)
{
	Assessment a;
	if (!k.ran)
		return a;
	a.nonFinite = !k.finite;
	a.failed = k.status == SolveStatus::failed && !k.expectedFailure && kind != Kind::newton;
	a.wrongVerdict = k.touchingWrong;
	if (k.status == SolveStatus::failed || !k.finite)
		return a;
	const bool unique = UniqueNormal(c, kind);
	a.wrongNormal = unique && k.normal > std::max(kWrongNormal, 1e2 * k.normalRounding);
	a.wrongLevel = k.level > std::max(kWrongLevel, 1e2 * k.levelRounding);
	a.illNormal = unique && IllConditionedNormal(k);
	a.illLevel = IllConditionedLevel(k);
	a.inaccurate = KindStats::Inaccurate(k);
	return a;
}

/// The configurations of one range (Range) and their answers: counts of configurations with a
/// failure, a wrong verdict, a wrong normal or level, or an inaccurate answer (any of their
/// results, cold or warm), and the worst errors of the well-posed ones (points where they are
/// well-conditioned, normals where they are unique).
struct RangeStats
{
	std::uint64_t configurations = 0, failed = 0, nonFinite = 0, wrongVerdicts = 0, wrongNormals = 0, wrongLevels = 0,
	              inaccurate = 0, tipAgainstTip = 0, scaleAtItsTip = 0, illNormals = 0, illLevels = 0;
	/// Of the failed and the wrong: at a level below 1e-9 of the own (needles crossing or
	/// overlapping deep inside each other), and heart pairs (the grid method's tips).
	std::uint64_t failedDeep = 0, wrongNormalsDeep = 0, wrongLevelsDeep = 0;
	std::uint64_t wrongNormalsHearts = 0, wrongLevelsHearts = 0;
	std::uint64_t overlapAxis = 0; ///< contacts by the axis of least overlap (no level met the standard), coincident centres apart
	std::uint64_t warmSteps = 0, warmUnchecked = 0;
	std::uint64_t warmFailed = 0, warmWrongVerdicts = 0, warmWrongNormals = 0, warmWrongLevels = 0;
	/// The worst errors of the well-posed answers, of superellipse pairs (common level) and of heart
	/// pairs (the grid method's one-sided scales) apart.
	struct Worst
	{
		Max point, level, normal, separation;
		Json ToJson() const
		{
			return Json{{"point_error_well_conditioned", point.ToJson()}, {"level_error", level.ToJson()},
			            {"normal_angle_error", normal.ToJson()}, {"separation_error", separation.ToJson()}};
		}
	} worstCommon, worstHearts;
	std::array<KindStats, int(Kind::count)> kind;
	KindStats warm;

	/// Adds a configuration's results in this range: the one-sided scale its contact does not use
	/// (`unused`), or all others. Flags the configurations that fall short under `name` in `worst`.
	void Add(const Config& c, const Outcome& o, bool unused, const std::string& name, WorstCases& worst)
	{
		++configurations;
		if (!unused && c.category != Category::coincident && o.contact.method == SolveMethod::overlapAxis) ++overlapAxis;
		if (c.tipAgainstTip) ++tipAgainstTip;
		else if ((c.cornerA && o.check[int(Kind::scaleAB)].ran && o.check[int(Kind::scaleAB)].unusedSide == unused) ||
		         (c.cornerB && o.check[int(Kind::scaleBA)].ran && o.check[int(Kind::scaleBA)].unusedSide == unused))
			++scaleAtItsTip;
		Assessment any;
		for (int i = 0; i < int(Kind::count); ++i)
		{
			const Check& k = o.check[i];
			if (!k.ran || k.unusedSide != unused)
				continue;
			kind[i].Add(k, c.index);
			any.Merge(Assess(c, k, Kind(i)));
			AddWorst(c, k, Kind(i));
		}
		for (const WarmCheck& w : o.warm)
		{
			if (unused)
				break;
			++warmSteps;
			warm.Add(w.check, c.index);
			const Assessment a = Assess(c, w.check, Kind::contact);
			warmFailed += a.failed;
			warmWrongVerdicts += a.wrongVerdict;
			warmWrongNormals += a.wrongNormal;
			warmWrongLevels += a.wrongLevel;
			any.Merge(a);
			AddWorst(c, w.check, Kind::contact);
		}
		if (!unused) warmUnchecked += o.warmUnchecked;
		failed += any.failed;
		const bool deep = o.referenceLevel < kDeepLevel;
		failedDeep += any.failed && deep;
		wrongNormalsDeep += any.wrongNormal && deep && c.problem == Problem::common;
		wrongLevelsDeep += any.wrongLevel && deep && c.problem == Problem::common;
		nonFinite += any.nonFinite;
		wrongVerdicts += any.wrongVerdict;
		wrongNormals += any.wrongNormal;
		wrongLevels += any.wrongLevel;
		wrongNormalsHearts += any.wrongNormal && c.problem == Problem::scaleA;
		wrongLevelsHearts += any.wrongLevel && c.problem == Problem::scaleA;
		inaccurate += any.inaccurate;
		illNormals += any.illNormal;
		illLevels += any.illLevel;
		const std::string key = name + "/" + CategoryName(c.category);
		// (In range every one of them, up to 100 per category and kind: they are the run's news.)
		const size_t keep = name == RangeName(Range::inRange) ? 100 : 20;
		if (any.failed) worst.Flag(key + "/failed", c.index, keep);
		if (any.nonFinite) worst.Flag(key + "/non_finite", c.index, keep);
		if (any.wrongVerdict) worst.Flag(key + "/wrong_verdict", c.index, keep);
		if (any.wrongNormal) worst.Flag(key + "/wrong_normal", c.index, keep);
		if (any.wrongLevel) worst.Flag(key + "/wrong_level", c.index, keep);
	}
	void AddWorst(const Config& c, const Check& k, Kind kind)
	{
		if (k.status == SolveStatus::failed || !k.finite)
			return;
		Worst& w = c.problem == Problem::common ? worstCommon : worstHearts;
		if (KindStats::WellConditioned(k)) w.point.Add(k.point, c.index);
		if (!IllConditionedLevel(k)) w.level.Add(k.level, c.index);
		if (UniqueNormal(c, kind) && !IllConditionedNormal(k)) w.normal.Add(k.normal, c.index);
		w.separation.Add(k.separation, c.index);
	}
	Json ToJson() const
	{
		Json j;
		j["configurations"] = configurations;
		j["failed"] = failed;
		j["failed_at_levels_below_1e-9"] = failedDeep;
		j["non_finite"] = nonFinite;
		j["wrong_verdicts"] = wrongVerdicts;
		j["wrong_normals"] = wrongNormals;
		j["wrong_normals_of_heart_pairs"] = wrongNormalsHearts;
		j["wrong_normals_of_superellipse_pairs_below_level_1e-9"] = wrongNormalsDeep;
		j["wrong_levels"] = wrongLevels;
		j["wrong_levels_of_heart_pairs"] = wrongLevelsHearts;
		j["wrong_levels_of_superellipse_pairs_below_level_1e-9"] = wrongLevelsDeep;
		j["non_unique_normals"] = Json{{"tip_against_tip", tipAgainstTip}, {"one_sided_scale_at_its_tip", scaleAtItsTip}};
		j["ill_conditioned_normals"] = illNormals;
		j["contacts_by_the_axis_of_least_overlap"] = overlapAxis;
		j["ill_conditioned_levels"] = illLevels;
		j["inaccurate"] = inaccurate;
		j["worst_superellipse_pairs"] = worstCommon.ToJson();
		j["worst_heart_pairs"] = worstHearts.ToJson();
		if (warmSteps || warmUnchecked)
			j["warm"] = Json{{"steps", warmSteps}, {"unchecked", warmUnchecked}, {"failed", warmFailed},
			                 {"wrong_verdicts", warmWrongVerdicts}, {"wrong_normals", warmWrongNormals},
			                 {"wrong_levels", warmWrongLevels}, {"contact_warm", warm.ToJson()}};
		Json results;
		for (int i = 0; i < int(Kind::count); ++i)
			if (kind[i].runs) results[KindName(Kind(i))] = kind[i].ToJson();
		j["results"] = results;
		return j;
	}
};

/// Largest errors of the automatic contact, and Newton's failures, per range of a pair property.
struct Breakdown
{
	struct Bin
	{
		std::uint64_t configurations = 0, fallback = 0, newtonFailed = 0, inaccurate = 0;
		Max point, level, normal;
	};
	std::vector<Bin> bins;
	std::vector<std::string> labels;
	explicit Breakdown(std::vector<std::string> names) : bins(names.size()), labels(std::move(names)) {}
	void Add(int bin, const Outcome& o, std::uint64_t index)
	{
		Bin& b = bins[std::clamp(bin, 0, int(bins.size()) - 1)];
		const Check& k = o.check[int(Kind::contact)];
		++b.configurations;
		if (k.status == SolveStatus::convergedAfterFallback) ++b.fallback;
		if (o.check[int(Kind::newton)].ran && o.check[int(Kind::newton)].status == SolveStatus::failed) ++b.newtonFailed;
		if (KindStats::WellConditioned(k)) b.point.Add(k.point, index);
		b.level.Add(k.level, index);
		b.normal.Add(k.normal, index);
		if (KindStats::Inaccurate(k)) ++b.inaccurate;
	}
	Json ToJson(const char* what) const
	{
		Json a = Json::array();
		for (size_t i = 0; i < bins.size(); ++i)
		{
			const Bin& b = bins[i];
			a.push_back(Json{{what, labels[i]}, {"configurations", b.configurations}, {"fallback", b.fallback},
			                 {"newton_failed", b.newtonFailed}, {"inaccurate", b.inaccurate},
			                 {"max_point_error_well_conditioned", b.point.ToJson()}, {"max_level_error", b.level.ToJson()},
			                 {"max_normal_angle_error", b.normal.ToJson()}});
		}
		return a;
	}
};

/// Aspect ratio of a shape (1 for hearts).
double Aspect(const ShapeSpec& s) { return s.heart ? 1.0 : std::max(s.a, s.b) / std::min(s.a, s.b); }

// ---------------------------------------------------------------------------------------------
// Output of one configuration in full precision
// ---------------------------------------------------------------------------------------------

/// A double as "%.17g" (round-trips) in JSON's number form, and its hex float beside it.
Json Exact(double v)
{
	char hex[64];
	std::snprintf(hex, sizeof hex, "%a", v);
	return Json{{"value", v}, {"hex", hex}};
}
Json Exact(Vec2 v) { return Json::array({Exact(v.x), Exact(v.y)}); }
Json Point(V v) { return Json::array({double(v.x), double(v.y)}); }

Json ShapeJson(const ShapeSpec& s)
{
	if (s.heart) return Json{{"type", "heart"}, {"alpha", Exact(s.alpha)}};
	return Json{{"type", "superellipse"}, {"a", Exact(s.a)}, {"b", Exact(s.b)}, {"n", Exact(s.n)}, {"m", Exact(s.m)}};
}

Json PoseJson(const Pose& p, double angle)
{
	return Json{{"x", Exact(p.p.x)}, {"y", Exact(p.p.y)}, {"angle", Exact(angle)}};
}

Json ContactJson(const ContactResult& r)
{
	return Json{{"status", StatusName(r.status)}, {"method", MethodName(r.method)}, {"failure", r.failure},
	            {"iterations", r.iterations}, {"level", Exact(r.level)}, {"point", Exact(r.point)},
	            {"normal", Exact(r.normal)}, {"pointA", Exact(r.pointA)}, {"pointB", Exact(r.pointB)},
	            {"separation", Exact(r.separation)}, {"touching", r.touching}};
}

Json LevelJson(const LevelResult& r)
{
	return Json{{"status", StatusName(r.status)}, {"method", MethodName(r.method)}, {"failure", r.failure},
	            {"iterations", r.iterations}, {"level", Exact(r.level)}, {"point", Exact(r.point)},
	            {"normal", Exact(r.normal)}, {"multiplier", Exact(r.multiplier)}};
}

Json CheckJson(const Check& k)
{
	auto num = [](double v) { return v == v ? Json(v) : Json(nullptr); };
	return Json{{"point_error", num(k.point)}, {"level_error", num(k.level)}, {"normal_angle_error", num(k.normal)},
	            {"point_error_estimate", num(k.estimate)}, {"separation_error", num(k.separation)},
	            {"surface_point_error", num(k.surface)}, {"overlap_axis_excess", num(k.axisExcess)},
	            {"point_condition", num(k.condition)}, {"normal_rounding", num(k.normalRounding)},
	            {"against_built_answer", k.exact}, {"grazing", k.grazing}, {"touching_mismatch", k.touchingWrong}};
}

Json ConfigJson(const Config& c, const Outcome& o)
{
	Json j;
	j["index"] = c.index;
	j["category"] = CategoryName(c.category);
	j["problem"] = c.problem == Problem::common ? "common_level" : "scale_a";
	j["a"] = ShapeJson(c.a);
	j["b"] = ShapeJson(c.b);
	j["pose_a"] = PoseJson(c.pa, c.angleA);
	j["pose_b"] = PoseJson(c.pb, c.angleB);
	j["size"] = c.size;
	if (c.constructed)
	{
		j["built_for"] = Json{{"level", c.targetLevel}, {"normal_angle", c.normalAngle}, {"heart_tip", c.corner}};
		j["answer"] = Json{{"converged", c.answer.ok}, {"level", double(c.answer.level)}, {"point", Point(c.answer.point)},
		                   {"normal", Point(c.answer.normal)}, {"correction", double(c.answer.lastStep / c.size)}};
	}
	j["centre_inside_other"] = c.centreInside;
	Json results;
	results["contact_auto"] = ContactJson(o.contact);
	if (c.problem == Problem::common)
	{
		results["level_auto"] = LevelJson(o.level);
		results["newton"] = LevelJson(o.newton);
	}
	else if (c.category != Category::coincident)
	{
		results["scale_ab_auto"] = LevelJson(o.scaleAB);
		results["scale_ba_auto"] = LevelJson(o.scaleBA);
	}
	j["results"] = results;
	Json checks;
	for (int i = 0; i < int(Kind::count); ++i)
		if (o.check[i].ran) checks[KindName(Kind(i))] = CheckJson(o.check[i]);
	j["checks"] = checks;
	if (!o.warm.empty() || o.warmUnchecked)
	{
		Json warm = Json::array();
		for (const WarmCheck& w : o.warm)
			warm.push_back(Json{{"pose_a", PoseJson(w.pa, std::atan2(w.pa.q.s, w.pa.q.c))},
			                    {"pose_b", PoseJson(w.pb, std::atan2(w.pb.q.s, w.pb.q.c))},
			                    {"answer", Json{{"level", double(w.answer.level)}, {"point", Point(w.answer.point)},
			                                    {"normal", Point(w.answer.normal)}}},
			                    {"contact_warm", ContactJson(w.contact)}, {"check", CheckJson(w.check)}});
		j["warm_steps"] = warm;
		j["warm_steps_unchecked"] = o.warmUnchecked;
	}
	if (o.full.done)
		j["dense_reference"] = Json{{"reference", o.full.reference}, {"level", double(o.full.level)},
		                            {"point", Point(o.full.point)}, {"built_answer_level_difference", o.full.builtLevel},
		                            {"built_answer_point_difference", o.full.builtPoint},
		                            {"automatic_level_difference", o.full.libraryLevel},
		                            {"automatic_point_difference", o.full.libraryPoint}};
	return j;
}

/// The summary's headline: the in-range counts and worst errors, each beyond-range kind apart,
/// and the automatic contact's overall counts (no maximum pooled over ranges).
Json Headline(bool quick, std::uint64_t seed, std::uint64_t count, const std::array<RangeStats, int(Range::count)>& ranges,
              const KindStats* total)
{
	std::uint64_t nonFinite = 0;
	for (const RangeStats& r : ranges)
		nonFinite += r.nonFinite;
	const KindStats& contact = total[int(Kind::contact)];
	Json j;
	j["benchmark"] = "b2a_stress";
	j["quick"] = quick;
	j["seed"] = seed;
	j["configurations"] = count;
	j["converged"] = contact.converged;
	j["fallback"] = contact.fallback;
	j["failed"] = contact.failed;
	j["non_finite"] = nonFinite;
	j["in_range"] = ranges[int(Range::inRange)].ToJson();
	Json beyond;
	for (int r = int(Range::inRange) + 1; r < int(Range::count); ++r)
		beyond[RangeName(Range(r))] = ranges[r].ToJson();
	j["beyond_range"] = beyond;
	j["notes"] = Json::array({
		"in range: size ratio below 1e4, common level (or one-sided scale, in units of the own level) within 1e-30 to 1e30, neither centre inside the other particle; beyond range, each kind apart (the first that applies, in the order coincident centres, centre inside the other, size ratio, level), and a heart pair's one-sided scale that its contact was not built from",
		"failures and wrong answers are also counted apart where the level is below 1e-9 of the own (needles crossing or overlapping deep inside each other) and for heart pairs (the grid method's tips)",
		"where no level meets the solvers' standard and the pair overlaps, the contact is the axis of least overlap (as for coincident centres), checked as such (contacts_by_the_axis_of_least_overlap)",
		"counts are of configurations: one counts as failed, wrong or inaccurate when any of its results (contact_auto, level_auto, newton, scale_ab_auto, scale_ba_auto, and the warm-started contacts) is; Newton alone (newton) may fail, as the automatic path then falls back, but its converged answers are held to the same standard",
		"a normal is wrong when it is off by more than 1e-6 rad, a level when it is off by more than 1e-9 of itself, and either only beyond 100 times what the rounding of the coordinates alone explains (eps*max|coordinate|*(kappaA + kappaB) for normals, eps*max|coordinate|*|grad|/C for levels); where that rounding exceeds a hundredth of the standard the normal (level) is counted as ill-conditioned (ill_conditioned_normals, ill_conditioned_levels), and worst errors leave it out; normals that are not unique are counted (non_unique_normals) but not judged: a heart's tip against another heart's tip, and a one-sided scale's normal (the scaled particle's gradient) where the point is the scaled heart's own tip",
		"warm: after its cold contact, every common-level configuration with a reference is solved again with a WarmStart, then after each of 3 small rigid motions of both bodies (moves of 1e-6 to 1e-2 of the smaller size, turns of 1e-6 to 1e-2 rad) from the WarmStart the last solve left, as the Box2D adapter does; each checked against the long-double solution at its poses",
		"errors are relative to the smaller particle's bounding radius (points, separations) or to the level itself; separations and contact points relative to the smaller size plus the distance along the normal line",
		"worst errors are those of the well-posed answers, superellipse pairs and heart pairs apart; point errors leave out points along flat contacts, where 1/((kappaA + kappaB) size) > 1e6 and double precision fixes the point only to eps times that",
		"inaccurate: a point or level error above 1e4 times what double rounding of the coordinates explains (eps*max|coordinate|*|grad|/C for levels, eps*(max|coordinate|/size + 1/((kappaA + kappaB) size)) for points)",
		"converged/fallback/failed count ComputeContact with the automatic method, one per configuration, in every range",
		"categories, the dense-reference comparison and the breakdowns by size ratio, aspect and level cover every configuration, beyond range included",
		"mean_microseconds of the heart pairs' contact_auto is a second solve: each is solved once untimed first, which builds the pool shapes' surface samples on first use"});
	return j;
}

/// Per-category statistics as JSON.
Json CategoriesJson(const std::array<CategoryStats, int(Category::count)>& categories)
{
	Json cats;
	for (int c = 0; c < int(Category::count); ++c)
		cats[CategoryName(Category(c))] = categories[c].ToJson();
	return cats;
}

/// The one-line summary on stdout: in range, the counts of configurations with a failure, a wrong
/// verdict, a wrong normal or level (the standard), those not judged (non-unique normals) and
/// those judged against their rounding (ill-conditioned), and the worst errors of the well-posed
/// answers; then each beyond-range kind apart with its own counts.
std::string SummaryLine(std::uint64_t count, double seconds, double cpuSeconds,
                        const std::array<RangeStats, int(Range::count)>& ranges)
{
	const RangeStats& in = ranges[int(Range::inRange)];
	char text[2048];
	std::snprintf(text, sizeof text,
	              "b2a_stress: %" PRIu64 " configurations in %.1f s (CPU %.1f s); in range %" PRIu64 ": %" PRIu64
	              " failed (%" PRIu64 " below level 1e-9), %" PRIu64 " non-finite, %" PRIu64 " wrong verdicts, %" PRIu64
	              " wrong normals (%" PRIu64 " of heart pairs, %" PRIu64 " below level 1e-9), %" PRIu64 " wrong levels (%" PRIu64
	              " of heart pairs, %" PRIu64 " below level 1e-9), %" PRIu64 " inaccurate; not judged: %" PRIu64
	              " non-unique normals (%" PRIu64 " tip against tip, %" PRIu64 " one-sided scale at its tip);"
	              " ill-conditioned, judged against 100 times their rounding: %" PRIu64 " normals, %" PRIu64
	              " levels; worst of superellipse pairs: point %.2g, level %.2g, normal %.2g rad; of heart pairs: point"
	              " %.2g, level %.2g, normal %.2g rad; %" PRIu64 " warm steps (%" PRIu64 " wrong normals, %" PRIu64
	              " wrong levels); beyond range:",
	              count, seconds, cpuSeconds, in.configurations, in.failed, in.failedDeep, in.nonFinite, in.wrongVerdicts,
	              in.wrongNormals, in.wrongNormalsHearts, in.wrongNormalsDeep, in.wrongLevels, in.wrongLevelsHearts, in.wrongLevelsDeep,
	              in.inaccurate, in.tipAgainstTip + in.scaleAtItsTip, in.tipAgainstTip, in.scaleAtItsTip, in.illNormals,
	              in.illLevels, in.worstCommon.point.value, in.worstCommon.level.value, in.worstCommon.normal.value,
	              in.worstHearts.point.value, in.worstHearts.level.value, in.worstHearts.normal.value, in.warmSteps,
	              in.warmWrongNormals, in.warmWrongLevels);
	std::string line = text;
	for (int r = int(Range::inRange) + 1; r < int(Range::count); ++r)
	{
		const RangeStats& k = ranges[r];
		std::snprintf(text, sizeof text,
		              "%s %s %" PRIu64 " (%" PRIu64 " failed, %" PRIu64 " wrong verdicts, %" PRIu64 " wrong normals, %" PRIu64
		              " wrong levels)",
		              r == int(Range::inRange) + 1 ? "" : ",", RangeName(Range(r)), k.configurations, k.failed,
		              k.wrongVerdicts, k.wrongNormals, k.wrongLevels);
		line += text;
	}
	return line;
}

/// The run passes when no result anywhere is non-finite and, in range, cold or warm-started, nothing
/// failed, no verdict is wrong and no converged answer misses the standard, with no exemption
/// for deep needle crossings or heart tips (which the summary still counts apart).
bool Passed(const std::array<RangeStats, int(Range::count)>& ranges)
{
	std::uint64_t nonFinite = 0;
	for (const RangeStats& r : ranges)
		nonFinite += r.nonFinite;
	const RangeStats& in = ranges[int(Range::inRange)];
	return nonFinite == 0 && in.wrongVerdicts == 0 && in.failed == 0 && in.wrongNormals == 0 && in.wrongLevels == 0 &&
	       in.warmFailed == 0 && in.warmWrongVerdicts == 0 && in.warmWrongNormals == 0 && in.warmWrongLevels == 0;
}

} // namespace

int main(int argc, char** argv)
{
	std::uint64_t count = 0, fullEvery = 500;
	int poolSize = 0;
	demo::CommandLine cli("b2a_stress", kHelp);
	cli.Add("--count", count, 1000000, 40000, "N", "number of configurations (default 1000000, 40000 with --quick)",
	        demo::WholeNumber(1, 1e9));
	cli.Add("--full-every", fullEvery, "K",
	        "check one configuration in K (a fixed pseudo-random choice) against the\ndense references (default 500)",
	        demo::WholeNumber(1, 1e9));
	cli.Add("--pool", poolSize, 16384, 512, "N",
	        "superellipse shapes to draw from (default 16384, 512 with --quick; hearts:\n"
	        "N/16). Making a heart costs a millisecond, so configurations share them.",
	        demo::WholeNumber(16, 1e6));
	std::vector<int> ids;
	cli.Add("--ids", ids, "I,J,...",
	        "run only these configurations (of the run --seed and --pool make) and write\n"
	        "each in full, with its results and checks, to DIR/configurations.json",
	        demo::WholeNumber(0, 1e9));
	const demo::DemoOptions o = cli.Parse(argc, argv);
	demo::Progress progress("b2a_stress");
	const double cpuStart = bench::ThreadCpuNanoseconds();
	ShapePool pool(o.seed, poolSize, poolSize / 16);
	if (!ids.empty())
	{
		Json list = Json::array();
		for (int i : ids)
		{
			const Config c = MakeConfig(o.seed, std::uint64_t(i), pool);
			list.push_back(ConfigJson(c, Run(c, true)));
		}
		demo::WriteJson(o.out + "/configurations.json", list);
		std::printf("%zu configurations -> %s/configurations.json\n", ids.size(), o.out.c_str());
		return 0;
	}
	// The dense subset: a fixed pseudo-random choice (every K-th index would always fall in the
	// same category, whose slots repeat every 100).
	auto dense = [&](std::uint64_t i) { return Mix(i ^ 0xD1B54A32D192ED03ull) % fullEvery == 0; };
	Breakdown bySizeRatio({"1-10", "10-1e2", "1e2-1e3", "1e3-1e4", "1e4-1e5", "1e5-1e6", "1e6+"});
	Breakdown byAspect({"1-10", "10-1e2", "1e2-1e3", "1e3"});
	Breakdown byLevel({"<1e-12", "1e-12-1e-9", "1e-9-1e-6", "1e-6-1e-3", "1e-3-1", "1-1e3", ">=1e3"});

	std::array<CategoryStats, int(Category::count)> categories;
	std::array<RangeStats, int(Range::count)> ranges;
	KindStats total[int(Kind::count)];
	FullStats fullTotal;
	WorstCases worst;
	for (std::uint64_t i = 0; i < count; ++i)
	{
		const Config c = MakeConfig(o.seed, i, pool);
		const Outcome out = Run(c, dense(i));
		if (c.problem == Problem::common && c.category != Category::coincident)
		{
			const double ra = c.shapeA->BoundingRadius(), rb = c.shapeB->BoundingRadius();
			bySizeRatio.Add(int(std::floor(std::log10(std::max(ra, rb) / std::min(ra, rb)))), out, i);
			byAspect.Add(int(std::floor(std::log10(std::max(Aspect(c.a), Aspect(c.b))))), out, i);
			const double level = out.check[int(Kind::contact)].reference;
			if (level == level)
				byLevel.Add(level < 1e-12 ? 0 : int(std::floor(std::log10(level) / 3.0)) + 5, out, i);
		}
		categories[int(c.category)].Add(c, out);
		ranges[int(out.range)].Add(c, out, false, RangeName(out.range), worst);
		if (c.problem == Problem::scaleA && c.category != Category::coincident)
			ranges[int(Range::unusedSide)].Add(c, out, true, RangeName(Range::unusedSide), worst);
		for (int k = 0; k < int(Kind::count); ++k)
			total[k].Add(out.check[k], i);
		fullTotal.Add(out.full, i);
		worst.Add(c, out);
		if (i % 256 == 0 || i + 1 == count)
		{
			const RangeStats& in = ranges[int(Range::inRange)];
			char note[200];
			std::snprintf(note, sizeof note, "%" PRIu64 "/%" PRIu64 " configurations; in range: failed %" PRIu64
			              ", wrong normals %" PRIu64 ", wrong levels %" PRIu64, i + 1, count, in.failed, in.wrongNormals,
			              in.wrongLevels);
			progress.Report(double(i + 1) / double(count), note);
		}
	}
	const double runSeconds = progress.Elapsed();
	const double runCpuSeconds = 1e-9 * (bench::ThreadCpuNanoseconds() - cpuStart);

	// The worst cases again, in full, with the dense references.
	Json worstList = Json::array();
	for (std::uint64_t i : worst.Indices())
	{
		const Config c = MakeConfig(o.seed, i, pool);
		worstList.push_back(ConfigJson(c, Run(c, true)));
	}

	Json j = Headline(o.quick, o.seed, count, ranges, total);
	j["categories"] = CategoriesJson(categories);
	j["dense_reference"] = fullTotal.ToJson();
	j["by_size_ratio"] = bySizeRatio.ToJson("size_ratio");
	j["by_aspect_ratio"] = byAspect.ToJson("aspect_ratio");
	j["by_level"] = byLevel.ToJson("level");
	j["shape_pool"] = Json{{"superellipses", pool.Count(false)}, {"hearts", pool.Count(true)}};
	j["worst_cases"] = worst.ToJson();
	j["machine"] = bench::MachineJson(bench::GetMachineInfo());
	j["seconds"] = runSeconds;
	j["cpu_seconds"] = runCpuSeconds;
	j["seconds_with_worst_cases"] = progress.Elapsed();
	j["cpu_seconds_with_worst_cases"] = 1e-9 * (bench::ThreadCpuNanoseconds() - cpuStart);
	demo::WriteJson(o.out + "/summary.json", j);
	demo::WriteJson(o.out + "/worst_cases.json", worstList);
	for (int c = 0; c < int(Category::count); ++c)
		demo::WriteText(o.out + "/" + CategoryName(Category(c)) + ".csv", categories[c].Csv());

	std::printf("%s -> %s\n", SummaryLine(count, runSeconds, runCpuSeconds, ranges).c_str(), o.out.c_str());
	return Passed(ranges) ? 0 : 1;
}

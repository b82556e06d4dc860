// b2analytic benchmark: numerical stability of the contact solvers over a million random pairs.
//
// Every configuration is solved by the automatic path (ComputeContact, and SolveCommonLevel or
// the one-sided SolveScaleA both ways for hearts) and by Newton alone, and every answer is
// checked in long double against the shapes' formulas (StressReference.h): against the exact
// answer the configuration was built from (StressConfig.h), and by one long-double Newton step
// on the optimality conditions from the answer itself (the cheap check, which also serves the
// random poses that were not built from an answer). A deterministic subset, and every worst
// case, is checked again against the dense references of the unit tests (CommonLevelRef,
// Perram–Wertheim, SurfaceMin), which validates both.
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
and checked in long double against the exact answer it was built from and by the optimality
conditions at the answer; every 500th configuration and every worst case also against the
dense references of the unit tests.

Writes DIR/summary.json (counts, largest errors per category and result kind, worst cases
with full-precision configurations, machine, run time), DIR/worst_cases.json and one CSV per
category (DIR/<category>.csv: how many answers fall in each decade of error). Exits 1 when any
result has a non-finite field or the automatic path fails on a configuration whose level is at
least 1e-12 of the own level (failures deeper than that, nearly concentric particles, are
counted and reported apart).
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
	double reference = kNaN;       ///< the reference level (built answer, or the answer's own)
	bool grazing = false;          ///< the normal line nearly misses a particle: points ill-conditioned
	bool touchingWrong = false;    ///< `touching` disagrees with the reference level (beyond 1e-12)
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
/// the kink stops at ~1e-9 of the size: floors of 1e-9 (point) and 1e-8 (level) there.
void SetFloors(const Config& c, const Posed& A, const Posed& B, V X, LD L, bool tip, Check& k)
{
	const LD eps = std::numeric_limits<double>::epsilon();
	const LD reach = std::max({ref::Len(X), ref::Len(A.pose.p), ref::Len(B.pose.p)});
	const LD grad = std::max(ref::Len(WorldDeriv(A, X).grad), ref::Len(WorldDeriv(B, X).grad));
	const LD condition = k.condition == k.condition ? LD(k.condition) : 0.0L;
	k.pointFloor = double(eps * (reach / c.size + condition));
	k.levelFloor = double(eps * reach * grad / L);
	if (tip)
	{
		k.pointFloor = std::max(k.pointFloor, 1e-9);
		k.levelFloor = std::max(k.levelFloor, 1e-8);
	}
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
		SetFloors(c, A, B, built ? c.answer.point : X, built ? c.answer.level : L, atTip || (built && c.corner), k);
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
	const V expected = !contact ? na : (ref::Dot(na, nb) < 0.0L ? ref::Unit(na - nb) : V{-nb.x, -nb.y});
	k.normal = Angle(n, expected);
	return k;
}

/// The contact-specific checks of a common-level contact against the built answer: pointA,
/// pointB and the separation from the reference point and normal, and `touching`.
void CheckContactPoints(const Config& c, const ContactResult& r, const Posed& A, const Posed& B, Check& k)
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
	if (c.problem != Problem::common)
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

/// Everything one configuration produced.
struct Outcome
{
	std::array<Check, int(Kind::count)> check;
	ContactResult contact;
	LevelResult level, newton, scaleAB, scaleBA;
	FullCheck full;
	bool nearTangentVerified = false; ///< |C* − 1| < 1e-9 for the exact answer
	bool beyondRange = false;         ///< the level is below 1e-12 of the own level (see AutomaticFailed)
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

Outcome Run(const Config& c, bool dense)
{
	Outcome o;
	const Shape& a = *c.shapeA;
	const Shape& b = *c.shapeB;
	const Posed A{c.a.Ref(), ref::Of(c.pa)}, B{c.b.Ref(), ref::Of(c.pb)};
	auto& k = o.check;
	double t = 0.0;
	// A pool shape samples its surface on first use (the grid method's and the line searches'
	// samples), and that set-up was most of a heart pair's mean time here (33 to 80 µs from run
	// to run, against 5 to 9 µs for the contact itself): the grid pairs are solved once untimed,
	// so that their times are the contacts' own. (Building the samples alone, untimed, left
	// half of that: the first solve after it still ran several times slower, at the same
	// instruction count.)
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
		kc.seconds = seconds;
		CheckContactPoints(c, o.contact, A, B, kc);
	}
	if (c.category == Category::nearTangent)
		o.nearTangentVerified = c.answer.ok && std::fabs(c.answer.level - 1.0L) < 1e-9L;
	// A failure needs the true level to say whether it lies in the stress range (levels down to
	// 1e-12 of the own level: random poses of high exponents reach 1e-25, nearly concentric
	// particles): the built answer, else the dense reference.
	if (dense || (o.AutomaticFailed() && !(c.constructed && c.answer.ok)))
	{
		const Kind main = c.problem == Problem::common ? Kind::level : Kind::scaleAB;
		const Answer automatic = main == Kind::level ? Of(o.level) : Of(o.scaleAB);
		o.full = DenseReference(c, A, B, automatic, k[int(main)]);
	}
	const LD own = c.problem == Problem::common ? 1.0L : A.shape.Own();
	if (c.constructed && c.answer.ok)
		o.beyondRange = c.answer.level < 1e-12L * own;
	else if (o.full.done)
		o.beyondRange = o.full.level < 1e-12L * own;
	if (!dense)
		o.full = FullCheck(); // only the chosen subset enters the dense statistics
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
	void Flag(const std::string& key, std::uint64_t index)
	{
		auto& list = bad[key];
		if (list.size() < 20) list.push_back(index);
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
	            {"point_condition", num(k.condition)},
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
	if (o.full.done)
		j["dense_reference"] = Json{{"reference", o.full.reference}, {"level", double(o.full.level)},
		                            {"point", Point(o.full.point)}, {"built_answer_level_difference", o.full.builtLevel},
		                            {"built_answer_point_difference", o.full.builtPoint},
		                            {"automatic_level_difference", o.full.libraryLevel},
		                            {"automatic_point_difference", o.full.libraryPoint}};
	return j;
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
	const demo::DemoOptions o = cli.Parse(argc, argv);
	demo::Progress progress("b2a_stress");
	const double cpuStart = bench::ThreadCpuNanoseconds();
	ShapePool pool(o.seed, poolSize, poolSize / 16);
	// The dense subset: a fixed pseudo-random choice (every K-th index would always fall in the
	// same category, whose slots repeat every 100).
	auto dense = [&](std::uint64_t i) { return Mix(i ^ 0xD1B54A32D192ED03ull) % fullEvery == 0; };
	Breakdown bySizeRatio({"1-10", "10-1e2", "1e2-1e3", "1e3-1e4", "1e4-1e5", "1e5-1e6", "1e6+"});
	Breakdown byAspect({"1-10", "10-1e2", "1e2-1e3", "1e3"});
	Breakdown byLevel({"<1e-12", "1e-12-1e-9", "1e-9-1e-6", "1e-6-1e-3", "1e-3-1", "1-1e3", ">=1e3"});

	std::array<CategoryStats, int(Category::count)> categories;
	KindStats total[int(Kind::count)];
	FullStats fullTotal;
	WorstCases worst;
	std::uint64_t failedInRange = 0, failedBeyondRange = 0;
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
		for (int k = 0; k < int(Kind::count); ++k)
			total[k].Add(out.check[k], i);
		fullTotal.Add(out.full, i);
		worst.Add(c, out);
		if (out.AutomaticFailed())
			++(out.beyondRange ? failedBeyondRange : failedInRange);
		if (i % 256 == 0 || i + 1 == count)
		{
			const KindStats& t = total[int(Kind::contact)];
			char note[200];
			std::snprintf(note, sizeof note, "%" PRIu64 "/%" PRIu64 " configurations, failed %" PRIu64 ", non-finite %" PRIu64
			              ", max point error %.2g", i + 1, count, t.failed, t.nonFinite, t.pointWell.value);
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

	std::uint64_t nonFinite = 0;
	for (int k = 0; k < int(Kind::count); ++k)
		nonFinite += total[k].nonFinite;
	const KindStats& contact = total[int(Kind::contact)];
	// The automatic path's largest errors: the contact, the level solve, the scales.
	Max point, pointWell, level, normal;
	std::uint64_t illConditioned = 0, touchingWrong = 0, inaccurate = 0;
	for (Kind k : {Kind::contact, Kind::level, Kind::scaleAB, Kind::scaleBA})
	{
		const KindStats& s = total[int(k)];
		for (auto [into, from] : {std::pair<Max*, const Max*>{&point, &s.point}, {&pointWell, &s.pointWell},
		                          {&level, &s.level}, {&normal, &s.normal}})
			if (from->any) into->Add(from->value, from->index);
		illConditioned += s.illConditioned;
		touchingWrong += s.touchingWrong;
		inaccurate += s.inaccurate;
	}

	Json j;
	j["benchmark"] = "b2a_stress";
	j["quick"] = o.quick;
	j["seed"] = o.seed;
	j["configurations"] = count;
	j["converged"] = contact.converged;
	j["fallback"] = contact.fallback;
	j["failed"] = contact.failed;
	j["non_finite"] = nonFinite;
	j["failed_configurations_in_range"] = failedInRange;
	j["failed_configurations_beyond_range"] = failedBeyondRange;
	j["max_point_error"] = point.value;
	j["max_point_error_well_conditioned"] = pointWell.value;
	j["ill_conditioned_points"] = illConditioned;
	j["max_level_error"] = level.value;
	j["max_normal_angle_error"] = normal.value;
	j["max_separation_error"] = contact.separation.value;
	j["touching_mismatches"] = touchingWrong;
	j["inaccurate"] = inaccurate;
	j["notes"] = Json::array({
		"errors are relative to the smaller particle's bounding radius (points, separations) or to the level itself",
		"converged/fallback/failed count ComputeContact with the automatic method, one per configuration",
		"a point is ill-conditioned when 1/((kappaA + kappaB) size) > 1e6: along a flat contact double precision fixes it only to eps times that",
		"newton is SolveCommonLevel with MethodChoice::newton alone: its failures show how often the automatic path needs its fallback",
		"mean_microseconds of the heart pairs' contact_auto is a second solve: each is solved once untimed first, which builds the pool shapes' surface samples on first use",
		"inaccurate: a point or level error above 1e4 times what double rounding of the coordinates explains (eps*max|coordinate|*|grad|/C for levels, eps*(max|coordinate|/size + 1/((kappaA + kappaB) size)) for points)",
		"separations and contact points are relative to the smaller size plus the distance along the normal line"});
	Json kinds;
	for (int k = 0; k < int(Kind::count); ++k)
		if (total[k].runs) kinds[KindName(Kind(k))] = total[k].ToJson();
	j["kinds"] = kinds;
	Json cats;
	for (int c = 0; c < int(Category::count); ++c)
		cats[CategoryName(Category(c))] = categories[c].ToJson();
	j["categories"] = cats;
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

	std::printf("b2a_stress: %" PRIu64 " configurations in %.1f s (CPU %.1f s): %" PRIu64 " converged, %" PRIu64 " after fallback, %" PRIu64
	            " failed (%" PRIu64 " beyond level 1e-12), %" PRIu64 " non-finite; Newton alone failed %" PRIu64
	            "; max point error %.3g (well-conditioned %.3g), level %.3g, normal %.3g rad; inaccurate %" PRIu64
	            ", touching mismatches %" PRIu64 " -> %s\n",
	            count, runSeconds, runCpuSeconds, contact.converged, contact.fallback, contact.failed, failedBeyondRange, nonFinite,
	            total[int(Kind::newton)].failed, point.value, pointWell.value, level.value, normal.value, inaccurate,
	            touchingWrong, o.out.c_str());
	return nonFinite == 0 && failedInRange == 0 ? 0 : 1;
}

// b2analytic: the one table that decides which solver handles a pair of 2D shape kinds.
//
//                  circle    ellipse   superellipse  smooth_convex  convex   non_convex   polygon
//  circle          Circle    Ellipse   Superellipse  Newton         Grid     Grid         SepAxis
//  ellipse                   Ellipse   Superellipse  Newton         Grid     Grid         SepAxis
//  superellipse                        Superellipse  Newton         Grid     Grid         SepAxis
//  smooth_convex                                     Newton         Grid     Grid         SepAxis
//  convex                                                           Grid     Grid         SepAxis
//  non_convex                                                                Grid         SepAxis
//  (symmetric; a kind registered later: Newton between two of solver class smoothConvex, Grid
//  for any other pair, SepAxis against polygons, until a function is registered for the pair.
//  polygon: a convex polygon or segment by its vertices, Box2D's polygons, edges and chain links.)
//
// Each cell is a chain, written once here: its solver, and where the pair goes when that gives up.
//  contact        solver                                    → where it gives up      level (SolveCommonLevel)
//  Circle         closed form (coincident → OverlapAxis)                             CircleLevel
//  Ellipse        ellipse pair, points in closed form       → from EllipseLevel      EllipseLevel
//  Superellipse   inline Newton, raw-level finish            → from NewtonLevel       NewtonLevel
//  Newton         from NewtonLevel                                                   NewtonLevel
//  Grid           one side (ChooseGridSide)                  → both ways              GridLevel
//  SepAxis        separating axis over the support function
//  "from L": coincident centres → OverlapAxis; else ContactFromLevel of the level chain L
//           (L giving up on an overlapping pair → OverlapAxis).
//  level chains: CircleLevel   closed form
//                EllipseLevel  ellipse pair (Perram–Wertheim)  → NewtonLevel
//                NewtonLevel   Newton from the warm start      → Newton cold → Newton in A's frame, then
//                              B's (two superellipses) → min–max → grid (polished, else Newton in a
//                              particle's frame from its point)
//                GridLevel     the grid's fixed point (non-convex pairs are refused before the table)
//  Explicit methods, for any pair: MethodChoice::newton: from Newton alone (level: Newton alone);
//  MethodChoice::grid: Grid (level: GridLevel).
#include "contact/ContactParts.h"

#include "b2analytic/PolygonContact.h"

#include "contact/PairFrame.h"
#include "contact/PairTable.h"
#include "contact/ResultChecks.h"
#include "contact/SolverCore.h"

namespace b2a
{

namespace
{
// The level chains that are one solver (the others are ContactParts.h's).
LevelResult CircleLevelCell(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                            const WarmStart* warm, LevelSlide* slide);
LevelResult GridLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                      const WarmStart* warm, LevelSlide* slide);
LevelResult NewtonAlone(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                        const WarmStart* warm, LevelSlide* slide);

using Table2 = PairTable<ContactFunction, LevelFunction>;

// The default cell of two solver classes.
constexpr Table2::Cell CellOfClasses(SolverClass a, SolverClass b)
{
	const bool newton = a == SolverClass::smoothConvex && b == SolverClass::smoothConvex;
	return newton ? Table2::Cell{&NewtonContact, &NewtonLevelChain} : Table2::Cell{&GridContact, &GridLevel};
}

// The table above: every built-in cell set (the defaults by class too, so that the built-in
// kinds' pairs never look up a class), then the specialised ones.
struct BuiltTable : Table2
{
	constexpr BuiltTable() : Table2(2, &CellOfClasses)
	{
		for (int i = 0; i < BuiltinKinds::count; ++i)
			for (int j = 0; j < BuiltinKinds::count; ++j)
				SetCell(BuiltinKinds::all[i], BuiltinKinds::all[j],
				        CellOfClasses(BuiltinKinds::solverClasses[i], BuiltinKinds::solverClasses[j]));
		const ShapeKind circle = BuiltinKinds::circle, ellipse = BuiltinKinds::ellipse, superellipse = BuiltinKinds::superellipse;
		SetCell(circle, circle, {&CircleContact, &CircleLevelCell});
		SetCell(ellipse, circle, {&EllipseContact, &EllipseLevelChain});
		SetCell(ellipse, ellipse, {&EllipseContact, &EllipseLevelChain});
		SetCell(superellipse, circle, {&SuperellipseContact, &NewtonLevelChain});
		SetCell(superellipse, ellipse, {&SuperellipseContact, &NewtonLevelChain});
		SetCell(superellipse, superellipse, {&SuperellipseContact, &NewtonLevelChain});
	}
};

// Constant-initialized: filled at compile time, before any code runs (so a registration from
// another file's static initialiser finds it filled), and read without a guard.
B2A_CONSTINIT BuiltTable g_table;

// The polygon column.
B2A_CONSTINIT KindColumn<PolygonContactFunction> g_polygonColumn(&SeparatingAxisContact);

Table2& Table() { return g_table; }

LevelResult CircleLevelCell(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions&,
                            const WarmStart*, LevelSlide*)
{
	return CircleLevel(a, pa, b, pb);
}
LevelResult GridLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                      const WarmStart*, LevelSlide*)
{
	return SolveCommonLevelGrid(a, pa, b, pb, options);
}
LevelResult NewtonAlone(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                        const WarmStart* warm, LevelSlide* slide)
{
	return SolveCommonLevelNewton(a, pa, b, pb, options, warm, slide);
}
} // namespace

namespace
{
// A start in s's body frame from the world point X, for needles crossing deep inside each other.
// Its coordinate across s's thinner level set at C = o's level there (the axis whose extent,
// a·C^{1/n} or b·C^{1/m}, is the smaller) is set so that s's level is C too, on the side where
// o's level falls: beside a needle with an exponent 2 across it, at a level of 1e-23, that
// coordinate is 1e-14 of the size, and a point rounded in world coordinates (a grid's candidate)
// has it at 1e-19 or 1e-22, on the needle's axis, where its level is flat across it and Newton
// creeps. With `crossing`, X first moves along s's axis to where o's long axis crosses it: where
// both level sets are needles, one's tip touches the other's flank there, and a grid's candidate
// may be several of o's thicknesses (1e-10 of the size) away from it.
Vec2 LevelMatchedStart(const SuperellipseShape& s, const Pose& ps, const SuperellipseShape& o, const Pose& po, Vec2 X, bool crossing)
{
	const Pose rel = Relative(ps, po); // o's centre and axes in s's frame
	Vec2 x = ToBody(ps, X), g;
	auto levelOfO = [&](Vec2 at) {
		const Vec2 xo = InvRotate(rel.q, at - rel.p);
		g = Rotate(rel.q, o.Gradient(xo));
		return o.Level(xo);
	};
	auto thinX = [](const SuperellipseShape& k, double C) { return k.A() * std::pow(C, 1.0 / k.N()) <= k.B() * std::pow(C, 1.0 / k.M()); };
	double C = levelOfO(x);
	if (!(C > 0.0) || !std::isfinite(C) || !IsFinite(g))
		return x;
	if (crossing)
	{
		const Vec2 d = Rotate(rel.q, thinX(o, C) ? Vec2(0.0, 1.0) : Vec2(1.0, 0.0)); // o's long axis
		const bool alongY = thinX(s, C);                                                 // s's long axis
		const double t = alongY ? -rel.p.x / d.x : -rel.p.y / d.y;
		const Vec2 at = alongY ? Vec2(0.0, rel.p.y + t * d.y) : Vec2(rel.p.x + t * d.x, 0.0);
		if (!IsFinite(at))
			return x;
		x = at;
		C = levelOfO(x);
		if (!(C > 0.0) || !std::isfinite(C) || !IsFinite(g))
			return x;
	}
	if (thinX(s, C))
	{
		const double rest = C - std::pow(std::fabs(x.y) / s.B(), s.M());
		if (rest > 0.0)
			x.x = -std::copysign(s.A() * std::pow(rest, 1.0 / s.N()), g.x);
	}
	else
	{
		const double rest = C - std::pow(std::fabs(x.x) / s.A(), s.N());
		if (rest > 0.0)
			x.y = -std::copysign(s.B() * std::pow(rest, 1.0 / s.M()), g.y);
	}
	return x;
}

// Two smooth superellipses by Newton in one particle's body frame (SolveSuperellipsePairLevelChecked),
// in A's frame and then in B's: cold, or from `start` (a world point: a grid's candidate; in each
// frame, LevelMatchedStart). Needles crossing deep inside each other (common levels of 1e-30 to 1e-9, where a needle with
// an exponent 2 across it has a level set 1e-15 of its size thick) are out of reach of the
// generic solvers, which evaluate both shapes at world coordinates (rounded to 1e-16 of up to
// 1e3 sizes), and in reach of a frame whose origin is the thin particle's centre: there its
// coordinates are exact, and only the other particle's are rounded, against a level set that is
// not thin. Which particle is the thin one the solve finds out: each frame's exit tests the
// conditions to its own rounding.
LevelResult SuperellipseInItsFrame(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                                   const Vec2* start = nullptr)
{
	LevelResult r;
	r.failure = "Newton in a particle's frame needs two smooth superellipses";
	const SuperellipseShape* sa = AsSmoothSuperellipse(a);
	const SuperellipseShape* sb = sa ? AsSmoothSuperellipse(b) : nullptr;
	if (!sb)
		return r;
	// From a start: in each frame the level matched across the particle, then at the needles'
	// crossing (LevelMatchedStart), on the levels' gauge and then on their logarithms.
	WarmStart from; // the start in the solving particle's frame (μ balanced at its first step)
	from.valid = true;
	int spent = 0;
	for (const bool inB : {false, true})
		for (const bool log : {false, true})
			for (const bool crossing : {false, true})
			{
				if (!start && (crossing || log))
					continue;
				if (start)
					from.localPoint = inB ? LevelMatchedStart(*sb, pb, *sa, pa, *start, crossing)
					                      : LevelMatchedStart(*sa, pa, *sb, pb, *start, crossing);
				const WarmStart* w = start ? &from : nullptr;
				const SuperellipseShape &s = inB ? *sb : *sa, &o = inB ? *sa : *sb;
				const Pose &ps = inB ? pb : pa, &po = inB ? pa : pb;
				r = SolveSuperellipsePairLevelChecked(s, ps, o, po, options, w, log);
				spent += r.iterations;
				r.iterations = spent;
				if (r.Ok())
				{
					if (inB)
					{
						r.normal = -r.normal;
						r.multiplier = 1.0 / r.multiplier;
					}
					return r;
				}
			}
	return r;
}

// The grid's common level sampling B's level surface (or A's, `flipped`), held to the solvers'
// standard (CheckGridCommonLevel); where its polish stops short, Newton in a particle's frame
// from its candidate point (SuperellipseInItsFrame: needles crossing deep inside each other that
// it does not solve cold). Answers for (A, B) either way.
LevelResult GridLevelChecked(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                             bool flipped)
{
	const LevelResult grid = flipped ? SolveCommonLevelGrid(b, pb, a, pa, options) : SolveCommonLevelGrid(a, pa, b, pb, options);
	LevelResult r = flipped ? CheckGridCommonLevel(b, pb, a, pa, options, grid) : CheckGridCommonLevel(a, pa, b, pb, options, grid);
	if (r.Ok() && flipped)
	{
		r.normal = -r.normal;
		r.multiplier = r.multiplier > 0.0 ? 1.0 / r.multiplier : 0.0;
	}
	if (r.Ok() || !grid.Ok())
		return r;
	LevelResult framed = SuperellipseInItsFrame(a, pa, b, pb, options, &grid.point);
	r.iterations += framed.iterations;
	if (!framed.Ok())
		return r; // the grid's failure
	framed.iterations = r.iterations; // (a Newton answer: its method stays newton)
	return framed;
}
} // namespace

LevelResult NewtonLevelChain(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                             const WarmStart* warm, LevelSlide* slide)
{
	LevelResult r = SolveCommonLevelNewton(a, pa, b, pb, options, warm, slide);
	if (!r.Ok() && warm && warm->valid)
		r = SolveCommonLevelNewton(a, pa, b, pb, options, nullptr, slide);
	if (!r.Ok())
	{
		// Two superellipses first in a particle's own frame, whose exit holds the answer to the
		// standard wherever it is thin; the min–max and the grid, in world coordinates, may only
		// meet it to their rounding (normals to 1e-4 rad) where a needle is thinner than that.
		const int spent = r.iterations;
		r = SuperellipseInItsFrame(a, pa, b, pb, options);
		r.iterations += spent;
		if (!r.Ok())
		{
			const int spentFramed = r.iterations;
			r = SolveCommonLevelMinMax(a, pa, b, pb, options);
			r.iterations += spentFramed;
		}
		if (!r.Ok())
		{
			// Min–max that stops short of the standard says so; the grid, which needs neither
			// smoothness nor a good start, is the last resort, its answer held to the same
			// standard (its samples and bracket stop at their own tolerances: needles crossing
			// deep inside each other were answered 0.5 off in level, 3 rad in normal).
			const int spentBoth = r.iterations;
			r = GridLevelChecked(a, pa, b, pb, options, false);
			if (!r.Ok())
			{
				// The grid samples B's level-C surface; where the minimum of λA over it is a
				// sliver its samples straddle (A's level-C set a needle of aspect 1e7 against
				// B's of 1e5, far apart: C ~ 1e24), A's samples find it, as the contact's grid
				// tries both sides (GridContact).
				const int spentOne = r.iterations;
				LevelResult other = GridLevelChecked(a, pa, b, pb, options, true);
				other.iterations += spentOne;
				if (!other.Ok())
					other.failure = r.failure;
				r = other;
			}
			r.iterations += spentBoth;
		}
		if (r.Ok())
			r.status = SolveStatus::convergedAfterFallback;
	}
	return r;
}

LevelResult EllipseLevelChain(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                              const WarmStart* warm, LevelSlide* slide)
{
	const SuperellipseShape* ea = AsPlainEllipse(a);
	const SuperellipseShape* eb = ea ? AsPlainEllipse(b) : nullptr;
	if (eb)
	{
		LevelResult r = SolveEllipsePairLevel(*ea, pa, *eb, pb, warm);
		if (r.Ok())
			return r;
	}
	return NewtonLevelChain(a, pa, b, pb, options, warm, slide);
}

namespace
{
// A level chain's answer as SolveCommonLevel gives it: a pose that is not finite refused, the
// answer checked, and recorded as the next warm start (with the slide where the chain computed
// one). A function stored flipped solves (B, A), without the warm start, and its answer is
// turned back: the same point and level, the normal reversed, the multiplier inverted.
LevelResult RunLevel(LevelFunction f, bool flipped, const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                     const SolverOptions& options, WarmStart* warm)
{
	if (!PoseFinite(pa) || !PoseFinite(pb))
	{
		if (warm)
			warm->valid = false;
		return NonFinitePoseFailure<LevelResult>();
	}
	LevelSlide slide; // the chain's, for the next warm start
	LevelResult r;
	if (flipped)
	{
		r = f(b, pb, a, pa, options, nullptr, nullptr);
		r.normal = -r.normal;
		r.multiplier = r.multiplier > 0.0 ? 1.0 / r.multiplier : 0.0;
	}
	else
		r = f(a, pa, b, pb, options, warm, warm ? &slide : nullptr);
	CheckResult(r);
	RecordWarmStart(warm, pa, pb, r, &slide); // (valid only where the chain computed it)
	return r;
}
} // namespace

ContactResult ContactFromLevelChain(LevelFunction level, const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                    const SolverOptions& options, WarmStart* warm)
{
	if (CentresCoincide(a, pa, b, pb))
		return OverlapAxisContact(a, pa, b, pb);
	const LevelResult r = RunLevel(level, false, a, pa, b, pb, options, warm);
	if (!r.Ok())
	{
		// No level meets the solvers' standard (needles crossing deep inside each other, levels
		// of 1e-12 and below): where the particles overlap, the axis of least overlap still
		// separates them, as for coincident centres. (Not for Newton alone, asked for by name.)
		if (level != &NewtonAlone)
		{
			ContactResult axis = OverlapAxisContact(a, pa, b, pb);
			if (axis.touching)
				return axis;
		}
		return FailedContact(r);
	}
	return ContactFromLevel(a, pa, b, pb, r, r.level <= 1.0);
}

ContactResult EllipseContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                             WarmStart* warm)
{
	// (One named result, so that it is built in the caller's: returning other objects beside
	// it would copy it out on every contact.)
	ContactResult c = EllipsePairContact(a, pa, b, pb, warm);
	if (Declined(c))
		c = ContactFromLevelChain(&EllipseLevelChain, a, pa, b, pb, options, warm);
	return c;
}

ContactResult SuperellipseContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                                  WarmStart* warm)
{
	ContactResult c = SuperellipsePairContact(a, pa, b, pb, options, warm);
	if (Declined(c))
		c = ContactFromLevelChain(&NewtonLevelChain, a, pa, b, pb, options, warm);
	return c;
}

ContactResult NewtonContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                            WarmStart* warm)
{
	return ContactFromLevelChain(&NewtonLevelChain, a, pa, b, pb, options, warm);
}

ContactResult ConvexContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                            WarmStart* warm)
{
	if (a.IsSmoothConvex() && b.IsSmoothConvex())
		return NewtonContact(a, pa, b, pb, options, warm);
	return GridContact(a, pa, b, pb, options, warm);
}

namespace
{
// The public functions' checks: registered 2D kinds, and a function where one is set.
void RequirePair(const char* who, ShapeKind a, ShapeKind b)
{
	Table().RequireKind(a, who, "a");
	Table().RequireKind(b, who, "b");
}
void RequireFunction(const char* who, bool given)
{
	if (!given)
		throw InvalidParameter(std::string(who) + ": field 'function' is null", "function");
}
} // namespace

void RegisterContactFunction(ShapeKind a, ShapeKind b, ContactFunction function)
{
	RequirePair("RegisterContactFunction", a, b);
	RequireFunction("RegisterContactFunction", function != nullptr);
	Table().SetContact(a, b, function);
}

void RegisterLevelFunction(ShapeKind a, ShapeKind b, LevelFunction function)
{
	RequirePair("RegisterLevelFunction", a, b);
	RequireFunction("RegisterLevelFunction", function != nullptr);
	Table().SetLevel(a, b, function);
}

ContactFunction GetContactFunction(ShapeKind a, ShapeKind b)
{
	RequirePair("GetContactFunction", a, b);
	bool flipped = false;
	return Table().Contact(a, b, flipped);
}

LevelFunction GetLevelFunction(ShapeKind a, ShapeKind b)
{
	RequirePair("GetLevelFunction", a, b);
	bool flipped = false;
	return Table().Level(a, b, flipped);
}

void RegisterPolygonContactFunction(ShapeKind kind, PolygonContactFunction function)
{
	Table().RequireKind(kind, "RegisterPolygonContactFunction", "kind");
	RequireFunction("RegisterPolygonContactFunction", function != nullptr);
	g_polygonColumn.Set(kind, function);
}

PolygonContactFunction GetPolygonContactFunction(ShapeKind kind)
{
	Table().RequireKind(kind, "GetPolygonContactFunction", "kind");
	return g_polygonColumn.At(kind);
}

ContactResult ComputePolygonContact(const Shape& a, const Pose& pa, const Vec2* vertices, int count, const Pose& pb,
                                    const Vec2* guessNormal)
{
	return g_polygonColumn.At(a.Kind())(a, pa, vertices, count, pb, guessNormal);
}

namespace
{
ContactResult Dispatch(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                       const SolverOptions& options, WarmStart* warm)
{
	if (method == MethodChoice::grid)
		return GridContact(a, pa, b, pb, options, warm);
	if (method == MethodChoice::newton)
		return ContactFromLevelChain(&NewtonAlone, a, pa, b, pb, options, warm);
	bool flipped = false;
	const ContactFunction f = Table().Contact(a.Kind(), b.Kind(), flipped);
	// A function registered for (B, A): solved that way round and flipped. A warm start is
	// stored in the first shape's frame, so it is not shared across the flip.
	if (flipped)
		return FlipContact(f(b, pb, a, pa, options, nullptr));
	return f(a, pa, b, pb, options, warm);
}

// Dispatch's answer checked where it lies, the caller's result (one named return).
ContactResult CheckedDispatch(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                              const SolverOptions& options, WarmStart* warm)
{
	ContactResult c = Dispatch(a, pa, b, pb, method, options, warm);
	CheckResult(c);
	return c;
}
} // namespace

ContactResult ComputeContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                             const SolverOptions& options, WarmStart* warm)
{
	if (!PoseFinite(pa) || !PoseFinite(pb))
		return NonFinitePoseFailure<ContactResult>();
	return CheckedDispatch(a, pa, b, pb, method, options, warm);
}

LevelResult SolveCommonLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                             const SolverOptions& options, WarmStart* warm)
{
	if (!PoseFinite(pa) || !PoseFinite(pb))
	{
		if (warm)
			warm->valid = false;
		return NonFinitePoseFailure<LevelResult>();
	}
	// The common level needs convex shapes: SolveCommonLevelGrid's refusal for both methods that
	// would take it, before anything is solved or recorded (`warm` stays as it was).
	if (method != MethodChoice::newton && !(a.IsConvex() && b.IsConvex()))
		return SolveCommonLevelGrid(a, pa, b, pb, options);
	if (method == MethodChoice::newton)
		return RunLevel(&NewtonAlone, false, a, pa, b, pb, options, warm);
	if (method == MethodChoice::grid)
		return RunLevel(&GridLevel, false, a, pa, b, pb, options, warm);
	bool flipped = false;
	const LevelFunction f = Table().Level(a.Kind(), b.Kind(), flipped);
	return RunLevel(f, flipped, a, pa, b, pb, options, warm);
}

} // namespace b2a

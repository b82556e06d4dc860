// b2analytic: the one table that decides which solver handles a pair of 3D shape kinds (an
// instantiation of the 2D table's PairTable), with its fallback chains, and the public entry
// points that go through it.
//
//                         sphere       ellipsoid    superellipsoid  convex_superellipsoid
//  sphere                 ClosedForm   Ellipsoid    Newton          Grid
//  ellipsoid                           Ellipsoid    Newton          Grid
//  superellipsoid                                   Newton          Grid
//  convex_superellipsoid                                            Grid
//  (symmetric; a 3D kind registered later: Newton between two of solver class smoothConvex,
//  Grid for any other pair, until a function is registered for the pair)
//
// Each cell is a level chain, written once here; its contact is "from" the chain:
//  ClosedForm  the spheres' closed form
//  Ellipsoid   Perram–Wertheim's one-dimensional form, polished → Newton
//  Newton      Newton from the warm start → Newton cold → min–max → Grid
//  Grid        the grid's fixed point → the same with sixteen times the samples
//  "from L": coincident centres → the axis of least overlap; else ContactFromLevel of chain L
//  (where L gives up on centres within 1e-3 of the size: the axis of least overlap).
//  Explicit methods, for any pair: MethodChoice::newton: Newton alone (warm, else cold);
//  MethodChoice::grid: Grid.
#include "3d/Solvers3.h"

#include "b2analytic/3d/ShapeKind3.h"
#include "contact/PairTable.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace b2a
{

namespace
{
LevelResult3 ClosedFormLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions&,
                             const WarmStart3*)
{
	return SphereLevel(a, pa, b, pb);
}

LevelResult3 GridLevelChain(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                            const WarmStart3*)
{
	const LevelResult3 r = SolveCommonLevelGrid(a, pa, b, pb, options);
	if (r.Ok())
		return r;
	// Samples too sparse for a narrow valley of A's level (deep overlaps of unlike exponents).
	SolverOptions dense = options;
	dense.gridSamples = 16 * std::max(options.gridSamples, 16);
	LevelResult3 again = SolveCommonLevelGrid(a, pa, b, pb, dense);
	again.iterations += r.iterations;
	if (again.Ok())
		again.status = SolveStatus::convergedAfterFallback;
	return again;
}

LevelResult3 NewtonLevelChain(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                              const WarmStart3* warm)
{
	int iterations = 0;
	if (warm && warm->valid)
	{
		const LevelResult3 r = SolveCommonLevelNewton(a, pa, b, pb, options, warm);
		if (r.Ok())
			return r;
		iterations += r.iterations;
	}
	LevelResult3 r = SolveCommonLevelNewton(a, pa, b, pb, options, nullptr);
	if (r.Ok())
	{
		r.iterations += iterations;
		return r;
	}
	iterations += r.iterations;
	r = SolveCommonLevelMinMax(a, pa, b, pb, options);
	if (!r.Ok())
	{
		iterations += r.iterations;
		r = GridLevelChain(a, pa, b, pb, options, nullptr);
	}
	r.iterations += iterations;
	if (r.Ok())
		r.status = SolveStatus::convergedAfterFallback;
	return r;
}

LevelResult3 EllipsoidLevelChain(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                                 const WarmStart3* warm)
{
	const LevelResult3 r = SolveEllipsoidPairLevel(a, pa, b, pb);
	if (r.Ok())
		return r;
	LevelResult3 chain = NewtonLevelChain(a, pa, b, pb, options, warm);
	if (chain.Ok())
		chain.status = SolveStatus::convergedAfterFallback;
	chain.iterations += r.iterations;
	return chain;
}

LevelResult3 NewtonAlone(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                         const WarmStart3* warm)
{
	return SolveCommonLevelNewton(a, pa, b, pb, options, warm);
}

// The contact from a level chain: the axis of least overlap where the centres coincide, else
// ContactFromLevel of the chain's answer (recorded as the next warm start). Where the chain
// gives up on centres within 1e-3 of the pair's size of each other (a common level near 0, the
// particles deep through each other: thin plates crossing), the axis of least overlap too.
template <LevelFunction3 Level>
ContactResult3 ContactOf(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                         WarmStart3* warm)
{
	if (CentresCoincide(a, pa, b, pb))
	{
		if (warm)
			warm->valid = false;
		return OverlapAxisContact3(a, pa, b, pb);
	}
	const LevelResult3 r = Level(a, pa, b, pb, options, warm);
	RecordWarmStart3(warm, pa, pb, r);
	if (!r.Ok() && Distance(pa.p, pb.p) <= 1e-3 * 0.5 * (a.BoundingRadius() + b.BoundingRadius()))
	{
		ContactResult3 c = OverlapAxisContact3(a, pa, b, pb);
		c.status = SolveStatus::convergedAfterFallback;
		c.iterations += r.iterations;
		return c;
	}
	return ContactFromLevel(a, pa, b, pb, r, r.Ok() && r.level <= 1.0);
}

using Table3 = PairTable<ContactFunction3, LevelFunction3>;

// The default cell of two solver classes.
constexpr Table3::Cell CellOfClasses(SolverClass a, SolverClass b)
{
	const bool newton = a == SolverClass::smoothConvex && b == SolverClass::smoothConvex;
	return newton ? Table3::Cell{&ContactOf<&NewtonLevelChain>, &NewtonLevelChain}
	              : Table3::Cell{&ContactOf<&GridLevelChain>, &GridLevelChain};
}

// The table above: the built-in 3D kinds' cells by class, then the specialised ones.
struct BuiltTable : Table3
{
	constexpr BuiltTable() : Table3(3, &CellOfClasses)
	{
		for (int i = 0; i < BuiltinKinds3::count; ++i)
			for (int j = 0; j < BuiltinKinds3::count; ++j)
				SetCell(BuiltinKinds3::all[i], BuiltinKinds3::all[j],
				        CellOfClasses(BuiltinKinds3::solverClasses[i], BuiltinKinds3::solverClasses[j]));
		const ShapeKind sphere = BuiltinKinds3::sphere, ellipsoid = BuiltinKinds3::ellipsoid;
		SetCell(sphere, sphere, {&ContactOf<&ClosedFormLevel>, &ClosedFormLevel});
		SetCell(ellipsoid, sphere, {&ContactOf<&EllipsoidLevelChain>, &EllipsoidLevelChain});
		SetCell(ellipsoid, ellipsoid, {&ContactOf<&EllipsoidLevelChain>, &EllipsoidLevelChain});
	}
};

B2A_CONSTINIT BuiltTable g_table;

void RequirePair(const char* who, ShapeKind a, ShapeKind b)
{
	g_table.RequireKind(a, who, "a");
	g_table.RequireKind(b, who, "b");
}

void RequireFunction(const char* who, bool given)
{
	if (!given)
		throw InvalidParameter(std::string(who) + ": field 'function' is null", "function");
}
} // namespace

void RegisterContactFunction(ShapeKind a, ShapeKind b, ContactFunction3 function)
{
	RequirePair("RegisterContactFunction", a, b);
	RequireFunction("RegisterContactFunction", function != nullptr);
	g_table.SetContact(a, b, function);
}

void RegisterLevelFunction(ShapeKind a, ShapeKind b, LevelFunction3 function)
{
	RequirePair("RegisterLevelFunction", a, b);
	RequireFunction("RegisterLevelFunction", function != nullptr);
	g_table.SetLevel(a, b, function);
}

ContactFunction3 GetContactFunction3(ShapeKind a, ShapeKind b)
{
	RequirePair("GetContactFunction3", a, b);
	bool flipped = false;
	return g_table.Contact(a, b, flipped);
}

LevelFunction3 GetLevelFunction3(ShapeKind a, ShapeKind b)
{
	RequirePair("GetLevelFunction3", a, b);
	bool flipped = false;
	return g_table.Level(a, b, flipped);
}

LevelResult3 SolveCommonLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, MethodChoice method,
                              const SolverOptions& options, WarmStart3* warm)
{
	LevelResult3 r;
	if (method == MethodChoice::newton)
		r = NewtonAlone(a, pa, b, pb, options, warm);
	else if (method == MethodChoice::grid)
		r = GridLevelChain(a, pa, b, pb, options, warm);
	else
	{
		bool flipped = false;
		const LevelFunction3 f = g_table.Level(a.Kind(), b.Kind(), flipped);
		if (flipped)
		{
			// Registered for (B, A): solved that way round, without the warm start (stored in
			// the first shape's frame), and turned back.
			r = f(b, pb, a, pa, options, nullptr);
			r.normal = -r.normal;
			r.multiplier = r.multiplier > 0.0 ? 1.0 / r.multiplier : 0.0;
		}
		else
			r = f(a, pa, b, pb, options, warm);
	}
	RecordWarmStart3(warm, pa, pb, r);
	return r;
}

ContactResult3 ComputeContact(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, MethodChoice method,
                              const SolverOptions& options, WarmStart3* warm)
{
	if (method == MethodChoice::newton)
		return ContactOf<&NewtonAlone>(a, pa, b, pb, options, warm);
	if (method == MethodChoice::grid)
		return ContactOf<&GridLevelChain>(a, pa, b, pb, options, warm);
	bool flipped = false;
	const ContactFunction3 f = g_table.Contact(a.Kind(), b.Kind(), flipped);
	if (flipped)
		return FlipContact(f(b, pb, a, pa, options, nullptr));
	return f(a, pa, b, pb, options, warm);
}

} // namespace b2a

// b2analytic: the 3D dispatch table (which solver finds the common level of a pair, by the
// shapes' kinds) with its fallback chains, and the public entry points that go through it.
//
//                        sphere       ellipsoid    superellipsoid  convex_superellipsoid
//  sphere                closedForm   ellipsoid    newton          grid
//  ellipsoid                          ellipsoid    newton          grid
//  superellipsoid                                  newton          grid
//  convex_superellipsoid                                           grid
//  (symmetric: a cell below the diagonal is its mirror, the pair taken as given)
//
// Chains, each written once here:
//  closedForm  the spheres' closed form
//  ellipsoid   Perram–Wertheim's one-dimensional form → newton
//  newton      Newton warm (where a warm start is valid) → Newton cold → min–max → grid
//  grid        the grid method's fixed point C = g(C) → the same with 16 times the samples
//  ComputeContact first: coincident centres → the axis of least overlap (no level point exists)
//  MethodChoice::newton is Newton alone (warm, else cold); MethodChoice::grid the grid chain.
#include "3d/Solvers3.h"

#include <algorithm>
#include <cmath>

namespace b2a
{

namespace
{
using LevelFunction3 = LevelResult3 (*)(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                                        const SolverOptions& options, const WarmStart3* warm);

LevelResult3 NewtonChain(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
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
		r = SolveCommonLevelGrid(a, pa, b, pb, options);
	}
	r.iterations += iterations;
	if (r.Ok())
		r.status = SolveStatus::convergedAfterFallback;
	return r;
}

LevelResult3 ClosedFormCell(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions&,
                            const WarmStart3*)
{
	return SphereLevel(a, pa, b, pb);
}

LevelResult3 EllipsoidCell(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                           const WarmStart3* warm)
{
	const LevelResult3 r = SolveEllipsoidPairLevel(a, pa, b, pb);
	if (r.Ok())
		return r;
	LevelResult3 chain = NewtonChain(a, pa, b, pb, options, warm);
	if (chain.Ok())
		chain.status = SolveStatus::convergedAfterFallback;
	chain.iterations += r.iterations;
	return chain;
}

LevelResult3 GridCell(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                      const WarmStart3*)
{
	const LevelResult3 r = SolveCommonLevelGrid(a, pa, b, pb, options);
	if (r.Ok())
		return r;
	// Samples too sparse for a narrow valley of A's level (deep overlaps of unlike exponents):
	// sixteen times as many.
	SolverOptions dense = options;
	dense.gridSamples = 16 * std::max(options.gridSamples, 16);
	LevelResult3 again = SolveCommonLevelGrid(a, pa, b, pb, dense);
	again.iterations += r.iterations;
	if (again.Ok())
		again.status = SolveStatus::convergedAfterFallback;
	return again;
}

// The table: kTable[kind A][kind B], kinds in kKind3Names' order.
constexpr LevelFunction3 kTable[kKind3Count][kKind3Count] = {
	{ClosedFormCell, EllipsoidCell, NewtonChain, GridCell},
	{EllipsoidCell, EllipsoidCell, NewtonChain, GridCell},
	{NewtonChain, NewtonChain, NewtonChain, GridCell},
	{GridCell, GridCell, GridCell, GridCell},
};

LevelFunction3 Chosen(const Shape3& a, const Shape3& b, MethodChoice method)
{
	switch (method)
	{
	case MethodChoice::newton:
		return [](const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
		          const WarmStart3* warm) { return SolveCommonLevelNewton(a, pa, b, pb, options, warm); };
	case MethodChoice::grid:
		return GridCell;
	case MethodChoice::automatic:
		break;
	}
	return kTable[a.Kind()][b.Kind()];
}
} // namespace

LevelResult3 SolveCommonLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, MethodChoice method,
                              const SolverOptions& options, WarmStart3* warm)
{
	const LevelResult3 r = Chosen(a, b, method)(a, pa, b, pb, options, warm);
	RecordWarmStart3(warm, pa, pb, r);
	return r;
}

ContactResult3 ComputeContact(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, MethodChoice method,
                              const SolverOptions& options, WarmStart3* warm)
{
	if (CentresCoincide(a, pa, b, pb))
	{
		if (warm)
			warm->valid = false;
		return OverlapAxisContact3(a, pa, b, pb);
	}
	const LevelResult3 level = SolveCommonLevel(a, pa, b, pb, method, options, warm);
	return ContactFromLevel(a, pa, b, pb, level, level.Ok() && level.level <= 1.0);
}

} // namespace b2a

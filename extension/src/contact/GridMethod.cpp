// b2analytic: the grid method (paper section 3) with local refinement, and its common level.
#include "b2analytic/CommonLevel.h"

#include "contact/PairFrame.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
// A on B's level-LB surface, parametrised by B's polar angle θ, seen in A's body frame.
struct SurfaceWalk
{
	const Shape& a;
	const Shape& b;
	Pose bInA; // B body → A body
	double levelB;
	mutable int evaluations = 0;

	// λA at B's surface point X_B(θ).
	double Value(double theta) const
	{
		++evaluations;
		return a.Level(ToWorld(bInA, b.SurfacePoint(theta, levelB)));
	}
	// d/dθ λA(X_B(θ)). X_B = r u, X_B' = r' u + r u⊥ with r' = −r (∇λB·u⊥)/(∇λB·u) from
	// differentiating λB(r u) = LB. NaN where ∇λB·u ≤ 0 (only at a corner's conventional gradient).
	double Slope(double theta) const
	{
		++evaluations;
		const Vec2 u(std::cos(theta), std::sin(theta)), up(-u.y, u.x);
		const double r = b.RadiusAt(u, levelB);
		const Vec2 X = r * u;
		const Vec2 gB = b.Gradient(X);
		const double along = Dot(gB, u);
		if (!(along > 0.0) || !std::isfinite(along))
			return std::numeric_limits<double>::quiet_NaN();
		const double rp = -r * Dot(gB, up) / along;
		const Vec2 dX = rp * u + r * up;
		const Vec2 gA = a.Gradient(ToWorld(bInA, X));
		return Dot(gA, Rotate(bInA.q, dX));
	}
};

// Refine the sample minimum between its neighbours (angles lo < mid < hi).
void Refine(const SurfaceWalk& walk, double lo, double hi, double& theta, double& value)
{
	const double slo = walk.Slope(lo), shi = walk.Slope(hi);
	double t = theta;
	bool found = false;
	if (std::isfinite(slo) && std::isfinite(shi) && slo < 0.0 && shi > 0.0)
	{
		auto slope = [&](double x) {
			const double s = walk.Slope(x);
			return std::isfinite(s) ? s : 0.0; // a corner: stop there, its value is checked below
		};
		const ScalarResult r = FindRootBrent(slope, lo, hi, slo, shi, 0.0, 200);
		t = r.x;
		found = true;
	}
	if (!found)
	{
		auto f = [&](double x) { return walk.Value(x); };
		t = MinimizeBrent(f, lo, hi, 1e-15, 1e-15, 200).x;
	}
	const double v = walk.Value(t);
	if (v < value)
	{
		value = v;
		theta = t;
	}
}
} // namespace

LevelResult SolveGridScale(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                           double levelB)
{
	LevelResult result;
	result.method = SolveMethod::grid;
	const double LB = std::isnan(levelB) ? b.SurfaceLevel() : levelB;
	const auto samples = b.Samples(std::max(8, options.gridSamples));
	const int n = samples->Count();
	SurfaceWalk walk{a, b, Relative(pa, pb), LB};

	// Level of A at every sample of B's surface (the paper's grid).
	std::vector<double> value(n);
	const bool ownLevel = LB == b.SurfaceLevel();
	for (int k = 0; k < n; ++k)
	{
		const Vec2 p = ownLevel ? samples->point[k] : b.SurfacePoint(samples->angle[k], LB);
		value[k] = a.Level(ToWorld(walk.bInA, p));
		if (std::isnan(value[k]))
		{
			result.failure = "grid: a level value is NaN (check the shape functions)";
			return result;
		}
	}
	// Local minima of the cyclic sequence, lowest first.
	std::vector<int> minima;
	for (int k = 0; k < n; ++k)
	{
		const double prev = value[(k + n - 1) % n], next = value[(k + 1) % n];
		if (value[k] <= prev && value[k] < next)
			minima.push_back(k);
	}
	if (minima.empty())
		minima.push_back(int(std::min_element(value.begin(), value.end()) - value.begin()));
	std::sort(minima.begin(), minima.end(), [&](int i, int j) { return value[i] < value[j]; });
	if (int(minima.size()) > options.gridCandidates)
		minima.resize(std::max(1, options.gridCandidates));

	double bestTheta = samples->angle[minima[0]], bestValue = value[minima[0]];
	for (int k : minima)
	{
		double lo, hi;
		samples->NeighbourAngles(k, lo, hi);
		double theta = samples->angle[k], v = value[k];
		if (options.gridRefine)
			Refine(walk, lo, hi, theta, v);
		if (v < bestValue)
		{
			bestValue = v;
			bestTheta = theta;
		}
	}
	if (!std::isfinite(bestValue))
	{
		result.failure = "grid: no finite level of A on B's surface";
		return result;
	}
	const Vec2 X = ToWorld(pb, b.SurfacePoint(bestTheta, LB));
	Vec2 normal = Rotate(pa.q, a.Gradient(ToBody(pa, X)));
	if (!(LengthSquared(normal) > 0.0) || !IsFinite(normal))
		normal = -Rotate(pb.q, b.Gradient(ToBody(pb, X))); // A's centre on B's surface: use B's normal
	result.status = SolveStatus::converged;
	result.level = bestValue;
	result.point = X;
	result.normal = Normalize(normal);
	result.iterations = walk.evaluations;
	return result;
}

LevelResult SolveCommonLevelGrid(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options)
{
	if (CentresCoincide(a, pa, b, pb))
	{
		LevelResult r;
		r.method = SolveMethod::grid;
		r.failure = "coincident centres: no common-level point between them";
		return r;
	}
	// g(C) = smallest level of A on B's level-C surface decreases with C, so h(C) = g(C) − C has
	// one root, bracketed by 1 and g(1): if g(1) > 1 then h(1) > 0 ≥ h(g(1)), and vice versa.
	// Levels are in units of each shape's own level (1 for the superellipse family).
	const double unitA = a.SurfaceLevel() > 0.0 ? a.SurfaceLevel() : 1.0;
	const double unitB = b.SurfaceLevel() > 0.0 ? b.SurfaceLevel() : 1.0;
	int iterations = 0;
	LevelResult last;
	// G(C) is the smallest level of A over the solid B_C: when A's centre lies inside B_C that is
	// A's level at its centre, and only otherwise the minimum over B_C's surface. So defined, G
	// never increases with C (the surface minimum alone would, once B_C swallows A's centre).
	const double centreLevelA = a.Level(Vec2()) / unitA;
	auto h = [&](double C) {
		if (b.Level(ToBody(pb, pa.p)) <= C * unitB)
		{
			last.status = SolveStatus::converged;
			last.level = centreLevelA * unitA;
			return centreLevelA - C;
		}
		last = SolveGridScale(a, pa, b, pb, options, C * unitB);
		iterations += last.iterations;
		return last.Ok() ? last.level / unitA - C : std::numeric_limits<double>::quiet_NaN();
	};
	const double h1 = h(1.0);
	if (!last.Ok())
		return last;
	double lo = 1.0, hi = 1.0 + h1, hlo = h1;
	if (h1 < 0.0)
		std::swap(lo, hi);
	double hhi = hi == 1.0 ? h1 : h(hi);
	if (lo != 1.0)
		hlo = h(lo);
	LevelResult result;
	result.method = SolveMethod::grid;
	if (!(hlo >= 0.0 && hhi <= 0.0))
	{
		result.failure = "grid common level: the fixed point could not be bracketed";
		result.iterations = iterations;
		return result;
	}
	const ScalarResult root = FindRootBrent(h, lo, hi, hlo, hhi, 0.0, 200);
	h(root.x); // leave `last` at the answer
	if (!last.Ok())
		return last;
	result = last;
	result.level = root.x;
	result.iterations = iterations;
	return result;
}

} // namespace b2a

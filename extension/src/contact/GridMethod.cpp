// b2analytic: the grid method (paper section 3) with local refinement, and its common level.
#include "b2analytic/CommonLevel.h"

#include "contact/GridScale.h"
#include "contact/LevelAlongLine.h"
#include "contact/PairFrame.h"
#include "contact/SampleRuns.h"
#include "numerics/CodeLayout.h"
#include "numerics/RootFinding.h"
#include "numerics/SmallLinear.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
// The paths a grid solve seldom takes are out of line and apart from the hot code (B2A_COLD):
// inlined, they would spread the solve's code over more instruction-cache lines, and a heart
// contact runs through more code than the cache holds, so every solve fetches its lines again.

// A on B's level-LB surface, parametrised by B's polar angle θ, seen in A's body frame.
struct SurfaceWalk
{
	const Shape& a;
	const Shape& b;
	Pose bInA; // B body → A body
	double levelB;
	const LevelBounds* boundsA; // a.Bounds(), b.Bounds() (or null)
	const LevelBounds* boundsB;
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
		const Vec2 u = PolarDirection(theta), up(-u.y, u.x);
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

// Whether the direction of x lies on the counter-clockwise arc of directions from `from` to `to`
// (ends included), by cross products: the polar angles' comparison without atan2 and its
// unwrapping. Arcs of π or more are those whose complement, under π, does not hold x strictly.
inline bool WithinArc(Vec2 from, Vec2 to, Vec2 x)
{
	if (Cross(from, to) > 0.0)
		return Cross(from, x) >= 0.0 && Cross(x, to) >= 0.0;
	return !(Cross(to, x) > 0.0 && Cross(x, from) > 0.0);
}

// Sorts the few entries a solve orders (the runs to scan, the minima, the scanned runs) by
// insertion: where `less` is a strict total order (each use's is: no two entries tie), the order
// std::sort gives, in a fraction of the code its introsort inlines.
template <typename T, typename Less>
void SortFew(T* first, T* last, Less less)
{
	for (T* i = first + (first < last ? 1 : 0); i < last; ++i)
	{
		const T x = *i;
		T* j = i;
		for (; j > first && less(x, *(j - 1)); --j)
			*j = *(j - 1);
		*j = x;
	}
}

// Newton on the stationarity conditions of min λA over B's level-LB curve, in A's body frame:
//   ∇λA(y) + μ∇λB(y) = 0,  λB(y) − LB = 0,
// Jacobian [[HA + μHB, ∇λB], [∇λBᵀ, 0]]. Its tangential block tᵀ(HA + μHB)t, t ⟂ ∇λB, is the
// second derivative of λA along the curve (the μHB term carries the curve's bending), so it must
// stay positive for a minimum. Starts at sample `start` (on the curve) and converges
// quadratically; each step costs two derivative evaluations where the Brent search on the slope
// costs a radius solve per evaluation. Returns false (the caller then brackets) when the
// tangential curvature is not positive, a step leaves the neighbours' chord, the iteration cap
// is reached, or the answer lies outside the arc from B's point `from` to `to` (counter-clockwise,
// B's body frame) or above the sample's value: at corners and where two minima share a bracket.
bool RefineNewton(const SurfaceWalk& walk, Vec2 from, Vec2 to, Vec2 start, double startValue, double reach, double& value,
                  Vec2& point)
{
	const Rot q = walk.bInA.q;
	Vec2 y = ToWorld(walk.bInA, start);
	const double tolerance = 1e-13 * (Length(start) + reach);
	double mu = 0.0, last = 0.0; // (last: the previous step's length)
	bool first = true;
	for (int it = 0; it < 12; ++it)
	{
		++walk.evaluations;
		const LevelDerivatives dA = walk.a.Derivatives(y);
		const LevelDerivatives dB = walk.b.Derivatives(ToBody(walk.bInA, y));
		const Vec2 gB = Rotate(q, dB.gradient);
		const Sym22 HB = Rotate(q, dB.hessian);
		const double gB2 = LengthSquared(gB);
		if (!(gB2 > 0.0) || !std::isfinite(gB2) || !IsFinite(dA.gradient))
			return false;
		if (first)
			mu = -Dot(dA.gradient, gB) / gB2; // least squares of ∇λA + μ∇λB = 0
		first = false;
		const Sym22 H{dA.hessian.xx + mu * HB.xx, dA.hessian.xy + mu * HB.xy, dA.hessian.yy + mu * HB.yy};
		const Vec2 t = Perp(gB);
		const double curvature = t.x * (H.xx * t.x + H.xy * t.y) + t.y * (H.xy * t.x + H.yy * t.y);
		if (!(curvature > 0.0) || !std::isfinite(curvature))
			return false;
		// J = [[H, ∇λB], [∇λBᵀ, 0]]: bordered (SolveBordered: Solve3's answer in half the operations).
		// Its condition gets the full test (rcond > 1e-14) at the start only; the later Jacobians
		// lie within steps shorter than the neighbours' chord, each checked for curvature above.
		const double r[3] = {-(dA.gradient.x + mu * gB.x), -(dA.gradient.y + mu * gB.y), -(dB.value - walk.levelB)};
		double delta[3];
		// (SolveBordered's and SolveBorderedSolution's arithmetic, the adjugate written once.)
		const BorderedAdjugate adj = AdjugateOfBordered(H.xx, H.xy, H.yy, gB.x, gB.y, gB.x, gB.y);
		if (!AdjugateInvertible(adj))
			return false;
		if (it == 0 && !(BorderedRcond(adj, H.xx, H.xy, H.yy, gB.x, gB.y, gB.x, gB.y) > 1e-14))
			return false;
		ApplyAdjugate(adj, r, delta);
		const Vec2 step(delta[0], delta[1]);
		const double stepLength = Length(step);
		if (!(stepLength <= reach))
			return false;
		y += step;
		mu += delta[2];
		// Done one step sooner where Newton's quadratic regime puts the next step below the
		// tolerance (as the raw-level finish does): the step contracting by 4 or more from the
		// last, the error left, K·|δ|² with K = |δ|/|δ_last|², a thousand times below the
		// tolerance, and both levels smooth within a thousand last steps of the point. Near a
		// heart's axis (its tip, its notch) or a superellipse's, where an exponent is not an
		// even integer, the level is not smooth at the steps' scale and the prediction fails
		// (normals and points drift far above their rounding floor): there, and where either
		// shape claims no smoothness, the last step is taken. The margin of a thousand, not
		// ten, keeps the prediction's misses below rounding.
		const bool settled = last > 0.0 && stepLength < 0.25 * last &&
		                     1e3 * (stepLength / (last * last)) * (stepLength * stepLength) <= tolerance &&
		                     walk.boundsA && walk.boundsA->LevelSmoothOver(y, 1e3 * last) && walk.boundsB &&
		                     walk.boundsB->LevelSmoothOver(ToBody(walk.bInA, y), 1e3 * last);
		last = stepLength;
		if (stepLength <= tolerance || settled)
		{
			const Vec2 x = ToBody(walk.bInA, y);
			++walk.evaluations;
			const double v = walk.a.Level(y);
			if (!WithinArc(from, to, x) || !(v <= startValue))
				return false;
			value = v;
			point = x;
			return true;
		}
	}
	return false;
}

// True when the polar angle is one of the shape's corners (samples sit on corners exactly).
bool IsCorner(const Shape& s, double theta) { return s.NearCorner(theta, 1e-12); }

// The segment pl–ph straddles the ray from the origin along u (the line through it, on the
// ray's side of the origin).
bool SegmentMeetsRay(Vec2 u, Vec2 pl, Vec2 ph)
{
	return Cross(u, pl) * Cross(u, ph) <= 0.0 && (Dot(u, pl) > 0.0 || Dot(u, ph) > 0.0);
}

// The segment pl–ph straddles one of the shape's corner rays.
bool MeetsCornerRay(const Shape& s, Vec2 pl, Vec2 ph)
{
	for (const Vec2 u : s.CornerDirections())
		if (SegmentMeetsRay(u, pl, ph))
			return true;
	return false;
}

// A bracket of the crossing of B's curve with the ray along u nearest the chord pl–ph's, where
// the chord's bracket (its projections ± its length) holds none: B thinner than the chord (a
// plank 0.26 thick under a chord 0.65 long) has the ray enter and leave it inside, both ends
// outside. From the chord's crossing sc, steps of a quarter of the chord, shrinking by four,
// to the side where g changes sign.
template <typename G>
bool BracketNearChord(const G& g, Vec2 u, Vec2 pl, Vec2 ph, double margin, double& s0, double& s1, double& g0, double& g1)
{
	const double cl = Cross(u, pl), ch = Cross(u, ph);
	if (!(cl != ch))
		return false;
	const double sc = Dot(u, pl + (cl / (cl - ch)) * (ph - pl));
	const double gc = g(sc);
	if (gc == 0.0)
	{
		s0 = s1 = sc;
		g0 = g1 = 0.0;
		return true;
	}
	for (double d = 0.25 * margin; d > 1e-6 * margin; d *= 0.25)
	{
		const double below = std::max(0.0, sc - d), gb = g(below);
		if (gb * gc <= 0.0)
		{
			s0 = below, g0 = gb, s1 = sc, g1 = gc;
			return true;
		}
		const double ga = g(sc + d);
		if (ga * gc <= 0.0)
		{
			s0 = sc, g0 = gc, s1 = sc + d, g1 = ga;
			return true;
		}
	}
	return false;
}

// Where B's level-LB curve crosses the ray of one of A's corners (A's body frame) between the
// neighbours pl and ph of a sample. Along that ray λA is not differentiable: at the heart's tip
// it runs in a V-shaped valley, λA ≈ smooth + c|s|^{2/3} across it, so the crossing is a local
// minimum of λA along B's curve that Newton, which needs curvature, cannot converge to. The
// crossing is the root of λB − LB along the ray, bracketed by the neighbours' projections.
bool CornerRayCrossing(const SurfaceWalk& walk, Vec2 pl, Vec2 ph, double& value, Vec2& point)
{
	bool found = false;
	for (const Vec2 u : walk.a.CornerDirections())
	{
		if (!SegmentMeetsRay(u, pl, ph))
			continue;
		const double margin = Distance(pl, ph);
		double s0 = std::max(0.0, std::min(Dot(u, pl), Dot(u, ph)) - margin);
		double s1 = std::max(Dot(u, pl), Dot(u, ph)) + margin;
		auto g = [&](double s) {
			++walk.evaluations;
			return walk.b.Level(ToBody(walk.bInA, s * u)) - walk.levelB;
		};
		double g0 = g(s0), g1 = g(s1);
		if (!(g0 * g1 <= 0.0) && !BracketNearChord(g, u, pl, ph, margin, s0, s1, g0, g1))
			continue;
		const ScalarResult r = LevelRootAlongLine(walk.b, walk.bInA, Vec2(), u, walk.levelB, s0, s1, g0, g1);
		walk.evaluations += r.iterations;
		const Vec2 y = r.x * u;
		++walk.evaluations;
		const double v = walk.a.Level(y);
		if (v < value)
		{
			value = v;
			point = ToBody(walk.bInA, y);
			found = true;
		}
	}
	return found;
}

// Refine the sample minimum between its neighbours (angles lo < mid < hi) by bracketing: a root
// of the slope where it changes sign, else a Brent minimisation of the value.
B2A_COLD void Refine(const SurfaceWalk& walk, double lo, double hi, double& theta, double& value)
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

// Beside a kink at `point` (B's corner, or the valley where a corner ray of A crosses B), a
// smooth minimum may lie lower within the bracket [pl, ph]: Newton from each neighbour, held to
// its side of the kink, and the lower answer kept.
B2A_NOINLINE void NewtonBesideKink(const SurfaceWalk& walk, Vec2 pl, Vec2 ph, double reach, double& value, Vec2& point)
{
	const Vec2 kink = point;
	double v;
	Vec2 x;
	if (RefineNewton(walk, pl, kink, pl, value, reach, v, x) && v < value)
		value = v, point = x;
	if (RefineNewton(walk, kink, ph, ph, value, reach, v, x) && v < value)
		value = v, point = x;
}

// RefineCandidate's last resorts, where Newton failed from both starts (seldom): A's corner rays
// crossing the bracket, else the bracketing search.
template <typename SamplePoint, typename MarkSolved>
B2A_COLD void RefineWithoutNewton(const SurfaceWalk& walk, const SurfaceSamples& samples, int k, const SamplePoint& samplePoint,
                                  const MarkSolved& markSolved, Vec2 pl, Vec2 ph, double reach, double& value, Vec2& point)
{
	const int n = samples.Count();
	// A's corner rays: the crossing in each of the two sample segments beside the sample that
	// meets one. The corner-ray pass of SolveGridScale solves the same segments (of the scanned
	// runs) the same way; the ones solved here are marked, and it skips them (it would solve
	// them again, to the same crossing).
	const Pose& bInA = walk.bInA;
	bool crossed = false;
	for (const int i : {(k + n - 1) % n, k})
	{
		const Vec2 p = ToWorld(bInA, samplePoint(i)), q = ToWorld(bInA, samplePoint((i + 1) % n));
		if (!MeetsCornerRay(walk.a, p, q))
			continue;
		markSolved(i);
		crossed = CornerRayCrossing(walk, p, q, value, point) || crossed;
	}
	if (crossed)
	{
		// Beside the valley a smooth minimum may lie lower in the same bracket (where Newton from
		// the vertex and the sample, drawn into the valley, failed): Newton from each neighbour,
		// held to its side of the crossing, as beside B's corners. Where the valley is the
		// minimum, A's level is concave on both sides of it (|s|^{2/3}) and each stops at its
		// first curvature test.
		NewtonBesideKink(walk, pl, ph, reach, value, point);
		return;
	}
	const double sampleTheta = samples.angle[k];
	double lo, hi;
	samples.NeighbourAngles(k, lo, hi);
	double theta = sampleTheta;
	Refine(walk, lo, hi, theta, value);
	if (theta != sampleTheta)
		point = walk.b.SurfacePoint(theta, walk.levelB);
}

// Refine sample k, a local minimum of the samples, to the minimum of λA along B's curve between
// its neighbours: Newton from the sample on smooth stretches; at B's corners the corner or a
// smooth minimum beside it; where A's corner ray crosses the bracket, the crossing (Newton has
// no curvature there); anything else, the bracketing search.
template <typename SamplePoint, typename MarkSolved>
void RefineCandidate(const SurfaceWalk& walk, const SurfaceSamples& samples, int k, const SamplePoint& samplePoint,
                     const MarkSolved& markSolved, double valueBefore, double valueAfter, double& value, Vec2& point)
{
	const int n = samples.Count();
	const Vec2 pl = samplePoint((k + n - 1) % n), ph = samplePoint((k + 1) % n);
	const double reach = Distance(pl, ph);
	const double sampleValue = value;
	if (IsCorner(walk.b, samples.angle[k]))
	{
		// B's corner: its curve has no tangent there, so Newton cannot start on it. The corner
		// is the minimum unless a smooth minimum lies beside it, lower, within the bracket (an
		// edge of a diamond touched next to its vertex); Newton from each neighbour looks there.
		NewtonBesideKink(walk, pl, ph, reach, value, point);
		return;
	}
	// Newton starts at the vertex of the parabola through the three samples' values, on the
	// quadratic through their points (a point off B's curve by the cube of the spacing, which
	// the constraint's row corrects): its first step is then about a hundredth of the sample's,
	// and one step of four is saved. The vertex lies within half a spacing of the sample (the
	// sample is the lowest of the three). Only where the samples are dense against A's level:
	// the bracket under half the sample's distance from A's centre, the length over which a
	// level of the superellipse family or the heart's varies by its own order. Sparser (a
	// particle a thousandth the size of the one whose samples it is rescaled onto, or a deep
	// overlap near a heart's cusp) the bracket may hold two minima, the parabola says little,
	// and Newton starts at the sample. And where Newton from the vertex moves farther than
	// 0.075 of the bracket (a vertex that was no good guess), Newton from the sample runs too
	// and the lower answer is kept.
	Vec2 start = point;
	const double curvature = valueBefore - 2.0 * sampleValue + valueAfter;
	const bool dense = reach <= 0.5 * Length(ToWorld(walk.bInA, point));
	if (dense && curvature > 0.0 && std::isfinite(curvature))
	{
		const double tau = std::clamp(0.5 * (valueBefore - valueAfter) / curvature, -0.5, 0.5); // (in it but for rounding)
		const Vec2 half = 0.5 * (ph - pl), bend = 0.5 * (ph + pl) - point;
		start = point + tau * half + (tau * tau) * bend;
	}
	double vertexValue = 0.0;
	Vec2 vertexPoint;
	const bool fromVertex = RefineNewton(walk, pl, ph, start, sampleValue, reach, vertexValue, vertexPoint);
	if (fromVertex && Distance(vertexPoint, start) <= 0.075 * reach)
	{
		value = vertexValue;
		point = vertexPoint;
		return;
	}
	double sampleStartValue = 0.0;
	Vec2 sampleStartPoint;
	const bool fromSample = (start.x != point.x || start.y != point.y) &&
	                        RefineNewton(walk, pl, ph, point, sampleValue, reach, sampleStartValue, sampleStartPoint);
	if (fromVertex || fromSample)
	{
		const bool vertexBetter = fromVertex && (!fromSample || vertexValue <= sampleStartValue);
		value = vertexBetter ? vertexValue : sampleStartValue;
		point = vertexBetter ? vertexPoint : sampleStartPoint;
		return;
	}
	RefineWithoutNewton(walk, samples, k, samplePoint, markSolved, pl, ph, reach, value, point);
}

// SolveGridScale's work arrays, one set per thread.
struct GridScratch
{
	std::vector<double> value, bound, groupBound;
	std::vector<Vec2> inA, discs; // discs: centres of the discs being bounded, in A's frame
	std::vector<std::uint32_t> stamp; // value[k] is this call's where stamp[k] == generation
	std::vector<std::uint32_t> raySolved; // segment k → k + 1's corner-ray crossing solved where == generation
	std::vector<std::uint32_t> runStamp;  // bound[r] is this call's where runStamp[r] == generation
	std::vector<double> boxBound;         // run r's box bound (Scan's last look), this call's where
	std::vector<std::uint32_t> boxStamp;  // boxStamp[r] == generation
	std::uint32_t generation = 0;
	std::vector<char> scanned; // per run: evaluated whole
	std::vector<int> scannedRuns; // those runs, in increasing order (bounded scans)
	std::vector<std::pair<double, int>> order;
	std::vector<int> minima;
	// The last solve's key, where it succeeded on B's own surface (LastGridLevels): A's and B's
	// serials, B's samples and the relative pose; `published` false until then.
	bool published = false;
	bool groupsBounded = false; // groupBound holds every group's bound (the solve was grouped)
	std::uint64_t serialA = 0, serialB = 0;
	const SurfaceSamples* samples = nullptr;
	Pose bInA;
	// Every array sized for n samples in `runs` runs and `groups` groups, the stamps cleared
	// (the first call, or another sample count).
	B2A_COLD void Size(int n, int runs, int groups)
	{
		stamp.assign(n, 0);
		raySolved.assign(n, 0);
		runStamp.assign(runs, 0);
		boxStamp.assign(runs, 0);
		generation = 0;
		value.resize(n);
		inA.resize(n);
		bound.resize(runs);
		boxBound.resize(runs);
		groupBound.resize(groups);
		discs.resize(std::max(groups, runs));
		scanned.resize(runs);
		scannedRuns.resize(runs);
		order.resize(runs);
		minima.resize(n);
	}
	// The stamps cleared, where the generation wrapped round.
	B2A_COLD void ClearStamps()
	{
		std::fill(stamp.begin(), stamp.end(), 0u);
		std::fill(raySolved.begin(), raySolved.end(), 0u);
		std::fill(runStamp.begin(), runStamp.end(), 0u);
		std::fill(boxStamp.begin(), boxStamp.end(), 0u);
		generation = 1;
	}
	static GridScratch& ForThread()
	{
		thread_local GridScratch scratch;
		return scratch;
	}
};

// One grid solve (SolveGridScale): A's level over the samples of B's level-LB curve, found by
// branch and bound over runs of samples where A has bounds (or by evaluating every sample),
// then its lowest local minima refined between their neighbours. The steps, in Solve's order:
// Bound (the groups' and runs' bounds), Scan (branch and bound) or ScanAll, CollectMinima,
// RefineMinima, CornerRayPass.
class GridScan
{
public:
	GridScan(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, double levelB);
	LevelResult Solve(Vec2* bodyGradientA);

private:
	bool Evaluated(int k) const { return stamp[k] == generation; }
	// A's level at sample k (in A's frame: inA[k]); false where it is NaN.
	bool Evaluate(int k)
	{
		const Vec2 p = ownLevel ? samples->point[k] : b.SurfacePoint(samples->angle[k], LB);
		inA[k] = ToWorld(walk.bInA, p);
		value[k] = a.Level(inA[k]);
		stamp[k] = generation;
		return !std::isnan(value[k]);
	}
	// Samples are scanned a run at a time: run g is samples g·kRunLength … (g+1)·kRunLength, its
	// last sample being the next run's first (sample 0 for the last run).
	void RunSamples(int g, int& first, int& last) const
	{
		first = g * SampleRuns::kRunLength;
		last = std::min(first + SampleRuns::kRunLength, n);
	}
	// Group G's runs.
	void GroupRuns(int G, int& first, int& last) const
	{
		first = G * SampleRuns::kGroupRuns;
		last = std::min(first + SampleRuns::kGroupRuns, runs);
	}
	// A's lower bounds over discs first … last − 1 of the hierarchy's, into out, together
	// (LevelBounds::LevelLowerBounds: the heart does two at a time).
	void BoundDiscs(const std::vector<Vec2>& centres, const std::vector<double>& radii, int first, int last, double* out)
	{
		for (int i = first; i < last; ++i)
			discs[i - first] = ToWorld(walk.bInA, centres[i]);
		boundsA->LevelLowerBounds(discs, radii.data() + first, last - first, out);
	}
	// Group G's runs' bounds, each at least the group's (a run's disc lies in its group's), so
	// that a run without a bound of its own keeps the group's.
	void BoundRuns(int G)
	{
		int first, last;
		GroupRuns(G, first, last);
		BoundDiscs(hierarchy.runCentre, hierarchy.runRadius, first, last, bound + first);
		for (int g = first; g < last; ++g)
		{
			bound[g] = bound[g] > groupBound[G] ? bound[g] : groupBound[G];
			runStamp[g] = generation;
		}
	}
	void Bound();
	void ScanRun(int g);
	// Run g, where its bound is at or below the lowest level found and it is not `best` (scanned
	// already), added to the order of runs to scan (written always, counted where it belongs).
	void AddToOrder(int g, int best, int& orderCount)
	{
		order[orderCount] = {bound[g], g};
		orderCount += int(g != best) & int(bound[g] <= lowest);
	}
	void Scan();
	B2A_COLD void ScanAll();
	// Sample k a minimum of its neighbours' values: added to the minima. (Written always, counted
	// where it is one: which samples are minima is data, a branch on it often mispredicted.)
	void Consider(int k, int before, int after)
	{
		minima[minimaCount] = k;
		minimaCount += int(value[k] <= value[before]) & int(value[k] < value[after]);
	}
	void ConsiderRunEdge(int i);
	void CollectMinima();
	Vec2 SamplePoint(int k) const { return ownLevel ? samples->point[k] : b.SurfacePoint(samples->angle[k], LB); }
	// The disc holding B's curve between two consecutive samples p and q (A's frame), by the run
	// discs' rule: half the chord and twice the curve's measured deviation from it.
	double SegmentRadius(Vec2 p, Vec2 q) const { return 0.5 * Distance(p, q) + 2.0 * samples->maxDeviation; }
	void RefineMinima(double& bestValue, Vec2& bestPoint);
	void CornerRayPass(double& bestValue, Vec2& bestPoint);

	const Shape& a;
	const Shape& b;
	const Pose& pa;
	const Pose& pb;
	const SolverOptions& options;
	const double LB;
	const SampleRuns& hierarchy;
	const SurfaceSamples* const samples;
	const int n;
	const LevelBounds* const boundsA;
	SurfaceWalk walk;
	const bool ownLevel;
	const int runs, groups;
	// The thread's work arrays (GridScratch), sized in the constructor and used through plain
	// pointers: through the vectors, every access reloaded the array's address (a virtual call or
	// a store through a double* may have moved it, as far as the compiler knows).
	std::uint32_t generation = 0;
	double* value = nullptr;
	std::uint32_t* stamp = nullptr;
	std::uint32_t* raySolved = nullptr;
	std::uint32_t* runStamp = nullptr;
	double* boxBound = nullptr;
	std::uint32_t* boxStamp = nullptr;
	Vec2* inA = nullptr; // each evaluated sample in A's body frame
	char* scanned = nullptr; // per run: evaluated whole
	int* scannedRuns = nullptr; // those runs (in increasing order once sorted)
	int scannedCount = 0;
	double* bound = nullptr;
	double* groupBound = nullptr;
	Vec2* discs = nullptr;
	std::pair<double, int>* order = nullptr;
	int* minima = nullptr;
	int minimaCount = 0;
	bool ok = true;       // no NaN level so far
	bool bounded = false; // branch and bound over runs (else every sample is evaluated)
	bool grouped = false; // groups of runs bounded first
	double lowest = std::numeric_limits<double>::infinity(); // the lowest level scanned
};

GridScan::GridScan(const Shape& a_, const Pose& pa_, const Shape& b_, const Pose& pb_, const SolverOptions& options_, double levelB)
	: a(a_), b(b_), pa(pa_), pb(pb_), options(options_), LB(std::isnan(levelB) ? b_.SurfaceLevel() : levelB),
	  hierarchy(SampleRunsOf(b_, std::max(8, options_.gridSamples))), samples(hierarchy.samples), n(samples->Count()),
	  boundsA(a_.Bounds()), walk{a_, b_, Relative(pa_, pb_), LB, boundsA, b_.Bounds()}, ownLevel(LB == b_.SurfaceLevel()),
	  runs((n + SampleRuns::kRunLength - 1) / SampleRuns::kRunLength),
	  groups((runs + SampleRuns::kGroupRuns - 1) / SampleRuns::kGroupRuns)
{
	// Level of A at every sample of B's surface (the paper's grid), evaluated where needed. The
	// work arrays are the thread's own, kept between calls (no allocation a call), and a
	// sample's value belongs to this call where its stamp is this call's generation (no
	// clearing a call).
	GridScratch& scratch = GridScratch::ForThread();
	scratch.published = false;
	if (int(scratch.stamp.size()) != n || int(scratch.runStamp.size()) != runs || int(scratch.groupBound.size()) != groups)
		scratch.Size(n, runs, groups);
	if (++scratch.generation == 0)
		scratch.ClearStamps();
	generation = scratch.generation;
	std::fill(scratch.scanned.begin(), scratch.scanned.end(), char(0));
	value = scratch.value.data();
	stamp = scratch.stamp.data();
	raySolved = scratch.raySolved.data();
	runStamp = scratch.runStamp.data();
	boxBound = scratch.boxBound.data();
	boxStamp = scratch.boxStamp.data();
	inA = scratch.inA.data();
	scanned = scratch.scanned.data();
	scannedRuns = scratch.scannedRuns.data();
	bound = scratch.bound.data();
	groupBound = scratch.groupBound.data();
	discs = scratch.discs.data();
	order = scratch.order.data();
	minima = scratch.minima.data();
}

void GridScan::Bound()
{
	bounded = ownLevel && boundsA && int(hierarchy.runCentre.size()) == runs;
	// Groups of runs are bounded first (their discs enclose their runs'), and a run's own disc
	// only where its group's bound does not already rule it out: about half the bounds.
	grouped = bounded && int(hierarchy.groupCentre.size()) == groups;
	const double noBound = -std::numeric_limits<double>::infinity();
	if (grouped)
	{
		BoundDiscs(hierarchy.groupCentre, hierarchy.groupRadius, 0, groups, groupBound);
		for (int G = 0; G < groups && grouped; ++G)
			grouped = groupBound[G] > noBound; // else bound every run
	}
	if (bounded && !grouped)
	{
		BoundDiscs(hierarchy.runCentre, hierarchy.runRadius, 0, runs, bound);
		std::fill(runStamp, runStamp + runs, generation);
		for (int g = 0; g < runs && bounded; ++g)
			bounded = bound[g] > noBound; // else no bound: scan everything
	}
}

// Run g evaluated whole. Its samples are evaluated together (Shape::Levels: one virtual call a
// run, not one a sample), but for its end samples where a neighbouring run, scanned, shares
// them. A NaN stops the scan (reported by Solve).
void GridScan::ScanRun(int g)
{
	scanned[g] = 1;
	scannedRuns[scannedCount++] = g;
	int first, last;
	RunSamples(g, first, last);
	int end = std::min(last, n - 1); // (sample n is sample 0: done apart below)
	if (Evaluated(first))
		++first;
	if (end >= first && Evaluated(end))
		--end;
	for (int k = first; k <= end; ++k)
		inA[k] = ToWorld(walk.bInA, samples->point[k]);
	if (end >= first)
		a.Levels(inA + first, end - first + 1, value + first);
	bool nan = false; // (one test after the loop, not a branch a sample)
	for (int k = first; k <= end; ++k)
	{
		stamp[k] = generation;
		lowest = std::min(lowest, value[k]);
		nan |= std::isnan(value[k]);
	}
	ok = ok && !nan;
	if (last == n && ok && !Evaluated(0))
	{
		ok = Evaluate(0);
		lowest = std::min(lowest, value[0]);
	}
}

// Branch and bound over runs: runs in the order of A's lower bound over their discs, each
// evaluated whole, until a run's bound exceeds the lowest level found so far. The skipped runs
// cannot hold anything lower (the bound covers the curve between the samples too), so the
// minima refined later are those of the full scan. The run of the lowest bound (of the group of
// the lowest bound, when grouped) goes first; only the runs whose bound is below the level found
// there are sorted, and only the groups whose bound is below it are opened.
void GridScan::Scan()
{
	int best = 0, bestGroup = -1;
	if (grouped)
	{
		bestGroup = int(std::min_element(groupBound, groupBound + groups) - groupBound);
		BoundRuns(bestGroup);
		int first, last;
		GroupRuns(bestGroup, first, last);
		best = int(std::min_element(bound + first, bound + last) - bound);
	}
	else
		best = int(std::min_element(bound, bound + runs) - bound);
	ScanRun(best);
	int orderCount = 0;
	if (grouped)
	{
		for (int G = 0; G < groups; ++G)
		{
			if (!(groupBound[G] <= lowest))
				continue;
			if (G != bestGroup)
				BoundRuns(G);
			int first, last;
			GroupRuns(G, first, last);
			for (int g = first; g < last; ++g)
				AddToOrder(g, best, orderCount);
		}
	}
	else
	{
		for (int g = 0; g < runs; ++g)
			AddToOrder(g, best, orderCount);
	}
	SortFew(order, order + orderCount, std::less<>());
	for (int i = 0; i < orderCount; ++i)
	{
		const auto [runBound, g] = order[i];
		if (runBound > lowest || !ok)
			break;
		// A last look with A's tighter bound (where it has one) over the run's box, before the
		// run's samples.
		OrientedBox box = hierarchy.runBox[g];
		box.centre = ToWorld(walk.bInA, box.centre);
		box.axis = Rotate(walk.bInA.q, box.axis);
		boxBound[g] = boundsA->TightLevelLowerBound(box);
		boxStamp[g] = generation;
		if (boxBound[g] > lowest)
			continue;
		ScanRun(g);
	}
}

void GridScan::ScanAll()
{
	for (int k = 0; k < n && ok; ++k)
		ok = Evaluate(k);
	std::fill(scanned, scanned + runs, char(1));
}

// A scanned run's first or last sample i (n stands for sample 0), whose neighbour may lie in a
// run not scanned: that neighbour is evaluated only where the sample is below its inside one
// (else it is no minimum whatever lies outside).
void GridScan::ConsiderRunEdge(int i)
{
	const int k = i == n ? 0 : i;
	const int before = k == 0 ? n - 1 : k - 1, after = k == n - 1 ? 0 : k + 1;
	if (Evaluated(before) && !(value[k] <= value[before]))
		return;
	if (Evaluated(after) && !(value[k] < value[after]))
		return;
	if (!Evaluated(before))
		ok = ok && Evaluate(before); // a NaN stops all evaluation; reported by Solve
	if (!Evaluated(after))
		ok = ok && Evaluate(after);
	Consider(k, before, after);
}

// Local minima of the cyclic sequence over the scanned runs, lowest first, at most
// options.gridCandidates of them. At the edge of a skipped run the neighbour is evaluated first,
// so that the edge is a minimum only if it is one. Each scanned sample is visited once: a run's
// last sample belongs to the next run when that one was scanned too.
void GridScan::CollectMinima()
{
	if (!bounded && ok && n >= 3)
	{
		// Every sample evaluated: plain neighbours, the ends wrapped (same minima, same order).
		Consider(0, n - 1, 1);
		for (int k = 1; k + 1 < n; ++k)
			Consider(k, k - 1, k + 1);
		Consider(n - 1, n - 2, 0);
	}
	if (bounded)
		SortFew(scannedRuns, scannedRuns + scannedCount, std::less<>());
	for (int r = 0; r < scannedCount && ok && bounded; ++r)
	{
		const int g = scannedRuns[r];
		int first, last;
		RunSamples(g, first, last);
		if (scanned[g + 1 == runs ? 0 : g + 1])
			--last;
		// Only a run's first and last samples can have a neighbour outside it (in a run not
		// scanned); those in between compare with their own run's samples.
		const int inner = std::min(last, n - 1); // i + 1 ≤ n − 1 below: no wrap
		ConsiderRunEdge(first);
		for (int i = first + 1; i < inner; ++i)
			Consider(i, i - 1, i + 1);
		for (int i = std::max(first + 1, inner); i <= last; ++i)
			ConsiderRunEdge(i);
	}
	if (!ok)
		return;
	if (minimaCount == 0)
	{
		int lowestSample = -1;
		for (int k = 0; k < n; ++k)
			if (Evaluated(k) && (lowestSample < 0 || value[k] < value[lowestSample]))
				lowestSample = k;
		minima[minimaCount++] = lowestSample;
	}
	SortFew(minima, minima + minimaCount, [&](int i, int j) { return value[i] < value[j] || (value[i] == value[j] && i < j); });
	minimaCount = std::min(minimaCount, std::max(1, options.gridCandidates));
}

// The candidates refined between their neighbours (RefineCandidate), the lowest answer kept.
void GridScan::RefineMinima(double& bestValue, Vec2& bestPoint)
{
	auto samplePoint = [&](int k) { return SamplePoint(k); };
	auto markSolved = [&](int i) { raySolved[i] = generation; };
	bestValue = value[minima[0]];
	bestPoint = SamplePoint(minima[0]);
	for (int m = 0; m < minimaCount; ++m)
	{
		const int k = minima[m];
		double v = value[k];
		Vec2 point = SamplePoint(k);
		if (options.gridRefine)
		{
			// (The neighbours of a local minimum of the samples were evaluated; those of the
			// lowest sample, taken when no sample is one, need not have been: no parabola then.
			// That sample is the only candidate, so the later ones all have theirs.)
			const int before = k == 0 ? n - 1 : k - 1, after = k == n - 1 ? 0 : k + 1;
			if (m > 0 && bounded)
			{
				// A later candidate whose arc between its neighbours A's level cannot reach below
				// the best level refined so far is not refined: the discs of its two sample
				// segments bound everything the refinement could find there.
				const Vec2 centres[2] = {0.5 * (inA[before] + inA[k]), 0.5 * (inA[k] + inA[after])};
				const double radii[2] = {SegmentRadius(inA[before], inA[k]), SegmentRadius(inA[k], inA[after])};
				double bounds[2];
				boundsA->LevelLowerBounds(centres, radii, 2, bounds);
				if (bounds[0] > bestValue && bounds[1] > bestValue)
					continue;
			}
			const double nan = std::numeric_limits<double>::quiet_NaN();
			RefineCandidate(walk, *samples, k, samplePoint, markSolved, Evaluated(before) ? value[before] : nan,
			                Evaluated(after) ? value[after] : nan, v, point);
		}
		if (v < bestValue)
		{
			bestValue = v;
			bestPoint = point;
		}
	}
}

// Where B's curve crosses one of A's corner rays, A's level has a V-shaped valley (the heart's
// tip): a minimum between two samples that the samples need not show as one, when the valley
// lies on the slope of a smooth basin. Each crossing between two scanned samples is solved for
// (the skipped runs' bounds cover their valleys), unless A's lower bound over the disc holding
// that arc of B's curve is above the best level already; only runs whose disc reaches a ray are
// searched.
void GridScan::CornerRayPass(double& bestValue, Vec2& bestPoint)
{
	const std::vector<Vec2>& rays = a.CornerDirections();
	auto reaches = [&](Vec2 c, double r) {
		for (const Vec2 u : rays)
			if (std::fabs(Cross(u, c)) <= r && Dot(u, c) >= -r)
				return true;
		return false;
	};
	for (int r = 0, count = bounded ? scannedCount : runs; r < count; ++r)
	{
		const int g = bounded ? scannedRuns[r] : r;
		if (bounded && !reaches(ToWorld(walk.bInA, hierarchy.runCentre[g]), hierarchy.runRadius[g]))
			continue;
		int first, last;
		RunSamples(g, first, last);
		for (int i = first; i < last; ++i)
		{
			const Vec2 p = inA[i], q = inA[i + 1 == n ? 0 : i + 1];
			if (!MeetsCornerRay(a, p, q) || raySolved[i] == generation)
				continue; // (no ray here, or solved by the refinement)
			// (CornerRayCrossing tries every corner ray.)
			if (!bounded || !(boundsA->LevelLowerBound(0.5 * (p + q), SegmentRadius(p, q)) > bestValue))
				CornerRayCrossing(walk, p, q, bestValue, bestPoint);
		}
	}
}

LevelResult GridScan::Solve(Vec2* bodyGradientA)
{
	LevelResult result;
	result.method = SolveMethod::grid;
	Bound();
	if (bounded)
		Scan();
	else
		ScanAll();
	CollectMinima();
	if (!ok)
	{
		result.failure = "grid: a level value is NaN (check the shape functions)";
		return result;
	}
	double bestValue;
	Vec2 bestPoint;
	RefineMinima(bestValue, bestPoint);
	if (options.gridRefine && !a.CornerAngles().empty())
		CornerRayPass(bestValue, bestPoint);
	if (!std::isfinite(bestValue))
	{
		result.failure = "grid: no finite level of A on B's surface";
		return result;
	}
	const Vec2 X = ToWorld(pb, bestPoint);
	const Vec2 gradientA = a.Gradient(ToBody(pa, X));
	if (bodyGradientA)
		*bodyGradientA = gradientA;
	Vec2 normal = Rotate(pa.q, gradientA);
	if (!(LengthSquared(normal) > 0.0) || !IsFinite(normal))
		normal = -Rotate(pb.q, b.Gradient(ToBody(pb, X))); // A's centre on B's surface: use B's normal
	result.status = SolveStatus::converged;
	if (ownLevel)
	{
		// Every level the solve evaluated is A's Level at ToWorld(walk.bInA, samples->point[k]):
		// the manifold's part search (OverlapParts) takes them again rather than evaluate them.
		GridScratch& scratch = GridScratch::ForThread();
		scratch.published = true;
		scratch.groupsBounded = grouped;
		scratch.serialA = a.Serial();
		scratch.serialB = b.Serial();
		scratch.samples = samples;
		scratch.bInA = walk.bInA;
	}
	result.level = bestValue;
	result.point = X;
	result.normal = Normalize(normal);
	result.iterations = walk.evaluations;
	return result;
}
} // namespace

LevelResult SolveGridScale(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                           double levelB)
{
	return SolveGridScale(a, pa, b, pb, options, levelB, nullptr);
}

LevelResult SolveGridScale(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                           double levelB, Vec2* bodyGradientA)
{
	return GridScan(a, pa, b, pb, options, levelB).Solve(bodyGradientA);
}

bool LastGridLevels(const Shape& a, const Shape& b, const Pose& bInA, const SurfaceSamples& samples, GridLevels* out)
{
	const GridScratch& scratch = GridScratch::ForThread();
	auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }; // bit for bit
	const Pose& p = scratch.bInA;
	if (!scratch.published || scratch.serialA != a.Serial() || scratch.serialB != b.Serial() || scratch.samples != &samples ||
	    !same(p.p.x, bInA.p.x) || !same(p.p.y, bInA.p.y) || !same(p.q.c, bInA.q.c) || !same(p.q.s, bInA.q.s))
		return false;
	out->value = scratch.value.data();
	out->stamp = scratch.stamp.data();
	out->generation = scratch.generation;
	out->groupBound = scratch.groupsBounded ? scratch.groupBound.data() : nullptr;
	out->runBound = scratch.bound.data();
	out->runStamp = scratch.runStamp.data();
	out->scanned = scratch.scanned.data();
	out->boxBound = scratch.boxBound.data();
	out->boxStamp = scratch.boxStamp.data();
	return true;
}

LevelResult SolveCommonLevelGrid(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options)
{
	if (!a.IsConvex() || !b.IsConvex())
	{
		// A non-convex level (the heart's) is not star-shaped about the centre: its level-C sets
		// need not nest, and the fixed point can land on A's centre with no normal there.
		LevelResult r;
		r.method = SolveMethod::grid;
		r.failure = "the common level needs convex shapes; use the one-sided scale (scale_a) for non-convex ones";
		return r;
	}
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
	const double centreLevelA = a.CentreLevel() / unitA;
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

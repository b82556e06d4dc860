// b2analytic: the parts of two particles' overlap, for non-convex pairs' manifolds.
#include "contact/OverlapParts.h"

#include "contact/GridScale.h"
#include "contact/SampleRuns.h"
#include "numerics/CodeLayout.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
// Scratch of one call, kept per thread and grown, never shrunk: neither allocated nor
// initialised a call (two heap allocations a call cost a tenth as much as the levels they held).
// Everything is held per place (a reachable sample, in increasing order of the samples): a
// sample that is not reachable is outside outer, and its level counts as +∞.
struct Scratch
{
	std::vector<Vec2> x;          // places to evaluate (outer's body frame)
	std::vector<double> level;    // per place
	std::vector<double> gathered; // per place evaluated here
	std::vector<int> index;       // the sample of each place
	std::vector<int> minima;      // the minima's samples, in order
	std::vector<int> slot;        // the place of each place evaluated here; then the places inside
	static Scratch& ForThread(int n)
	{
		thread_local Scratch s;
		if (int(s.level.size()) < n)
		{
			s.level.resize(size_t(n));
			s.gathered.resize(size_t(n));
			s.minima.resize(size_t(n));
			s.x.resize(size_t(n));
			s.index.resize(size_t(n + SampleRuns::kRunLength + 1));
			s.slot.resize(size_t(n));
		}
		return s;
	}
};

// The index of the lowest bit set in `bits` (not zero).
inline int LowestBit(std::uint64_t bits)
{
#if defined(__GNUC__) || defined(__clang__)
	return __builtin_ctzll(bits);
#else
	int r = 0;
	for (; !(bits & 1); bits >>= 1)
		++r;
	return r;
#endif
}

// All ones where a lower bound leaves the surface level open (NaN included), else zero: a mask
// computed, not a branch taken.
inline std::uint64_t Open(double lower, double surface)
{
	return std::uint64_t(0) - std::uint64_t(!(lower >= surface));
}

// The samples of every run over which outer's level bounds lie below its surface level, in
// increasing order, into index (returns their count): only they can be inside outer. Groups of
// runs first, then each run's disc, then its thin box, as the grid method bounds them. Every
// sample where the shape has no bounds. `known`: the grid solve's levels and bounds in this pose.
int ReachableSamples(const Shape& outer, const Pose& rel, const SampleRuns& runs, bool fast, const GridLevels* known, int* index)
{
	const int n = runs.samples->Count();
	const LevelBounds* bounds = fast ? outer.Bounds() : nullptr;
	const int groups = int(runs.groupCentre.size()), runCount = int(runs.runCentre.size());
	constexpr int kMaxDiscs = 64;
	// (Counts beyond the discs' scratch: every sample, as without bounds.)
	if (!bounds || groups > kMaxDiscs || runCount > kMaxDiscs)
	{
		for (int i = 0; i < n; ++i)
			index[i] = i;
		return n;
	}
	const double surface = outer.SurfaceLevel();
	// (The discs' centres unset until written: a Vec2 array is zeroed where it is declared.)
	union Discs
	{
		Discs() {}
		Vec2 centre[kMaxDiscs];
	} discs;
	Vec2* centres = discs.centre;
	double radii[kMaxDiscs], lower[kMaxDiscs], fresh[kMaxDiscs];
	int slot[kMaxDiscs];
	// The bounds the grid solve took in this relative pose (known: the same LevelLowerBounds over
	// the same discs, bit for bit) are taken again; the others are evaluated together.
	if (known && known->groupBound)
		std::copy(known->groupBound, known->groupBound + groups, lower);
	else
	{
		for (int g = 0; g < groups; ++g)
		{
			centres[g] = ToWorld(rel, runs.groupCentre[size_t(g)]);
			radii[g] = runs.groupRadius[size_t(g)];
		}
		bounds->LevelLowerBounds(centres, radii, groups, lower);
	}
	// The runs still open, one bit a run (at most kMaxDiscs): a verdict a bit, not a branch on
	// each bound (which runs a bound rules out follows no pattern a predictor learns). A bound
	// that is NaN rules nothing out.
	using Bits = std::uint64_t;
	Bits open = 0; // the runs of groups not ruled out
	for (int g = 0; g < groups; ++g)
	{
		const int firstRun = g * SampleRuns::kGroupRuns, count = std::min(SampleRuns::kGroupRuns, runCount - firstRun);
		const Bits mask = ((Bits(1) << count) - 1) << firstRun;
		open |= mask & Open(lower[g], surface);
	}
	// A run's bound from the grid is at least its group's, which lies below the surface level
	// here: below it exactly where the run's own bound is.
	Bits discOpen = 0; // the runs whose own disc does not rule them out either
	int toBound = 0;
	for (Bits rest = open; rest != 0; rest &= rest - 1)
	{
		const int r = LowestBit(rest);
		if (known && known->runStamp[r] == known->generation)
		{
			discOpen |= (Bits(1) << r) & Open(known->runBound[r], surface);
			continue;
		}
		centres[toBound] = ToWorld(rel, runs.runCentre[size_t(r)]);
		radii[toBound] = runs.runRadius[size_t(r)];
		slot[toBound++] = r;
	}
	if (toBound > 0)
		bounds->LevelLowerBounds(centres, radii, toBound, fresh);
	for (int i = 0; i < toBound; ++i)
		discOpen |= (Bits(1) << slot[i]) & Open(fresh[i], surface);
	int m = 0;
	bool wrapsToZero = false; // the last run's last sample is sample 0
	for (Bits rest = discOpen; rest != 0; rest &= rest - 1)
	{
		const int r = LowestBit(rest);
		// Runs come in increasing order and share their end samples: each sample once.
		const int first = r * SampleRuns::kRunLength;
		const int last = std::min(first + SampleRuns::kRunLength, n);
		// The run's thin box, where its disc did not rule it out (as the grid method's last
		// look before it evaluates a run), unless the grid solve evaluated the run whole (every
		// level of it known; with runs of eight samples no other run is known whole, its middle
		// samples being evaluated by its own scan alone): a run the box rules out is outside, and
		// its levels, evaluated or +∞, order its samples the same against any sample inside.
		// (The grid solve's box bound where it took one: the same bound over the same box.)
		if (!(known && known->scanned[r]))
		{
			double boxLower;
			if (known && known->boxStamp[r] == known->generation)
				boxLower = known->boxBound[r];
			else
			{
				OrientedBox box = runs.runBox[size_t(r)];
				box.centre = ToWorld(rel, box.centre);
				box.axis = Rotate(rel.q, box.axis);
				boxLower = bounds->TightLevelLowerBound(box);
			}
			if (boxLower >= surface)
				continue;
		}
		// (All the run's samples written, from the last one written where the runs meet: a loop
		// of a fixed count. The index holds n + kRunLength places for the writes past `stop`.)
		const int stop = std::min(last, n - 1);
		m -= m > 0 && index[m - 1] == first ? 1 : 0;
		for (int k = 0; k <= SampleRuns::kRunLength; ++k)
			index[m + k] = first + k;
		m += stop - first + 1;
		wrapsToZero = wrapsToZero || last == n;
	}
	if (wrapsToZero && !(m > 0 && index[0] == 0))
	{
		for (int j = m; j > 0; --j)
			index[j] = index[j - 1];
		index[0] = 0;
		++m;
	}
	return m;
}

// Whether every point of inner's surface between sample k's neighbours (body frame) lies within
// `within` of p: the samples' distances, plus the arcs' measured deviation from their chords
// (taken four times over: the grid's discs take it twice) and the rounding of two poses.
bool SurelyWithin(const SurfaceSamples& s, int k, Vec2 p, double within, double size)
{
	const int n = s.Count();
	const int before = (k + n - 1) % n, after = (k + 1) % n;
	const double far = std::max({Distance(s.point[size_t(before)], p), Distance(s.point[size_t(k)], p),
	                             Distance(s.point[size_t(after)], p)});
	const double deviation = std::max(s.arcDeviation[size_t(before)], s.arcDeviation[size_t(k)]);
	return far + 4.0 * deviation + 1e-9 * size <= within;
}

// A part's normal (outer's body frame, out of outer) from outer's level gradient g at the deepest
// point q of inner's surface inside it and inner's gradient gi there (turned to outer's frame).
// At a smooth minimum of outer's level along inner's surface the two are opposite (g is normal to
// inner's surface there), and either is the part's normal. At a corner of either surface (a
// heart's tip, where its level's gradient grows without bound and turns over across the axis)
// that side's direction flips between neighbouring poses, and the other's is the normal. Each
// unit direction is weighted by 1/(|g|·R/λs)², its gradient against the scale of the shape's
// own (R its bounding radius, λs its surface level): a corner's weight falls to zero where its
// gradient diverges, so the normal goes over to the other side's continuously, in the poses too.
Vec2 PartNormal(const Shape& outer, Vec2 g, const Shape& inner, Vec2 gi)
{
	auto weight = [](const Shape& shape, Vec2 gradient) {
		const double scale = std::fabs(shape.SurfaceLevel()) / shape.BoundingRadius();
		const double r = Length(gradient) / (scale > 0.0 ? scale : 1.0);
		return std::isfinite(r) && r > 0.0 ? 1.0 / (r * r) : 0.0;
	};
	const double wo = weight(outer, g), wi = weight(inner, gi);
	const Vec2 sum = (wo > 0.0 ? wo * Normalize(g) : Vec2()) - (wi > 0.0 ? wi * Normalize(gi) : Vec2());
	return LengthSquared(sum) > 0.0 && std::isfinite(LengthSquared(sum)) ? Normalize(sum) : Normalize(g);
}
// The part about inner's sample `deepest`, a local minimum of outer's level inside it (rel: inner's
// body to outer's), into *part; false where it is not refined to one. Out of line: the call is
// taken by some parts, not by every search, whose loops it would otherwise spread over more of
// the instruction cache.
B2A_NOINLINE bool RefinePart(const Shape& outer, const Pose& po, const Shape& inner, const Pose& rel, bool outerIsA,
                             const SurfaceSamples& samples, int deepest, OverlapPart* part)
{
	const double surface = outer.SurfaceLevel();
	double lo, hi;
	samples.NeighbourAngles(deepest, lo, hi);
	// The surface point of the search's answer is kept as it is evaluated: Brent's x is the
	// latest place whose level is at or below every earlier one (the rule below, NaN
	// included), and a point kept for the same angle, bit for bit, is the one it would
	// compute again.
	double keptTheta = 0.0, keptLevel = 0.0;
	Vec2 kept;
	bool anyKept = false;
	auto levelAt = [&](double theta) {
		const Vec2 p = inner.SurfacePoint(theta);
		const double value = outer.Level(ToWorld(rel, p));
		if (!anyKept || value <= keptLevel)
		{
			keptTheta = theta;
			keptLevel = value;
			kept = p;
			anyKept = true;
		}
		return value;
	};
	const ScalarResult mb = MinimizeBrent(levelAt, lo, hi, 1e-10, 1e-12, 60);
	const bool sameTheta = anyKept && std::memcmp(&keptTheta, &mb.x, sizeof keptTheta) == 0;
	const Vec2 qi = sameTheta ? kept : inner.SurfacePoint(mb.x);
	const Vec2 q = ToWorld(rel, qi); // outer's body frame
	const Vec2 g = outer.Gradient(q);
	if (!(mb.fx < surface) || !(LengthSquared(g) > 0.0) || !std::isfinite(LengthSquared(g)))
		return false;
	// (Against a convex particle, outer's gradient alone: with the blend there too, the mixed
	// pile of the game bucket slept later, medians of seeds 1-10 15.1 s against 11.2 s.)
	const Vec2 u = outer.IsConvex() || inner.IsConvex() ? Normalize(g) : PartNormal(outer, g, inner, Rotate(rel.q, inner.Gradient(qi)));
	// The depth: where the line from q along u leaves outer, bracketed by steps that double
	// from the first-order guess (at most 24, out to 2R) and found by Brent's method to
	// 1e-12 of the size. (Newton's steps along u, which a corner's gradient turns across the
	// line, went backwards there, and the part was lost every other step.)
	auto excess = [&](double t) { return outer.Level(q + t * u) - surface; };
	const double size = outer.BoundingRadius();
	double inner0 = 0.0, fin = mb.fx - surface, step = std::max((surface - mb.fx) / Length(g), 1e-6 * size);
	double outer0 = step, fout = excess(outer0);
	for (int it = 0; it < 24 && !(fout > 0.0) && outer0 <= 2.0 * size; ++it)
	{
		inner0 = outer0;
		fin = fout;
		step *= 2.0;
		outer0 += step;
		fout = excess(outer0);
	}
	if (!(fout > 0.0) || !(fin <= 0.0))
		return false;
	const double s = FindRootBrent(excess, inner0, outer0, fin, fout, 1e-12 * size, 100).x;
	if (!(s > 0.0) || !std::isfinite(s))
		return false;
	const Vec2 qw = ToWorld(po, q), sw = ToWorld(po, q + s * u), uw = Rotate(po.q, u);
	part->normal = outerIsA ? uw : -uw;
	part->pointA = outerIsA ? sw : qw;
	part->pointB = outerIsA ? qw : sw;
	part->separation = -s;
	return true;
}
} // namespace

int OverlapParts(const Shape& outer, const Pose& po, const Shape& inner, const Pose& pi, bool outerIsA, OverlapPart* out, int max,
                 const OverlapSkip* skip, bool fast)
{
	const SampleRuns& runs = SampleRunsOf(inner, Shape::kDefaultSampleCount);
	const SurfaceSamples& samples = *runs.samples;
	const int n = samples.Count();
	const Pose rel = Relative(po, pi); // inner's body to outer's body
	Scratch& scratch = Scratch::ForThread(n);
	// The levels this thread's last grid solve evaluated, where it rescaled outer onto inner's
	// surface in this relative pose (the contact's solve, just before): the same Level at the
	// same point, bit for bit (LastGridLevels), taken rather than evaluated again.
	GridLevels known;
	const bool reuse = fast && LastGridLevels(outer, inner, rel, samples, &known);
	const int* index = scratch.index.data();
	const int m = ReachableSamples(outer, rel, runs, fast, reuse ? &known : nullptr, scratch.index.data());
	double* level = scratch.level.data(); // per place
	if (reuse)
	{
		int evaluated = 0;
		for (int j = 0; j < m; ++j)
		{
			const int k = index[j];
			if (known.stamp[k] == known.generation)
				level[j] = known.value[k];
			else
			{
				scratch.x[evaluated] = ToWorld(rel, samples.point[size_t(k)]);
				scratch.slot[evaluated++] = j;
			}
		}
		outer.Levels(scratch.x.data(), evaluated, scratch.gathered.data());
		for (int e = 0; e < evaluated; ++e)
			level[scratch.slot[e]] = scratch.gathered[e];
	}
	else
	{
		for (int j = 0; j < m; ++j)
			scratch.x[j] = ToWorld(rel, samples.point[size_t(index[j])]);
		outer.Levels(scratch.x.data(), m, level);
	}
	const double surface = outer.SurfaceLevel();
	auto inside = [&](int j) { return level[j] < surface; };
	// The first sample not inside: the first one not reachable, or a reachable one outside.
	int start = -1, first = 0; // first: the places at or before `start`
	{
		int j = 0;
		while (j < m && index[j] == j && inside(j))
			++j;
		if (j < n)
		{
			start = j;
			first = j < m && index[j] == j ? j + 1 : j;
		}
	}
	if (start < 0)
		return 0;
	// Every local minimum of the level along a run is a part: a long run (a lobe lying along the
	// other's side) has one at either end, and the contact, warm-started, at either; with the
	// run's deepest sample alone, the part at the contact's end was its own, and the manifold
	// had two points one step and one the next. They are taken in order from the sample after
	// `start`, cyclically (the order decides which of more than `max` stay). A neighbour that is
	// not a place is outside (+∞); sample 0 and sample n − 1 are neighbours.
	// The places inside first, without a branch on each (whether a place lies inside follows no
	// pattern a predictor learns), then the minima among them: the places outside, most of
	// those reached, are no minima.
	int* insidePlaces = scratch.slot.data();
	int insideCount = 0;
	for (int j = 0; j < m; ++j)
	{
		insidePlaces[insideCount] = j;
		insideCount += inside(j) ? 1 : 0;
	}
	int* minima = scratch.minima.data();
	int candidates = 0;
	{
		const double infinity = std::numeric_limits<double>::infinity();
		const bool wraps = m > 0 && index[0] == 0 && index[m - 1] == n - 1;
		auto take = [&](int i) {
			const int j = insidePlaces[i];
			const double here = level[j];
			const double before = j > 0 ? (index[j - 1] == index[j] - 1 ? level[j - 1] : infinity) : (wraps ? level[m - 1] : infinity);
			const double after = j + 1 < m ? (index[j + 1] == index[j] + 1 ? level[j + 1] : infinity) : (wraps ? level[0] : infinity);
			minima[candidates] = index[j];
			candidates += int(here <= before) & int(here < after);
		};
		int split = 0; // the inside places at or before `start` come last
		while (split < insideCount && insidePlaces[split] < first)
			++split;
		for (int i = split; i < insideCount; ++i)
			take(i);
		for (int i = 0; i < split; ++i)
			take(i);
	}
	const bool mayskip = fast && skip && candidates <= max;
	const Vec2 skipPoint = mayskip ? ToBody(pi, skip->point) : Vec2();
	int found = 0;
	for (int j = 0; j < candidates; ++j)
	{
		const int deepest = minima[j];
		if (mayskip && SurelyWithin(samples, deepest, skipPoint, skip->within, inner.BoundingRadius()))
			continue; // the caller's own part, discarded there, and taking no other's place
		OverlapPart part;
		if (!RefinePart(outer, po, inner, rel, outerIsA, samples, deepest, &part))
			continue;
		if (found < max)
			out[found++] = part;
		else
		{
			int shallowest = 0;
			for (int j = 1; j < found; ++j)
				if (out[j].separation > out[shallowest].separation)
					shallowest = j;
			if (part.separation < out[shallowest].separation)
				out[shallowest] = part;
		}
	}
	return found;
}

} // namespace b2a

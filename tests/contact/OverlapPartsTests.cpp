// OverlapParts (contact/OverlapParts.h), the parts of a non-convex pair's overlap behind its
// two-part manifold: its shortcuts (outer's level evaluated only where its bounds do not rule
// inner's samples out, and the contact's own part not refined where it surely lies within the
// caller's reach) must give exactly what every sample and every part refined gives, the parts
// the caller keeps bit for bit, in the same order.
//
// Reference: OverlapParts with `fast` false (every sample evaluated, every part refined) on the
// same poses, and, for the count of parts, a dense outline of B (8192 points) tested against A's
// level: each part the full path finds is a stretch of that outline inside A.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "contact/GridScale.h"
#include "contact/OverlapParts.h"
#include "contact/SampleRuns.h"
#include "TestSupport.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace b2a;

namespace
{
// Whether two parts are the same to the bit.
bool SameBits(const OverlapPart& p, const OverlapPart& q)
{
	return std::memcmp(&p.pointA, &q.pointA, sizeof(Vec2)) == 0 && std::memcmp(&p.pointB, &q.pointB, sizeof(Vec2)) == 0 &&
	       std::memcmp(&p.normal, &q.normal, sizeof(Vec2)) == 0 && std::memcmp(&p.separation, &q.separation, sizeof(double)) == 0;
}

// The stretches of inner's dense outline (polar angle, 8192 steps of inner.SurfacePoint) inside
// outer: the overlap's parts as a brute force sees them.
int DenseStretchesInside(const Shape& outer, const Pose& po, const Shape& inner, const Pose& pi)
{
	const int n = 8192;
	std::vector<bool> inside(static_cast<size_t>(n));
	for (int i = 0; i < n; ++i)
	{
		const double theta = -kPi + 2.0 * kPi * i / n;
		inside[size_t(i)] = outer.Level(ToBody(po, ToWorld(pi, inner.SurfacePoint(theta)))) < outer.SurfaceLevel();
	}
	int stretches = 0;
	for (int i = 0; i < n; ++i)
		stretches += inside[size_t(i)] && !inside[size_t((i + n - 1) % n)] ? 1 : 0;
	return stretches;
}

struct Tally
{
	int poses = 0, skippable = 0, twoParts = 0, denseAgree = 0;
};

// Random touching poses of B about A at the origin (B's centre within the sum of bounding radii,
// any angle; kept where the contact overlaps by at most a tenth of the smaller particle, as the
// manifold's parts do): the fast path against the full path, from both sides, with the contact's
// own point as the skip of each side.
void CompareOnRandomPoses(const Shape& a, const Shape& b, std::uint64_t seed, int wanted, Tally& tally)
{
	test::Random random(seed);
	const double reach = a.BoundingRadius() + b.BoundingRadius();
	const double apart = 0.1 * std::min(a.BoundingRadius(), b.BoundingRadius());
	const Pose pa(Vec2(0.0, 0.0), random.Angle());
	int tries = 0;
	while (tally.poses < wanted && tries++ < 200 * wanted)
	{
		const double dir = random.Angle(), dist = random.Uniform(0.3, 1.0) * reach;
		const Pose pb(Vec2(dist * std::cos(dir), dist * std::sin(dir)), random.Angle());
		const ContactResult c = ComputeContact(a, pa, b, pb);
		if (!c.Ok() || !(c.separation <= 0.0) || !(c.separation >= -apart))
			continue;
		++tally.poses;
		CAPTURE(tally.poses);
		for (int side = 0; side < 2; ++side)
		{
			const bool outerIsA = side == 0;
			const Shape& outer = outerIsA ? a : b;
			const Shape& inner = outerIsA ? b : a;
			const Pose& po = outerIsA ? pa : pb;
			const Pose& pi = outerIsA ? pb : pa;
			const OverlapSkip skip{outerIsA ? c.pointB : c.pointA, apart};
			OverlapPart full[4], fast[4];
			const int nFull = OverlapParts(outer, po, inner, pi, outerIsA, full, 4, nullptr, false);
			const int nFast = OverlapParts(outer, po, inner, pi, outerIsA, fast, 4, &skip, true);
			// What the caller keeps: the parts whose inner point lies farther than `apart` from the
			// contact's (the manifold drops the others as the contact's own part).
			auto kept = [&](const OverlapPart* parts, int count, std::vector<OverlapPart>& out) {
				for (int k = 0; k < count; ++k)
				{
					const Vec2 q = outerIsA ? parts[k].pointB : parts[k].pointA;
					if (!(Distance(q, skip.point) <= apart))
						out.push_back(parts[k]);
				}
			};
			std::vector<OverlapPart> keptFull, keptFast;
			kept(full, nFull, keptFull);
			kept(fast, nFast, keptFast);
			tally.skippable += nFast < nFull ? 1 : 0;
			tally.twoParts += keptFull.size() >= 1 ? 1 : 0;
			REQUIRE(keptFast.size() == keptFull.size());
			for (size_t k = 0; k < keptFull.size(); ++k)
				CHECK(SameBits(keptFast[k], keptFull[k]));
			// The full path against the brute force: as many parts as stretches of inner's outline
			// inside outer (a stretch with two minima gives two parts; one narrower than the
			// samples' spacing, a grazing touch, none).
			tally.denseAgree += nFull == DenseStretchesInside(outer, po, inner, pi) ? 1 : 0;
		}
	}
	CHECK(tally.poses == wanted);
}
} // namespace

TEST_CASE("OverlapParts: the shortcuts keep exactly the full path's parts on random touching poses")
{
	struct Pair
	{
		ShapePtr a, b;
		std::string name;
	};
	const Pair pairs[] = {
		{MakeHeart(0.2), MakeHeart(0.2), "heart 0.2 / heart 0.2"},
		{MakeHeart(0.35), MakeHeart(0.1), "heart 0.35 / heart 0.1"},
		{MakeHeart(0.2), MakeEllipse(0.5, 0.3), "heart / ellipse"},
		{MakeHeart(0.2), MakeSuperellipse(0.5, 0.3, 4.0, 4.0), "heart / superellipse n = 4"},
	};
	std::uint64_t seed = 4401;
	for (const Pair& p : pairs)
	{
		CAPTURE(p.name);
		Tally tally;
		CompareOnRandomPoses(*p.a, *p.b, seed++, 300, tally);
		// Not vacuous: the own part was skipped on many poses, and a second part seen on some.
		CHECK(tally.skippable > tally.poses / 4);
		CHECK(tally.twoParts > 0);
		// The full path sees the brute force's parts on most poses (two minima in one stretch,
		// or a stretch narrower than the samples' spacing, make the rest).
		CHECK(tally.denseAgree > 2 * tally.poses * 8 / 10);
		MESSAGE(p.name << ": poses " << tally.poses << ", own part skipped " << tally.skippable << ", kept parts " << tally.twoParts
		                << ", dense agree " << tally.denseAgree);
	}
}

// OverlapParts takes the levels the thread's last grid solve evaluated (LastGridLevels) where that
// solve rescaled its outer particle onto its inner one's surface in the same relative pose. The
// reused levels must be Level's own at those places, bit for bit, and the parts found with them
// the parts found without (the last grid solve another pair's), bit for bit; a pose one ulp off
// or the sides swapped must not match. Reference: Shape::Level at ToWorld(rel, sample) and
// OverlapParts after a grid solve that does not match.
TEST_CASE("OverlapParts: the grid solve's levels, reused, give the parts bit for bit")
{
	const ShapePtr a = MakeHeart(0.2), b = MakeHeart(0.15);
	const SampleRuns& runs = SampleRunsOf(*b, Shape::kDefaultSampleCount);
	const double nan = std::numeric_limits<double>::quiet_NaN();
	test::Random random(4402);
	const double reach = a->BoundingRadius() + b->BoundingRadius();
	int poses = 0, reusedLevels = 0, reusedBounds = 0, scannedRuns = 0, reusedBoxes = 0, withParts = 0;
	for (int tries = 0; tries < 4000 && poses < 300; ++tries)
	{
		const Pose pa(Vec2(0.0, 0.0), random.Angle());
		const double dir = random.Angle(), dist = random.Uniform(0.3, 1.0) * reach;
		const Pose pb(Vec2(dist * std::cos(dir), dist * std::sin(dir)), random.Angle());
		if (!SolveGridScale(*a, pa, *b, pb, SolverOptions{}, nan).Ok())
			continue;
		if (!(SolveGridScale(*a, pa, *b, pb, SolverOptions{}, nan).level < a->SurfaceLevel()))
			continue; // (touching poses: the manifold's case)
		++poses;
		CAPTURE(poses);
		const Pose rel = Relative(pa, pb);
		GridLevels known;
		REQUIRE(LastGridLevels(*a, *b, rel, *runs.samples, &known));
		for (int k = 0; k < runs.samples->Count(); ++k)
		{
			if (known.stamp[k] != known.generation)
				continue;
			++reusedLevels;
			const double own = a->Level(ToWorld(rel, runs.samples->point[size_t(k)]));
			REQUIRE(std::memcmp(&own, &known.value[k], sizeof own) == 0);
		}
		// The reused bounds: each group's A's LevelLowerBounds over its disc, bit for bit; each run
		// the solve bounded, the larger of its own disc's and its group's.
		REQUIRE(known.groupBound != nullptr);
		const int groups = int(runs.groupCentre.size());
		for (int g = 0; g < groups; ++g)
		{
			const Vec2 centre = ToWorld(rel, runs.groupCentre[size_t(g)]);
			double own = 0.0;
			a->Bounds()->LevelLowerBounds(&centre, &runs.groupRadius[size_t(g)], 1, &own);
			REQUIRE(std::memcmp(&own, &known.groupBound[g], sizeof own) == 0);
		}
		for (int r = 0; r < int(runs.runCentre.size()); ++r)
		{
			if (known.runStamp[r] != known.generation)
				continue;
			++reusedBounds;
			const Vec2 centre = ToWorld(rel, runs.runCentre[size_t(r)]);
			double own = 0.0;
			a->Bounds()->LevelLowerBounds(&centre, &runs.runRadius[size_t(r)], 1, &own);
			const double expected = std::max(own, known.groupBound[r / SampleRuns::kGroupRuns]);
			REQUIRE(std::memcmp(&expected, &known.runBound[r], sizeof expected) == 0);
		}
		// A run the solve marks scanned has every level known, both ends included (OverlapParts
		// then skips its box): checked against the stamps.
		const int n = runs.samples->Count();
		for (int r = 0; r < int(runs.runCentre.size()); ++r)
		{
			if (!known.scanned[r])
				continue;
			++scannedRuns;
			const int first = r * SampleRuns::kRunLength, last = std::min(first + SampleRuns::kRunLength, n);
			for (int k = first; k <= last; ++k)
				REQUIRE(known.stamp[k == n ? 0 : k] == known.generation);
		}
		// The box bounds the solve took: A's TightLevelLowerBound over the run's box, bit for bit.
		for (int r = 0; r < int(runs.runCentre.size()); ++r)
		{
			if (known.boxStamp[r] != known.generation)
				continue;
			++reusedBoxes;
			OrientedBox box = runs.runBox[size_t(r)];
			box.centre = ToWorld(rel, box.centre);
			box.axis = Rotate(rel.q, box.axis);
			const double own = a->Bounds()->TightLevelLowerBound(box);
			REQUIRE(std::memcmp(&own, &known.boxBound[r], sizeof own) == 0);
		}
		// Keys that must not match: the sides swapped, the pose one ulp off.
		GridLevels other;
		CHECK_FALSE(LastGridLevels(*b, *a, rel, *runs.samples, &other));
		Pose nudged = rel;
		nudged.p.x = std::nextafter(nudged.p.x, 1e9);
		CHECK_FALSE(LastGridLevels(*a, *b, nudged, *runs.samples, &other));
		OverlapPart reused[4], fresh[4];
		const int nReused = OverlapParts(*a, pa, *b, pb, true, reused, 4);
		SolveGridScale(*b, pb, *a, pa, SolverOptions{}, nan); // another key: nothing to reuse
		REQUIRE_FALSE(LastGridLevels(*a, *b, rel, *runs.samples, &other));
		const int nFresh = OverlapParts(*a, pa, *b, pb, true, fresh, 4);
		REQUIRE(nReused == nFresh);
		withParts += nFresh > 0 ? 1 : 0;
		for (int k = 0; k < nFresh; ++k)
			CHECK(SameBits(reused[k], fresh[k]));
	}
	CHECK(poses == 300);
	// Not vacuous: levels were reused on every pose, and parts found on most.
	CHECK(reusedLevels >= poses);
	CHECK(reusedBounds >= poses);
	CHECK(scannedRuns >= poses);
	CHECK(reusedBoxes > 0);
	CHECK(withParts > poses / 2);
	MESSAGE("poses " << poses << ", reused levels " << reusedLevels << ", reused run bounds " << reusedBounds << ", with parts " << withParts);
}

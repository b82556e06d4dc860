// BuildContactManifold on a flat contact: a small n = 4 superellipse B lying tilted on the top
// face of a larger one A, so that the patch is B's. Its two points must be B's patch ends:
// the points of B's surface within `patchTolerance` of its lowest point along the normal.
//
// Reference: the ends from B's own formula, in long double and without the library's surface
// queries: x(φ) = (a·c|cos φ|^(1/2), b·s|sin φ|^(1/2)) (c, s the signs) parametrises
// |x/a|⁴ + |y/b|⁴ = 1; along the unit direction e the support value is the dual norm
// (|a·ex|^(4/3) + |b·ey|^(4/3))^(3/4); the ends are the two roots of h − x(φ)·e − tol, found by a
// scan of 20,000 parameters and bisection to rounding. Tolerance: 1e-9 of the size (the search
// finds each end's angle to 1e-10 rad).
//
// The persistent cache (ManifoldCache) carries each end and its slope to the next step, where
// secant steps start from them; the cached manifold must be the reference's at every step of a
// slow roll, and so must one built from a cache that is wrong in every way.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "b2analytic/ContactManifold.h"
#include "TestSupport.h"

#include <cmath>
#include <vector>

using namespace b2a;

namespace
{
using LD = long double;

const double kA = 1.0, kB = 0.625; // B's semi-axes (A: 3 × 1)
const double kTol = 0.0025;        // the fixtures' default patch tolerance, 0.5 b2_linearSlop

struct LDVec
{
	LD x, y;
};

LDVec SurfaceLD(LD phi)
{
	const LD c = std::cos(phi), s = std::sin(phi);
	return {kA * std::copysign(std::sqrt(std::fabs(c)), c), kB * std::copysign(std::sqrt(std::fabs(s)), s)};
}

// B's patch ends along world direction −n (B's near side), in world coordinates.
std::vector<Vec2> ReferenceEnds(const Pose& pb, Vec2 n)
{
	const LD angle = std::atan2(LD(pb.q.s), LD(pb.q.c));
	const LD cq = std::cos(angle), sq = std::sin(angle);
	// e = Rᵀ(−n) in B's frame.
	const LD ex = -(cq * n.x + sq * n.y), ey = -(-sq * n.x + cq * n.y);
	const LD h = std::pow(std::pow(std::fabs(kA * ex), 4.0L / 3.0L) + std::pow(std::fabs(kB * ey), 4.0L / 3.0L), 0.75L);
	auto g = [&](LD phi) {
		const LDVec x = SurfaceLD(phi);
		return h - (x.x * ex + x.y * ey) - kTol;
	};
	std::vector<Vec2> ends;
	const int scan = 20000;
	const LD twoPi = 2.0L * 3.14159265358979323846264338327950288L;
	for (int i = 0; i < scan; ++i)
	{
		LD lo = twoPi * i / scan, hi = twoPi * (i + 1) / scan;
		LD glo = g(lo);
		const LD ghi = g(hi);
		if ((glo <= 0) == (ghi <= 0))
			continue;
		for (int k = 0; k < 80; ++k)
		{
			const LD mid = 0.5L * (lo + hi);
			const LD gm = g(mid);
			if ((gm <= 0) == (glo <= 0))
			{
				lo = mid;
				glo = gm;
			}
			else
				hi = mid;
		}
		const LDVec x = SurfaceLD(0.5L * (lo + hi));
		ends.push_back(Vec2(double(pb.p.x + cq * x.x - sq * x.y), double(pb.p.y + sq * x.x + cq * x.y)));
	}
	return ends;
}

// The manifold's two points are the reference ends (in either order).
void CheckEnds(const ContactManifold& m, const std::vector<Vec2>& ends)
{
	REQUIRE(ends.size() == 2);
	REQUIRE(m.count == 2);
	const bool straight = Distance(m.points[0].pointB, ends[0]) < Distance(m.points[0].pointB, ends[1]);
	const Vec2 e0 = straight ? ends[0] : ends[1], e1 = straight ? ends[1] : ends[0];
	CHECK(Distance(m.points[0].pointB, e0) < 1e-9);
	CHECK(Distance(m.points[1].pointB, e1) < 1e-9);
	CHECK(m.points[0].separation <= 0.0);
	CHECK(m.points[1].separation <= 0.0);
}
} // namespace

TEST_CASE("BuildContactManifold: a tilted block on a flat face gets its patch ends, with and without the step-to-step cache")
{
	const ShapePtr a = MakeSuperellipse(3.0, 1.0, 4.0, 4.0);
	const ShapePtr b = MakeSuperellipse(kA, kB, 4.0, 4.0);
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const double minWidth = 0.25 * b->BoundingRadius();
	ManifoldCache cache;
	int steps = 0;
	for (int step = 0; step < 40; ++step)
	{
		CAPTURE(step);
		// B sinks 4e-3 into A's top face (more than the tolerance, so both ends touch), tilted by
		// 2e-3 rad and rolling by 5e-5 rad and sliding 1e-3 per step: a settling pile's motion.
		// (At a tilt of 1e-2 its face dips across the tolerance: one point, a corner.)
		const double tilt = 0.002 + 5e-5 * step;
		const Pose pb(Vec2(0.2 + 1e-3 * step, 1.0 + kB - 4e-3), tilt);
		const ContactResult c = ComputeContact(*a, pa, *b, pb);
		REQUIRE(c.Ok());
		const ManifoldSide sa{a.get(), pa}, sb{b.get(), pb};
		const std::vector<Vec2> ends = ReferenceEnds(pb, c.normal);
		CheckEnds(BuildContactManifold(c, sa, sb, kTol, minWidth, 0.0, &cache), ends);
		CheckEnds(BuildContactManifold(c, sa, sb, kTol, minWidth), ends); // no cache: the search from scratch
		++steps;
	}
	CHECK(steps == 40);
	// Both sides' ends carry slopes for the next step's secant: the excess rises outwards, so
	// the slope is negative at the end on the clockwise side and positive at the other.
	CHECK(cache.validA);
	CHECK(cache.validB);
	CHECK(cache.slopesB[0] < 0.0);
	CHECK(cache.slopesB[1] > 0.0);
	CHECK(cache.slopesA[0] < 0.0);
	CHECK(cache.slopesA[1] > 0.0);
}

TEST_CASE("BuildContactManifold: a cache that is wrong in every way still gives the patch ends")
{
	const ShapePtr a = MakeSuperellipse(3.0, 1.0, 4.0, 4.0);
	const ShapePtr b = MakeSuperellipse(kA, kB, 4.0, 4.0);
	const Pose pa(Vec2(0.0, 0.0), 0.0), pb(Vec2(0.25, 1.0 + kB - 4e-3), 0.003);
	const ContactResult c = ComputeContact(*a, pa, *b, pb);
	REQUIRE(c.Ok());
	const ManifoldSide sa{a.get(), pa}, sb{b.get(), pb};
	const std::vector<Vec2> ends = ReferenceEnds(pb, c.normal);
	// Ends from far away or on the wrong side, slopes of the wrong sign, far too small or too
	// large, and not finite.
	const double endsTried[] = {0.0, 1e-6, -2.0, 3.0, 1.5707963, -1.5707963};
	const double slopesTried[] = {-1.0, 1.0, 1e-30, 1e30, -1e-12, std::nan(""), INFINITY};
	int cases = 0;
	for (double e0 : endsTried)
		for (double e1 : endsTried)
			for (double s : slopesTried)
			{
				ManifoldCache cache;
				cache.endsA[0] = cache.endsB[0] = e0;
				cache.endsA[1] = cache.endsB[1] = e1;
				cache.slopesA[0] = cache.slopesB[0] = s;
				cache.slopesA[1] = cache.slopesB[1] = -s;
				cache.validA = cache.validB = true;
				CAPTURE(e0);
				CAPTURE(e1);
				CAPTURE(s);
				CheckEnds(BuildContactManifold(c, sa, sb, kTol, 0.25 * b->BoundingRadius(), 0.0, &cache), ends);
				++cases;
			}
	CHECK(cases == 6 * 6 * 7);
}

// Sweeps: a circle slides along a horizontal line past another particle; contact must happen
// exactly on the interval(s) known independently, including just inside and just outside each end.
//
// References: a circle of radius r centred at P touches a particle exactly when the distance from
// P to the particle is ≤ r (P outside it). For a circle past a circle that is the closed form
// |x| ≤ √((R + r)² − h²). For an ellipse, a rotated superellipse and a heart the distance is
// computed in long double (dense samples of a closed-form surface parametrisation, then
// golden-section and derivative-sign polishing of the nearest samples), and the tangency
// positions are its crossings of r, bisected to long-double resolution. For a convex particle
// the distance is a convex function of x along the line, so there are exactly two crossings; for
// the heart the crossings are found by scanning.
//
// Tolerance: positions within 1e-9 (relative to the particle size) of a tangency are not
// classified in the coarse sweep; the explicit "just inside / just outside" probes sit at 1e-3,
// 1e-6 and 1e-9 of the size from each end, where the level differs from the own level by ~1e-9
// at least, 1e4 times the solvers' resolution (~1e-13), so the verdict must be exact there.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"
#include "ContactChecks.h"
#include "ContactReference.h"

#include <vector>

using namespace b2a;
using namespace b2a::test;
using ref::LD;
using ref::V;

namespace
{
// Distance from a world point P outside a particle to the particle (long double).
struct DistanceRef
{
	ref::RefShape shape;
	ref::RefPose pose;
	ref::Curve curve;

	DistanceRef(const ref::RefShape& s, const ref::RefPose& p, int samples = 4096)
		: shape(s), pose(p), curve(ref::SampleCurve(s, s.Own(), samples))
	{
	}

	LD operator()(V P, bool polish = true) const
	{
		auto d2 = [&](LD s) {
			const V d = ref::ToWorldL(pose, shape.Surface(s, shape.Own())) - P;
			return ref::Dot(d, d);
		};
		const int N = int(curve.point.size());
		std::vector<LD> value(N);
		for (int k = 0; k < N; ++k)
		{
			const V d = ref::ToWorldL(pose, curve.point[k]) - P;
			value[k] = ref::Dot(d, d);
		}
		std::vector<int> minima;
		for (int k = 0; k < N; ++k)
			if (value[k] <= value[(k + N - 1) % N] && value[k] < value[(k + 1) % N])
				minima.push_back(k);
		std::sort(minima.begin(), minima.end(), [&](int i, int j) { return value[i] < value[j]; });
		if (minima.size() > 3) minima.resize(3);
		LD best = value[minima[0]];
		if (polish)
		{
			for (int k : minima)
				best = std::min(best, ref::Minimise1D(d2, curve.s[k] - 4.0L / N, curve.s[k] + 4.0L / N).second);
			for (int c = 0; c < 4; ++c)
				best = std::min(best, d2(LD(c)));
		}
		return std::sqrt(best);
	}

	// A circle of radius r centred at P touches the particle: P inside it, or within r of it.
	bool Touches(V P, LD r, bool polish = true) const
	{
		return shape.Level(ref::ToBodyL(pose, P)) <= shape.Own() || (*this)(P, polish) <= r;
	}
};

// The x where dist((x, h)) crosses r between lo (one side) and hi (the other side).
LD Crossing(const DistanceRef& dist, LD h, LD r, LD lo, LD hi)
{
	const bool loTouch = dist.Touches(V{lo, h}, r);
	for (int i = 0; i < 90; ++i)
	{
		const LD mid = 0.5L * (lo + hi);
		if (dist.Touches(V{mid, h}, r) == loTouch) lo = mid; else hi = mid;
	}
	return 0.5L * (lo + hi);
}

// Sweep a circle of radius r at height h along x past (shape, pose) and compare the verdicts of
// ComputeContact (both orders, each method) with the intervals [ends[2i], ends[2i+1]].
void CheckSweep(const Shape& shape, const Pose& pose, double r, double h, const std::vector<LD>& ends,
                const std::vector<MethodChoice>& methods, double size)
{
	REQUIRE(ends.size() % 2 == 0);
	const auto circle = MakeCircle(r);
	auto inside = [&](LD x) {
		for (size_t i = 0; i < ends.size(); i += 2)
			if (x >= ends[i] && x <= ends[i + 1]) return true;
		return false;
	};
	auto nearEnd = [&](LD x) {
		for (LD e : ends)
			if (std::fabs(x - e) <= 1e-9L * size) return true;
		return false;
	};
	auto verdicts = [&](double x, bool want) {
		const Pose pc(Vec2(x, h), 0.3);
		for (MethodChoice m : methods)
		{
			INFO("x=" << x << " method " << int(m));
			const ContactResult ab = ComputeContact(*circle, pc, shape, pose, m);
			const ContactResult ba = ComputeContact(shape, pose, *circle, pc, m);
			REQUIRE(ab.Ok());
			REQUIRE(ba.Ok());
			CHECK(ab.touching == want);
			CHECK(ba.touching == want);
		}
	};
	const LD lo = ends.front() - 2.0L * r, hi = ends.back() + 2.0L * r;
	for (int k = 0; k <= 200; ++k)
	{
		const LD x = lo + (hi - lo) * k / 200.0L;
		if (!nearEnd(x))
			verdicts(double(x), inside(x));
	}
	for (size_t i = 0; i < ends.size(); ++i)
	{
		const LD inward = (i % 2 == 0) ? 1.0L : -1.0L; // left ends open to the right, right ends to the left
		for (LD delta : {1e-3L, 1e-6L, 1e-9L})
		{
			verdicts(double(ends[i] + inward * delta * size), true);
			verdicts(double(ends[i] - inward * delta * size), false);
		}
	}
}
} // namespace

TEST_CASE("sweep: a circle passing a circle touches exactly on |x| <= sqrt((R + r)^2 - h^2)")
{
	const double R = 1.3, r = 0.45;
	const auto big = MakeCircle(R);
	// As a circle (closed form), and as a user shape (Newton path) of the same geometry.
	const auto bigUser = MakeUserCircle(R);
	for (double h : {0.0, 0.9, 1.7})
	{
		const LD half = std::sqrt((LD(R) + r) * (LD(R) + r) - LD(h) * h);
		INFO("h=" << h);
		CheckSweep(*big, Pose(Vec2(0.0, 0.0), 0.0), r, h, {-half, half},
		           {MethodChoice::automatic, MethodChoice::newton, MethodChoice::grid}, R + r);
		CheckSweep(*bigUser, Pose(Vec2(0.0, 0.0), 0.0), r, h, {-half, half}, {MethodChoice::automatic}, R + r);
	}
}

TEST_CASE("sweep: a circle passing an axis-aligned ellipse touches exactly between the long-double tangency positions")
{
	const double a = 2.5, b = 0.8, r = 0.35;
	const auto ellipse = MakeEllipse(a, b);
	const DistanceRef dist(ref::RefShape::Ellipse(a, b), ref::RefPose{});
	for (double h : {0.5, 1.0, 1.12})
	{
		// The distance is convex in x and symmetric: one crossing on each side.
		const LD right = Crossing(dist, h, r, 0.0L, a + 2.0L * r), left = -right;
		// Sanity of the reference: at the crossing the distance is r, and for h ≤ b + r the
		// circle reaches the ellipse directly above its centre.
		CHECK(double(std::fabs(dist(V{right, h}) - r)) <= 1e-15);
		INFO("h=" << h << " tangency at x=±" << double(right));
		CheckSweep(*ellipse, Pose(Vec2(0.0, 0.0), 0.0), r, h, {left, right},
		           {MethodChoice::automatic, MethodChoice::newton, MethodChoice::grid}, a);
	}
}

TEST_CASE("sweep: a circle passing a rotated superellipse (n = 4, m = 6) touches exactly between its two tangency positions")
{
	const double a = 1.8, b = 0.9, r = 0.3;
	const auto se = MakeSuperellipse(a, b, 4.0, 6.0);
	const Pose pose(Vec2(0.4, -0.1), 0.6);
	const DistanceRef dist(ref::RefShape::Super(a, b, 4.0, 6.0), ref::Of(pose));
	for (double h : {0.2, 1.0})
	{
		// The line meets the particle's r-neighbourhood in one interval (convex): bracket each
		// end from a point inside it (the x minimising the distance, found coarsely) and outside.
		LD xMin = 0.0L, dMin = 1e9L;
		for (int k = -300; k <= 300; ++k)
		{
			const LD x = 0.4L + 3.0L * k / 300.0L;
			const LD d = dist.Touches(V{x, h}, 0.0L, false) ? 0.0L : dist(V{x, h}, false);
			if (d < dMin) { dMin = d; xMin = x; }
		}
		REQUIRE(dMin < r);
		const LD left = Crossing(dist, h, r, xMin, xMin - 4.0L), right = Crossing(dist, h, r, xMin, xMin + 4.0L);
		INFO("h=" << h << " interval [" << double(left) << ", " << double(right) << "]");
		CHECK(right - left > 0.5L);
		CheckSweep(*se, pose, r, h, {left, right}, {MethodChoice::automatic, MethodChoice::newton, MethodChoice::grid}, a);
	}
}

TEST_CASE("sweep: a circle passing over the lobes of a heart touches on two separate intervals")
{
	// Non-convex: at h = 1.3 a circle of radius 0.15 touches each lobe (tops at y ≈ 1.2367,
	// x ≈ ±0.514) but passes over the notch (at (0, 1)) without touching. Crossings are found by
	// scanning the long-double distance and bisecting each sign change.
	const double r = 0.15, h = 1.3;
	const auto heart = MakeHeart(1.0);
	const DistanceRef dist(ref::RefShape::Heart(1.0L), ref::RefPose{}, 8192);
	std::vector<LD> ends;
	LD prevX = -2.0L;
	bool prev = dist.Touches(V{prevX, h}, r, false);
	for (int k = 1; k <= 400; ++k)
	{
		const LD x = -2.0L + 4.0L * k / 400.0L;
		const bool now = dist.Touches(V{x, h}, r, false);
		if (now != prev)
			ends.push_back(Crossing(dist, h, r, prevX, x));
		prev = now;
		prevX = x;
	}
	REQUIRE(ends.size() == 4); // two intervals, one per lobe
	CHECK(double(ends[1]) < -0.05);
	CHECK(double(ends[2]) > 0.05);
	// The mirror symmetry of the heart: the intervals mirror each other.
	CHECK(double(std::fabs(ends[0] + ends[3])) <= 1e-12);
	CHECK(double(std::fabs(ends[1] + ends[2])) <= 1e-12);
	CheckSweep(*heart, Pose(Vec2(0.0, 0.0), 0.0), r, h, ends, {MethodChoice::automatic}, 1.0);
}

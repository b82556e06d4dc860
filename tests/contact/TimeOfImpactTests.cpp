// Time of impact for constant linear and angular velocities, against independent first-contact
// times.
//
// References:
//  - two circles: the smaller root of |d₀ + w t| = rA + rB (w the relative velocity), in long
//    double; rotation does not matter for circles;
//  - ellipses: the Perram–Wertheim common level C(t) (long double, ContactReference.h) stepped in
//    time to the first step with C ≤ 1, then bisected to long-double resolution;
//  - superellipses and hearts: the same stepping and bisection on the independent touching test
//    "smallest level of A over B's surface ≤ A's own level" (dense samples of B's surface in its
//    body frame, moved rigidly with B, plus golden/derivative polishing of the best candidates).
//    The poses at time t are built here in long double from the initial angle + ω·t.
//
// Tolerances: the library brackets the root to 1e-13 of tMax. The references' levels are exact
// to ~1e-17 (ellipses, superellipses) and ~1e-11 for hearts (at the |x|^{2/3} valley of its
// axis, see HeartContactTests), and the level changes at a rate of order 1 per unit time at
// first contact, so: circles and ellipses to 1e-9 relative (the brief), superellipses 1e-9,
// hearts 1e-8.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"
#include "ContactChecks.h"
#include "ContactReference.h"

#include <functional>
#include <vector>

using namespace b2a;
using namespace b2a::test;
using ref::LD;
using ref::V;

namespace
{
// A motion as the test defines it: initial position, angle, velocity, angular velocity.
struct Move
{
	Vec2 p, v;
	double angle = 0.0, omega = 0.0;
	Motion ToMotion() const
	{
		Motion m;
		m.pose = Pose(p, angle);
		m.velocity = v;
		m.angularVelocity = omega;
		return m;
	}
	ref::RefPose At(LD t) const { return ref::PoseL(V{p.x + t * v.x, p.y + t * v.y}, LD(angle) + t * omega); }
};

// First t in [0, tMax] with touching(t), by `steps` equal steps and a bisection to long-double
// resolution; -1 when none.
LD FirstContact(const std::function<bool(LD)>& touching, LD tMax, int steps)
{
	if (touching(0.0L))
		return 0.0L;
	LD prev = 0.0L;
	for (int k = 1; k <= steps; ++k)
	{
		const LD t = tMax * k / steps;
		if (touching(t))
		{
			LD lo = prev, hi = t;
			for (int i = 0; i < 80; ++i)
			{
				const LD mid = 0.5L * (lo + hi);
				(touching(mid) ? hi : lo) = mid;
			}
			return 0.5L * (lo + hi);
		}
		prev = t;
	}
	return -1.0L;
}

// The touching test of two posed reference shapes via the smallest level of A over B's surface
// (B's samples in its body frame, precomputed).
struct SurfaceTouch
{
	ref::RefShape A, B;
	ref::Curve curve;
	SurfaceTouch(const ref::RefShape& a, const ref::RefShape& b, int samples) : A(a), B(b), curve(ref::SampleCurve(b, b.Own(), samples)) {}
	bool operator()(const ref::RefPose& pa, const ref::RefPose& pb) const
	{
		return ref::SurfaceMin(A, pa, B, pb, B.Own(), 0, 4, &curve).value <= A.Own();
	}
};

// TimeOfImpactResult has no Ok() (unlike LevelResult and ContactResult).
bool Succeeded(const TimeOfImpactResult& r) { return r.status != SolveStatus::failed; }

void CheckHit(const TimeOfImpactResult& r, LD want, double tol, const char* what)
{
	INFO(std::string(what) << ": want t=" << double(want) << " got " << r.time);
	REQUIRE(Succeeded(r));
	REQUIRE(r.hit);
	CHECK(double(std::fabs(LD(r.time) - want) / want) <= tol);
	CHECK(r.contact.Ok());
	CHECK(r.contact.touching);
	CHECK(AllFinite(r.contact));
}
} // namespace

TEST_CASE("time of impact: two circles head on and obliquely, against the closed form")
{
	struct Row { double rA, rB; Move a, b; double tMax; };
	const Row rows[] = {
		// Head on: gap 10 − 3 closed at speed 2 → t = 3.5.
		{1.0, 2.0, {Vec2(0, 0), Vec2(1, 0)}, {Vec2(10, 0), Vec2(-1, 0)}, 10.0},
		// The same with spin, which must not matter for circles.
		{1.0, 2.0, {Vec2(0, 0), Vec2(1, 0), 0.3, 5.0}, {Vec2(10, 0), Vec2(-1, 0), -1.0, -3.0}, 10.0},
		// Oblique, both moving.
		{0.7, 0.5, {Vec2(0, 0), Vec2(2, 0.5)}, {Vec2(6, 2.2), Vec2(-1, -0.2)}, 10.0},
		// Small and fast against large and slow.
		{0.05, 3.0, {Vec2(-20, 1), Vec2(40, 0.5)}, {Vec2(5, -1), Vec2(-0.5, 0)}, 1.0},
	};
	for (const Row& row : rows)
	{
		const auto a = MakeCircle(row.rA), b = MakeCircle(row.rB);
		const V d0{LD(row.b.p.x) - row.a.p.x, LD(row.b.p.y) - row.a.p.y};
		const V w{LD(row.b.v.x) - row.a.v.x, LD(row.b.v.y) - row.a.v.y};
		const LD R = LD(row.rA) + row.rB;
		const LD qa = ref::Dot(w, w), qb = ref::Dot(d0, w), qc = ref::Dot(d0, d0) - R * R;
		const LD want = (-qb - std::sqrt(qb * qb - qa * qc)) / qa;
		REQUIRE(want > 0);
		REQUIRE(want < row.tMax);
		const TimeOfImpactResult r = TimeOfImpact(*a, row.a.ToMotion(), *b, row.b.ToMotion(), row.tMax);
		CheckHit(r, want, 1e-9, "circles");
		CHECK(std::fabs(r.contact.separation) <= 1e-9 * R);
	}
}

TEST_CASE("time of impact: a miss, and particles already touching at t = 0")
{
	const auto a = MakeCircle(1.0), b = MakeCircle(0.5);
	// Passing each other 1.6 apart (> 1.5): no contact, time = tMax.
	{
		const Move ma{Vec2(-10, 0), Vec2(2, 0)}, mb{Vec2(10, 1.6), Vec2(-2, 0)};
		const TimeOfImpactResult r = TimeOfImpact(*a, ma.ToMotion(), *b, mb.ToMotion(), 20.0);
		REQUIRE(Succeeded(r));
		CHECK_FALSE(r.hit);
		CHECK(r.time == 20.0);
		CHECK_FALSE(r.contact.touching);
	}
	// Moving apart: no contact.
	{
		const auto e = MakeEllipse(2.0, 0.3);
		const Move ma{Vec2(0, 0), Vec2(-1, 0), 0.0, 2.0}, mb{Vec2(3, 0), Vec2(1, 0)};
		const TimeOfImpactResult r = TimeOfImpact(*e, ma.ToMotion(), *b, mb.ToMotion(), 5.0);
		REQUIRE(Succeeded(r));
		CHECK_FALSE(r.hit);
	}
	// Overlapping at t = 0 (circles, ellipses, hearts): time 0.
	{
		const Move ma{Vec2(0, 0), Vec2(1, 0)}, mb{Vec2(1.2, 0.3), Vec2(-1, 0)};
		for (const auto& [sa, sb] : {std::pair<ShapePtr, ShapePtr>{a, b}, {MakeEllipse(1.5, 0.4), MakeEllipse(0.6, 1.0)},
		                             {MakeHeart(1.0), MakeHeart(0.4)}})
		{
			const TimeOfImpactResult r = TimeOfImpact(*sa, ma.ToMotion(), *sb, mb.ToMotion(), 3.0);
			REQUIRE(Succeeded(r));
			CHECK(r.hit);
			CHECK(r.time == 0.0);
			CHECK(r.contact.touching);
		}
	}
	// Invalid input: a clear failure, not a NaN.
	{
		const Move ma{Vec2(0, 0), Vec2(1, 0)}, mb{Vec2(5, 0), Vec2(-1, 0)};
		const TimeOfImpactResult neg = TimeOfImpact(*a, ma.ToMotion(), *b, mb.ToMotion(), -1.0);
		CHECK_FALSE(Succeeded(neg));
		CHECK(std::string(neg.failure).find("tMax") != std::string::npos);
		Motion bad = ma.ToMotion();
		bad.velocity.x = std::nan("");
		const TimeOfImpactResult nan = TimeOfImpact(*a, bad, *b, mb.ToMotion(), 1.0);
		CHECK_FALSE(Succeeded(nan));
		CHECK(std::string(nan.failure).size() > 0);
	}
}

TEST_CASE("time of impact: no contact is solved while the bounding circles are apart")
{
	// Found by the solver fuzzer: a bare user star (level by a root search per evaluation,
	// declared convex though it is not, so every contact falls back to the min–max solver) racing
	// away from an ellipse. Conservative advancement doubled its step with the growing gap and
	// solved a contact at every step: the 200 steps took over two minutes. The bounding circles'
	// centres move on straight lines, so the search now starts where they first overlap and ends
	// where they part; this motion needs only the contact reported at tMax.
	int calls = 0;
	UserShapeDef star;
	star.name = "bare star";
	star.function = [&calls](Vec2 x, double L) {
		++calls;
		const double R = 2.0 * (1.0 + 0.9 * std::cos(8.0 * std::atan2(x.y, x.x) + 3.14159));
		const double rho = Length(x) / R;
		return rho * rho - L;
	};
	star.convex = star.smooth = true; // wrong on purpose
	star.lengthScale = 2.0;
	const ShapePtr a = MakeEllipse(0.05, 0.31), b = MakeUserShape(star);
	const Move ma{Vec2(-52.2, 40.2), Vec2(3e3, -4e3), 0.1, 5.0}, mb{Vec2(0.2, -52.4), Vec2(-2e3, 7e3), -0.8, -3.0};
	const double tMax = 1.7;
	calls = 0;
	(void)ComputeContact(*a, ma.ToMotion().At(tMax), *b, mb.ToMotion().At(tMax));
	const int oneContact = calls;
	calls = 0;
	const TimeOfImpactResult r = TimeOfImpact(*a, ma.ToMotion(), *b, mb.ToMotion(), tMax);
	REQUIRE(Succeeded(r));
	CHECK_FALSE(r.hit);
	CHECK(r.time == tMax);
	CHECK(r.iterations == 1);
	CHECK(calls == oneContact);

	// Circles passing 1.6 apart when their radii add to 1.5 are never solved in between either,
	// and when the circles do overlap for a while the search stays inside that window: the
	// head-on pair below meets at the closed-form time (|d + w t| = 1.5 at t = (20 - 1.5)/4).
	const auto c1 = MakeCircle(1.0), c2 = MakeCircle(0.5);
	const TimeOfImpactResult pass = TimeOfImpact(*c1, Move{Vec2(-1e3, 0), Vec2(2, 0)}.ToMotion(), *c2,
	                                             Move{Vec2(1e3, 1.6), Vec2(-2, 0)}.ToMotion(), 1e3);
	REQUIRE(Succeeded(pass));
	CHECK_FALSE(pass.hit);
	CHECK(pass.iterations == 1);
	const TimeOfImpactResult meet = TimeOfImpact(*c1, Move{Vec2(-10, 0), Vec2(2, 0)}.ToMotion(), *c2,
	                                             Move{Vec2(10, 0), Vec2(-2, 0)}.ToMotion(), 100.0);
	REQUIRE(Succeeded(meet));
	CHECK(meet.hit);
	CHECK(std::fabs(meet.time - 18.5 / 4.0) <= 1e-9 * 18.5 / 4.0);
	CHECK(meet.iterations <= 4);

	// A horizon far beyond the contact (the fuzzer's tMax of 1e291) changes nothing: the search
	// probes and brackets near the time reached, and the time is exact relative to itself.
	const TimeOfImpactResult far = TimeOfImpact(*c1, Move{Vec2(-10, 0), Vec2(2, 0)}.ToMotion(), *c2,
	                                            Move{Vec2(10, 0.3), Vec2(-2, 0)}.ToMotion(), 1e291);
	REQUIRE(Succeeded(far));
	CHECK(far.hit);
	const double tFar = (20.0 - std::sqrt(1.5 * 1.5 - 0.3 * 0.3)) / 4.0;
	CHECK(std::fabs(far.time - tFar) <= 1e-9 * tFar);

	// The same for a bare user disc, whose every level is a root search: the far horizon costs
	// no more shape calls than a near one (it once probed the poses at t = 1e282).
	UserShapeDef disc;
	disc.name = "bare disc";
	disc.function = [&calls](Vec2 x, double L) {
		++calls;
		return Length(x) - L;
	};
	disc.convex = disc.smooth = true;
	const ShapePtr d1 = MakeUserShape(disc);
	std::vector<double> times;
	std::vector<int> cost;
	for (const double horizon : {10.0, 1e291})
	{
		calls = 0;
		const TimeOfImpactResult rd = TimeOfImpact(*d1, Move{Vec2(-10, 0), Vec2(2, 0)}.ToMotion(), *c2,
		                                           Move{Vec2(10, 0.3), Vec2(-2, 0)}.ToMotion(), horizon);
		REQUIRE(Succeeded(rd));
		CHECK(rd.hit);
		times.push_back(rd.time);
		cost.push_back(calls);
	}
	CHECK(std::fabs(times[1] - tFar) <= 1e-8 * tFar);
	CHECK(cost[1] <= cost[0] + cost[0] / 2);
}

TEST_CASE("time of impact: ellipses translating and turning, against bisection on the Perram-Wertheim level")
{
	struct Row { double aA, bA, aB, bB; Move a, b; double tMax; };
	const Row rows[] = {
		// A translating toward a resting B.
		{2.0, 0.5, 1.0, 1.5, {Vec2(-5, 0.3), Vec2(3, 0.2), 0.3, 0.0}, {Vec2(2, -0.5), Vec2(0, 0), -0.4, 0.0}, 4.0},
		// Both moving, A also turning.
		{2.0, 0.5, 1.0, 1.5, {Vec2(-5, 0.3), Vec2(3, 0.2), 0.3, 1.2}, {Vec2(2, -0.5), Vec2(-0.5, 0.1), -0.4, -0.3}, 4.0},
		// Thin ellipses (aspect 40), A turning into B.
		{4.0, 0.1, 3.0, 0.15, {Vec2(0, 0), Vec2(0, 0), 0.0, 2.0}, {Vec2(1.0, 2.5), Vec2(0, -0.3), 0.1, 0.0}, 2.0},
	};
	for (const Row& row : rows)
	{
		const auto a = MakeEllipse(row.aA, row.bA), b = MakeEllipse(row.aB, row.bB);
		auto touching = [&](LD t) {
			return ref::PerramWertheim(ref::QuadOf(row.aA, row.bA, row.a.At(t)), ref::QuadOf(row.aB, row.bB, row.b.At(t))).level <= 1.0L;
		};
		const LD want = FirstContact(touching, row.tMax, 400);
		REQUIRE(want > 0);
		const TimeOfImpactResult r = TimeOfImpact(*a, row.a.ToMotion(), *b, row.b.ToMotion(), row.tMax);
		CheckHit(r, want, 1e-9, "ellipses");
	}
}

TEST_CASE("time of impact: rotating superellipses, against stepping and bisection on an independent touching test")
{
	struct Row { double a[2], b[2], n[2], m[2]; Move ma, mb; double tMax; };
	const Row rows[] = {
		// A spinning in place, B approaching and turning (the paper's kind; its parameters are missing).
		{{1.5, 1.0}, {0.6, 1.0}, {4.0, 8.0}, {6.0, 8.0}, {Vec2(0, 0), Vec2(0, 0), 0.2, 3.0}, {Vec2(3.5, 0.5), Vec2(-1, 0), 0.0, -1.0}, 3.0},
		// Figure-1 superellipses (n = 6, m = 8, a = 2, b = 4) closing in on each other.
		{{2.0, 2.0}, {4.0, 4.0}, {6.0, 6.0}, {8.0, 8.0}, {Vec2(0, 0), Vec2(1, 0.5), kPi / 4, 0.5}, {Vec2(12, 3), Vec2(-2, 0), -0.5, -0.8}, 4.0},
	};
	for (const Row& row : rows)
	{
		const auto a = MakeSuperellipse(row.a[0], row.b[0], row.n[0], row.m[0]);
		const auto b = MakeSuperellipse(row.a[1], row.b[1], row.n[1], row.m[1]);
		const SurfaceTouch touch(ref::RefShape::Super(row.a[0], row.b[0], row.n[0], row.m[0]),
		                         ref::RefShape::Super(row.a[1], row.b[1], row.n[1], row.m[1]), 1024);
		const LD want = FirstContact([&](LD t) { return touch(row.ma.At(t), row.mb.At(t)); }, row.tMax, 200);
		REQUIRE(want > 0);
		const TimeOfImpactResult r = TimeOfImpact(*a, row.ma.ToMotion(), *b, row.mb.ToMotion(), row.tMax);
		CheckHit(r, want, 1e-9, "superellipses");
	}
}

TEST_CASE("time of impact: hearts, against stepping and bisection on a dense-sample touching test")
{
	struct Row { double alphaA, alphaB; Move ma, mb; double tMax; };
	const Row rows[] = {
		// A heart sliding and turning into a resting one.
		{1.0, 0.6, {Vec2(-3, 0), Vec2(2, 0), 0.0, 1.5}, {Vec2(1, 0.4), Vec2(0, 0), 2.0, 0.0}, 3.0},
		// A small heart dropping into the notch of a big one (the cleft: non-convex contact).
		{0.05, 1.0, {Vec2(0.02, 2.0), Vec2(0, -1), 0.1, 0.0}, {Vec2(0, 0), Vec2(0, 0), 0.0, 0.0}, 2.0},
		// Both moving and turning.
		{0.8, 1.2, {Vec2(-2.5, 1.5), Vec2(1, -0.5), 1.0, -1.0}, {Vec2(2, -1), Vec2(-1, 0.4), -0.5, 0.7}, 4.0},
	};
	for (const Row& row : rows)
	{
		const auto a = MakeHeart(row.alphaA), b = MakeHeart(row.alphaB);
		const SurfaceTouch touch(ref::RefShape::Heart(row.alphaA), ref::RefShape::Heart(row.alphaB), 8192);
		const LD want = FirstContact([&](LD t) { return touch(row.ma.At(t), row.mb.At(t)); }, row.tMax, 300);
		REQUIRE(want > 0);
		const TimeOfImpactResult r = TimeOfImpact(*a, row.ma.ToMotion(), *b, row.mb.ToMotion(), row.tMax);
		CheckHit(r, want, 1e-8, "hearts");
	}
}

// BuildContactManifold: faces touching faces get two points, as Box2D's boxes do; curved
// contacts and tilted faces one.
//
// Reference: the faces of superellipses |x/a|^n + |y/b|^n ≤ 1 (n > 2) in closed form, in long
// double and without the library's surface queries. A side's flattest point is its axis point
// (the curvature vanishes there), and its face is the arc within the tolerance of the tangent
// there: the bottom face of an unrotated particle is the arc with y ≤ −(b − tol), whose ends are
// x = ±a·(1 − ((b − tol)/b)^n)^(1/n); its surface is y = ±b·(1 − |x/a|^n)^(1/n). A point's
// separation is its height above the lower particle's face plane, as Box2D measures a box's
// points against its reference face. Tolerance: 1e-9 of the size (the faces' ends are found to
// 1e-10 rad).
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

const double kTol = 0.0025; // the fixtures' default patch tolerance, 0.5 b2_linearSlop

// The half-width of a superellipse's face across its semi-axis `b` (the other semi-axis a).
LD FaceHalfWidth(LD a, LD b, LD n)
{
	return a * std::pow(1.0L - std::pow((b - kTol) / b, n), 1.0L / n);
}

// The height of the top surface of the unrotated superellipse at the origin, at x.
LD TopHeight(LD a, LD b, LD n, LD x)
{
	return b * std::pow(1.0L - std::pow(std::fabs(x / a), n), 1.0L / n);
}

// A surface point of the superellipse at `pose` from its body coordinates' x on its bottom.
Vec2 BottomPoint(const Pose& pose, LD a, LD b, LD n, LD x)
{
	const LD y = -TopHeight(a, b, n, x);
	const LD c = std::cos(LD(pose.q.Angle())), s = std::sin(LD(pose.q.Angle()));
	return Vec2(double(pose.p.x + c * x - s * y), double(pose.p.y + s * x + c * y));
}

// The manifold's points are `ends` (world, in either order), each with its height above A's face
// plane y = bA as its separation (A unrotated at the origin; the normal is +y).
void CheckFaceEnds(const ContactManifold& m, const std::vector<Vec2>& ends, LD bA)
{
	REQUIRE(ends.size() == 2);
	REQUIRE(m.count == 2);
	CHECK(std::fabs(m.normal.x) < 1e-12);
	CHECK(m.normal.y == doctest::Approx(1.0).epsilon(1e-12));
	CHECK(std::fabs(m.pointA.y - double(bA)) < 1e-12);
	const bool straight = std::fabs(m.points[0].pointB.x - ends[0].x) < std::fabs(m.points[0].pointB.x - ends[1].x);
	for (int k = 0; k < 2; ++k)
	{
		const Vec2 e = ends[straight ? k : 1 - k];
		CAPTURE(k);
		CHECK(Distance(m.points[k].pointB, e) < 1e-9);
		CHECK(std::fabs(m.points[k].separation - double(e.y - bA)) < 1e-9);
		CHECK(m.points[k].separation <= 0.0);
	}
	CHECK(m.points[0].id != m.points[1].id);
}
} // namespace

TEST_CASE("BuildContactManifold: a block lying on a face stands on its own face's ends, with and without the cache")
{
	// B (1 × 0.625, n = 4) sinks 4e-3 into the top face of A (3 × 1, n = 4), tilted by 1e-3 rad
	// and more, rolling by 2.5e-5 rad and sliding 1e-3 per step: a settling pile's motion. Its
	// face is its own, so its ends are the same body points at every step, at depths that differ
	// by the tilt (1.4 mm at the last step, where the higher end lies 0.8 mm below A's face).
	const ShapePtr a = MakeSuperellipse(3.0, 1.0, 4.0, 4.0);
	const ShapePtr b = MakeSuperellipse(1.0, 0.625, 4.0, 4.0);
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const LD half = FaceHalfWidth(1.0L, 0.625L, 4.0L);
	ManifoldCache cache;
	for (int step = 0; step < 40; ++step)
	{
		CAPTURE(step);
		const double tilt = 0.001 + 2.5e-5 * step;
		const Pose pb(Vec2(0.2 + 1e-3 * step, 1.0 + 0.625 - 4e-3), tilt);
		const ContactResult c = ComputeContact(*a, pa, *b, pb);
		REQUIRE(c.Ok());
		const ManifoldSide sa{a.get(), pa}, sb{b.get(), pb};
		const std::vector<Vec2> ends{BottomPoint(pb, 1.0L, 0.625L, 4.0L, -half), BottomPoint(pb, 1.0L, 0.625L, 4.0L, half)};
		CheckFaceEnds(BuildContactManifold(c, sa, sb, kTol, 0.0, 0.0, &cache), ends, 1.0L);
		CheckFaceEnds(BuildContactManifold(c, sa, sb, kTol, 0.0), ends, 1.0L); // no cache: the search from scratch
	}
	CHECK(cache.validA);
	CHECK(cache.validB);
	// The faces kept are the axis points' (B's bottom, A's top) and their ends.
	CHECK(std::fabs(std::remainder(cache.faceB[0] + 0.5 * kPi, 2.0 * kPi)) < 1e-6);
	CHECK(std::fabs(std::remainder(cache.faceA[0] - 0.5 * kPi, 2.0 * kPi)) < 1e-6);
}

TEST_CASE("BuildContactManifold: a stale or broken cache is searched anew")
{
	const ShapePtr a = MakeSuperellipse(3.0, 1.0, 4.0, 4.0);
	const ShapePtr b = MakeSuperellipse(1.0, 0.625, 4.0, 4.0);
	const Pose pa(Vec2(0.0, 0.0), 0.0), pb(Vec2(0.25, 1.0 + 0.625 - 4e-3), 0.003);
	const ContactResult c = ComputeContact(*a, pa, *b, pb);
	REQUIRE(c.Ok());
	const ManifoldSide sa{a.get(), pa}, sb{b.get(), pb};
	const LD half = FaceHalfWidth(1.0L, 0.625L, 4.0L);
	const std::vector<Vec2> ends{BottomPoint(pb, 1.0L, 0.625L, 4.0L, -half), BottomPoint(pb, 1.0L, 0.625L, 4.0L, half)};
	// Faces that do not hold the contact (other sides, none at all, reversed ends) and values
	// that are not finite.
	const double tried[][3] = {{0.0, -0.3, 0.3},       {kPi, 2.8, 3.5},        {0.5 * kPi, 2.0, 1.0},
	                           {-0.5 * kPi, -1.0, -2.0}, {std::nan(""), -4.0, 4.0}, {0.0, -INFINITY, INFINITY}};
	int cases = 0;
	for (const auto& faceA : tried)
		for (const auto& faceB : tried)
		{
			ManifoldCache cache;
			for (int k = 0; k < 3; ++k)
			{
				cache.faceA[k] = faceA[k];
				cache.faceB[k] = faceB[k];
			}
			cache.validA = cache.validB = true;
			CAPTURE(cases);
			CheckFaceEnds(BuildContactManifold(c, sa, sb, kTol, 0.0, 0.0, &cache), ends, 1.0L);
			++cases;
		}
	CHECK(cases == 36);
}

TEST_CASE("BuildContactManifold: blocks offset by half their width, as in a pyramid, touch on two points")
{
	// Two n = 8 superellipses 1 × 1, B above A offset by 0.5625 (Box2D's pyramid), overlapping by
	// the slop where their shoulders meet. The faces' overlap runs from B's face's left end to A's
	// face's right end: 0.1 wide, each end B's surface with its gap to A's.
	const ShapePtr s = MakeSuperellipse(0.5, 0.5, 8.0, 8.0);
	const LD half = FaceHalfWidth(0.5L, 0.5L, 8.0L), offset = 0.5625L;
	const LD touching = 2.0L * TopHeight(0.5L, 0.5L, 8.0L, 0.5L * offset);
	const Pose pa(Vec2(0.0, 0.0), 0.0), pb(Vec2(double(offset), double(touching - 0.005L)), 0.0);
	const ContactResult c = ComputeContact(*s, pa, *s, pb);
	REQUIRE(c.Ok());
	// (The contact normal the solver gives is tilted by 0.018 rad at the shoulders: not the faces'.)
	CHECK(std::fabs(c.normal.x) > 0.01);
	const ManifoldSide sa{s.get(), pa}, sb{s.get(), pb};
	const std::vector<Vec2> ends{BottomPoint(pb, 0.5L, 0.5L, 8.0L, -half), BottomPoint(pb, 0.5L, 0.5L, 8.0L, half - offset)};
	CHECK(double(half - (offset - half)) == doctest::Approx(0.1047).epsilon(1e-3));
	CheckFaceEnds(BuildContactManifold(c, sa, sb, kTol, 0.0), ends, 0.5L);
	// A minimum width above the overlap leaves the contact's own point.
	const ContactManifold one = BuildContactManifold(c, sa, sb, kTol, 0.2);
	REQUIRE(one.count == 1);
	CHECK(one.points[0].pointB.x == c.pointB.x);
	CHECK(one.normal.x == c.normal.x);
}

TEST_CASE("BuildContactManifold: a tilted face stands on its lower end; one barely touching on the contact point")
{
	const ShapePtr a = MakeSuperellipse(3.0, 1.0, 4.0, 4.0);
	const ShapePtr b = MakeSuperellipse(1.0, 0.625, 4.0, 4.0);
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const LD half = FaceHalfWidth(1.0L, 0.625L, 4.0L);
	// Tilted by 0.02 rad, B's face ends lie 14 mm apart in height: the higher one lifts off.
	const Pose tilted(Vec2(0.1, 1.0 + 0.625 - 4e-3), 0.02);
	const ContactResult c = ComputeContact(*a, pa, *b, tilted);
	REQUIRE(c.Ok());
	const ContactManifold m = BuildContactManifold(c, ManifoldSide{a.get(), pa}, ManifoldSide{b.get(), tilted}, kTol, 0.0);
	REQUIRE(m.count == 1);
	const Vec2 lower = BottomPoint(tilted, 1.0L, 0.625L, 4.0L, -half); // (turned counter-clockwise: the left end is lower)
	CHECK(std::fabs(m.points[0].pointB.x - lower.x) < 1e-9);
	CHECK(m.points[0].separation == doctest::Approx(lower.y - 1.0).epsilon(1e-9));
	CHECK(m.points[0].separation < 0.0);
	// Lying flat and sunk by 1 mm, less than the tolerance: both face ends lie above A's face,
	// and the manifold is the contact's own point.
	const Pose flat(Vec2(0.1, 1.0 + 0.625 - 1e-3), 0.0);
	const ContactResult d = ComputeContact(*a, pa, *b, flat);
	REQUIRE(d.Ok());
	const ContactManifold single = BuildContactManifold(d, ManifoldSide{a.get(), pa}, ManifoldSide{b.get(), flat}, kTol, 0.0);
	REQUIRE(single.count == 1);
	CHECK(single.points[0].pointB.x == d.pointB.x);
	CHECK(single.points[0].pointB.y == d.pointB.y);
	CHECK(single.points[0].separation == doctest::Approx(d.separation).epsilon(1e-12));
}

TEST_CASE("BuildContactManifold: curved contacts keep one point; a needle lying on a floor has a face")
{
	// A floor segment as A (Box2D's edge: a face both ways), particles resting on it by 3e-3.
	const Vec2 floor[2] = {Vec2(-10.0, 0.0), Vec2(10.0, 0.0)};
	ManifoldSide sa;
	sa.vertices = floor;
	sa.count = 2;
	auto onFloor = [&](const ShapePtr& shape, double height, double angle) {
		const Pose pb(Vec2(0.3, height - 3e-3), angle);
		ContactResult c;
		c.status = SolveStatus::converged;
		c.normal = Vec2(0.0, 1.0);
		c.pointB = WorldSupport(*shape, pb, Vec2(0.0, -1.0));
		c.pointA = Vec2(c.pointB.x, 0.0);
		c.separation = c.pointB.y;
		return BuildContactManifold(c, sa, ManifoldSide{shape.get(), pb}, kTol, 0.0);
	};
	CHECK(onFloor(MakeCircle(0.4), 0.4, 0.7).count == 1);
	CHECK(onFloor(MakeEllipse(0.5, 0.3), 0.3, 0.0).count == 1);  // κR = 0.6 at its flattest
	CHECK(onFloor(MakeEllipse(3.0, 1.0), 1.0, 0.0).count == 1);  // κR = 0.33
	CHECK(onFloor(MakeEllipse(12.0, 1.0), 1.0, 0.0).count == 2); // κR = 0.083: flat
	CHECK(onFloor(MakeSuperellipse(0.5, 0.3, 4.0, 4.0), 0.3, 0.0).count == 2);
	// Two ellipses crest on crest, and circles: one point.
	const ShapePtr e = MakeEllipse(0.5, 0.3), circle = MakeCircle(0.4);
	for (const ShapePtr& s : {e, circle})
	{
		const double h = s->Support(Vec2(0.0, 1.0)).y;
		const Pose pa(Vec2(0.0, 0.0), 0.0), pb(Vec2(0.05, 2.0 * h - 3e-3), 0.0);
		const ContactResult c = ComputeContact(*s, pa, *s, pb);
		REQUIRE(c.Ok());
		CHECK(BuildContactManifold(c, ManifoldSide{s.get(), pa}, ManifoldSide{s.get(), pb}, kTol, 0.0).count == 1);
	}
}

TEST_CASE("BuildContactManifold: a heart upside down on a floor stands on both lobes")
{
	// The heart's lobes, upside down, are its body frame's highest points either side of the
	// axis: y = r(θ) sin θ at its largest over θ in (0, π/2), r(θ) the surface's radius from the
	// heart's polynomial (x² + y² − α)³ = x² y³ (bisection in long double), and its mirror image.
	const double alpha = 0.2;
	auto radius = [&](LD theta) {
		LD lo = 0.0L, hi = 3.0L * std::sqrt(LD(alpha));
		for (int it = 0; it < 200; ++it)
		{
			const LD r = 0.5L * (lo + hi), x = r * std::cos(theta), y = r * std::sin(theta);
			const LD w = x * x + y * y - alpha;
			(w * w * w - x * x * y * y * y <= 0.0L ? lo : hi) = r;
		}
		return lo;
	};
	LD a = 0.01L, b = 0.5L * kPi; // golden-section search for the largest r sin θ
	for (int it = 0; it < 200; ++it)
	{
		const LD m1 = a + 0.382L * (b - a), m2 = a + 0.618L * (b - a);
		if (radius(m1) * std::sin(m1) < radius(m2) * std::sin(m2))
			a = m1;
		else
			b = m2;
	}
	const LD top = 0.5L * (a + b), xTop = radius(top) * std::cos(top), yTop = radius(top) * std::sin(top);
	const ShapePtr heart = MakeHeart(alpha);
	const Pose pose(Vec2(0.3, double(yTop) - 3e-3), kPi); // both lobes 3 mm below the floor's line
	const Vec2 floor[2] = {Vec2(-5.0, 0.0), Vec2(5.0, 0.0)};
	const ContactResult c = ComputePolygonContact(*heart, pose, floor, 2, Pose());
	REQUIRE(c.Ok());
	ManifoldSide sa;
	sa.vertices = floor;
	sa.count = 2;
	const ContactManifold m = BuildContactManifold(FlipContact(c), sa, ManifoldSide{heart.get(), pose}, kTol, 0.0);
	REQUIRE(m.count == 2);
	CHECK(m.normal.y == doctest::Approx(1.0).epsilon(1e-12));
	// (The lobes' ends in order along the floor's tangent, −x: the right one first.)
	const Vec2 ends[2] = {Vec2(0.3 + double(xTop), -3e-3), Vec2(0.3 - double(xTop), -3e-3)};
	for (int k = 0; k < 2; ++k)
	{
		CAPTURE(k);
		CHECK(m.points[k].id == k);
		CHECK(std::fabs(m.points[k].pointB.x - ends[k].x) < 1e-6); // (the lobe is flat there: x to √ of the depth's tolerance)
		CHECK(std::fabs(m.points[k].pointB.y - ends[k].y) < 1e-9);
		CHECK(m.points[k].separation == doctest::Approx(-3e-3).epsilon(1e-6));
	}
	// Lifted so that one lobe alone touches (tilted), the manifold is that lobe's point.
	const Pose tilted(Vec2(0.3, double(yTop) - 3e-3), kPi + 0.02);
	const ContactResult d = ComputePolygonContact(*heart, tilted, floor, 2, Pose());
	REQUIRE(d.Ok());
	const ContactManifold one = BuildContactManifold(FlipContact(d), sa, ManifoldSide{heart.get(), tilted}, kTol, 0.0);
	REQUIRE(one.count == 1);
	CHECK(one.points[0].separation == doctest::Approx(d.separation).epsilon(1e-6));
}

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
#include "contact/OverlapParts.h"

#include <algorithm>
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

// The pose p moved by up to `amp` (m and rad) at a test's step `step`: a fixed sequence of
// jitters in [−1, 1] times amp, for its position's two coordinates and its angle.
Pose Jittered(const Pose& p, int step, double amp)
{
	auto jitter = [](int k) {
		const double x = std::sin(k * 12.9898) * 43758.5453;
		return 2.0 * (x - std::floor(x)) - 1.0;
	};
	return Pose(p.p + amp * Vec2(jitter(3 * step + 1), jitter(3 * step + 2)), p.q.Angle() + amp * jitter(3 * step + 3));
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

TEST_CASE("BuildContactManifold: a superellipse's face is the shape's own, the same from every contact on it")
{
	// Blocks at different places and tilts on A's top face, each contact with a fresh cache: the
	// face kept is A's top face, the same angles to the bit whichever contact point found it
	// (a search from each contact point finds the flattest point to 1e-8 rad only), and its ends
	// those of the closed form (CheckFaceEnds, through B's).
	const ShapePtr a = MakeSuperellipse(3.0, 1.0, 4.0, 4.0);
	const ShapePtr b = MakeSuperellipse(1.0, 0.625, 4.0, 4.0);
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const LD half = FaceHalfWidth(1.0L, 0.625L, 4.0L);
	double first[3] = {0.0, 0.0, 0.0};
	for (int k = 0; k < 6; ++k)
	{
		CAPTURE(k);
		const Pose pb(Vec2(-0.5 + 0.2 * k, 1.0 + 0.625 - 4e-3), 0.0007 * (k - 2));
		const ContactResult c = ComputeContact(*a, pa, *b, pb);
		REQUIRE(c.Ok());
		const ManifoldSide sa{a.get(), pa}, sb{b.get(), pb};
		ManifoldCache cache;
		const std::vector<Vec2> ends{BottomPoint(pb, 1.0L, 0.625L, 4.0L, -half), BottomPoint(pb, 1.0L, 0.625L, 4.0L, half)};
		CheckFaceEnds(BuildContactManifold(c, sa, sb, kTol, 0.0, 0.0, &cache), ends, 1.0L);
		REQUIRE(cache.validA);
		CHECK(std::fabs(cache.faceA[0] - 0.5 * kPi) < 1e-6);
		if (k == 0)
			std::copy(cache.faceA, cache.faceA + 3, first);
		for (int j = 0; j < 3; ++j)
			CHECK(cache.faceA[j] == first[j]);
	}
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

TEST_CASE("BuildContactManifold: a contact point that leaves its face by less than the tolerance keeps the two points")
{
	// Two blocks n = 4, 1 × 0.6 (the game bucket's), B on A's top face tilted by 0.024 rad
	// (its left end lower) and sunk by 5 mm, sliding right by 0.5 mm a step until the faces
	// overlap by 1.5 cm. From an overlap of about 4 cm the contact point lies past the end of B's
	// face, and a manifold built afresh at each step falls to one point; one built with the last
	// step's cache keeps B's face while the contact point lies within twice the tolerance of its
	// plane, and so its two points: B's face's left end and B's surface above A's face's right end.
	const ShapePtr s = MakeSuperellipse(0.5, 0.3, 4.0, 4.0);
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const LD half = FaceHalfWidth(0.5L, 0.3L, 4.0L);
	const double bA = 0.3; // A's face plane y = bA (its flattest point is the axis point)
	ManifoldCache cache;
	int fresh = 0, steps = 0;
	for (double dx = 0.30; dx <= 0.405; dx += 0.0005, ++steps)
	{
		CAPTURE(dx);
		const Pose pb(Vec2(dx, 0.6 - 0.005), 0.024);
		const ContactResult c = ComputeContact(*s, pa, *s, pb);
		REQUIRE(c.Ok());
		const ManifoldSide sa{s.get(), pa}, sb{s.get(), pb};
		fresh += BuildContactManifold(c, sa, sb, kTol, 0.0).count == 2;
		const ContactManifold m = BuildContactManifold(c, sa, sb, kTol, 0.0, 0.0, &cache);
		REQUIRE(m.count == 2);
		CHECK(std::fabs(m.normal.x) < 1e-12);
		// (Ids follow the tangent Perp(n), which runs towards −x here.)
		const Vec2 left = BottomPoint(pb, 0.5L, 0.3L, 4.0L, -half);
		CHECK(std::fabs(m.points[0].pointB.x - double(half)) < 1e-9);
		CHECK(Distance(m.points[1].pointB, left) < 1e-9);
		CHECK(m.points[0].id == 0);
		CHECK(m.points[1].id == 1);
		for (int k = 0; k < 2; ++k)
		{
			CHECK(m.points[k].separation == doctest::Approx(m.points[k].pointB.y - bA).epsilon(1e-9));
			CHECK(m.points[k].separation < 0.0);
		}
	}
	// Afresh, two points up to an overlap of about 4 cm, then one over the last 2.8 cm of the slide.
	CHECK(fresh > steps / 2);
	CHECK(steps - fresh >= 50);
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

namespace
{
// `shape` at `pose` against a floor segment from (−5, 0) to (5, 0) as A (Box2D's edge, whose skin
// is `radii`), the contact (ComputePolygonContact, flipped to the floor's side) in `contact`.
ContactManifold OnFloorSegment(const Shape& shape, const Pose& pose, double radii = 0.0, ContactResult* contact = nullptr)
{
	const Vec2 floor[2] = {Vec2(-5.0, 0.0), Vec2(5.0, 0.0)};
	const ContactResult c = FlipContact(ComputePolygonContact(shape, pose, floor, 2, Pose()));
	REQUIRE(c.Ok());
	if (contact)
		*contact = c;
	ManifoldSide sa;
	sa.vertices = floor;
	sa.count = 2;
	return BuildContactManifold(c, sa, ManifoldSide{&shape, pose}, kTol, 0.0, radii);
}
} // namespace

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
	const ContactManifold m = OnFloorSegment(*heart, pose);
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
	ContactResult d;
	const ContactManifold one = OnFloorSegment(*heart, tilted, 0.0, &d);
	REQUIRE(one.count == 1);
	CHECK(one.points[0].separation == doctest::Approx(d.separation).epsilon(1e-6));
}

namespace
{
// The heart (x² + y² − α)³ ≤ x² y³ independently of the library: its polynomial's sign, and its
// surface along rays from its origin (it is star-shaped about it) by bisection in long double.
bool InsideHeart(LD alpha, LD x, LD y)
{
	const LD w = x * x + y * y - alpha;
	return w * w * w - x * x * y * y * y < 0.0L;
}

LD HeartRadius(LD alpha, LD theta)
{
	LD lo = 0.0L, hi = 3.0L * std::sqrt(alpha);
	for (int it = 0; it < 80; ++it)
	{
		const LD r = 0.5L * (lo + hi);
		(InsideHeart(alpha, r * std::cos(theta), r * std::sin(theta)) ? lo : hi) = r;
	}
	return lo;
}

struct WorldPoint
{
	LD x, y;
};

// The heart's surface at `pose`, at n polar angles evenly spaced (world).
std::vector<WorldPoint> HeartOutline(LD alpha, const Pose& pose, int n)
{
	std::vector<WorldPoint> out;
	const LD c = std::cos(LD(pose.q.Angle())), s = std::sin(LD(pose.q.Angle()));
	for (int i = 0; i < n; ++i)
	{
		const LD theta = 2.0L * LD(kPi) * i / n, r = HeartRadius(alpha, theta);
		const LD x = r * std::cos(theta), y = r * std::sin(theta);
		out.push_back({pose.p.x + c * x - s * y, pose.p.y + s * x + c * y});
	}
	return out;
}

// One part of the overlap of B's outline with A (A at the origin, unrotated), on one side of
// A's axis: the x range of B's outline inside A there, and the depth, the largest distance from
// one of those points to A's outline (brute force over both outlines).
struct PartReference
{
	int points = 0;
	LD xMin = 1e9L, xMax = -1e9L, depth = 0.0L;
};

PartReference OverlapOnSide(LD alpha, const std::vector<WorldPoint>& outlineA, const std::vector<WorldPoint>& outlineB, int side)
{
	PartReference r;
	for (const WorldPoint& q : outlineB)
	{
		if ((q.x > 0.0L ? 1 : -1) != side || !InsideHeart(alpha, q.x, q.y))
			continue;
		++r.points;
		r.xMin = std::min(r.xMin, q.x);
		r.xMax = std::max(r.xMax, q.x);
		LD nearest = 1e9L;
		for (const WorldPoint& p : outlineA)
			nearest = std::min(nearest, std::hypot(p.x - q.x, p.y - q.y));
		r.depth = std::max(r.depth, nearest);
	}
	return r;
}
} // namespace

TEST_CASE("BuildContactManifold: two hearts lobe on lobe touch at both parts of their overlap, ids following the parts")
{
	// Heart B upside down on heart A, lobe on lobe, 2.5 mm deep: the overlap has two parts, one
	// either side of A's axis, and the contact (the deeper part) is one of them. The manifold
	// holds both, each point in its part (B's outline inside A over the part's x range, from the
	// brute force, widened by 1 mm) with the part's depth as its separation (within 3 %: the
	// depth along the common normal differs from the distance by the cosine, 1 − 1e-5 here).
	// Tilting B the other way makes the other part the deeper, and the contact's; each point's
	// id stays with its part; a part that comes apart drops its point, and the other keeps its id.
	const LD alpha = 0.2L;
	const ShapePtr heart = MakeHeart(double(alpha));
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const double top = heart->Support(Vec2(0.0, 1.0)).y; // (checked below against the outline)
	const std::vector<WorldPoint> outlineA = HeartOutline(alpha, pa, 20000);
	LD highest = -1.0L;
	for (const WorldPoint& p : outlineA)
		highest = std::max(highest, p.y);
	REQUIRE(std::fabs(double(highest) - top) < 1e-6);
	ManifoldCache cache;
	int idOfSide[2] = {-1, -1}; // the ids of the left (x < 0) and right parts
	struct Step
	{
		double dx, tilt;
		bool bothTouch;
	};
	const Step steps[] = {{0.002, 0.002, true}, {0.0025, -0.002, true}, {0.003, -0.002, true}, {0.003, -0.03, false}, {0.002, 0.002, true}};
	for (const Step& s : steps)
	{
		CAPTURE(s.dx);
		CAPTURE(s.tilt);
		const Pose pb(Vec2(s.dx, 2.0 * top - 0.0025), kPi + s.tilt);
		const ContactResult c = ComputeContact(*heart, pa, *heart, pb);
		REQUIRE(c.Ok());
		const ContactManifold m = BuildContactManifold(c, ManifoldSide{heart.get(), pa}, ManifoldSide{heart.get(), pb}, kTol, 0.0, 0.0, &cache);
		const std::vector<WorldPoint> outlineB = HeartOutline(alpha, pb, 20000);
		const PartReference parts[2] = {OverlapOnSide(alpha, outlineA, outlineB, -1), OverlapOnSide(alpha, outlineA, outlineB, 1)};
		REQUIRE(parts[1].points > 0);
		CHECK((parts[0].points > 0) == s.bothTouch);
		REQUIRE(m.count == (s.bothTouch ? 2 : 1));
		CHECK(m.normal.y > std::cos(0.02));
		bool seen[2] = {false, false};
		for (int k = 0; k < m.count; ++k)
		{
			CAPTURE(k);
			const int side = m.points[k].pointB.x > 0.0 ? 1 : 0;
			CHECK(!seen[side]);
			seen[side] = true;
			const PartReference& r = parts[side];
			CHECK(m.points[k].pointB.x >= double(r.xMin) - 1e-3);
			CHECK(m.points[k].pointB.x <= double(r.xMax) + 1e-3);
			CHECK(m.points[k].separation == doctest::Approx(-double(r.depth)).epsilon(0.03));
			if (idOfSide[side] >= 0)
				CHECK(m.points[k].id == idOfSide[side]);
			idOfSide[side] = m.points[k].id;
		}
		if (!s.bothTouch)
			idOfSide[0] = -1; // (a part that comes back takes an id of its own)
		if (m.count == 2)
			CHECK(m.points[0].id != m.points[1].id);
	}
}

TEST_CASE("BuildContactManifold: a heart's lobes within a chain link's skin both touch, the higher one too")
{
	// Box2D's edges carry a 1 cm skin (the radii): an upside-down heart tilted on a floor, its
	// lobes' lowest points 3 and about 4.6 mm above the floor's line, touches on both lobes,
	// each at its lowest point (the brute-force outline's lowest point either side of the heart's
	// axis) with its height less the skin as its separation.
	const LD alpha = 0.2L;
	const ShapePtr heart = MakeHeart(double(alpha));
	const double radii = 0.01, tilt = 0.0027;
	const Pose pose0(Vec2(0.0, 0.0), kPi + tilt);
	const std::vector<WorldPoint> outline0 = HeartOutline(alpha, pose0, 40000);
	LD lowest = 1e9L;
	for (const WorldPoint& p : outline0)
		lowest = std::min(lowest, p.y);
	const Pose pose(Vec2(0.1, 0.003 - double(lowest)), kPi + tilt);
	const std::vector<WorldPoint> outline = HeartOutline(alpha, pose, 40000);
	WorldPoint low[2] = {{0.0L, 1e9L}, {0.0L, 1e9L}}; // left and right of the heart's axis
	for (const WorldPoint& p : outline)
	{
		const int side = p.x > LD(pose.p.x) ? 1 : 0;
		if (p.y < low[side].y)
			low[side] = p;
	}
	REQUIRE(double(std::min(low[0].y, low[1].y)) == doctest::Approx(0.003).epsilon(1e-6));
	REQUIRE(double(std::max(low[0].y, low[1].y)) > 0.004);
	REQUIRE(double(std::max(low[0].y, low[1].y)) < radii);
	const ContactManifold m = OnFloorSegment(*heart, pose, radii);
	REQUIRE(m.count == 2);
	for (int k = 0; k < 2; ++k)
	{
		CAPTURE(k);
		const WorldPoint& r = low[m.points[k].pointB.x > pose.p.x ? 1 : 0];
		CHECK(std::fabs(m.points[k].pointB.x - double(r.x)) < 1e-4); // (the lobe is flat there)
		CHECK(m.points[k].separation == doctest::Approx(double(r.y) - radii).epsilon(1e-5));
	}
	CHECK((m.points[0].pointB.x > pose.p.x) != (m.points[1].pointB.x > pose.p.x));
}

TEST_CASE("BuildContactManifold: two hearts overlapping in three parts keep one pair of them while the pose jitters")
{
	// Two hearts lobe along lobe in a settled bucket pile (b2a_demo_game, seed 5 at 10.2 s),
	// overlapping in three parts 6 to 12 mm deep, two with about the same normal and one 55
	// degrees from it; B jittered by up to 1 mm and 1 mrad at each of 60 steps. The parts keep
	// their depths within a factor of two, so the manifold keeps the pair it took: its normal
	// never turns by more than 0.1 rad from one step to the next. Built afresh at each step it
	// takes whichever pair the contact and the deepest part name, and turns by 0.5 rad at half of
	// the steps. (When the cache found its parts by the manifold's points, which are moved along
	// the normal by up to 0.3 m here, it turned at 10 steps.)
	const ShapePtr h = MakeHeart(0.2);
	Pose pa, pb;
	pa.p = Vec2(-7.3026604652404785, 4.4931292533874512);
	pa.q.c = 0.22687190081934536;
	pa.q.s = -0.97392460725592978;
	pb.p = Vec2(-6.2415404319763184, 5.0509800910949707);
	pb.q.c = -0.23751451115152436;
	pb.q.s = 0.97138399049626734;
	OverlapPart parts[4];
	REQUIRE(OverlapParts(*h, pa, *h, pb, true, parts, 4) == 3);
	WarmStart warm;
	ManifoldCache cache;
	Vec2 last, lastFresh;
	int turns = 0, freshTurns = 0;
	for (int step = 0; step < 60; ++step)
	{
		CAPTURE(step);
		const Pose q = Jittered(pb, step, 1e-3);
		const ContactResult c = ComputeContact(*h, pa, *h, q, MethodChoice::automatic, SolverOptions{}, &warm);
		REQUIRE(c.Ok());
		const ManifoldSide sa{h.get(), pa}, sb{h.get(), q};
		const ContactManifold m = BuildContactManifold(c, sa, sb, kTol, 0.0, 0.0, &cache);
		const ContactManifold fresh = BuildContactManifold(c, sa, sb, kTol, 0.0);
		REQUIRE(m.count == 2);
		turns += step > 0 && Distance(m.normal, last) > 0.1;
		freshTurns += step > 0 && Distance(fresh.normal, lastFresh) > 0.1;
		last = m.normal;
		lastFresh = fresh.normal;
	}
	CHECK(turns == 0);
	CHECK(freshTurns >= 20);
}

TEST_CASE("BuildContactManifold: a heart on a block's face and corner keeps the two parts whichever the contact finds")
{
	// A heart (A) against a block n = 4, 1 × 0.6 (B) in a 20-particle mixed pile (b2a_demo_game's
	// bucket 3 m wide, seed 1 at 13.8 s): one lobe on the block's end face, the heart overlapping
	// the block's corner too, the two about equally deep (9.7 and 9.3 mm). The block jittered by
	// up to 1 mm and 1 mrad at each of 60 steps; the scaling-factor contact lies now at the face,
	// now at the corner. The manifold, built from the block's side as the adapter builds it, has
	// the two parts at every step and its normal never turns by more than 0.1 rad. (Taking the
	// lobe on the face alone where the contact lay there, it had one point at 46 steps and turned
	// by 0.54 rad at 26.)
	const ShapePtr h = MakeHeart(0.2), block = MakeSuperellipse(0.5, 0.3, 4.0, 4.0);
	Pose pa, pb;
	pa.p = Vec2(-0.05677013099193573, 1.6568324565887451);
	pa.q.c = 0.45530689520086787;
	pa.q.s = 0.89033456137709599;
	pb.p = Vec2(-1.0003961324691772, 2.0721228122711182);
	pb.q.c = -0.99995133055933294;
	pb.q.s = -0.0098659268505010469;
	WarmStart warm;
	ManifoldCache cache;
	Vec2 last;
	int turns = 0, atFace = 0;
	for (int step = 0; step < 60; ++step)
	{
		CAPTURE(step);
		const Pose q = Jittered(pb, step, 1e-3);
		const ContactResult c = ComputeContact(*h, pa, *block, q, MethodChoice::automatic, SolverOptions{}, &warm);
		REQUIRE(c.Ok());
		const ContactResult fromBlock = FlipContact(c);
		atFace += std::fabs(fromBlock.normal.y) < 0.1; // the end face's normal is ±x
		const ContactManifold m = BuildContactManifold(fromBlock, ManifoldSide{block.get(), q}, ManifoldSide{h.get(), pa}, kTol, 0.0, 0.0, &cache);
		REQUIRE(m.count == 2);
		turns += step > 0 && Distance(m.normal, last) > 0.1;
		last = m.normal;
	}
	// Both minima were found.
	CHECK(atFace > 10);
	CHECK(atFace < 50);
	CHECK(turns == 0);
}

TEST_CASE("BuildContactManifold: a heart's tip wedged against another keeps two parts and a normal that turns with the poses")
{
	// Heart A's tip pokes 3 mm into heart B beside a second part of their overlap 6 cm away (the
	// wedge of a settled pile). B slides by 4 mm and turns by 4 mrad in 200 steps. The tip part's
	// normal from B's surface inside A is A's level gradient at a corner of A, which turns over
	// across A's axis: given that, the part came and went and the normal turned by up to 0.31 rad
	// a step (9.9 rad in all) with 37 one-point manifolds. Each part's normal now leans to the
	// side that is smooth there, so the manifold keeps both parts at every step and its normal
	// turns by a few times the pose change over the parts' distance, except once, where the tip
	// part first shows in B's surface inside A (found before from A's tip inside B, with the same
	// normal to 1.2 degrees and twice the depth, which weighs the common normal).
	const double alpha = 0.2;
	const ShapePtr heart = MakeHeart(alpha);
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const double r = 0.99268, phi = 3.9601, theta = 5.7476; // (found by a search over poses 3 mm deep)
	const Vec2 centre = r * Vec2(std::cos(phi), std::sin(phi));
	ManifoldCache cache;
	constexpr int kSteps = 200;
	const double span = 0.004;
	Vec2 last;
	std::vector<double> turns;
	int twoParts = 0;
	for (int i = 0; i <= kSteps; ++i)
	{
		CAPTURE(i);
		const double s = double(i) / kSteps - 0.5;
		const Pose pb(centre + Vec2(span * s, 0.0), theta + span * s);
		const ContactResult c = ComputeContact(*heart, pa, *heart, pb);
		REQUIRE(c.Ok());
		const ContactManifold m = BuildContactManifold(c, ManifoldSide{heart.get(), pa}, ManifoldSide{heart.get(), pb}, kTol, 0.0, 0.0, &cache);
		twoParts += m.count == 2 ? 1 : 0;
		if (i > 0)
			turns.push_back(std::acos(std::clamp(Dot(m.normal, last), -1.0, 1.0)));
		last = m.normal;
	}
	std::sort(turns.begin(), turns.end());
	double total = 0.0;
	for (double t : turns)
		total += t;
	// The pose change a step, as a turn of the 6 cm between the parts.
	const double poseTurn = (span + heart->BoundingRadius() * span) / kSteps / 0.06;
	MESSAGE("two-part manifolds " << twoParts << " of " << kSteps + 1 << "; turns: largest " << turns.back() << ", next "
	                              << turns[turns.size() - 2] << ", total " << total << " rad; pose change " << poseTurn << " rad a step");
	CHECK(twoParts == kSteps + 1);
	CHECK(turns[turns.size() - 2] <= 20.0 * poseTurn);
	CHECK(turns.back() <= 0.1);
	CHECK(total <= 0.2);
}

namespace
{
// How far B's outline points on one side of A's axis (x < 0: side −1, else 1) must move along n
// before none lies inside A: steps of 0.1 mm out to 0.4 m, then bisection (brute force).
LD EscapeAlong(LD alpha, const std::vector<WorldPoint>& outlineB, int side, LD nx, LD ny)
{
	auto clear = [&](LD s) {
		for (const WorldPoint& q : outlineB)
			if ((q.x > 0.0L ? 1 : -1) == side && InsideHeart(alpha, q.x + s * nx, q.y + s * ny))
				return false;
		return true;
	};
	LD lo = 0.0L, hi = 0.0L;
	while (!clear(hi) && hi < 0.4L)
	{
		lo = hi;
		hi += 1e-4L;
	}
	for (int it = 0; it < 30; ++it)
		(clear(0.5L * (lo + hi)) ? hi : lo) = 0.5L * (lo + hi);
	return hi;
}
} // namespace

TEST_CASE("BuildContactManifold: two hearts deep lobe on lobe keep both parts, each as deep as moving out along the normal undoes")
{
	// Heart B upside down on heart A, lobe on lobe, 8 and 9 cm deep (beyond a tenth of the
	// heart's bounding radius, 6.5 cm): the overlap still has two parts, one either side of A's
	// axis (their depths from the brute force of two outlines). The manifold holds both, its
	// normal upright to 0.05 rad, each point in its part and as deep as the distance B's outline
	// there must move along the normal to leave A (brute force, within 3 %): what the position
	// solver must undo. (With the contact's point alone for overlaps this deep, the deepest part
	// by the scaling factor changed from pose to pose in a loaded pile, and the normal with it.)
	const LD alpha = 0.2L;
	const ShapePtr heart = MakeHeart(double(alpha));
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const double top = heart->Support(Vec2(0.0, 1.0)).y;
	REQUIRE(0.08 > 0.1 * heart->BoundingRadius());
	const std::vector<WorldPoint> outlineA = HeartOutline(alpha, pa, 20000);
	for (double depth : {0.08, 0.09})
	{
		CAPTURE(depth);
		const Pose pb(Vec2(0.003, 2.0 * top - depth), kPi + 0.002);
		const ContactResult c = ComputeContact(*heart, pa, *heart, pb);
		REQUIRE(c.Ok());
		ManifoldCache cache;
		const ContactManifold m = BuildContactManifold(c, ManifoldSide{heart.get(), pa}, ManifoldSide{heart.get(), pb}, kTol, 0.0, 0.0, &cache);
		const std::vector<WorldPoint> outlineB = HeartOutline(alpha, pb, 20000);
		const PartReference parts[2] = {OverlapOnSide(alpha, outlineA, outlineB, -1), OverlapOnSide(alpha, outlineA, outlineB, 1)};
		REQUIRE(parts[0].points > 0);
		REQUIRE(parts[1].points > 0);
		CHECK(parts[0].depth > 0.1L * LD(heart->BoundingRadius()));
		CHECK(parts[1].depth > 0.1L * LD(heart->BoundingRadius()));
		REQUIRE(m.count == 2);
		CHECK(m.normal.y > std::cos(0.05));
		bool seen[2] = {false, false};
		for (int k = 0; k < 2; ++k)
		{
			CAPTURE(k);
			const int side = m.points[k].pointB.x > 0.0 ? 1 : 0;
			CHECK(!seen[side]);
			seen[side] = true;
			const PartReference& r = parts[side];
			CHECK(m.points[k].pointB.x >= double(r.xMin) - 1e-3);
			CHECK(m.points[k].pointB.x <= double(r.xMax) + 1e-3);
			const LD escape = EscapeAlong(alpha, outlineB, side == 1 ? 1 : -1, LD(m.normal.x), LD(m.normal.y));
			MESSAGE("depth " << depth << " side " << side << ": separation " << m.points[k].separation << ", part depth "
			                 << double(r.depth) << ", escape along the normal " << double(escape));
			CHECK(m.points[k].separation == doctest::Approx(-double(escape)).epsilon(0.03));
		}
	}
}

TEST_CASE("BuildContactManifold: deep parts off centre keep their ids while the hearts slide")
{
	// Heart B upside down on heart A, 6 cm deep and 10 cm to the side, sliding sideways by 1 mm a
	// step for 10 steps: the overlap has two parts, either side of A's axis (brute force of the
	// outlines), at every step, and each part's point keeps its id throughout. (The manifold's
	// points are the parts' points moved along the common normal onto their separations, here
	// some centimetres; matched by those, each step's parts lay farther than a tenth of the
	// heart from the last step's, and took new ids: 8 changes in these 10 steps.)
	const LD alpha = 0.2L;
	const ShapePtr heart = MakeHeart(double(alpha));
	const Pose pa(Vec2(0.0, 0.0), 0.0);
	const double top = heart->Support(Vec2(0.0, 1.0)).y;
	const std::vector<WorldPoint> outlineA = HeartOutline(alpha, pa, 20000);
	ManifoldCache cache;
	int idOfSide[2] = {-1, -1};
	for (int i = 0; i <= 10; ++i)
	{
		CAPTURE(i);
		const Pose pb(Vec2(0.1 + 0.001 * i, 2.0 * top - 0.06), kPi);
		const ContactResult c = ComputeContact(*heart, pa, *heart, pb);
		REQUIRE(c.Ok());
		const ContactManifold m = BuildContactManifold(c, ManifoldSide{heart.get(), pa}, ManifoldSide{heart.get(), pb}, kTol, 0.0, 0.0, &cache);
		const std::vector<WorldPoint> outlineB = HeartOutline(alpha, pb, 20000);
		const PartReference parts[2] = {OverlapOnSide(alpha, outlineA, outlineB, -1), OverlapOnSide(alpha, outlineA, outlineB, 1)};
		REQUIRE(parts[0].points > 0);
		REQUIRE(parts[1].points > 0);
		REQUIRE(m.count == 2);
		for (int k = 0; k < 2; ++k)
		{
			CAPTURE(k);
			// The point's side: the part whose x range (widened by 2 cm) holds it, and only one.
			const double x = m.points[k].pointB.x;
			const bool left = x >= double(parts[0].xMin) - 0.02 && x <= double(parts[0].xMax) + 0.02;
			const bool right = x >= double(parts[1].xMin) - 0.02 && x <= double(parts[1].xMax) + 0.02;
			REQUIRE(left != right);
			const int side = right ? 1 : 0;
			if (idOfSide[side] >= 0)
				CHECK(m.points[k].id == idOfSide[side]);
			idOfSide[side] = m.points[k].id;
		}
		CHECK(m.points[0].id != m.points[1].id);
	}
}

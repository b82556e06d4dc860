// FirstSurfaceCrossing on non-convex shapes: the bounded march (the heart steps over stretches
// its level bounds clear) against an independent brute force, and against the plain march of
// the same level function given as a user shape, which has no bounds.
//
// Reference: the first sign change of λ − α along the line on a grid of 20000 steps over the
// search length, then bisection in long double to the double's rounding. A crossing pair
// thinner than the grid step (1e-4 of the particle) would be missed by the reference; the
// random lines below make that unlikely, and the tolerance is far above the reference's error.
#include <doctest/doctest.h>

#include "TestSupport.h"
#include "contact/SurfaceCrossing.h"
#include "GeometryReference.h"

#include <b2analytic/b2analytic.h>

#include <cmath>
#include <limits>

using namespace b2a;
using namespace b2a::test;

namespace
{
// The reference crossing, or −1 where the grid sees none.
double BruteFirstCrossing(const Shape& s, const Pose& pose, Vec2 X, Vec2 dir, double sMax)
{
	const double own = s.SurfaceLevel();
	auto f = [&](long double t) { return s.Level(ToBody(pose, X + double(t) * dir)) - own; };
	const int steps = 20000;
	long double a = 0.0L;
	double fa = f(a);
	for (int k = 1; k <= steps; ++k)
	{
		long double b = sMax * (long double)k / steps;
		const double fb = f(b);
		if ((fb <= 0.0) != (fa <= 0.0))
		{
			for (int it = 0; it < 200 && b - a > 1e-18L * (1.0L + b); ++it)
			{
				const long double m = 0.5L * (a + b);
				if ((f(m) <= 0.0) == (fa <= 0.0))
					a = m;
				else
					b = m;
			}
			return double(0.5L * (a + b));
		}
		a = b;
		fa = fb;
	}
	return -1.0;
}
} // namespace

TEST_CASE("FirstSurfaceCrossing on hearts: the bounded march finds the brute-force first crossing, inside and outside")
{
	Random rng(43);
	for (double alpha : {0.4, 1.0, 3.0})
	{
		const auto heart = MakeHeart(alpha);
		const auto plain = MakeUserShape(UserHeartDef(alpha)); // same level, no bounds
		const double R = heart->BoundingRadius();
		int inside = 0, outside = 0, found = 0;
		for (int i = 0; i < 200; ++i)
		{
			const Pose pose(Vec2(rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)), rng.Angle());
			// Starts inside and outside the heart, near it and in its notch.
			const Vec2 X = pose.p + rng.Uniform(0.0, 1.5 * R) * Vec2(std::cos(rng.Angle()), std::sin(rng.Angle()));
			const double t = rng.Angle();
			const Vec2 dir = rng.LogUniform(0.3, 3.0) * Vec2(std::cos(t), std::sin(t));
			const double sMax = (Distance(X, pose.p) + 1.01 * R) / Length(dir);
			const double s = FirstSurfaceCrossing(*heart, pose, X, dir, sMax);
			const double ref = BruteFirstCrossing(*heart, pose, X, dir, sMax);
			const double plainS = FirstSurfaceCrossing(*plain, pose, X, dir, sMax);
			CAPTURE(alpha);
			CAPTURE(i);
			(heart->Level(ToBody(pose, X)) < alpha ? inside : outside)++;
			REQUIRE((s >= 0.0) == (ref >= 0.0));
			if (ref < 0.0)
				continue;
			++found;
			CHECK(std::fabs(s - ref) * Length(dir) <= 1e-10 * R);
			CHECK(std::fabs(heart->Level(ToBody(pose, X + s * dir)) - alpha) <= 1e-9 * alpha);
			REQUIRE(plainS >= 0.0);
			CHECK(std::fabs(plainS - s) * Length(dir) <= 1e-10 * R);
		}
		CHECK(inside > 40);
		CHECK(outside > 40);
		CHECK(found > 100);
	}
}

TEST_CASE("FirstSurfaceCrossing on hearts: a line clipping the tip finds the sliver the plain march steps over")
{
	// Near the tip (0, −1) of the α = 1 heart, at height δ above it, the heart is |x| ≤ (2δ)^{3/2}
	// about: a sliver 6e-3 wide for δ = 0.01 and 9e-4 for δ = 0.003, thinner than the plain
	// march's step.
	const auto heart = MakeHeart(1.0);
	const auto plain = MakeUserShape(UserHeartDef(1.0));
	for (double angle : {0.0, 0.7, -2.1})
	{
		const Pose pose(Vec2(0.3, -0.2), angle);
		for (double delta : {0.01, 0.003})
		{
			const Vec2 X = ToWorld(pose, Vec2(-2.0, -1.0 + delta));
			const Vec2 dir = Rotate(pose.q, Vec2(1.0, 0.0));
			const double s = FirstSurfaceCrossing(*heart, pose, X, dir, 4.0);
			const double ref = BruteFirstCrossing(*heart, pose, X, dir, 4.0);
			CAPTURE(angle);
			CAPTURE(delta);
			REQUIRE(ref > 0.0);
			CHECK(ref < 2.0); // the sliver, before the heart's axis
			CHECK(std::fabs(s - ref) <= 1e-10);
			// The same level without bounds steps over it and misses the heart (the documented
			// limit of the plain march: crossing pairs thinner than its step).
			const double plainS = FirstSurfaceCrossing(*plain, pose, X, dir, 4.0);
			CHECK((plainS < 0.0 || plainS > ref + 1e-3));
		}
	}
}

TEST_CASE("FirstSurfaceCrossing on hearts: a start all but on the surface finds its crossing to the point's rounding")
{
	// X a hair (1e-13 to 1e-8 of the size) off the surface, inside or outside, and the line
	// towards the surface along the normal, as a near-tangent contact's point asks: the root is
	// taken to a few roundings of |x| (not to 2 eps of its own tiny s, which the level's rounding
	// cannot resolve), and must still be that close to the reference crossing.
	Random rng(47);
	int checked = 0;
	for (double alpha : {0.4, 1.0, 3.0})
	{
		const auto heart = MakeHeart(alpha);
		const double R = heart->BoundingRadius();
		for (int i = 0; i < 100; ++i)
		{
			const Pose pose(Vec2(rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)), rng.Angle());
			const double theta = rng.Angle();
			if (heart->NearCorner(theta, 1e-3))
				continue;
			const Vec2 q = heart->SurfacePoint(theta, alpha);
			const Vec2 n = Normalize(heart->Gradient(q));
			const double side = i % 2 ? 1.0 : -1.0, delta = rng.LogUniform(1e-13, 1e-8) * R;
			const Vec2 X = ToWorld(pose, q + side * delta * n), dir = Rotate(pose.q, -side * n);
			const double sMax = (Distance(X, pose.p) + 1.01 * R) / Length(dir);
			const double s = FirstSurfaceCrossing(*heart, pose, X, dir, sMax);
			const double ref = BruteFirstCrossing(*heart, pose, X, dir, sMax);
			CAPTURE(alpha);
			CAPTURE(i);
			CAPTURE(delta);
			REQUIRE(ref >= 0.0);
			CHECK(std::fabs(s - ref) <= 2e-15 * (Length(X) + R));
			CHECK(std::fabs(s - delta) <= 1e-3 * delta + 2e-15 * (Length(X) + R)); // (the normal line: s ≈ δ)
			++checked;
		}
	}
	CHECK(checked > 250);
}

TEST_CASE("FirstSurfaceCrossing given the slope at its start: the brute-force first crossing, bracketed by curvature or marched")
{
	// The contact's search is given the level's slope at X along the line. Heading for the
	// surface where the heart bounds its curvature over the stretch ahead and the level is
	// convex there, the parabolas through X bracket the first crossing and Halley's steps
	// find it (CrossingByCurvature); elsewhere the march heads for where the level is
	// estimated to reach the surface. Without the slope (NaN) the march doubles its way. All
	// three against the reference: starts inside and outside, near the surface and across
	// the notch, along the gradient (the contact's line) or any way, in lengths of dir 0.3
	// to 3. (Of the 600 lines, the curvature's bracket decides 150.)
	Random rng(53);
	int guidedRight = 0, found = 0;
	for (double alpha : {0.4, 1.0, 3.0})
	{
		const auto heart = MakeHeart(alpha);
		const double R = heart->BoundingRadius();
		for (int i = 0; i < 200; ++i)
		{
			const Pose pose(Vec2(rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)), rng.Angle());
			const Vec2 X = pose.p + rng.Uniform(0.0, 1.5 * R) * Vec2(std::cos(rng.Angle()), std::sin(rng.Angle()));
			const Vec2 x = ToBody(pose, X);
			const double f0 = heart->Level(x) - alpha;
			// Towards the surface along the gradient (the contact's line) or any way at all.
			const double t = rng.Angle();
			const Vec2 gradient = heart->Gradient(x);
			const Vec2 along = i % 2 ? Vec2(std::cos(t), std::sin(t)) : (f0 < 0.0 ? 1.0 : -1.0) * Normalize(Rotate(pose.q, gradient));
			const Vec2 dir = rng.LogUniform(0.3, 3.0) * along;
			const double sMax = (Distance(X, pose.p) + 1.01 * R) / Length(dir);
			const double slope = Dot(gradient, InvRotate(pose.q, dir));
			const double ref = BruteFirstCrossing(*heart, pose, X, dir, sMax);
			CAPTURE(alpha);
			CAPTURE(i);
			for (const double given : {slope, std::numeric_limits<double>::quiet_NaN()})
			{
				CAPTURE(given);
				const double s = FirstSurfaceCrossingFrom(*heart, pose, X, dir, sMax, f0, given);
				REQUIRE((s >= 0.0) == (ref >= 0.0));
				if (ref < 0.0)
					continue;
				CHECK(std::fabs(s - ref) * Length(dir) <= 1e-10 * R);
				if (!std::isnan(given))
				{
					++found;
					// Where the level is quadratic along the line, the march's guess is close.
					const double level0 = f0 + alpha;
					const double est = -2.0 * level0 * (1.0 - std::sqrt(alpha / level0)) / slope;
					guidedRight += f0 * slope < 0.0 && std::fabs(est - ref) <= 0.25 * ref;
				}
			}
		}
	}
	CHECK(found > 300);
	CHECK(guidedRight > found / 2); // (361 of 502 guesses within a quarter)
}

TEST_CASE("FirstSurfaceCrossing: a direction that is not finite has no crossing, even from a point on the surface")
{
	// Reference: the documented answer −1 for "no crossing"; a NaN or infinite direction gives no
	// line to cross along.
	const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
	for (const ShapePtr& s : {ShapePtr(MakeHeart(1.0)), ShapePtr(MakeSuperellipse(1.0, 0.5, 4.0, 4.0))})
	{
		const Pose pose(Vec2(0.2, -0.1), 0.3);
		const Vec2 onSurface = ToWorld(pose, s->SurfacePoint(0.4));
		for (const Vec2 X : {pose.p, onSurface, pose.p + Vec2(3.0, 0.0)})
			for (const Vec2 dir : {Vec2(nan, 1.0), Vec2(inf, 0.0), Vec2(0.0, -inf)})
			{
				CAPTURE(s->Describe());
				CHECK(FirstSurfaceCrossing(*s, pose, X, dir, 4.0) == -1.0);
				CHECK(FirstSurfaceCrossingFrom(*s, pose, X, dir, 4.0, s->Level(ToBody(pose, X)) - s->SurfaceLevel(), 1.0) == -1.0);
			}
	}
}

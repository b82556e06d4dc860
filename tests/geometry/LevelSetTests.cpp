// Level sets of every shape kind: SurfacePoint / RadiusAt land on the requested level.
#include <doctest/doctest.h>

#include "GeometryReference.h"
#include "TestSupport.h"

#include <cmath>
#include <limits>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("level sets: Level(SurfacePoint(theta, L)) equals L for every shape kind")
{
	// 1e-12 relative: the radial solves are converged to a few ulps, and the level is
	// well-conditioned in the radius (relative level error ≈ p × relative radius error, p ≤ 60)
	// over each case's level range, 1e-3 to 1e3 (see HeartCase for why the heart's stops at 1e-3).
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		Random rng(7);
		for (int i = 0; i < 300; ++i)
		{
			const double theta = rng.Angle();
			const double L = i == 0 ? s.SurfaceLevel() : rng.LogUniform(c.levelLo, c.levelHi);
			CAPTURE(theta);
			CAPTURE(L);
			const Vec2 p = s.SurfacePoint(theta, L);
			REQUIRE(IsFinite(p));
			CHECK(RelativeError(s.Level(p), L) < 1e-12);
			CHECK(RelativeError(double(c.levelRef(p)), L) < 1e-12); // independent long-double level
			// The point is on the ray at angle θ, at distance RadiusAt.
			const Vec2 u(std::cos(theta), std::sin(theta));
			CHECK(std::fabs(Cross(u, p)) <= 1e-15 * Length(p));
			CHECK(Dot(u, p) > 0.0);
			CHECK(RelativeError(Length(p), s.RadiusAt(u, L)) < 1e-15);
		}
	}
}

TEST_CASE("level sets: the own surface is the level SurfaceLevel()")
{
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		for (int k = 0; k < 16; ++k)
		{
			const double theta = -kPi + 2.0 * kPi * (k + 0.3) / 16;
			const Vec2 p = s.SurfacePoint(theta);
			CHECK(Distance(p, s.SurfacePoint(theta, s.SurfaceLevel())) == 0.0);
			CHECK(RelativeError(double(c.levelRef(p)), s.SurfaceLevel()) < 1e-12);
		}
	}
}

TEST_CASE("level sets: the radius grows with the level along every ray (nested level sets)")
{
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		Random rng(8);
		for (int i = 0; i < 50; ++i)
		{
			const Vec2 u = Rotate(Rot(rng.Angle()), Vec2(1, 0));
			const double L1 = rng.LogUniform(c.levelLo, c.levelHi), L2 = L1 * 1.01;
			CHECK(s.RadiusAt(u, L1) < s.RadiusAt(u, L2));
			// Points strictly inside (outside) the level-L set along the ray lie below (above) L.
			const double R = s.RadiusAt(u, L1);
			CHECK(s.Level(0.99 * R * u) < L1);
			CHECK(s.Level(1.01 * R * u) > L1);
		}
	}
}

TEST_CASE("level sets: the heart's Levels, two points at a time, is Level bit for bit at every magnitude")
{
	// The heart's Levels evaluates pairs of points in SSE2 lanes. Reference: Level, one point at
	// a time, and the long-double level. Coordinates from 1e-150 to 1e150 (x² from 1e-300 to
	// 1e300: the cube root's range ends at 1e-290 and 1e290, past which a pair takes the scalar
	// path), both signs, and pairs with one lane on the axis, non-finite or out of range.
	const auto heart = MakeHeart(1.3);
	Random rng(12);
	std::vector<Vec2> points;
	for (int i = 0; i < 2000; ++i)
	{
		const double scale = rng.LogUniform(1e-150, 1e150);
		const double angle = rng.Angle();
		points.emplace_back(scale * std::cos(angle), scale * std::sin(angle));
	}
	const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
	for (const Vec2 odd : {Vec2(0.0, 0.7), Vec2(1e-160, 0.3), Vec2(1e160, 1.0), Vec2(inf, 1.0), Vec2(nan, 0.5), Vec2(0.2, nan)})
	{
		points.push_back(Vec2(0.4, -0.6)); // a pair: a plain point and the odd one, either order
		points.push_back(odd);
		points.push_back(odd);
		points.push_back(Vec2(-0.9, 0.1));
	}
	std::vector<double> out(points.size());
	heart->Levels(points.data(), int(points.size()), out.data());
	int compared = 0;
	for (size_t i = 0; i < points.size(); ++i)
	{
		CAPTURE(points[i].x);
		CAPTURE(points[i].y);
		const double level = heart->Level(points[i]);
		if (std::isnan(level))
		{
			CHECK(std::isnan(out[i]));
			continue;
		}
		CHECK(out[i] == level);
		const long double x = points[i].x, y = points[i].y;
		const long double ref = x * x + y * y - std::cbrt(x * x) * y;
		if (std::isfinite(double(ref)))
		{
			CHECK(std::fabs(out[i] - double(ref)) <= 1e-14 * (std::fabs(double(x * x + y * y)) + std::fabs(double(std::cbrt(x * x) * y))));
			++compared;
		}
	}
	CHECK(compared > 2000);
}

TEST_CASE("level sets: Levels answers Level for each point, bit for bit, for every shape kind")
{
	// The grid method scans its samples through Levels (the heart's own loop, the default's calls
	// of Level): the same values, so that a scan a run at a time finds the same minima. Points on
	// the axes (the heart's cusp term at x = 0) and at the centre included; each value also
	// agrees with the independent long-double level.
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		Random rng(11);
		std::vector<Vec2> points;
		for (int i = 0; i < 200; ++i)
		{
			const double r = s.BoundingRadius() * rng.Uniform(0.0, 2.0), angle = rng.Angle();
			points.emplace_back(r * std::cos(angle), r * std::sin(angle));
		}
		points.insert(points.end(), {Vec2(), Vec2(0.0, 0.5), Vec2(0.0, -0.5), Vec2(0.5, 0.0), Vec2(-0.5, 0.0)});
		std::vector<double> out(points.size() + 1, -1.0);
		s.Levels(points.data(), int(points.size()), out.data());
		for (size_t i = 0; i < points.size(); ++i)
		{
			CAPTURE(points[i].x);
			CAPTURE(points[i].y);
			CHECK(out[i] == s.Level(points[i]));
			CHECK(std::fabs(out[i] - double(c.levelRef(points[i]))) <= 1e-12 * std::max(1.0, std::fabs(out[i])));
		}
		CHECK(out.back() == -1.0); // nothing written beyond count
		s.Levels(points.data(), 0, out.data()); // none: nothing written, no crash
		CHECK(out[0] == s.Level(points[0]));
	}
}

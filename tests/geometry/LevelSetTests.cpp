// Level sets of every shape kind: SurfacePoint / RadiusAt land on the requested level.
#include <doctest/doctest.h>

#include "GeometryReference.h"

#include <cmath>

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

// Two circles against their closed forms, through every solver and every way to make a circle.
//
// Reference (exact, computed in long double from the double inputs): for circles of radii rA,
// rB at distance d, the level sets are concentric circles of radius r·√L, so
//   common level C = (d / (rA + rB))²,
//   common point X = cA + rA/(rA + rB)·(cB − cA) (it divides the centre segment in the ratio
//   of the radii), normal n = (cB − cA)/d, pointA = cA + rA·n, pointB = cB − rB·n,
//   separation d − rA − rB,
// and A's one-sided scale with B held at its surface is ((d − rB)/rA)².
//
// Tolerances: the closed-form path is a handful of double operations. The iterative solvers stop
// at rounding level, but they work with world coordinates: a point known to eps·|X| (|X| up to
// ~100 here) carries a relative error eps·|X|/r in the level of a circle of radius r (down to
// 0.01), i.e. up to ~2e-12 (measured: 7e-12 at worst). 1e-10 keeps a margin over that while any
// real fault (a wrong branch, a stalled or early-stopped iteration, a sample-spaced answer) is
// ≥ 1e-8.
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
struct CircleCase
{
	double rA, rB;
	Pose pa, pb;
};

struct CircleExpect
{
	LD d, C, sep, scaleA, scaleB;
	V X, n, pA, pB;
};

CircleExpect Expected(const CircleCase& c)
{
	CircleExpect e;
	const V ca = ref::FromVec(c.pa.p), cb = ref::FromVec(c.pb.p), dv = cb - ca;
	const LD rA = c.rA, rB = c.rB;
	e.d = ref::Len(dv);
	e.C = (e.d / (rA + rB)) * (e.d / (rA + rB));
	e.X = ca + (rA / (rA + rB)) * dv;
	e.n = (1.0L / e.d) * dv;
	e.pA = ca + rA * e.n;
	e.pB = cb - rB * e.n;
	e.sep = e.d - rA - rB;
	e.scaleA = ((e.d - rB) / rA) * ((e.d - rB) / rA);
	e.scaleB = ((e.d - rA) / rB) * ((e.d - rA) / rB);
	return e;
}

// Circle pairs: radii from 0.01 to 100, random centres and orientations (which must not matter),
// distances from deep overlap (one centre inside the other) through tangency (±1e-9) to far apart.
std::vector<CircleCase> Cases()
{
	Random rng(20240611);
	const double factors[] = {0.05, 0.3, 0.7, 0.999, 1.0 - 1e-9, 1.0 + 1e-9, 1.001, 1.5, 4.0, 30.0};
	std::vector<CircleCase> out;
	for (int k = 0; k < 6; ++k)
	{
		const double rA = rng.LogUniform(0.01, 100.0), rB = rng.LogUniform(0.01, 100.0);
		const Vec2 ca(rng.Uniform(-100.0, 100.0), rng.Uniform(-100.0, 100.0));
		for (double f : factors)
		{
			const double phi = rng.Angle(), d = f * (rA + rB);
			const Vec2 cb = ca + d * Vec2(std::cos(phi), std::sin(phi));
			out.push_back({rA, rB, Pose(ca, rng.Angle()), Pose(cb, rng.Angle())});
		}
	}
	return out;
}

constexpr double kTol = 1e-10; // see the header comment

// Relative error of a level and the error of a point relative to the pair's length scale.
double LevelErr(double got, LD want) { return double(std::fabs(LD(got) - want) / want); }
double PointErr(Vec2 got, V want, LD scale) { return double(ref::Dist(got, want) / scale); }
} // namespace

TEST_CASE("circles: every common-level solver gives C = (d/(rA+rB))^2 at the point dividing the centres in the ratio of the radii")
{
	auto check = [](const char* name, const LevelResult& r, const CircleExpect& e, LD scale) {
		INFO(std::string(name));
		REQUIRE(r.Ok());
		CHECK(LevelErr(r.level, e.C) <= kTol);
		CHECK(PointErr(r.point, e.X, scale) <= kTol);
		// The normal is ∇λA at the point: along the centre line.
		CHECK(PointErr(r.normal, e.n, 1.0L) <= kTol);
	};
	for (const CircleCase& c : Cases())
	{
		const auto a = MakeCircle(c.rA), b = MakeCircle(c.rB);
		const CircleExpect e = Expected(c);
		const LD scale = std::max(e.d, LD(c.rA + c.rB));
		INFO("rA=" << c.rA << " rB=" << c.rB << " d=" << double(e.d));
		const LevelResult automatic = SolveCommonLevel(*a, c.pa, *b, c.pb);
		CHECK(automatic.method == SolveMethod::closedForm);
		check("automatic", automatic, e, scale);
		check("SolveCommonLevelNewton", SolveCommonLevelNewton(*a, c.pa, *b, c.pb), e, scale);
		check("SolveCommonLevelMinMax", SolveCommonLevelMinMax(*a, c.pa, *b, c.pb), e, scale);
		check("SolveCommonLevelGrid", SolveCommonLevelGrid(*a, c.pa, *b, c.pb), e, scale);
		check("SolveCommonLevel(newton)", SolveCommonLevel(*a, c.pa, *b, c.pb, MethodChoice::newton), e, scale);
		check("SolveCommonLevel(grid)", SolveCommonLevel(*a, c.pa, *b, c.pb, MethodChoice::grid), e, scale);
	}
}

TEST_CASE("circles: the one-sided scale of A with B at its surface is ((d - rB)/rA)^2 (grid and Newton)")
{
	for (const CircleCase& c : Cases())
	{
		const auto a = MakeCircle(c.rA), b = MakeCircle(c.rB);
		const CircleExpect e = Expected(c);
		if (e.d <= c.rB * 1.01)
			continue; // A's centre inside (or on) B: the Newton start assumes an outside centre
		INFO("rA=" << c.rA << " rB=" << c.rB << " d=" << double(e.d));
		// The point is B's surface point nearest to A's centre.
		const V pointB = ref::FromVec(c.pb.p) - LD(c.rB) * e.n;
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::grid, MethodChoice::newton})
		{
			const LevelResult r = SolveScaleA(*a, c.pa, *b, c.pb, m);
			REQUIRE(r.Ok());
			CHECK(LevelErr(r.level, e.scaleA) <= kTol);
			CHECK(PointErr(r.point, pointB, e.d) <= kTol);
		}
	}
}

TEST_CASE("circles: ComputeContact gives the closed-form normal, points and separation d - rA - rB for every method")
{
	int touchingCount = 0, apartCount = 0;
	for (const CircleCase& c : Cases())
	{
		const auto a = MakeCircle(c.rA), b = MakeCircle(c.rB);
		const CircleExpect e = Expected(c);
		const LD scale = std::max(e.d, LD(c.rA + c.rB));
		// The grid's one-sided solves meet an internal tangency when a centre lies inside the other
		// circle; that case has its own test case below.
		const bool centreInside = e.d < std::max(c.rA, c.rB);
		INFO("rA=" << c.rA << " rB=" << c.rB << " d=" << double(e.d));
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::newton, MethodChoice::grid})
		{
			if (m == MethodChoice::grid && centreInside)
				continue;
			INFO("method " << int(m));
			const ContactResult r = ComputeContact(*a, c.pa, *b, c.pb, m);
			REQUIRE(r.Ok());
			CHECK(PointErr(r.normal, e.n, 1.0L) <= kTol);
			CHECK(PointErr(r.pointA, e.pA, scale) <= kTol);
			CHECK(PointErr(r.pointB, e.pB, scale) <= kTol);
			CHECK(std::fabs(LD(r.separation) - e.sep) <= kTol * scale);
			// The sign is decided when the gap is beyond rounding (all cases here: ≥ 1e-9 relative).
			CHECK(r.touching == (e.sep <= 0));
			CHECK(r.touching == (r.separation <= 0.0));
			if (m == MethodChoice::grid)
			{
				// The grid reports one of the two one-sided scales (the one it chose).
				const double errA = LevelErr(r.level, e.scaleA), errB = LevelErr(r.level, e.scaleB);
				CHECK(std::fmin(errA, errB) <= kTol);
			}
			else
			{
				CHECK(LevelErr(r.level, e.C) <= kTol);
			}
		}
		(e.sep <= 0 ? touchingCount : apartCount)++;
	}
	// The case list covers both sides of tangency.
	CHECK(touchingCount >= 20);
	CHECK(apartCount >= 20);
}

TEST_CASE("circles: grid contact with one centre inside the other circle keeps the centre-line normal")
{
	// When A's centre lies inside B, A rescaled onto B's surface touches it from the inside
	// (an internal tangency: ∇λA and ∇λB point the same way at the point). The contact must still
	// be the closed form: normal along the centre line, separation d − rA − rB.
	struct Row { double rA, rB; Vec2 ca, cb; };
	const Row rows[] = {
		{0.5, 3.0, {0.2, 0.1}, {0.0, 0.0}},  // A entirely inside B
		{1.0, 1.5, {0.0, 0.0}, {0.9, 0.4}},  // each centre inside the other
		{2.0, 0.7, {-1.0, 2.0}, {-0.2, 2.9}} // B's centre inside A
	};
	for (const Row& row : rows)
	{
		const auto a = MakeCircle(row.rA), b = MakeCircle(row.rB);
		const CircleCase c{row.rA, row.rB, Pose(row.ca, 0.3), Pose(row.cb, -1.1)};
		const CircleExpect e = Expected(c);
		INFO("rA=" << c.rA << " rB=" << c.rB << " d=" << double(e.d));
		const ContactResult r = ComputeContact(*a, c.pa, *b, c.pb, MethodChoice::grid);
		REQUIRE(r.Ok());
		CHECK(r.touching);
		CHECK(PointErr(r.normal, e.n, 1.0L) <= 1e-9);
		CHECK(std::fabs(LD(r.separation) - e.sep) <= 1e-9 * (c.rA + c.rB));
	}
}

TEST_CASE("circles made as ellipses, superellipses, zeta-forms and user shapes behave as circles")
{
	const double r1 = 0.75, r2 = 1.3;
	const CircleCase c{r1, r2, Pose(Vec2(0.4, -0.2), 0.7), Pose(Vec2(2.1, 1.0), -2.0)}; // d ≈ 2.08 ≥ r1 + r2: apart
	const CircleCase o{r1, r2, Pose(Vec2(0.4, -0.2), 0.7), Pose(Vec2(1.5, 0.6), -2.0)}; // d ≈ 1.36: overlapping
	// Every way to make a circle lands in the circle family (closed forms apply).
	CHECK(MakeEllipse(r1, r1)->Kind() == BuiltinKinds::circle);
	CHECK(MakeSuperellipse(r1, r1, 2.0, 2.0)->Kind() == BuiltinKinds::circle);
	CHECK(SuperellipseShape::FromZeta(r1, r1, 1.0)->Kind() == BuiltinKinds::circle);

	const std::vector<std::pair<const char*, ShapePtr>> asA = {
		{"MakeEllipse(r, r)", MakeEllipse(r1, r1)},
		{"MakeSuperellipse(r, r, 2, 2)", MakeSuperellipse(r1, r1, 2.0, 2.0)},
		{"FromZeta(r, r, 1)", SuperellipseShape::FromZeta(r1, r1, 1.0)},
		// A user shape is not in the circle family: the automatic path runs Newton on it.
		{"user circle", MakeUserCircle(r1)},
		// An ellipse that is a circle to 1e-12: family ellipse, Newton path; must be continuous
		// with the closed form (differences of order 1e-12).
		{"ellipse(r(1+1e-12), r)", MakeEllipse(r1 * (1.0 + 1e-12), r1)},
	};
	for (const CircleCase* cc : {&c, &o})
	{
		const CircleExpect e = Expected(*cc);
		const auto b = MakeCircle(r2);
		for (const auto& item : asA)
		{
			const auto& name = item.first;
			const auto& a = item.second;
			INFO(std::string(name) << (cc == &c ? " apart" : " overlapping"));
			const LevelResult level = SolveCommonLevel(*a, cc->pa, *b, cc->pb);
			REQUIRE(level.Ok());
			// 1e-11: the near-circle ellipse differs from the circle by 1e-12 in its axis.
			CHECK(LevelErr(level.level, e.C) <= 1e-11);
			CHECK(PointErr(level.point, e.X, e.d) <= 1e-11);
			for (bool swap : {false, true})
			{
				const ContactResult r = swap ? FlipContact(ComputeContact(*b, cc->pb, *a, cc->pa))
				                             : ComputeContact(*a, cc->pa, *b, cc->pb);
				REQUIRE(r.Ok());
				CHECK(PointErr(r.normal, e.n, 1.0L) <= 1e-11);
				CHECK(PointErr(r.pointA, e.pA, e.d) <= 1e-11);
				CHECK(PointErr(r.pointB, e.pB, e.d) <= 1e-11);
				CHECK(std::fabs(LD(r.separation) - e.sep) <= 1e-11 * e.d);
				CHECK(r.touching == (e.sep <= 0));
			}
		}
	}
}

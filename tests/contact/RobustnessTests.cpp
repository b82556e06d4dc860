// Robustness: coincident centres, identical particles, extreme sizes, large separations, deep
// overlap, and the statuses and failure strings.
//
// References: closed forms where the geometry gives one (coincident circles: depth rA + rB;
// coincident ellipses: the smallest support width, in long double), the long-double
// Perram–Wertheim level (ContactReference.h), the scale identity (scaling every length by s
// leaves every level unchanged and scales every point and separation by s), and mirror symmetry
// (a pair symmetric about the x axis has its contact normal along x).
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"
#include "ContactChecks.h"
#include "ContactPairs.h"
#include "ContactReference.h"

#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;
using ref::LD;
using ref::V;

namespace
{
bool Contains(const char* text, const char* word) { return std::string(text).find(word) != std::string::npos; }

// Smallest overlap depth of two ellipses with a common centre: min over unit n of the support
// widths h_A(n) + h_B(n), h(n) = √(nᵀ M⁻¹ n) = √((a·n·e₁)² + (b·n·e₂)²) in the body axes; a dense
// angle scan plus golden polishing in long double.
LD CoincidentEllipseDepth(LD aA, LD bA, LD thA, LD aB, LD bB, LD thB)
{
	auto width = [&](LD t) {
		auto h = [&](LD a, LD b, LD th) {
			const LD u = std::cos(t - th), v = std::sin(t - th);
			return std::sqrt(a * a * u * u + b * b * v * v);
		};
		return h(aA, bA, thA) + h(aB, bB, thB);
	};
	LD best = 1e30L, bestT = 0.0L;
	const int N = 4096;
	for (int k = 0; k < N; ++k)
	{
		const LD t = ref::kPiL * k / N, w = width(t);
		if (w < best) { best = w; bestT = t; }
	}
	return ref::Minimise1D(width, bestT - ref::kPiL / N, bestT + ref::kPiL / N).second;
}
} // namespace

TEST_CASE("coincident centres and identical particles: a finite overlap-axis contact with the closed-form depth")
{
	const Vec2 c(5.0, -3.0);
	// Circles: every axis is an axis of least overlap, the depth is rA + rB.
	{
		const auto a = MakeCircle(1.0), b = MakeCircle(2.0);
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::newton, MethodChoice::grid})
		{
			const ContactResult r = ComputeContact(*a, Pose(c, 0.3), *b, Pose(c, 1.1), m);
			REQUIRE(r.Ok());
			CHECK(r.method == SolveMethod::overlapAxis);
			CHECK(AllFinite(r));
			CHECK(r.touching);
			CHECK(std::fabs(r.separation + 3.0) <= 1e-12);
			CHECK(std::fabs(Length(r.normal) - 1.0) <= 1e-14);
			CHECK(std::fabs(Distance(r.pointA, c) - 1.0) <= 1e-12);
			CHECK(std::fabs(Distance(r.pointB, c) - 2.0) <= 1e-12);
		}
	}
	// Ellipses with a common centre: the depth is the smallest support width (identical particles
	// included: twice the minor semi-axis, across the minor axis).
	struct Row { double aA, bA, thA, aB, bB, thB; };
	for (const Row& row : {Row{2.0, 1.0, 0.3, 2.0, 1.0, 0.3}, Row{2.0, 1.0, 0.3, 1.5, 0.7, 1.0}, Row{3.0, 0.2, -1.0, 0.5, 2.5, 0.4}})
	{
		const auto a = MakeEllipse(row.aA, row.bA), b = MakeEllipse(row.aB, row.bB);
		const Pose pa(c, row.thA), pb(c, row.thB);
		const LD depth = CoincidentEllipseDepth(row.aA, row.bA, row.thA, row.aB, row.bB, row.thB);
		INFO("A=(" << row.aA << "," << row.bA << ") B=(" << row.aB << "," << row.bB << ")");
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::newton, MethodChoice::grid})
		{
			const ContactResult r = ComputeContact(*a, pa, *b, pb, m);
			REQUIRE(r.Ok());
			CHECK(AllFinite(r));
			CHECK(r.touching);
			// The library minimises the same width over the direction (Brent from 64 directions):
			// the minimum is quadratic, so its value is exact to ~1e-15.
			CHECK(std::fabs(LD(r.separation) + depth) <= 1e-9L);
			CHECK(std::fabs(RelativeLevel(*a, pa, r.pointA) - 1.0) <= 1e-9);
			CHECK(std::fabs(RelativeLevel(*b, pb, r.pointB) - 1.0) <= 1e-9);
		}
		if (row.aA == row.aB && row.thA == row.thB)
		{
			const ContactResult r = ComputeContact(*a, pa, *b, pb);
			CHECK(std::fabs(r.separation + 2.0 * row.bA) <= 1e-9);
			CHECK(std::fabs(Dot(r.normal, Rotate(pa.q, Vec2(1.0, 0.0)))) <= 1e-6); // across the minor axis
		}
	}
	// Every family, identical and coincident: finite, touching, points on the surfaces.
	for (const ShapePair& p : FamilyPairs())
	{
		INFO(p.name);
		for (const auto& item : {std::pair<ShapePtr, ShapePtr>{p.a, p.b}, {p.a, p.a}})
		{
			const auto& sa = item.first;
			const auto& sb = item.second;
			const ContactResult r = ComputeContact(*sa, Pose(c, 0.7), *sb, Pose(c, -0.4));
			REQUIRE(r.Ok());
			CHECK(AllFinite(r));
			CHECK(r.touching);
			CHECK(r.separation < 0.0);
			CHECK(std::fabs(Length(r.normal) - 1.0) <= 1e-14);
			CHECK(std::fabs(RelativeLevel(*sa, Pose(c, 0.7), r.pointA) - 1.0) <= 1e-9);
			CHECK(std::fabs(RelativeLevel(*sb, Pose(c, -0.4), r.pointB) - 1.0) <= 1e-9);
		}
	}
}

TEST_CASE("coincident centres: the level solvers fail with a reason, or answer with the centre as the common point")
{
	// With a common centre the common level is 0 (both levels vanish there) and the only point
	// where it is attained is that centre. A solver may decline ("coincident centres"), but an
	// answer it gives must be that point, with a unit normal, and no field may be NaN.
	const Vec2 c(5.0, 5.0);
	const auto a = MakeEllipse(2.0, 1.0), b = MakeEllipse(1.5, 0.7);
	const auto ca = MakeCircle(1.0), cb = MakeCircle(2.0);
	const Pose pa(c, 0.3), pb(c, 1.0);
	const std::pair<const char*, LevelResult> results[] = {
		{"newton", SolveCommonLevelNewton(*a, pa, *b, pb)},
		{"min-max", SolveCommonLevelMinMax(*a, pa, *b, pb)},
		{"automatic", SolveCommonLevel(*a, pa, *b, pb)},
		{"grid", SolveCommonLevelGrid(*a, pa, *b, pb)},
		{"circles automatic", SolveCommonLevel(*ca, pa, *cb, pb)},
		{"circles grid", SolveCommonLevel(*ca, pa, *cb, pb, MethodChoice::grid)},
	};
	for (const auto& item : results)
	{
		const auto& name = item.first;
		const auto& r = item.second;
		INFO(std::string(name) << ": " << std::string(StatusName(r.status)) << " " << std::string(MethodName(r.method)) << " '"
		                       << std::string(r.failure) << "'");
		CHECK(AllFinite(r));
		if (r.Ok())
		{
			CHECK(r.method != SolveMethod::none);
			CHECK(std::fabs(r.level) <= 1e-12);
			CHECK(MaxDiff(r.point, c) <= 1e-9);
			CHECK(std::fabs(Length(r.normal) - 1.0) <= 1e-12);
		}
		else
		{
			CHECK(Contains(r.failure, "coincident"));
		}
	}
}

TEST_CASE("extreme sizes: scaling every length by 1e-3 or 1e3 leaves levels unchanged and scales points and separations")
{
	// Identity: λ(x/s) for a shape scaled by s, so every level is unchanged and every point and
	// length scales by s. The solvers normalise the frame to the pair's size, so the results agree
	// to rounding (1e-10 relative).
	struct Made { ShapePtr a, b; };
	auto make = [](double s) {
		return Made{MakeSuperellipse(2.0 * s, 0.5 * s, 4.0, 6.0), MakeEllipse(1.0 * s, 0.8 * s)};
	};
	const Made unit = make(1.0);
	for (double dx : {1.5, 2.8, 4.0}) // overlapping, near, apart
	{
		const Pose pa(Vec2(0.3, -0.2), 0.4), pb(Vec2(0.3 + dx, 0.9), -1.2);
		const ContactResult base = ComputeContact(*unit.a, pa, *unit.b, pb);
		REQUIRE(base.Ok());
		for (double s : {1e-3, 1e3})
		{
			INFO("dx=" << dx << " s=" << s);
			const Made scaled = make(s);
			const Pose qa(s * pa.p, pa.q.Angle()), qb(s * pb.p, pb.q.Angle());
			for (MethodChoice m : {MethodChoice::automatic, MethodChoice::grid})
			{
				const ContactResult r0 = m == MethodChoice::automatic ? base : ComputeContact(*unit.a, pa, *unit.b, pb, m);
				const ContactResult r = ComputeContact(*scaled.a, qa, *scaled.b, qb, m);
				REQUIRE(r.Ok());
				CHECK(r.touching == r0.touching);
				CHECK(RelativeError(r.level, r0.level) <= 1e-10);
				CHECK(std::fabs(r.separation - s * r0.separation) <= 1e-10 * s);
				CHECK(MaxDiff(r.normal, r0.normal) <= 1e-10);
				CHECK(MaxDiff(r.pointA, s * r0.pointA) <= 1e-10 * s);
				CHECK(MaxDiff(r.pointB, s * r0.pointB) <= 1e-10 * s);
			}
		}
	}
}

TEST_CASE("extreme sizes: a 1e-3 particle against a 1e3 particle matches the long-double reference")
{
	// A tiny circle (1e-3) and a huge ellipse (1e3 × 300): apart, just touching, and with the
	// tiny one inside. Conditioning: the tiny level is evaluated at world coordinates ~1e3, so
	// rounding moves it by ~eps·1e3/1e-3 ≈ 2e-10 relative; 1e-8 leaves a margin.
	const auto tiny = MakeCircle(1e-3), huge = MakeEllipse(1e3, 300.0);
	const Pose ph(Vec2(0.0, 0.0), 0.25);
	const Vec2 up = Rotate(ph.q, Vec2(0.0, 1.0)); // the huge ellipse's minor axis direction
	for (double gap : {5e-3, 5e-4, -5e-4, -200.0})
	{
		// The tiny circle on the huge ellipse's minor axis, `gap` outside its surface.
		const Pose pt((300.0 + 1e-3 + gap) * up, 1.0);
		INFO("gap=" << gap);
		const ref::PwResult want = ref::PerramWertheim(ref::QuadOf(1e-3L, 1e-3L, ref::Of(pt)), ref::QuadOf(1e3L, 300.0L, ref::Of(ph)));
		for (bool swap : {false, true})
		{
			const LevelResult r = swap ? SolveCommonLevel(*huge, ph, *tiny, pt) : SolveCommonLevel(*tiny, pt, *huge, ph);
			REQUIRE(r.Ok());
			CHECK(double(std::fabs(LD(r.level) - want.level) / want.level) <= 1e-8);
			const ContactResult c = swap ? ComputeContact(*huge, ph, *tiny, pt) : ComputeContact(*tiny, pt, *huge, ph);
			REQUIRE(c.Ok());
			CHECK(AllFinite(c));
			CHECK(c.touching == (gap < 0.0));
			// The configuration is symmetric about the minor axis: the separation is the gap
			// (to 1e-10 of the coordinates' size 300), except when the tiny circle is deep inside,
			// where the contact along the axis has no preferred side.
			if (gap > -1.0)
				CHECK(std::fabs(c.separation - gap) <= 3e-8);
		}
	}
}

TEST_CASE("large separations: levels from 1e6 to 1e11 match the long-double reference, with finite contacts")
{
	// Ellipses of size ~1 at distances 2e3 to 1e6: C ≈ 1e6 to 2.5e11 (for ellipses C grows
	// exactly as the square of the distance along a fixed direction). The solvers normalise the
	// frame to the pair's size, so the level is still exact to rounding: 1e-10 relative. Newton
	// alone may decline far apart pairs (its steps are limited to half the pair's size), but the
	// automatic path and the grid must answer, and answer right.
	const auto a = MakeEllipse(1.0, 0.4), b = MakeEllipse(0.7, 1.3);
	for (double d : {2e3, 1e4, 1e6})
	{
		const Pose pa(Vec2(0.1, 0.2), 0.3), pb(Vec2(0.1, 0.2) + d * Vec2(std::cos(0.8), std::sin(0.8)), -0.9);
		const ref::Quad qa = ref::QuadOf(1.0L, 0.4L, ref::Of(pa)), qb = ref::QuadOf(0.7L, 1.3L, ref::Of(pb));
		const ref::EllipseContactRef want = ref::EllipseContact(qa, qb);
		INFO("d=" << d << " C_ref=" << double(want.level.level));
		CHECK(want.level.level > 0.2L * LD(d) * d);
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::grid, MethodChoice::newton})
		{
			INFO("method " << int(m));
			const LevelResult r = SolveCommonLevel(*a, pa, *b, pb, m);
			CHECK(AllFinite(r));
			if (m == MethodChoice::newton && !r.Ok())
			{
				CHECK(std::string(r.failure).size() > 0);
				continue;
			}
			REQUIRE(r.Ok());
			CHECK(double(std::fabs(LD(r.level) - want.level.level) / want.level.level) <= 1e-10);
			const ContactResult c = ComputeContact(*a, pa, *b, pb, m);
			REQUIRE(c.Ok());
			CHECK(AllFinite(c));
			CHECK_FALSE(c.touching);
			// The common-level contact is the reference construction (line or radial points); the
			// grid's one-sided contact is another construction, bounded by the centre distance.
			if (m != MethodChoice::grid)
				CHECK(double(std::fabs(LD(c.separation) - want.separation)) <= 1e-9 * d);
			CHECK(c.separation > 0.0);
			CHECK(c.separation <= d);
		}
	}
}

TEST_CASE("deep overlap: one centre inside the other, through the common level, against Perram-Wertheim")
{
	struct Row { double aA, bA, aB, bB; Vec2 pa, pb; double thA, thB; };
	const Row rows[] = {
		{0.5, 0.2, 3.0, 2.0, Vec2(0.3, 0.1), Vec2(0.0, 0.0), 0.4, -0.3}, // A entirely inside B
		{2.0, 0.5, 1.5, 1.0, Vec2(0.0, 0.0), Vec2(0.6, 0.2), 0.1, 1.2},  // each centre inside the other
		{4.0, 0.3, 0.4, 0.4, Vec2(0.0, 0.0), Vec2(3.0, 0.1), 0.0, 0.0},  // B's centre inside a thin A
	};
	for (const Row& row : rows)
	{
		const auto a = MakeEllipse(row.aA, row.bA), b = MakeEllipse(row.aB, row.bB);
		const Pose pa(row.pa, row.thA), pb(row.pb, row.thB);
		const ref::EllipseContactRef want = ref::EllipseContact(ref::QuadOf(row.aA, row.bA, ref::Of(pa)), ref::QuadOf(row.aB, row.bB, ref::Of(pb)));
		INFO("A=(" << row.aA << "," << row.bA << ") B=(" << row.aB << "," << row.bB << ") C_ref=" << double(want.level.level));
		CHECK(want.level.level < 1.0L);
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::newton})
		{
			const ContactResult c = ComputeContact(*a, pa, *b, pb, m);
			REQUIRE(c.Ok());
			CHECK(c.touching);
			CHECK(double(std::fabs(LD(c.level) - want.level.level) / want.level.level) <= 1e-10);
			CHECK(double(ref::Dist(c.normal, want.level.normal)) <= 1e-9);
			CHECK(double(std::fabs(LD(c.separation) - want.separation)) <= 1e-9);
		}
		const LevelResult g = SolveCommonLevelGrid(*a, pa, *b, pb);
		REQUIRE(g.Ok());
		CHECK(double(std::fabs(LD(g.level) - want.level.level) / want.level.level) <= 1e-10);
	}
}

TEST_CASE("deep overlap through the grid: a pair symmetric about the x axis gets the normal along x and depth 2a - d")
{
	// Two identical axis-aligned particles, B offset by d along +x: the configuration is symmetric
	// about the x axis, so the contact normal must be +x (from A to B), the points (a, 0) and
	// (d − a, 0), and the separation d − 2a, whatever the overlap. Shapes with corners take the
	// grid path automatically (n = 1.5); ellipses are sent through it explicitly.
	// For d < a each centre lies inside the other particle, and the one-sided grid solves meet an
	// internal tangency (both gradients point the same way at the point).
	const std::pair<const char*, ShapePtr> shapes[] = {{"superellipse n = 1.5", MakeSuperellipse(2.0, 1.0, 1.5, 1.5)},
	                                                  {"ellipse", MakeEllipse(2.0, 1.0)}};
	for (const auto& item : shapes)
	{
		const auto& name = item.first;
		const auto& s = item.second;
		for (double d : {0.3, 1.0, 1.9, 2.5, 3.5})
		{
			INFO(std::string(name) << " d=" << d);
			const Pose pa(Vec2(0.0, 0.0), 0.0), pb(Vec2(d, 0.0), 0.0);
			const ContactResult r = ComputeContact(*s, pa, *s, pb, MethodChoice::grid);
			REQUIRE(r.Ok());
			CHECK(r.touching);
			// 1e-6: at the axis points of an n = 1.5 superellipse the gradient has a |y|^{1/2}
			// singularity, so a point off the axis by rounding (~1e-15) tilts the normal by ~1e-8.
			// The internal-tangency failure is of order 1.
			CHECK(MaxDiff(r.normal, Vec2(1.0, 0.0)) <= 1e-6);
			CHECK(std::fabs(r.separation - (d - 4.0)) <= 1e-6);
			CHECK(MaxDiff(r.pointA, Vec2(2.0, 0.0)) <= 1e-6);
			CHECK(MaxDiff(r.pointB, Vec2(d - 2.0, 0.0)) <= 1e-6);
		}
	}
}

TEST_CASE("one-sided scale with A's centre inside B: the smallest level, through grid and Newton")
{
	// SolveScaleA is documented as the smallest level of A at which A touches B held at its
	// surface. With A's centre inside B, λA restricted to B's surface has a minimum and a maximum
	// (and the Lagrange system both as solutions); the answer must be the minimum. Reference: the
	// long-double brute-force minimum over B's surface (ContactReference.h, SurfaceMin).
	Random rng(9101);
	int cases = 0;
	for (int k = 0; k < 40 && cases < 16; ++k)
	{
		const double aA = rng.LogUniform(0.3, 2.0), bA = rng.LogUniform(0.3, 2.0);
		const double aB = rng.LogUniform(1.0, 4.0), bB = rng.LogUniform(0.5, 2.0);
		const Pose pb(Vec2(1.0, -2.0), rng.Angle());
		const Vec2 offset(0.4 * aB * rng.Uniform(-1.0, 1.0), 0.4 * bB * rng.Uniform(-1.0, 1.0));
		const Pose pa(ToWorld(pb, offset), rng.Angle());
		const auto a = MakeEllipse(aA, bA), b = MakeEllipse(aB, bB);
		REQUIRE(b->Level(ToBody(pb, pa.p)) < 1.0);
		++cases;
		const ref::SurfaceMinResult want = ref::SurfaceMin(ref::RefShape::Ellipse(aA, bA), ref::Of(pa), ref::RefShape::Ellipse(aB, bB),
		                                                   ref::Of(pb), 1.0L, 4096, 8);
		INFO("A=(" << aA << "," << bA << ") B=(" << aB << "," << bB << ") offset=(" << offset.x << "," << offset.y << ") ref=" << double(want.value));
		for (MethodChoice m : {MethodChoice::grid, MethodChoice::newton})
		{
			INFO("method " << int(m));
			const LevelResult r = SolveScaleA(*a, pa, *b, pb, m);
			if (m == MethodChoice::newton && !r.Ok())
				continue; // declining is acceptable; a wrong answer is not
			REQUIRE(r.Ok());
			CHECK(double(std::fabs(LD(r.level) - want.value) / want.value) <= 1e-10);
		}
	}
	CHECK(cases == 16);
}

TEST_CASE("statuses and failure strings are sensible")
{
	CHECK(std::string(StatusName(SolveStatus::converged)) == "converged");
	CHECK(std::string(StatusName(SolveStatus::convergedAfterFallback)) == "converged_after_fallback");
	CHECK(std::string(StatusName(SolveStatus::failed)) == "failed");
	CHECK(std::string(MethodName(SolveMethod::closedForm)) == "closed_form");
	CHECK(std::string(MethodName(SolveMethod::newton)) == "newton");
	CHECK(std::string(MethodName(SolveMethod::minMax)) == "min_max");
	CHECK(std::string(MethodName(SolveMethod::grid)) == "grid");
	CHECK(std::string(MethodName(SolveMethod::overlapAxis)) == "overlap_axis");
	CHECK(std::string(MethodName(SolveMethod::none)) == "none");

	const ShapePtr heart = MakeHeart(1.0), ellipse = MakeEllipse(1.0, 0.5), cornered = MakeSuperellipse(1.0, 1.0, 1.5, 3.0);
	const Pose pa(Vec2(0.0, 0.0), 0.0), pb(Vec2(2.5, 0.3), 0.4);
	// Newton needs smooth, strictly convex shapes.
	for (const LevelResult& r : {SolveCommonLevelNewton(*heart, pa, *ellipse, pb), SolveCommonLevelNewton(*cornered, pa, *ellipse, pb),
	                             SolveCommonLevel(*ellipse, pa, *heart, pb, MethodChoice::newton),
	                             SolveScaleA(*heart, pa, *ellipse, pb, MethodChoice::newton)})
	{
		CHECK_FALSE(r.Ok());
		CHECK(r.status == SolveStatus::failed);
		CHECK(Contains(r.failure, "smooth"));
		CHECK(AllFinite(r));
	}
	CHECK(Contains(SolveCommonLevelMinMax(*heart, pa, *ellipse, pb).failure, "smooth"));
	// The common level needs convex shapes, through the automatic path and from the grid solver
	// called directly (which once answered level 0 with a zero normal for an ellipse whose centre
	// lay inside a heart: the first pose below).
	const Pose inside(Vec2(0.1049, -0.1332), -2.6750), heartPose(Vec2(0.0, 0.0), -3.0921);
	for (const LevelResult& r : {SolveCommonLevel(*heart, pa, *ellipse, pb, MethodChoice::automatic),
	                             SolveCommonLevel(*heart, pa, *ellipse, pb, MethodChoice::grid), SolveCommonLevelGrid(*heart, pa, *ellipse, pb),
	                             SolveCommonLevelGrid(*ellipse, pa, *heart, pb), SolveCommonLevelGrid(*ellipse, inside, *heart, heartPose)})
	{
		CHECK_FALSE(r.Ok());
		CHECK(Contains(r.failure, "convex"));
		CHECK(AllFinite(r));
	}
	// The refusal comes before any solve: the warm start it was given stays as it was.
	for (MethodChoice m : {MethodChoice::automatic, MethodChoice::grid})
	{
		WarmStart warm;
		REQUIRE(SolveCommonLevel(*ellipse, pa, *ellipse, pb, MethodChoice::automatic, {}, &warm).Ok());
		REQUIRE(warm.valid);
		const WarmStart before = warm;
		CHECK_FALSE(SolveCommonLevel(*heart, pa, *ellipse, pb, m, {}, &warm).Ok());
		CHECK(warm.valid);
		CHECK(warm.multiplier == before.multiplier);
	}
	// ComputeContact with Newton forced on a heart: failed, with the reason, and no NaN.
	const ContactResult c = ComputeContact(*heart, pa, *ellipse, pb, MethodChoice::newton);
	CHECK_FALSE(c.Ok());
	CHECK(Contains(c.failure, "smooth"));
	CHECK(AllFinite(c));
	// Valid convex input: Ok, and successes carry an empty failure string.
	const LevelResult ok = SolveCommonLevel(*ellipse, pa, *cornered, pb);
	CHECK(ok.Ok());
	CHECK(std::string(ok.failure).empty());
	CHECK(ComputeContact(*ellipse, pa, *heart, pb).Ok());
}

TEST_CASE("fuzz: no NaN in any field for random pairs of every family, sizes 1e-3 to 1e3, coincident to far apart")
{
	Random rng(9201);
	auto randomShape = [&](double size) -> ShapePtr {
		switch (int(rng.Uniform(0.0, 6.0)))
		{
		case 0: return MakeCircle(size);
		case 1: return MakeEllipse(size, size * rng.LogUniform(0.01, 1.0));
		case 2: return MakeSuperellipse(size, size * rng.LogUniform(0.1, 1.0), rng.Uniform(2.0, 12.0), rng.Uniform(2.0, 12.0));
		case 3: return MakeSuperellipse(size, size * rng.LogUniform(0.1, 1.0), rng.Uniform(1.0, 2.0), rng.Uniform(1.0, 4.0));
		case 4: return MakeHeart(size * size);
		default: return MakeUserEllipse(size, size * rng.LogUniform(0.2, 1.0));
		}
	};
	int convexOk = 0, convexAll = 0;
	for (int k = 0; k < 150; ++k)
	{
		const double sA = rng.LogUniform(1e-3, 1e3), sB = sA * rng.LogUniform(0.1, 10.0);
		const ShapePtr a = randomShape(sA), b = randomShape(sB);
		const double reach = a->BoundingRadius() + b->BoundingRadius();
		const double kinds[] = {0.0, 1e-13, 1e-9, 0.3, 0.9, 1.0, 1.2, 1e3, 1e6};
		const double f = kinds[k % 9];
		const Vec2 ca(rng.Uniform(-10.0, 10.0) * sA, rng.Uniform(-10.0, 10.0) * sA);
		const double dir = rng.Angle();
		const Pose pa(ca, rng.Angle()), pb(ca + f * reach * Vec2(std::cos(dir), std::sin(dir)), rng.Angle());
		INFO(a->Describe() << " vs " << b->Describe() << " f=" << f);
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::grid, MethodChoice::newton})
		{
			INFO("method " << int(m));
			const ContactResult c = ComputeContact(*a, pa, *b, pb, m);
			CHECK(AllFinite(c));
			if (c.Ok())
			{
				CHECK(std::fabs(Length(c.normal) - 1.0) <= 1e-12);
				CHECK(c.touching == (c.separation <= 0.0));
			}
			else
			{
				CHECK(std::string(c.failure).size() > 0);
			}
			const LevelResult s = SolveScaleA(*a, pa, *b, pb, m);
			CHECK(AllFinite(s));
			if (a->IsConvex() && b->IsConvex() && m == MethodChoice::automatic)
			{
				++convexAll;
				convexOk += c.Ok();
				const LevelResult l = SolveCommonLevel(*a, pa, *b, pb, m);
				CHECK(AllFinite(l));
			}
		}
	}
	// The automatic contact never fails for convex input.
	CHECK(convexOk == convexAll);
	CHECK(convexAll > 40);
}

TEST_CASE("regression: Newton never reports convergence at a point with parallel gradients (thin particles, deep overlap)")
{
	// Found by a random stress run: a 700:1 superellipse and a thin n != m superellipse whose
	// centres nearly coincide (common level 9.1e-5). Newton's residual test was met at a point
	// where both gradients are tiny but point the same way; the true common level, which the
	// min-max and grid solvers agree on, is 9.14258914525e-05.
	SuperellipseShape a(5.862182501192625, 0.0083921172252187318, 5.8285195072834375, 5.8285195072834375);
	SuperellipseShape b(3.7808904246430717, 0.2401122080947537, 15.668506954534768, 5.4362854956609397);
	const Pose pa(Vec2(0.0, 0.0), 1.6526901519841188), pb(Vec2(-0.10624618428425103, -1.18452383843897), 2.9249518768690339);
	const LevelResult minmax = SolveCommonLevelMinMax(a, pa, b, pb);
	const LevelResult grid = SolveCommonLevelGrid(a, pa, b, pb);
	REQUIRE(minmax.Ok());
	REQUIRE(grid.Ok());
	CHECK(RelativeError(grid.level, minmax.level) < 1e-9);
	const LevelResult newton = SolveCommonLevelNewton(a, pa, b, pb);
	if (newton.Ok())
		CHECK(RelativeError(newton.level, minmax.level) < 1e-9);
	const LevelResult automatic = SolveCommonLevel(a, pa, b, pb);
	REQUIRE(automatic.Ok());
	CHECK(RelativeError(automatic.level, minmax.level) < 1e-9);
}

// Two smooth superellipses: SuperellipseContact, the dispatch table's entry for superellipse
// pairs (SuperellipsePairLevel.cpp: Newton with the levels evaluated inline), against the
// long-double reference and against the generic path it replaces.
//
// Reference (PairReference.h, CommonContactRef): the common level as the fixed point of the
// surface minimum (ContactReference.h, CommonLevelRef), its point polished by Newton's method in
// long double (PolishLagrange), the normal from the long-double gradients there, and the
// points by bisection along the normal, all from the shapes' formulas; nothing of the library's
// solvers. (Unpolished, the minimum's point was fixed only to ~3e-10 of the size, the square
// root of the rounding of the values it compares, and that was what these tests measured
// before 2026-12-05: 3.6e-10 cold, 3.2e-10 warm.)
//
// Tolerances: points, separation and normal to 1e-11 of the pair's size (the benchmarks promise
// 1e-9; measured: 5.7e-15 cold, 1.0e-15 warm, 1.1e-13 on the blocky pairs, 1.2e-14 against
// ellipses and circles), the level to 1e-12 relative (measured 2.5e-13). The generic path
// agrees with the fast one to 7e-14 on the same pairs; the agreement is checked to 1e-12.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"
#include "ContactChecks.h"
#include "PairReference.h"
#include "contact/WarmSlide.h"
#include "geometry/SuperellipseTerms.h"

#include <vector>

using namespace b2a;
using namespace b2a::test;
using ref::LD;

namespace
{
struct Pair
{
	std::shared_ptr<SuperellipseShape> a, b;
	Pose pa, pb;
};

// Random pairs with exponents from `exponents` (n ≠ m allowed), semi-axes 0.4 to 2.5 (aspect up
// to about 6), placed at centre distances from deep overlap to well apart.
std::vector<Pair> Pairs(std::uint64_t seed, int count, const std::vector<double>& exponents)
{
	Random rng(seed);
	auto pick = [&] { return exponents[size_t(rng.Uniform(0.0, double(exponents.size())))]; };
	std::vector<Pair> out;
	for (int k = 0; k < count; ++k)
	{
		Pair p;
		p.a = std::make_shared<SuperellipseShape>(rng.LogUniform(0.4, 2.5), rng.LogUniform(0.4, 2.5), pick(), pick());
		p.b = std::make_shared<SuperellipseShape>(rng.LogUniform(0.4, 2.5), rng.LogUniform(0.4, 2.5), pick(), pick());
		const double reach = p.a->BoundingRadius() + p.b->BoundingRadius();
		const double dir = rng.Angle(), f = rng.Uniform(0.3, 1.6);
		p.pa = Pose(Vec2(rng.Uniform(-3.0, 3.0), rng.Uniform(-3.0, 3.0)), rng.Angle());
		p.pb = Pose(p.pa.p + f * reach * Vec2(std::cos(dir), std::sin(dir)), rng.Angle());
		out.push_back(p);
	}
	return out;
}

ref::RefShape RefOf(const SuperellipseShape& s) { return ref::RefShape::Super(s.A(), s.B(), s.N(), s.M()); }

bench::RefContact Reference(const Pair& p)
{
	const bench::RefPosed A{RefOf(*p.a), ref::Of(p.pa), p.a->BoundingRadius(), nullptr};
	const bench::RefPosed B{RefOf(*p.b), ref::Of(p.pb), p.b->BoundingRadius(), nullptr};
	return bench::CommonContactRef(A, B);
}

struct Worst
{
	double point = 0.0, level = 0.0, normal = 0.0, separation = 0.0;
	void Add(const ContactResult& c, const bench::RefContact& want, double size)
	{
		point = std::max(point, double(std::max(ref::Dist(c.pointA, want.pointA), ref::Dist(c.pointB, want.pointB))) / size);
		level = std::max(level, double(std::fabs(LD(c.level) - want.level) / want.level));
		normal = std::max(normal, double(ref::Dist(c.normal, want.normal)));
		separation = std::max(separation, double(std::fabs(LD(c.separation) - want.separation)) / size);
	}
};

double Size(const Pair& p) { return 0.5 * (p.a->BoundingRadius() + p.b->BoundingRadius()); }
} // namespace

TEST_CASE("superellipse pairs: the dispatch table sends smooth superellipses to SuperellipseContact")
{
	for (ShapeKind other : {BuiltinKinds::superellipse, BuiltinKinds::ellipse, BuiltinKinds::circle})
	{
		// (Function pointers compared as bool: doctest cannot print them.)
		CHECK(bool(GetContactFunction(BuiltinKinds::superellipse, other) == &SuperellipseContact));
		CHECK(bool(GetContactFunction(other, BuiltinKinds::superellipse) == &SuperellipseContact));
	}
	CHECK(bool(GetContactFunction(BuiltinKinds::ellipse, BuiltinKinds::ellipse) == &EllipseContact));
}

TEST_CASE("superellipse pairs: integer and non-integer exponents from 2 to 12 match the long-double reference, cold")
{
	const auto pairs = Pairs(4242, 40, {2.0, 3.0, 4.0, 5.5, 6.0, 8.0, 12.0});
	Worst worst;
	int touching = 0;
	for (const Pair& p : pairs)
	{
		const bench::RefContact want = Reference(p);
		INFO(p.a->Describe() << " vs " << p.b->Describe() << " C_ref=" << double(want.level));
		const ContactResult c = ComputeContact(*p.a, p.pa, *p.b, p.pb);
		REQUIRE(c.Ok());
		CHECK(c.method == SolveMethod::newton);
		CHECK(c.status == SolveStatus::converged);
		CHECK(c.touching == (want.level <= 1.0L));
		worst.Add(c, want, Size(p));
		touching += c.touching;
	}
	CAPTURE(worst.point);
	CAPTURE(worst.level);
	CAPTURE(worst.normal);
	CAPTURE(worst.separation);
	CHECK(worst.point <= 1e-11);
	CHECK(worst.separation <= 1e-11);
	CHECK(worst.level <= 1e-12);
	CHECK(worst.normal <= 1e-11);
	CHECK(touching >= 10);
	CHECK(touching <= 30);
}

TEST_CASE("superellipse pairs: warm starts along small motions stay on the reference and take few steps")
{
	// A motion of B by 1e-3 of the size and 1 mrad per step, as between time steps. The warm
	// start predicts the point from where it sat in both bodies and how far it slid
	// (WarmStart::slide); with it a warm solve takes two Newton steps (measured: 2.0 on average,
	// 2.9 without the slide), the last without evaluating the shapes.
	const auto pairs = Pairs(777, 16, {2.0, 4.0, 6.0, 8.0});
	Worst worst;
	int solves = 0, iterations = 0, maxIterations = 0;
	for (const Pair& start : pairs)
	{
		Pair p = start;
		WarmStart warm;
		ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::automatic, {}, &warm);
		REQUIRE(warm.valid);
		REQUIRE(warm.hasPointB);
		for (int step = 0; step < 4; ++step)
		{
			p.pb = Pose(p.pb.p + 1e-3 * Size(p) * Vec2(0.6, -0.8), p.pb.q.Angle() + 1e-3);
			const ContactResult c = ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::automatic, {}, &warm);
			REQUIRE(c.Ok());
			CHECK(c.status == SolveStatus::converged);
			worst.Add(c, Reference(p), Size(p));
			++solves;
			iterations += c.iterations;
			maxIterations = std::max(maxIterations, c.iterations);
			// The warm start holds the answer in both frames.
			CHECK(MaxDiff(ToWorld(p.pa, warm.localPoint), c.point) <= 1e-12 * Size(p));
			CHECK(MaxDiff(ToWorld(p.pb, warm.localPointB), c.point) <= 1e-12 * Size(p));
		}
	}
	CAPTURE(worst.point);
	CAPTURE(worst.level);
	CHECK(solves == 64);
	CHECK(worst.point <= 1e-11);
	CHECK(worst.level <= 1e-12);
	CAPTURE(double(iterations) / solves);
	CHECK(double(iterations) / solves <= 2.1);
	CHECK(maxIterations <= 4);
}

TEST_CASE("superellipse pairs: the warm start's slide is the derivative of the contact point along the motion")
{
	// WarmStart's documented first-order model of where the point goes when B moves relative to
	// A, as the solvers' start (WarmStartPoint) applies it: along the normal n, h = v·n/(1 + μ);
	// along t = Perp(n), s = slide·(ω, v·t, v·n), with v the move of B's material point at the
	// point and ω B's turn. Checked against central
	// differences of the long-double reference's level point over motions of 1e-5 of the size
	// (and 1e-5 rad): translations along t and n and turns of B about its centre, one at a time.
	// Measured: 1.5e-5 of the size per unit motion (the solve's Hessians are from its last
	// evaluation, a last step away from the answer); the plain start's v/(1 + μ) is off by 0.9.
	const auto pairs = Pairs(4242, 40, {2.5, 4.0, 6.0, 8.0});
	int checked = 0;
	double worst = 0.0, worstPlain = 0.0;
	for (const Pair& p : pairs)
	{
		WarmStart warm;
		const ContactResult c = ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::automatic, {}, &warm);
		REQUIRE(c.Ok());
		REQUIRE(warm.valid);
		if (!warm.hasSlide)
			continue; // flat on flat: no slide recorded
		const double size = Size(p), eps = 1e-5;
		const Vec2 n(warm.normalA[0], warm.normalA[1]), t = Perp(n);
		const Vec2 nWorld = Rotate(p.pa.q, n), tWorld = Rotate(p.pa.q, t);
		for (int motion = 0; motion < 3; ++motion)
		{
			// B's pose after a motion of signed size e: along t, along n, or a turn about its centre.
			auto moved = [&](double e) {
				if (motion == 2)
					return Pose(p.pb.p, p.pb.q.Angle() + e);
				return Pose(p.pb.p + e * size * (motion == 0 ? tWorld : nWorld), p.pb.q.Angle());
			};
			auto refPoint = [&](const Pose& pb) {
				Pair q = p;
				q.pb = pb;
				const bench::RefContact r = Reference(q);
				return ToBody(p.pa, Vec2(double(r.point.x), double(r.point.y)));
			};
			const Vec2 exact = (refPoint(moved(eps)) - refPoint(moved(-eps))) / (2.0 * eps);
			// The start the solvers take (WarmStartPoint) for B at `pb`, with the slide or the plain
			// start without it, in A's frame; its central difference cancels the offset of the
			// float normals (a turn of about 6e-8 where B did not turn).
			WarmStart plainWarm = warm;
			plainWarm.hasSlide = false;
			auto model = [&](const Pose& pb, bool plain) {
				return WarmStartPoint(plain ? plainWarm : warm, p.pa, pb, size) - warm.localPoint;
			};
			const Vec2 predicted = (model(moved(eps), false) - model(moved(-eps), false)) / (2.0 * eps);
			const Vec2 plain = (model(moved(eps), true) - model(moved(-eps), true)) / (2.0 * eps);
			const double scale = size * (1.0 + Length(exact) / size);
			worst = std::max(worst, Length(predicted - exact) / scale);
			worstPlain = std::max(worstPlain, Length(plain - exact) / scale);
			++checked;
		}
	}
	CAPTURE(worst);
	CAPTURE(worstPlain);
	CHECK(checked >= 90); // most random pairs record a slide
	CHECK(worst <= 1e-4);
	CHECK(worstPlain >= 0.05); // the slide is what the plain start misses
}

TEST_CASE("superellipse pairs: solvers that do not record the slide clear it")
{
	// Perram and Wertheim's ellipse pair keeps no slide; one left from an earlier solve of another
	// pair would mislead the next start.
	const auto blocky = MakeSuperellipse(1.0, 0.7, 6.0, 6.0);
	const auto ellipse = MakeEllipse(1.0, 0.5);
	const Pose pa(Vec2(0.0, 0.0), 0.3), pb(Vec2(1.7, 0.4), -0.5);
	WarmStart warm;
	REQUIRE(ComputeContact(*blocky, pa, *blocky, pb, MethodChoice::automatic, {}, &warm).Ok());
	CHECK(warm.hasSlide);
	REQUIRE(ComputeContact(*ellipse, pa, *ellipse, pb, MethodChoice::automatic, {}, &warm).Ok());
	CHECK(warm.valid);
	CHECK_FALSE(warm.hasSlide);
}

TEST_CASE("superellipse pairs: the generic Newton records and follows the slide too")
{
	// The ζ-form (the generic solver's, as a user's shape would be) along the motions of the warm
	// test above: the generic Newton records the slide and starts from it, and takes the fast
	// solver's two steps (measured: 2.0; 2.9 with the plain start, which clearing the slide
	// before each solve gives).
	const auto zeta = SuperellipseShape::FromZeta(1.0, 0.6, 3.0);
	const auto other = SuperellipseShape::FromZeta(0.7, 0.5, 2.5);
	const double size = 0.5 * (zeta->BoundingRadius() + other->BoundingRadius());
	Random rng(31);
	int solves = 0, withSlide = 0, withoutSlide = 0;
	for (int k = 0; k < 20; ++k)
	{
		const Pose pa(Vec2(rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)), rng.Angle());
		const double dir = rng.Angle();
		const Pose start(pa.p + rng.Uniform(0.8, 1.2) * 2.0 * size * Vec2(std::cos(dir), std::sin(dir)), rng.Angle());
		for (bool slide : {true, false})
		{
			WarmStart warm;
			Pose pb = start;
			REQUIRE(ComputeContact(*zeta, pa, *other, pb, MethodChoice::automatic, {}, &warm).Ok());
			CHECK(warm.hasSlide);
			for (int step = 0; step < 4; ++step)
			{
				pb = Pose(pb.p + 1e-3 * size * Vec2(0.6, -0.8), pb.q.Angle() + 1e-3);
				if (!slide)
					warm.hasSlide = false;
				const ContactResult c = ComputeContact(*zeta, pa, *other, pb, MethodChoice::automatic, {}, &warm);
				REQUIRE(c.Ok());
				CHECK(c.method == SolveMethod::newton);
				(slide ? withSlide : withoutSlide) += c.iterations;
				solves += slide ? 1 : 0;
			}
		}
	}
	CAPTURE(double(withSlide) / solves);
	CAPTURE(double(withoutSlide) / solves);
	CHECK(double(withSlide) / solves <= 2.1);
	CHECK(withSlide < withoutSlide);
}

TEST_CASE("superellipse pairs: SuperellipseContact agrees with the generic path it replaces, and swapping flips it")
{
	// ConvexContact (generic Newton, ContactFromLevel) is what the table held before; both solve
	// the same equations, so they agree to rounding on well-conditioned pairs.
	const auto pairs = Pairs(99, 200, {2.0, 2.5, 4.0, 6.0, 8.0, 9.5});
	double worstPoint = 0.0, worstLevel = 0.0, worstSwap = 0.0;
	for (const Pair& p : pairs)
	{
		const ContactResult fast = SuperellipseContact(*p.a, p.pa, *p.b, p.pb, {}, nullptr);
		const ContactResult generic = ConvexContact(*p.a, p.pa, *p.b, p.pb, {}, nullptr);
		REQUIRE(fast.Ok());
		REQUIRE(generic.Ok());
		worstPoint = std::max(worstPoint, std::max(Distance(fast.pointA, generic.pointA), Distance(fast.pointB, generic.pointB)) / Size(p));
		worstLevel = std::max(worstLevel, RelativeError(fast.level, generic.level));
		CHECK(fast.touching == generic.touching);
		const ContactResult swapped = SuperellipseContact(*p.b, p.pb, *p.a, p.pa, {}, nullptr);
		REQUIRE(swapped.Ok());
		worstSwap = std::max(worstSwap, std::max(Distance(fast.pointA, swapped.pointB), Distance(fast.pointB, swapped.pointA)) / Size(p));
		CHECK(Dot(fast.normal, swapped.normal) <= -1.0 + 1e-12);
	}
	CAPTURE(worstPoint);
	CAPTURE(worstLevel);
	CAPTURE(worstSwap);
	CHECK(worstPoint <= 1e-12);
	CHECK(worstLevel <= 1e-12);
	CHECK(worstSwap <= 1e-12);
}

TEST_CASE("superellipse pairs: a superellipse against an ellipse or a circle takes the same path and matches the reference")
{
	Random rng(31);
	Worst worst;
	for (int k = 0; k < 24; ++k)
	{
		Pair p;
		p.a = std::make_shared<SuperellipseShape>(rng.LogUniform(0.5, 2.0), rng.LogUniform(0.5, 2.0), k % 2 ? 4.0 : 6.0, 8.0);
		const double r = rng.LogUniform(0.5, 2.0);
		p.b = k % 3 == 0 ? MakeCircle(r) : MakeEllipse(r, r / rng.LogUniform(1.0, 3.0));
		const double dir = rng.Angle();
		p.pa = Pose(Vec2(0.3, -0.2), rng.Angle());
		p.pb = Pose(p.pa.p + rng.Uniform(0.4, 1.4) * (p.a->BoundingRadius() + p.b->BoundingRadius()) * Vec2(std::cos(dir), std::sin(dir)),
		            rng.Angle());
		for (bool swap : {false, true})
		{
			const ContactResult c = swap ? FlipContact(ComputeContact(*p.b, p.pb, *p.a, p.pa)) : ComputeContact(*p.a, p.pa, *p.b, p.pb);
			REQUIRE(c.Ok());
			CHECK(c.method == SolveMethod::newton);
			worst.Add(c, Reference(p), Size(p));
		}
	}
	CAPTURE(worst.point);
	CAPTURE(worst.level);
	CHECK(worst.point <= 1e-11);
	CHECK(worst.level <= 1e-12);
}

TEST_CASE("superellipse pairs: shapes the fast path does not take go to the generic solvers unchanged")
{
	// The ζ-form (level f^{1/ζ}) and exponents below 2 (corners: the grid method) are not the
	// fast solver's; the table's entry hands them on, and the answer is ConvexContact's exactly.
	const auto zeta = SuperellipseShape::FromZeta(1.0, 0.6, 3.0);
	const auto blocky = MakeSuperellipse(1.0, 0.7, 6.0, 6.0);
	const auto cornered = MakeSuperellipse(0.8, 0.8, 1.5, 3.0);
	const Pose pa(Vec2(0.0, 0.0), 0.3), pb(Vec2(1.7, 0.4), -0.5);
	for (const ShapePtr& other : {ShapePtr(zeta), ShapePtr(cornered)})
	{
		const ContactResult viaTable = ComputeContact(*blocky, pa, *other, pb);
		const ContactResult generic = ConvexContact(*blocky, pa, *other, pb, {}, nullptr);
		REQUIRE(viaTable.Ok());
		CHECK(viaTable.method == generic.method);
		CHECK(viaTable.level == generic.level);
		CHECK(viaTable.pointA.x == generic.pointA.x);
		CHECK(viaTable.pointB.y == generic.pointB.y);
	}
	CHECK(ComputeContact(*blocky, pa, *cornered, pb).method == SolveMethod::grid);
}

TEST_CASE("superellipse pairs: on hard pairs the fast path is never less accurate than the generic one")
{
	// Aspect ratios to 1000, exponents 2 to 20 (integer or not, n ≠ m), sizes 1e-3 to 1e3 and
	// size ratios to 20, levels from deep overlap to far apart: where the two paths disagree
	// (about 0.2 % of these pairs: needles, flat sides, levels far from 1, where the answer is
	// ill-conditioned and each path stops at its own rounding floor), the long-double reference
	// decides, and the fast path must be as close to it as the generic one (within a factor 10,
	// or 1e-12 of the size). This is where an early stop of the fast Newton showed: a last step
	// taken unevaluated before the multiplier had settled cost up to 1e-8 of the level.
	Random rng(2024);
	int compared = 0, disagreed = 0, failed = 0;
	for (int k = 0; k < 3000; ++k)
	{
		const double size = rng.LogUniform(1e-3, 1e3);
		auto exponent = [&] { return rng.Uniform(0.0, 1.0) < 0.5 ? std::floor(rng.Uniform(2.0, 21.0)) : rng.Uniform(2.0, 20.0); };
		const double aA = size * rng.LogUniform(0.5, 2.0), aB = size * rng.LogUniform(0.5, 2.0) * rng.LogUniform(1.0, 10.0);
		Pair p;
		p.a = std::make_shared<SuperellipseShape>(aA, aA / rng.LogUniform(1.0, 1000.0), exponent(), exponent());
		p.b = std::make_shared<SuperellipseShape>(aB, aB / rng.LogUniform(1.0, 1000.0), exponent(), exponent());
		p.pa = Pose(10.0 * size * Vec2(rng.Uniform(-0.5, 0.5), rng.Uniform(-0.5, 0.5)), rng.Angle());
		const double dir = rng.Angle(), d = (p.a->BoundingRadius() + p.b->BoundingRadius()) * rng.LogUniform(0.05, 3.0);
		p.pb = Pose(p.pa.p + d * Vec2(std::cos(dir), std::sin(dir)), rng.Angle());
		const ContactResult fast = SuperellipseContact(*p.a, p.pa, *p.b, p.pb, {}, nullptr);
		const ContactResult generic = ConvexContact(*p.a, p.pa, *p.b, p.pb, {}, nullptr);
		if (!fast.Ok())
		{
			// Only where no path has an answer that meets the standard and the particles do not
			// overlap (where they do, the contact is the axis of least overlap): the level solve
			// fails, with a reason, for two needles crossing deep inside each other at a level of
			// 4e-31, which came back converged with its normals 0.06 rad apart.
			INFO(p.a->Describe() << " vs " << p.b->Describe() << ": " << std::string(fast.failure));
			CHECK(!generic.Ok());
			const ref::CommonLevelResult want = ref::CommonLevelRef(RefOf(*p.a), ref::Of(p.pa), RefOf(*p.b), ref::Of(p.pb));
			CHECK(double(want.level) < 1e-12);
			++failed;
			continue;
		}
		if (!generic.Ok())
			continue;
		++compared;
		const double small = std::min(p.a->BoundingRadius(), p.b->BoundingRadius());
		const double apart = std::max(Distance(fast.pointA, generic.pointA), Distance(fast.pointB, generic.pointB)) / small;
		if (!(apart > 1e-9 || RelativeError(fast.level, generic.level) > 1e-9))
			continue;
		++disagreed;
		const ref::CommonLevelResult want = ref::CommonLevelRef(RefOf(*p.a), ref::Of(p.pa), RefOf(*p.b), ref::Of(p.pb));
		INFO(p.a->Describe() << " vs " << p.b->Describe() << " C_ref=" << double(want.level));
		const double pointFast = double(ref::Dist(fast.point, want.point)) / small;
		const double pointGeneric = double(ref::Dist(generic.point, want.point)) / small;
		const double levelFast = double(std::fabs(LD(fast.level) - want.level) / want.level);
		const double levelGeneric = double(std::fabs(LD(generic.level) - want.level) / want.level);
		CHECK(pointFast <= std::max(10.0 * pointGeneric, 1e-12));
		CHECK(levelFast <= std::max(10.0 * levelGeneric, 1e-13));
	}
	CHECK(compared >= 2990);
	CHECK(disagreed <= 30);
	CHECK(failed <= 1);
}

namespace
{
// Cold contacts of `pairs` (the blocky start's): each converged, on the generic Newton's answer
// from its own start (GeometricStart) to 1e-12 of the size, and, where `reference`, on the
// long-double reference to 1e-11 (points, separation) and 1e-12 (level). Returns the mean
// Newton steps.
double CheckColdStarts(const std::vector<Pair>& pairs, bool reference)
{
	Worst worst;
	int iterations = 0;
	for (const Pair& p : pairs)
	{
		INFO(p.a->Describe() << " vs " << p.b->Describe());
		const ContactResult c = ComputeContact(*p.a, p.pa, *p.b, p.pb);
		REQUIRE(c.Ok());
		CHECK(c.status == SolveStatus::converged);
		iterations += c.iterations;
		const ContactResult g = ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::newton);
		REQUIRE(g.Ok());
		CHECK(MaxDiff(c.pointA, g.pointA) <= 1e-12 * Size(p));
		CHECK(MaxDiff(c.pointB, g.pointB) <= 1e-12 * Size(p));
		CHECK(std::fabs(c.level - g.level) <= 1e-12 * g.level);
		if (reference)
			worst.Add(c, Reference(p), Size(p));
	}
	CAPTURE(worst.point);
	CAPTURE(worst.level);
	CHECK(worst.point <= 1e-11);
	CHECK(worst.separation <= 1e-11);
	CHECK(worst.level <= 1e-12);
	return double(iterations) / double(pairs.size());
}
} // namespace

TEST_CASE("superellipse pairs: blocky pairs start cold from their boxes' contact, in fewer steps, on the reference")
{
	// Both shapes with every exponent at least 3 (Blocky in SuperellipsePairLevel.cpp): the cold
	// start is where the bounding boxes, scaled about their centres, first touch, a corner of one
	// against a face of the other, rather than the centre line's point. Measured over these
	// pairs (the gauge Newton's steps and the raw-level finish's that takes over, together):
	// 4.4, 4.4, 4.3 and 4.4 on average for n = 4, 8, 12 and 20, against 5.0, 5.6, 6.1 and 6.7
	// from the centre line, the answers the same (before 2026-12-05, when a cold solve began to
	// hand over its first small step unevaluated, for n = m at 10 % of the size, the count was
	// 4.3, 4.1, 3.7 and 3.6 against 5.0, 5.5 and 6.0, in more evaluations). The long-double
	// reference is checked up to n = 12 (at n = 20 its own point is off by 1e-3 on these pairs,
	// where the fast and the generic Newton, from different starts, agree to 6e-15).
	for (double n : {4.0, 8.0, 12.0, 20.0})
	{
		CAPTURE(n);
		CHECK(CheckColdStarts(Pairs(9090 + std::uint64_t(n), 40, {n}), n <= 12.0) <= 4.6);
	}
	// Mixed exponents of 3 or more, n ≠ m within a shape and between the shapes: the same start,
	// for n ≠ m from the point of the box side whose normal is along the face's (SupportNear
	// without steps). Measured over these pairs: 5.3 Newton steps on average from the boxes
	// (5.22 before 2026-12-05's hand-over; 5.23 from the exact supports then), 5.6 from the
	// centre line (where one pair's points also differed from the generic Newton's by more than
	// 1e-12 of the size).
	const auto mixed = Pairs(9191, 60, {3.0, 4.0, 6.0, 8.0});
	int unequal = 0;
	for (const Pair& p : mixed)
		unequal += p.a->N() != p.a->M() || p.b->N() != p.b->M() || p.a->N() != p.b->N();
	CHECK(unequal >= 55);
	CHECK(CheckColdStarts(mixed, true) <= 5.4);
}

namespace
{
// The full solve's contact (SolveSuperellipsePairLevel from the same warm start, or cold, and
// ContactFromLevel's rules), which the raw-level finish replaces.
ContactResult FullContact(const Pair& p, const WarmStart* warm)
{
	const LevelResult level = SolveSuperellipsePairLevel(*p.a, p.pa, *p.b, p.pb, {}, warm);
	REQUIRE(level.Ok());
	return ContactFromLevel(*p.a, p.pa, *p.b, p.pb, level, level.level <= 1.0);
}

// The largest difference between two contacts: points and separation in units of `size`, the
// normal in radians, the level relative.
double ContactDifference(const ContactResult& x, const ContactResult& y, double size)
{
	return std::max({Distance(x.pointA, y.pointA) / size, Distance(x.pointB, y.pointB) / size, Distance(x.point, y.point) / size,
	                 Distance(x.normal, y.normal), std::fabs(x.separation - y.separation) / size, RelativeError(x.level, y.level)});
}
} // namespace

TEST_CASE("superellipse pairs: the raw-level finish gives the full solve's contact, warm and handed over cold")
{
	// FinishSuperellipseContact (SuperellipseContactFinish.cpp) solves the same equations on the
	// raw levels f instead of the gauges f^{1/q} and finds the points by Halley steps: from a
	// warm start along small motions (1e-3 of the size and 1 mrad a step) and from a cold solve
	// handed over once its steps are below 5 % of the size, it must take nearly every pair and
	// give the full solve's contact to 1e-12 (measured: 3.4e-15 warm, 1.0e-14 cold; the points
	// where the normal line misses a particle far away by ContactFromLevel's search), and record
	// the same warm start (measured: 3.7e-15).
	const auto pairs = Pairs(4711, 60, {2.0, 3.0, 4.0, 6.0, 8.0});
	int warmSolves = 0, warmTaken = 0, coldTaken = 0;
	double worstWarm = 0.0, worstCold = 0.0, worstRecord = 0.0;
	for (const Pair& start : pairs)
	{
		INFO(start.a->Describe() << " vs " << start.b->Describe());
		REQUIRE(FinishApplies(*start.a, *start.b));
		// Cold: the hand-over and the finish against ConvexContact's full solve.
		SuperellipseHandOver handOver;
		SolveSuperellipsePairLevel(*start.a, start.pa, *start.b, start.pb, {}, nullptr, nullptr, &handOver);
		ContactResult cold;
		if (handOver.taken && FinishSuperellipseContact(*start.a, start.pa, *start.b, start.pb, {}, handOver.point,
		                                                handOver.multiplier, handOver.iterations, nullptr, cold))
		{
			++coldTaken;
			worstCold = std::max(worstCold, ContactDifference(cold, FullContact(start, nullptr), Size(start)));
		}
		// Warm, along a motion.
		Pair p = start;
		WarmStart warm;
		REQUIRE(ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::automatic, {}, &warm).Ok());
		for (int step = 0; step < 4; ++step)
		{
			p.pb = Pose(p.pb.p + 1e-3 * Size(p) * Vec2(0.6, -0.8), p.pb.q.Angle() + 1e-3);
			++warmSolves;
			WarmStart mine = warm, full = warm;
			ContactResult c;
			if (FinishSuperellipseContact(*p.a, p.pa, *p.b, p.pb, {}, WarmStartPoint(warm, p.pa, p.pb, Size(p)), warm.multiplier, 0,
			                              &mine, c))
			{
				++warmTaken;
				CHECK(c.status == SolveStatus::converged);
				CHECK(c.method == SolveMethod::newton);
				CHECK(c.touching == (c.separation <= 0.0));
				CHECK(c.iterations >= 1);
				worstWarm = std::max(worstWarm, ContactDifference(c, FullContact(p, &full), Size(p)));
				// The warm start it records is the full solve's.
				RecordWarmStart(&full, p.pa, p.pb, SolveSuperellipsePairLevel(*p.a, p.pa, *p.b, p.pb, {}, &warm));
				CHECK(mine.valid);
				CHECK(mine.hasPointB);
				worstRecord = std::max({worstRecord, Distance(mine.localPoint, full.localPoint) / Size(p),
				                        Distance(mine.localPointB, full.localPointB) / Size(p),
				                        RelativeError(mine.multiplier, full.multiplier)});
			}
			REQUIRE(ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::automatic, {}, &warm).Ok());
		}
	}
	CAPTURE(worstWarm);
	CAPTURE(worstCold);
	CAPTURE(worstRecord);
	CHECK(warmSolves == 240);
	CHECK(warmTaken >= 238); // measured: all 240
	CHECK(coldTaken >= 56);  // measured: 59 of 60
	CHECK(worstWarm <= 1e-12);
	CHECK(worstCold <= 1e-12);
	CHECK(worstRecord <= 1e-12);
}

TEST_CASE("superellipse pairs: the raw-level finish with real exponents matches the full solve and the long-double reference")
{
	// Exponents ≥ 2 that are not integers (the millimetre scenes' mixed particles draw n = m from
	// [2.5, 5.5)), n ≠ m too, against integer ones and ellipses: each axis's |X|^{n−2} from one
	// std::pow (SmoothSuperellipseDerivatives), and for an exponent in (2, 3), where ∇²f is only
	// Hölder continuous at an axis, the settled last step evaluated. Warm along small motions and
	// handed over cold, as in the test above: the full solve's contact to 1e-12, and the
	// long-double reference's level to 1e-12 relative, normal to 1e-9 rad and points to 1e-11 of
	// the size (measured: 2.3e-15 and 3.4e-14 from the full solve warm and cold, all 320 warm
	// solves and 78 of 80 cold ones taken; against the reference level 3.5e-14, normal 6.0e-15
	// rad, points 2.7e-14).
	const auto pairs = Pairs(5150, 80, {2.0, 2.2, 2.5, 2.8, 3.3, 3.7, 4.0, 4.6, 5.5});
	int real = 0, warmSolves = 0, warmTaken = 0, coldTaken = 0;
	double worstWarm = 0.0, worstCold = 0.0;
	Worst worst;
	for (const Pair& start : pairs)
	{
		INFO(start.a->Describe() << " vs " << start.b->Describe());
		REQUIRE(FinishApplies(*start.a, *start.b));
		const bool isReal = !IntegerExponents(start.a->Terms()) || !IntegerExponents(start.b->Terms());
		real += isReal;
		SuperellipseHandOver handOver;
		SolveSuperellipsePairLevel(*start.a, start.pa, *start.b, start.pb, {}, nullptr, nullptr, &handOver);
		ContactResult cold;
		if (handOver.taken && FinishSuperellipseContact(*start.a, start.pa, *start.b, start.pb, {}, handOver.point,
		                                                handOver.multiplier, handOver.iterations, nullptr, cold))
		{
			coldTaken += isReal;
			worstCold = std::max(worstCold, ContactDifference(cold, FullContact(start, nullptr), Size(start)));
			worst.Add(cold, Reference(start), Size(start));
		}
		Pair p = start;
		WarmStart warm;
		REQUIRE(ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::automatic, {}, &warm).Ok());
		for (int step = 0; step < 4; ++step)
		{
			p.pb = Pose(p.pb.p + 1e-3 * Size(p) * Vec2(0.6, -0.8), p.pb.q.Angle() + 1e-3);
			warmSolves += isReal;
			WarmStart mine = warm, full = warm;
			ContactResult c;
			if (FinishSuperellipseContact(*p.a, p.pa, *p.b, p.pb, {}, WarmStartPoint(warm, p.pa, p.pb, Size(p)), warm.multiplier, 0,
			                              &mine, c))
			{
				warmTaken += isReal;
				CHECK(c.status == SolveStatus::converged);
				CHECK(c.touching == (c.separation <= 0.0));
				worstWarm = std::max(worstWarm, ContactDifference(c, FullContact(p, &full), Size(p)));
				worst.Add(c, Reference(p), Size(p));
			}
			REQUIRE(ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::automatic, {}, &warm).Ok());
		}
	}
	CAPTURE(worstWarm);
	CAPTURE(worstCold);
	CAPTURE(worst.level);
	CAPTURE(worst.normal);
	CAPTURE(worst.point);
	CAPTURE(warmTaken);
	CAPTURE(coldTaken);
	CHECK(real == 80);
	CHECK(warmTaken >= warmSolves - 4);
	CHECK(coldTaken >= real - 6);
	CHECK(worstWarm <= 1e-12);
	CHECK(worstCold <= 1e-12);
	CHECK(worst.level <= 1e-12);
	CHECK(worst.normal <= 1e-9);
	CHECK(worst.point <= 1e-11);
	CHECK(worst.separation <= 1e-11);
}

TEST_CASE("superellipse pairs: the raw-level finish declines a start far from the answer and writes nothing")
{
	// A warm start from before B jumped by a third of the size is outside the finish's reach (a
	// first step over 5 % of the size): it returns false and leaves the contact and the warm
	// start as they were; ComputeContact then takes the full solve from the same warm start and
	// gives its answer. Exponents below 2 are not the finish's at all.
	const auto a = std::make_shared<SuperellipseShape>(1.0, 0.6, 4.0, 4.0), b = std::make_shared<SuperellipseShape>(0.8, 0.5, 4.0, 4.0);
	const SuperellipseShape *sa = a.get(), *sb = b.get();
	const Pose pa(Vec2(0.0, 0.0), 0.3), before(Vec2(1.6, 0.3), -0.4), after(Vec2(1.6, 0.6), -0.1);
	WarmStart warm;
	REQUIRE(ComputeContact(*a, pa, *b, before, MethodChoice::automatic, {}, &warm).Ok());
	const WarmStart kept = warm;
	ContactResult c;
	c.iterations = -7;
	const double size = 0.5 * (a->BoundingRadius() + b->BoundingRadius());
	CHECK_FALSE(FinishSuperellipseContact(*sa, pa, *sb, after, {}, WarmStartPoint(warm, pa, after, size), warm.multiplier, 0,
	                                      &warm, c));
	CHECK(c.iterations == -7);
	CHECK(c.status == SolveStatus::failed);
	CHECK(warm.localPoint.x == kept.localPoint.x);
	CHECK(warm.multiplier == kept.multiplier);
	CHECK(warm.slide[0] == kept.slide[0]);
	WarmStart full = warm;
	const ContactResult viaTable = ComputeContact(*a, pa, *b, after, MethodChoice::automatic, {}, &warm);
	const Pair p{a, b, pa, after};
	CHECK(ContactDifference(viaTable, FullContact(p, &full), size) <= 1e-12);
	CHECK_FALSE(FinishApplies(*sa, SuperellipseShape(1.0, 0.5, 1.5, 4.0)));
	CHECK_FALSE(FinishSuperellipseContact(*sa, pa, SuperellipseShape(1.0, 0.5, 1.5, 4.0), after, {}, Vec2(0.8, 0.1), 1.0, 0,
	                                      nullptr, c));
}

TEST_CASE("superellipse pairs: poses with Box2D's float rotations give unit normals, cold and warm")
{
	// The Box2D adapter builds poses from b2Rot, whose float cosine and sine are off unit length
	// by up to about 6e-8. The finish solves in A's frame and turned its unit normal into the world
	// with pa.q, so the normal was off unit length by as much (found by the world fuzzer); it is
	// now normalised after the turn, as ContactFromLevel's is.
	auto floatRot = [](double angle) {
		// As b2Rot(float) makes it: cosf and sinf of the float angle. (Not float(std::cos(angle)):
		// GCC 12 at -O2 folds cos and sin into one sincos and drops the conversion to float.)
		const float c = std::cos(float(angle)), s = std::sin(float(angle));
		Rot q;
		q.c = c;
		q.s = s;
		return q;
	};
	const auto pairs = Pairs(2718, 60, {2.0, 3.0, 4.0, 6.0, 8.0});
	double worstRotation = 0.0, worstNormal = 0.0, worstLevelNormal = 0.0;
	int contacts = 0;
	for (const Pair& start : pairs)
	{
		INFO(start.a->Describe() << " vs " << start.b->Describe());
		Pair p = start;
		p.pa.q = floatRot(start.pa.q.Angle());
		WarmStart warm;
		for (int step = 0; step < 4; ++step)
		{
			p.pb = Pose(start.pb.p + double(step) * 1e-3 * Size(p) * Vec2(0.6, -0.8), Rot());
			p.pb.q = floatRot(start.pb.q.Angle() + double(step) * 1e-3);
			worstRotation = std::max({worstRotation, std::fabs(std::hypot(p.pa.q.c, p.pa.q.s) - 1.0),
			                          std::fabs(std::hypot(p.pb.q.c, p.pb.q.s) - 1.0)});
			const ContactResult c = ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::automatic, {}, &warm);
			REQUIRE(c.Ok());
			++contacts;
			worstNormal = std::max(worstNormal, std::fabs(Length(c.normal) - 1.0));
			const LevelResult level = SolveCommonLevel(*p.a, p.pa, *p.b, p.pb);
			REQUIRE(level.Ok());
			worstLevelNormal = std::max(worstLevelNormal, std::fabs(Length(level.normal) - 1.0));
		}
	}
	CAPTURE(worstRotation);
	CAPTURE(worstNormal);
	CAPTURE(worstLevelNormal);
	CHECK(contacts == 240);
	CHECK(worstRotation > 1e-8); // the rotations are Box2D's: not unit to double precision
	CHECK(worstNormal <= 1e-15);
	CHECK(worstLevelNormal <= 1e-15);
}

TEST_CASE("superellipse pairs: a separated n = 4, m = 8 pose: the contact and the polished reference match a 60-digit solution")
{
	// A cold pose of b2a_bench_pairs (superellipse_n4_m8, seed 1; common level 4.43): before
	// PolishLagrange the reference's common point was 3.1e-10 of the size off, its normal
	// 5.1e-11 and its point on A 1.06e-9, which the bench reported as the library's error. The
	// values: Newton on (∇λA + μ∇λB, λA − λB) in 60-digit arithmetic (mpmath) from these exact
	// doubles, the points the far crossings of the normal line through it.
	Pair p;
	p.a = std::make_shared<SuperellipseShape>(1.0, 0.6, 4.0, 8.0);
	p.b = std::make_shared<SuperellipseShape>(0.8, 0.5, 4.0, 8.0);
	p.pa = PoseOf(Vec2(-0x1.a560209ccb552p-3, 0x1.5d10d103fbc5ap-2), -0x1.b9e06a53001afp-1, 0x1.02a111aaf317fp-1);
	p.pb = PoseOf(Vec2(-0x1.3a3c2c455ff82p-4, 0x1.d52d7c0f4f0eep+0), -0x1.d7c460bce889p-1, 0x1.8de4ba1a90469p-2);
	const ref::V normal{0.4043918304149193874330917L, 0.9145858338579660501468987L};
	const ref::V pointA{-0.8640524997756389282934389L, 1.179458871308181921877569L};
	const ref::V pointB{-0.6960643816957496569829422L, 1.559386311718357199270969L};
	const LD level = 4.425116164879762185616466L;
	const double size = Size(p);

	const ContactResult c = ComputeContact(*p.a, p.pa, *p.b, p.pb);
	REQUIRE(c.Ok());
	CHECK(double(std::fabs(LD(c.level) - level) / level) <= 1e-14);
	CHECK(double(ref::Dist(c.normal, normal)) <= 1e-14);
	CHECK(double(ref::Dist(c.pointA, pointA)) <= 1e-13 * size);
	CHECK(double(ref::Dist(c.pointB, pointB)) <= 1e-13 * size);

	const bench::RefContact want = Reference(p);
	CHECK(double(std::fabs(want.level - level) / level) <= 1e-14);
	CHECK(double(ref::Len(want.normal - normal)) <= 1e-14);
	CHECK(double(ref::Len(want.pointA - pointA)) <= 1e-13 * size);
	CHECK(double(ref::Len(want.pointB - pointB)) <= 1e-13 * size);
}

// Hearts (paper eq. 20, non-convex): the grid method against a brute-force minimum, contacts
// against independent verdicts, and a symmetry identity.
//
// Reference: the smallest level of A over B's surface, brute force in long double: 200000
// samples of B's surface (polar angle, radius from a long-double bisection of the heart's radial
// equation; closed form for circles), then each of the 8 lowest local minima and the cusps
// polished by golden-section search and a derivative-sign bisection (ContactReference.h). The
// level found is a value at a real surface point, exact to ~1e-18; the sample spacing (~3e-5)
// only decides which basins are polished.
//
// Tolerance 1e-9 relative (of max(|level|, α_A): the heart's level crosses 0 inside it): the
// library refines its 256-sample minimum to rounding (a bracketed root of the derivative along
// the surface). Where the minimum sits in the |x|^{2/3} valley along a heart's axis (common: the
// tip or the notch side facing the other particle) a double-precision point, off by δ ~ 1e-16,
// costs δ^{2/3} ~ 2e-11 in the level (measured up to 1.1e-10 relative); a refinement that
// stopped early or a wrong basin is off by 1e-7 to 1e-1. The point is checked where the minimum is unique (the next
// local minimum is at least 1e-6 higher), to 1e-7 of the size: near a minimum the level is
// quadratic, so a point error δ costs only ~δ² in the level; the point is resolved to ~√eps.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"
#include "ContactChecks.h"
#include "ContactReference.h"
#include "contact/GridScale.h"

#include <map>
#include <tuple>
#include <vector>

using namespace b2a;
using namespace b2a::test;
using ref::LD;
using ref::V;

namespace
{
struct Posed
{
	ShapePtr shape;
	ref::RefShape refShape;
	Pose pose;
};

Posed Heart(double alpha, Vec2 p, double angle) { return {MakeHeart(alpha), ref::RefShape::Heart(alpha), Pose(p, angle)}; }
Posed Circle(double r, Vec2 p) { return {MakeCircle(r), ref::RefShape::Circle(r), Pose(p, 0.2)}; }
Posed Super(double a, double b, double n, double m, Vec2 p, double angle)
{
	return {MakeSuperellipse(a, b, n, m), ref::RefShape::Super(a, b, n, m), Pose(p, angle)};
}
Posed Diamond(double a, double b, Vec2 p, double angle) { return Super(a, b, 1.0, 1.0, p, angle); }

// Dense surface samples, computed once per distinct reference shape.
const ref::Curve& DenseCurve(const ref::RefShape& s)
{
	static std::map<std::tuple<int, long double, long double, long double, long double>, ref::Curve> cache;
	const auto key = s.kind == ref::RefShape::Kind::heart ? std::make_tuple(int(s.kind), s.alpha, 0.0L, 0.0L, 0.0L)
	                                                      : std::make_tuple(int(s.kind), s.a, s.b, s.n, s.m);
	auto it = cache.find(key);
	if (it == cache.end())
		it = cache.emplace(key, ref::SampleCurve(s, s.Own(), 200000)).first;
	return it->second;
}

ref::SurfaceMinResult BruteForce(const Posed& a, const Posed& b)
{
	return ref::SurfaceMin(a.refShape, ref::Of(a.pose), b.refShape, ref::Of(b.pose), b.refShape.Own(), 0, 8,
	                       &DenseCurve(b.refShape));
}

struct NamedPair
{
	const char* name;
	Posed a, b;
	bool severalMinima; // the configuration puts A in a cleft: several comparable local minima
};

std::vector<NamedPair> Pairs()
{
	return {
		{"heart vs circle, apart", Heart(1.0, {0, 0}, 0.0), Circle(0.3, {2.0, 0.5}), false},
		{"circle vs heart, apart", Circle(0.3, {2.0, 0.5}), Heart(1.0, {0, 0}, 0.0), false},
		{"heart vs circle, overlapping", Heart(1.0, {0, 0}, 0.0), Circle(0.4, {0.9, 0.4}), false},
		{"circle vs heart, overlapping", Circle(0.4, {0.9, 0.4}), Heart(1.0, {0, 0}, 0.0), false},
		// A small circle in the notch: its level over the heart's surface has a minimum on each
		// inner slope of the cleft, nearly equal (the circle sits 0.005 off the axis).
		{"circle in the notch vs heart", Circle(0.12, {0.005, 1.12}), Heart(1.0, {0, 0}, 0.0), true},
		{"heart vs circle in the notch", Heart(1.0, {0, 0}, 0.0), Circle(0.12, {0.005, 1.12}), false},
		// A small heart in the notch of a big one, slightly off the axis and turned.
		{"small heart in the notch vs big heart", Heart(0.05, {0.003, 1.2}, 0.02), Heart(1.0, {0, 0}, 0.0), true},
		{"big heart vs small heart in the notch", Heart(1.0, {0, 0}, 0.0), Heart(0.05, {0.003, 1.2}, 0.02), false},
		{"rotated hearts, apart", Heart(2.0, {0.5, -0.3}, 2.0), Heart(0.7, {3.4, 1.9}, -0.6), false},
		{"rotated hearts, overlapping", Heart(0.7, {2.2, 1.1}, -0.6), Heart(2.0, {0.5, -0.3}, 2.0), false},
		{"rotated heart vs circle, near", Heart(1.5, {-0.4, 0.2}, 0.8), Circle(0.25, {-1.9, 1.3}), false},
	};
}

double LevelTol(const Posed& a, LD want) { return 1e-9 * double(std::max(std::fabs(want), LD(a.shape->SurfaceLevel()))); }

// Hearts of α = 1 at the origin and α = 0.7 at a random distance in [near, far], both turned.
void AddRandomHeartPairs(std::vector<NamedPair>& cases, std::uint64_t seed, int count, double near, double far)
{
	Random rng(seed);
	for (int i = 0; i < count; ++i)
	{
		const double angle = rng.Angle(), distance = rng.Uniform(near, far);
		cases.push_back({"random hearts", Heart(1.0, {0.0, 0.0}, rng.Angle()),
		                 Heart(0.7, distance * Vec2(std::cos(angle), std::sin(angle)), rng.Angle()), false});
	}
}

// SolveGridScale both ways on each pair: the brute-force level, and a point on B's surface.
void CheckGridAgainstBruteForce(const std::vector<NamedPair>& cases)
{
	for (const NamedPair& p : cases)
		for (const bool swap : {false, true})
		{
			const Posed& a = swap ? p.b : p.a;
			const Posed& b = swap ? p.a : p.b;
			INFO(std::string(p.name) << (swap ? " (swapped)" : "") << " at " << b.pose.p.x << ", " << b.pose.p.y);
			const ref::SurfaceMinResult want = BruteForce(a, b);
			const LevelResult r = SolveGridScale(*a.shape, a.pose, *b.shape, b.pose);
			REQUIRE(r.Ok());
			CHECK(std::fabs(LD(r.level) - want.value) <= LevelTol(a, want.value));
			CHECK(std::fabs(RelativeLevel(*b.shape, b.pose, r.point) - 1.0) <= 2e-10);
		}
}
} // namespace

TEST_CASE("hearts: SolveGridScale (and SolveScaleA) match a 200000-sample brute-force minimum with polishing")
{
	int several = 0;
	for (const NamedPair& p : Pairs())
	{
		INFO(std::string(p.name));
		const ref::SurfaceMinResult want = BruteForce(p.a, p.b);
		if (p.severalMinima)
		{
			// The configuration does what it is meant to: a second local minimum close to the first.
			CHECK(want.secondValue - want.value <= 0.25L * std::fabs(want.value) + 0.05L * p.a.refShape.Own());
			++several;
		}
		for (const LevelResult& r : {SolveGridScale(*p.a.shape, p.a.pose, *p.b.shape, p.b.pose),
		                             SolveScaleA(*p.a.shape, p.a.pose, *p.b.shape, p.b.pose)})
		{
			REQUIRE(r.Ok());
			CHECK(r.method == SolveMethod::grid);
			CHECK(std::fabs(LD(r.level) - want.value) <= LevelTol(p.a, want.value));
			// The point lies on B's surface and A's level there is the reported level. (2e-10: on a
			// heart's axis its level is not Lipschitz, a rounding δ of x moves it by δ^{2/3} ~ 4e-11.)
			CHECK(std::fabs(RelativeLevel(*p.b.shape, p.b.pose, r.point) - 1.0) <= 2e-10);
			CHECK(std::fabs(p.a.shape->Level(ToBody(p.a.pose, r.point)) - r.level) <= 2e-10 * std::max(1.0, std::fabs(r.level)));
			if (want.secondValue - want.value > 1e-6L * std::max(std::fabs(want.value), 1.0L))
				CHECK(double(ref::Dist(r.point, want.point)) <= 1e-7 * p.b.shape->BoundingRadius());
		}
		// The internal overload that hands back A's body gradient at the point (for the grid's
		// contact): the same answer, and the gradient A's own there, the normal its direction.
		Vec2 gradient(0.0, 0.0);
		const LevelResult plain = SolveGridScale(*p.a.shape, p.a.pose, *p.b.shape, p.b.pose);
		const LevelResult handing = SolveGridScale(*p.a.shape, p.a.pose, *p.b.shape, p.b.pose, SolverOptions{},
		                                           std::numeric_limits<double>::quiet_NaN(), &gradient);
		CHECK(handing.level == plain.level);
		CHECK(handing.point.x == plain.point.x);
		CHECK(handing.point.y == plain.point.y);
		const Vec2 own = p.a.shape->Gradient(ToBody(p.a.pose, handing.point));
		CHECK(gradient.x == own.x);
		CHECK(gradient.y == own.y);
		CHECK(Length(Normalize(Rotate(p.a.pose.q, gradient)) - handing.normal) <= 1e-15);
		// Newton refuses a heart, with a reason.
		const LevelResult newton = SolveScaleA(*p.a.shape, p.a.pose, *p.b.shape, p.b.pose, MethodChoice::newton);
		CHECK_FALSE(newton.Ok());
		CHECK(std::string(newton.failure).size() > 0);
	}
	CHECK(several == 2);
}

TEST_CASE("hearts: with several local minima in the cleft, the grid refines the global one, not the nearest sample's")
{
	// Move a small circle across the notch: the two slope minima trade places as it crosses the
	// axis, and near the axis they differ by less than the 256-sample grid resolves. The refined
	// global minimum must match the brute force on both sides and at the crossing.
	for (double x : {-0.04, -0.01, -0.002, 0.0, 0.003, 0.012, 0.05})
	{
		const Posed c = Circle(0.1, {x, 1.1}), h = Heart(1.0, {0, 0}, 0.0);
		INFO("circle at x=" << x);
		const ref::SurfaceMinResult want = BruteForce(c, h);
		const LevelResult r = SolveGridScale(*c.shape, c.pose, *h.shape, h.pose);
		REQUIRE(r.Ok());
		CHECK(std::fabs(LD(r.level) - want.value) <= LevelTol(c, want.value));
		// The point is on the slope of the same side as the circle's offset (x = 0: either).
		if (x != 0.0)
			CHECK((r.point.x > 0.0) == (x > 0.0));
	}
}

TEST_CASE("hearts: ComputeContact's verdict matches the brute-force minima both ways, and the points lie on the surfaces")
{
	// Two particles overlap exactly when A's rescaling onto B's surface is at or below A's own
	// level, or the other way round (one inside the other shows up in the second test).
	for (const NamedPair& p : Pairs())
	{
		INFO(std::string(p.name));
		const ref::SurfaceMinResult ab = BruteForce(p.a, p.b), ba = BruteForce(p.b, p.a);
		const bool want = ab.value <= p.a.refShape.Own() || ba.value <= p.b.refShape.Own();
		// Keep clear of tangency so that the verdict is determined (all cases are).
		CHECK(std::fabs(ab.value / p.a.refShape.Own() - 1.0L) > 1e-6L);
		const ContactResult r = ComputeContact(*p.a.shape, p.a.pose, *p.b.shape, p.b.pose);
		REQUIRE(r.Ok());
		CHECK(AllFinite(r));
		CHECK(r.method == SolveMethod::grid);
		CHECK(r.touching == want);
		CHECK(r.touching == (r.separation <= 0.0));
		// Contact symmetry (exact for the grid path).
		const ContactResult s = ComputeContact(*p.b.shape, p.b.pose, *p.a.shape, p.a.pose);
		REQUIRE(s.Ok());
		CHECK(s.touching == r.touching);
		CHECK(s.separation == r.separation);
		CHECK(s.normal.x == -r.normal.x);
		CHECK(s.normal.y == -r.normal.y);
		CHECK(MaxDiff(s.pointA, r.pointB) == 0.0);
		CHECK(MaxDiff(s.pointB, r.pointA) == 0.0);
	}
}

TEST_CASE("hearts: a heart's tip pointing at a circle gives the axis as the normal, for every orientation")
{
	// Mirror symmetry: a heart is symmetric about its body y axis; a circle centred on that axis
	// below the tip makes the whole configuration symmetric, and the tip (0, −√α) is the nearest
	// point of the heart. So the contact normal must be the axis direction R(θ)(0, −1), pointA the
	// tip, pointB the circle's nearest point, and the separation the gap along the axis:
	//   circle centre at body (0, −1.5), r = 0.3: separation 0.2 (apart);
	//   circle centre at body (0, −1.2), r = 0.3: separation −0.1 (overlapping).
	// The heart's level function has a kink along its axis (|x|^{2/3}); the contact must not
	// depend on which side of the axis rounding puts the point.
	const auto heart = MakeHeart(1.0);
	const auto circle = MakeCircle(0.3);
	for (double theta : {0.0, 0.7, -2.1, 3.0})
		for (const auto& item : {std::pair<double, double>{1.5, 0.2}, {1.2, -0.1}})
		{
			const auto& depth = item.first;
			const auto& gap = item.second;
			const Pose ph(Vec2(0.4, -0.7), theta);
			const Pose pc(ToWorld(ph, Vec2(0.0, -depth)), 0.0);
			const Vec2 axis = Rotate(ph.q, Vec2(0.0, -1.0));
			INFO("theta=" << theta << " depth=" << depth);
			const ContactResult r = ComputeContact(*heart, ph, *circle, pc);
			REQUIRE(r.Ok());
			CHECK(r.touching == (gap <= 0.0));
			CHECK(MaxDiff(r.normal, axis) <= 1e-6);
			CHECK(std::fabs(r.separation - gap) <= 1e-6);
			CHECK(MaxDiff(r.pointA, ToWorld(ph, Vec2(0.0, -1.0))) <= 1e-6);
			CHECK(MaxDiff(r.pointB, pc.p - 0.3 * axis) <= 1e-6);
		}
}

TEST_CASE("hearts: minima at a cusp of either curve and at random poses match the brute force")
{
	// The refinement has three paths: Newton along B's curve (smooth minima), B's corner with a
	// Newton search on either side of it, and the crossing of A's corner ray (A's level runs in
	// a V-shaped valley along its tip axis, where Newton has no curvature to use). Each
	// configuration below puts the minimum on one of them; the random poses mix all three.
	std::vector<NamedPair> cases;
	for (double turn : {0.0, 0.9, -2.3})
	{
		// A's tip points at a big circle, slightly off its centre line: the minimum is where A's
		// tip axis crosses the circle.
		const Posed a = Heart(1.0, {0.0, 0.0}, turn);
		const Vec2 axis = Rotate(a.pose.q, Vec2(0.0, -1.0)), side = Perp(axis);
		cases.push_back({"A's tip at a circle", a, Circle(1.0, 2.05 * axis + 0.15 * side), false});
		// B's tip points at A: the minimum is B's corner sample.
		const Posed b = Heart(0.7, {0.3, 0.2}, turn);
		const Vec2 bAxis = Rotate(b.pose.q, Vec2(0.0, -1.0));
		cases.push_back({"B's tip at a circle", Circle(0.5, b.pose.p + 1.45 * bAxis + 0.05 * Perp(bAxis)), b, false});
		cases.push_back({"B's tip at a heart", Heart(1.0, b.pose.p + 2.1 * bAxis, turn + 0.4), b, false});
	}
	AddRandomHeartPairs(cases, 2026, 24, 0.6, 2.6);
	CheckGridAgainstBruteForce(cases);
}

TEST_CASE("hearts: superellipses against hearts, the grid pruned by the superellipse's level bounds, match the brute force")
{
	// With a superellipse as A the grid skips the runs of the heart's samples where the
	// superellipse's lower bound over the run's disc is above the lowest level found (for a heart
	// as A it always did). Each pair is checked both ways, so both bounds prune: superellipses of
	// exponents 2 to 8 and one with corners (n = 1), at random poses around a heart, and small
	// ones in the notch, where the heart's level has two comparable minima along their surface.
	std::vector<NamedPair> cases;
	Random rng(2027);
	const double exponents[][2] = {{2.0, 2.0}, {4.0, 4.0}, {8.0, 8.0}, {4.0, 8.0}, {2.5, 3.7}, {1.0, 1.0}};
	for (int i = 0; i < 30; ++i)
	{
		const double* e = exponents[i % 6];
		const double angle = rng.Angle(), distance = rng.Uniform(0.9, 2.4);
		cases.push_back({"superellipse around a heart", Super(0.8, 0.5, e[0], e[1], distance * Vec2(std::cos(angle), std::sin(angle)), rng.Angle()),
		                 Heart(1.0, {0.0, 0.0}, rng.Angle()), false});
	}
	for (double x : {-0.02, 0.004, 0.03})
		cases.push_back({"small superellipse in the notch", Super(0.1, 0.06, 4.0, 4.0, {x, 1.12}, 0.3), Heart(1.0, {0.0, 0.0}, 0.0), false});
	CheckGridAgainstBruteForce(cases);
}

TEST_CASE("grid: a contact on a diamond's edge next to its vertex refines past the vertex sample")
{
	// The samples crowd a vertex (half of them follow turning), so its neighbours lie within
	// about 1e-4 of it. A small circle whose nearest edge point lies between the vertex and its
	// neighbour makes the vertex the lowest sample while the minimum is on the straight edge
	// beside it: the refinement must leave the corner (Newton from the neighbour, on the edge).
	// Its level there is below the vertex's by (s/R)² ~ 1e-7 for an offset s ~ 3e-5, a hundred
	// times the tolerance.
	const Posed b = Diamond(0.8, 0.6, {0.1, -0.2}, 0.4);
	const auto samples = b.shape->Samples();
	int vertex = 0;
	for (int k = 0; k < samples->Count(); ++k)
		if (std::fabs(samples->angle[k]) < std::fabs(samples->angle[vertex]))
			vertex = k;
	REQUIRE(samples->angle[vertex] == 0.0); // the vertex (0.8, 0) is a sample
	const Vec2 v = samples->point[vertex], next = samples->point[vertex + 1];
	const double gap = Distance(v, next);
	CHECK(gap < 1e-3);
	const Vec2 edge = Normalize(next - v), outward = -Perp(edge); // the edge's outward normal
	for (double fraction : {0.2, 0.35, 0.5})
		for (double radius : {0.02, 0.05})
		{
			// The circle touches the edge's line at the foot v + fraction·gap·edge, from outside.
			const Vec2 foot = v + fraction * gap * edge;
			const Posed a = Circle(radius, ToWorld(b.pose, foot + 1.001 * radius * outward));
			INFO("fraction " << fraction << " radius " << radius);
			const ref::SurfaceMinResult want = BruteForce(a, b);
			const LevelResult r = SolveGridScale(*a.shape, a.pose, *b.shape, b.pose);
			REQUIRE(r.Ok());
			const double vertexLevel = a.shape->Level(ToBody(a.pose, ToWorld(b.pose, v)));
			CHECK(double(vertexLevel - want.value) > 100.0 * LevelTol(a, want.value)); // the vertex is not it
			CHECK(std::fabs(LD(r.level) - want.value) <= LevelTol(a, want.value));
			CHECK(Distance(r.point, ToWorld(b.pose, foot)) <= 1e-7);
		}
}

TEST_CASE("hearts: a tip valley on the slope of a smooth basin, between samples none of which is a minimum")
{
	// Where B's curve crosses A's tip axis on the flank of a smooth basin, A's level dips into
	// its |x|^{2/3} valley between two samples and the samples descend straight past it into
	// the basin: no sample marks the valley, whose bottom is lower than the basin's minimum.
	// (Two such poses came from b2a_bench_pairs --seed 9 and --seed 11; the bisection that
	// places its poses had stopped near them.) The grid solves every crossing of A's corner rays
	// between scanned samples whose disc A's bound does not rule out.
	std::vector<NamedPair> cases = {
		{"bench seed 9", Heart(1.0, {-0.11466308895789179, 0.098869122347475802}, -1.3995699001383219),
		 Heart(0.7, {-2.0934198425250901, 0.81450236905284645}, 3.1396374313364257), false},
		{"bench seed 11", Heart(1.0, {0.0078872851016547063, 0.063703832519970582}, 2.2426867913705473),
		 Heart(0.7, {-1.8468586420505186, 0.56035004750226358}, 1.6055512431842236), false},
	};
	// And random poses of the same pair at the distances where that happens (touching to a
	// fifth of the size apart), each both ways.
	AddRandomHeartPairs(cases, 909, 60, 1.6, 2.3);
	CheckGridAgainstBruteForce(cases);
	// The two bench poses' contacts: the valley is the minimum of A over B.
	const LevelResult seed9 = SolveGridScale(*cases[0].a.shape, cases[0].a.pose, *cases[0].b.shape, cases[0].b.pose);
	CHECK(seed9.level == doctest::Approx(1.410104666635).epsilon(1e-11));
}

TEST_CASE("grid contact: one side where it decides, the same answer as that side's, and a separation of the size the better side gives")
{
	// References: the two one-sided solves themselves (SolveGridScale, A onto B and B onto A,
	// each checked against brute force above) and their contacts. The verdict of either side
	// alone is exact only where the rescaled particle's centre lies outside the other; the
	// contact must agree with both sides' verdict, equal one side's contact bit for bit, and,
	// apart, not report a gap more than a few times the better side's (a single side's line
	// can cross a non-convex particle far from the point: the guard that falls back to both).
	struct Pair
	{
		ShapePtr a, b;
	};
	const Pair pairs[] = {{MakeHeart(1.0), MakeHeart(0.7)}, {MakeHeart(1.0), MakeSuperellipse(0.8, 0.5, 4, 4)},
	                      {MakeSuperellipse(0.8, 0.5, 4, 4), MakeHeart(1.0)}};
	Random rng(77);
	int oneSide = 0, total = 0;
	for (const Pair& p : pairs)
	{
		const double reach = p.a->BoundingRadius() + p.b->BoundingRadius();
		for (int k = 0; k < 150; ++k)
		{
			const Pose pa(Vec2(rng.Uniform(-1, 1), rng.Uniform(-1, 1)), rng.Angle());
			const double dir = rng.Angle();
			const Pose pb(pa.p + rng.Uniform(0.3, 1.05) * reach * Vec2(std::cos(dir), std::sin(dir)), rng.Angle());
			const LevelResult ab = SolveGridScale(*p.a, pa, *p.b, pb), ba = SolveGridScale(*p.b, pb, *p.a, pa);
			REQUIRE(ab.Ok());
			REQUIRE(ba.Ok());
			const ContactResult cab = ContactFromLevel(*p.a, pa, *p.b, pb, ab, ab.level <= p.a->SurfaceLevel(), true);
			const ContactResult cba = FlipContact(ContactFromLevel(*p.b, pb, *p.a, pa, ba, ba.level <= p.b->SurfaceLevel(), true));
			const ContactResult c = ComputeContact(*p.a, pa, *p.b, pb);
			CAPTURE(k);
			REQUIRE(c.Ok());
			CHECK(c.touching == (cab.touching || cba.touching));
			const bool isAB = c.level == cab.level && c.point.x == cab.point.x && c.separation == cab.separation;
			const bool isBA = c.level == cba.level && c.point.x == cba.point.x && c.separation == cba.separation;
			CHECK((isAB || isBA));
			if (!c.touching)
				CHECK(c.separation <= 4.5 * std::min(cab.separation, cba.separation) + 1e-9 * reach);
			// One side ran where the contact's iteration count is that side's alone.
			const GridSide side = ChooseGridSide(*p.a, pa, *p.b, pb);
			if (side != GridSide::bothWays && c.iterations == (side == GridSide::aOntoB ? ab : ba).iterations)
				++oneSide;
			++total;
		}
	}
	CAPTURE(oneSide);
	CHECK(oneSide > 2 * total / 5); // (the rest: a centre inside the other, deep, or a guard)

	// A small heart dropping tip first into a big one's notch: A's side alone measures its gap
	// along a line that crosses the small heart far from the point (0.08 where the gap is
	// 3e-5); the contact takes B's side there.
	const auto small = MakeHeart(0.05), big = MakeHeart(1.0);
	for (double t : {0.70, 0.71, 0.715, 0.7158})
	{
		const Pose pa(Vec2(0.02, 2.0 - t), 0.1), pb(Vec2(0.0, 0.0), 0.0);
		const LevelResult ab = SolveGridScale(*small, pa, *big, pb), ba = SolveGridScale(*big, pb, *small, pa);
		const ContactResult cab = ContactFromLevel(*small, pa, *big, pb, ab, false, true);
		const ContactResult cba = FlipContact(ContactFromLevel(*big, pb, *small, pa, ba, false, true));
		const ContactResult c = ComputeContact(*small, pa, *big, pb);
		CAPTURE(t);
		CHECK(!c.touching);
		CHECK(c.separation <= 1.01 * std::min(cab.separation, cba.separation));
	}
}

TEST_CASE("grid contact: of two particles of very different sizes the larger is rescaled, onto the smaller's dense samples")
{
	// From b2a_stress --seed 1 (configuration 9427): a heart 1e-4 the other's size (α = 1.9e-4
	// against 9.8e3) built touching, at A's level 1.039e-4 on B's surface. B's 256 samples lie
	// 3.4 apart, 180 times A's size: rescaled onto them, A was found at 0.0707, not touching.
	// Reference: the brute-force minima both ways (200000 samples each, long double).
	const Posed a{MakeHeart(0x1.91dacca229a07p-13), ref::RefShape::Heart(0x1.91dacca229a07p-13),
	              Pose(Vec2(0x1.2874a0f6b18aep-1, -0x1.3a1df20a44bd4p-3), 0x1.83f0ab8e211b4p+0)};
	const Posed b{MakeHeart(0x1.3110ca2ea2974p+13), ref::RefShape::Heart(0x1.3110ca2ea2974p+13),
	              Pose(Vec2(-0x1.30e4998700f09p+6, -0x1.fd89263ae3e99p+5), -0x1.317490c71cc74p+1)};
	const ref::SurfaceMinResult ab = BruteForce(a, b), ba = BruteForce(b, a);
	const bool want = ab.value <= a.refShape.Own() || ba.value <= b.refShape.Own();
	CHECK(want);
	CHECK(ChooseGridSide(*a.shape, a.pose, *b.shape, b.pose) == GridSide::bOntoA);
	CHECK(ChooseGridSide(*b.shape, b.pose, *a.shape, a.pose) == GridSide::aOntoB);
	const ContactResult c = ComputeContact(*a.shape, a.pose, *b.shape, b.pose);
	REQUIRE(c.Ok());
	CHECK(c.touching == want);
	CHECK(std::fabs(LD(c.level) - ba.value) <= 1e-9L * std::max(std::fabs(ba.value), b.refShape.Own()));
}

TEST_CASE("heart: the tip and the notch lie exactly on the axis, at the closed-form radius")
{
	// On the axis x = 0 the level is y², so the tip is (0, −√α) and the notch (0, √α). The angle
	// ±π/2 in double has a cosine of 6e-17, not 0, and the level's |x|^{2/3} term turned that
	// into a tip 1e-11 of the size off the axis and along it (every one-sided scale at a heart's
	// tip off by up to 3e-7 of the level).
	for (const double alpha : {1e-7, 2.7e-3, 0.57, 7.0, 6762.0})
	{
		CAPTURE(alpha);
		const ShapePtr h = MakeHeart(alpha);
		const double root = std::sqrt(alpha);
		const Vec2 tip = h->SurfacePoint(-0.5 * kPi), notch = h->SurfacePoint(0.5 * kPi);
		CHECK(tip.x == 0.0);
		CHECK(notch.x == 0.0);
		CHECK(std::fabs(tip.y + root) <= 4e-16 * root);
		CHECK(std::fabs(notch.y - root) <= 4e-16 * root);
		for (const Vec2 corner : h->CornerPoints())
		{
			CHECK(corner.x == 0.0);
			CHECK(std::fabs(std::fabs(corner.y) - root) <= 4e-16 * root);
		}
	}
}

TEST_CASE("grid scale: a heart's tip against a smooth particle is A's level at the exact tip")
{
	// From b2a_stress --seed 1 (configurations 678, 2816, 5578, 22051): a superellipse A rescaled
	// onto a heart B built touching at B's tip, each with neighbours (B turned by 1e-6 and 1e-3
	// rad about its centre, and moved by 1e-3 of its size). Where B's tip is the lowest point of
	// A's level on B's surface (the dense minimum, which cannot lie below the true one, is not
	// lower), the answer is A's level at (0, −√α) of B, computed in long double. The tip's
	// sample was 1e-11 of B's size off (see above): levels off by 1.5e-9 to 2.8e-7.
	struct Case
	{
		double a, b, n, m;
		Pose pa;
		double alpha;
		Pose pb;
	};
	const Case cases[] = {
		{0x1.4460daceb1673p-15, 0x1.9c8109d89945ep-10, 0x1.338a25ee61eb3p+1, 0x1.06adbc41378f4p+2,
		 Pose(Vec2(0x1.9dc77ed4b7c01p-9, 0x1.8ba91e8c71fd1p-8), 0x1.148370f7b06b4p+1), 0x1.bf77ace6bcdecp-14,
		 Pose(Vec2(-0x1.b8359e9e76fb1p-8, 0x1.245ec549e2bd9p-11), 0x1.08eb2936eeb58p+1)},
		{0x1.934a536057e6ap-8, 0x1.1491551fe053p-16, 2.0, 2.0, Pose(Vec2(0x1.c1d5253f635a1p-7, -0x1.19d1672bc375ap-8), -0x1.4e1c48e7b39ep-4),
		 0x1.51c634e206bc3p-7, Pose(Vec2(-0x1.46d2234febda7p-7, -0x1.a62b8adfb0b89p-4), 0x1.7456cd6a37554p+1)},
		{0x1.82c59bfb38dbfp-12, 0x1.ac068520ca8f3p-10, 11.0, 11.0, Pose(Vec2(-0x1.1e80078c29ba2p-8, 0x1.6bab8d931d94ep-8), 0x1.1fdc84b177c34p+0),
		 0x1.a049d3b373c9ap-2, Pose(Vec2(0x1.86714fb0b7402p-2, -0x1.02c939311d556p-1), -0x1.3f8aae735bd49p+1)},
		{0x1.cfeedc5174cap-4, 0x1.1e067534d833dp-12, 2.0, 2.0, Pose(Vec2(0x1.275abccb495b2p-2, -0x1.a71d3adad15e4p-2), 0x1.93008734179dp-1),
		 0x1.1988002b5bp-2, Pose(Vec2(0x1.900a249730b5ap-1, -0x1.354468fb7e99cp-1), -0x1.f577e873b5afap+0)},
	};
	int atTip = 0;
	for (const Case& k : cases)
	{
		const Posed a{MakeSuperellipse(k.a, k.b, k.n, k.m), ref::RefShape::Super(k.a, k.b, k.n, k.m), k.pa};
		const ShapePtr heart = MakeHeart(k.alpha);
		const double size = heart->BoundingRadius();
		const double turn = k.pb.q.Angle();
		const Pose neighbours[] = {k.pb,
		                           Pose(k.pb.p, turn + 1e-6),
		                           Pose(k.pb.p, turn - 1e-3),
		                           Pose(k.pb.p + Vec2(1e-3 * size, -0.5e-3 * size), turn)};
		for (const Pose& pb : neighbours)
		{
			const Posed b{heart, ref::RefShape::Heart(k.alpha), pb};
			CAPTURE(k.alpha);
			CAPTURE(pb.q.Angle());
			const ref::RefPose ra = ref::Of(a.pose), rb = ref::Of(b.pose);
			const V tip = ref::ToWorldL(rb, V{0.0L, -std::sqrt(LD(k.alpha))});
			const LD expected = a.refShape.Level(ref::ToBodyL(ra, tip));
			const ref::SurfaceMinResult dense = BruteForce(a, b);
			if (dense.value < expected * (1.0L - 1e-12L))
				continue; // the minimum left the tip: not this test's reference
			++atTip;
			const LevelResult r = SolveScaleA(*a.shape, a.pose, *b.shape, b.pose);
			REQUIRE(r.Ok());
			CHECK(double(std::fabs(LD(r.level) - expected) / expected) < 1e-10);
			CHECK(double(ref::Dist(r.point, tip)) < 1e-14 * size);
		}
	}
	CHECK(atTip >= 12); // (most neighbours keep the tip as the minimum)
}

TEST_CASE("grid scale: a smooth minimum beside a corner ray's valley in the same bracket")
{
	// From b2a_stress --seed 1 (configuration 144854): two hearts of α = 2.6e5 overlapping, A
	// rescaled onto B's surface. Between two of B's samples A's level has both the valley where
	// B's curve crosses A's tip ray (1182.7) and, beside it, the smooth minimum (1173.0); Newton
	// from the vertex and the sample, drawn into the valley, failed, and the crossing alone was
	// taken. Newton from each neighbour, held to its side of the crossing, finds it. Each pose
	// and its neighbours (B turned by 1e-6 and 1e-3 rad, A moved by 1e-3 of the size) against
	// the brute-force minimum.
	const double alpha = 0x1.fec4d77c102fcp+18;
	const Posed a = Heart(alpha, Vec2(0x1.343073a8cda31p+11, -0x1.9e2bf824384aap+9), 0x1.369c2095e53b8p-2);
	const Pose pb(Vec2(0x1.7054d238bd137p+11, -0x1.5d89388e937f3p+10), 0x1.431ade2410e8p+1);
	const double size = a.shape->BoundingRadius();
	const Pose poses[][2] = {{a.pose, pb},
	                         {a.pose, Pose(pb.p, pb.q.Angle() + 1e-6)},
	                         {a.pose, Pose(pb.p, pb.q.Angle() - 1e-3)},
	                         {Pose(a.pose.p + Vec2(1e-3 * size, 0.0), a.pose.q.Angle()), pb}};
	for (const auto& pair : poses)
	{
		const Posed pa{a.shape, a.refShape, pair[0]};
		const Posed b{MakeHeart(alpha), ref::RefShape::Heart(alpha), pair[1]};
		CAPTURE(pair[1].q.Angle());
		const ref::SurfaceMinResult want = BruteForce(pa, b);
		const LevelResult r = SolveGridScale(*pa.shape, pa.pose, *b.shape, b.pose);
		REQUIRE(r.Ok());
		CHECK(std::fabs(LD(r.level) - want.value) <= 1e-9L * std::max(std::fabs(want.value), LD(alpha)));
		CHECK(double(ref::Dist(r.point, want.point)) < 1e-7 * size);
	}
}

TEST_CASE("grid scale: a corner ray crossing a particle thinner than the samples' chord")
{
	// From b2a_stress --seed 1 (configuration 560689): a heart of α = 89 rescaled onto a plank
	// 82.5 × 0.132 (n = 14, m = 17) that crosses it. The minimum lies where the plank's surface
	// crosses the heart's tip ray, but the crossing's bracket, the chord's projections ± the
	// chord (0.65), held both of the plank's sides, with the level above the plank's at both
	// ends: no crossing was solved, and a point beside the ray gave 14.744 for 14.336. The
	// configuration and neighbours (the plank turned by 1e-6 and 1e-3 rad, the heart moved by
	// 1e-3 of its size) against the brute-force minimum.
	const Posed heart = Heart(0x1.64e1a4a34ce9ep+6, Vec2(-0x1.03cd33a2e5664p+4, 0x1.b5c31c4284eddp+4), 0x1.02b0399736c28p-2);
	const Posed plank = Super(0x1.49eb20a24ce5cp+6, 0x1.0e67edc426d0ep-3, 14.0, 17.0, Vec2(0x1.84e24802b5bd5p+5, 0x1.0fac3e5bcb07ap+3),
	                          -0x1.da482145dbeep-3);
	const double size = heart.shape->BoundingRadius(), turn = plank.pose.q.Angle();
	const Pose heartPoses[] = {heart.pose, heart.pose, heart.pose, Pose(heart.pose.p + Vec2(0.0, 1e-3 * size), heart.pose.q.Angle())};
	const Pose plankPoses[] = {plank.pose, Pose(plank.pose.p, turn + 1e-6), Pose(plank.pose.p, turn - 1e-3), plank.pose};
	for (int i = 0; i < 4; ++i)
	{
		CAPTURE(i);
		const Posed a{heart.shape, heart.refShape, heartPoses[i]}, b{plank.shape, plank.refShape, plankPoses[i]};
		const ref::SurfaceMinResult want = BruteForce(a, b);
		const LevelResult r = SolveScaleA(*a.shape, a.pose, *b.shape, b.pose);
		REQUIRE(r.Ok());
		CHECK(std::fabs(LD(r.level) - want.value) <= 1e-9L * std::max(std::fabs(want.value), a.refShape.Own()));
		CHECK(double(ref::Dist(r.point, want.point)) < 1e-7 * size);
	}
}

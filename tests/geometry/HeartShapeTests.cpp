// HeartShape (paper eq. 20): level function, cusps, axis convention, symmetry, area.
#include <doctest/doctest.h>

#include "GeometryReference.h"
#include "TestSupport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>
#include <limits>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("heart: the level is x^2 + y^2 - cbrt(x^2 y^3) and the particle is where G <= 0")
{
	const auto heart = MakeHeart(1.7);
	CHECK(heart->Kind() == BuiltinKinds::nonConvex);
	CHECK(heart->SurfaceLevel() == 1.7);
	CHECK(heart->Alpha() == 1.7);
	CHECK(heart->Describe() == "heart(alpha=1.7)");
	CHECK(!heart->IsConvex());
	CHECK(!heart->IsSmoothConvex());
	CHECK(heart->DerivativesCheap()); // closed forms: line searches take Newton steps
	Random rng(61);
	for (int i = 0; i < 1000; ++i)
	{
		const Vec2 x(rng.Uniform(-2.5, 2.5), rng.Uniform(-2.5, 2.5));
		const double lambda = heart->Level(x);
		// Absolute 1e-15 of the terms' size r²: the level itself can cancel to near 0.
		CHECK(std::fabs(lambda - double(HeartLevelRef(x))) <= 1e-15 * (1.0 + 2.0 * LengthSquared(x)));
		// G(x, α) = (r² − α)³ − (r² − λ)³ has the sign of λ − α: the particle is {λ ≤ α}.
		if (std::fabs(lambda - 1.7) > 1e-9)
			CHECK((HeartG(x, 1.7) > 0.0) == (lambda > 1.7));
	}
}

TEST_CASE("heart: notch and tip are corners at (0, +-sqrt(alpha)); the axes radii are sqrt(L)")
{
	for (double alpha : {0.3, 1.0, 2.5})
	{
		CAPTURE(alpha);
		const auto heart = MakeHeart(alpha);
		const double r = std::sqrt(alpha);
		REQUIRE(heart->CornerAngles().size() == 2);
		CHECK(heart->CornerAngles()[0] == -0.5 * kPi);
		CHECK(heart->CornerAngles()[1] == 0.5 * kPi);
		// The corners as rays and as points: tip (0, −√α), notch (0, √α).
		REQUIRE(heart->CornerDirections().size() == 2);
		REQUIRE(heart->CornerPoints().size() == 2);
		CHECK(Distance(heart->CornerDirections()[0], Vec2(0, -1)) <= 1e-16);
		CHECK(Distance(heart->CornerDirections()[1], Vec2(0, 1)) <= 1e-16);
		CHECK(Distance(heart->CornerPoints()[0], Vec2(0, -r)) <= 1e-10 * r);
		CHECK(Distance(heart->CornerPoints()[1], Vec2(0, r)) <= 1e-10 * r);
		// On x = 0 and on y = 0 the level is r², so the level-L set crosses the axes at √L.
		CHECK(RelativeError(heart->RadiusAt(Vec2(0, 1), alpha), r) < 1e-15);
		CHECK(RelativeError(heart->RadiusAt(Vec2(0, -1), alpha), r) < 1e-15);
		// SurfacePoint(±π/2) uses cos(π/2) ≈ 6e-17 rather than 0, and at a cusp the radius moves
		// like |Δθ|^{2/3}: (6e-17)^{2/3} ≈ 1.5e-11. So these agree to 1e-10, not to rounding.
		CHECK(Distance(heart->SurfacePoint(0.5 * kPi), Vec2(0, r)) <= 1e-10 * r);
		CHECK(Distance(heart->SurfacePoint(-0.5 * kPi), Vec2(0, -r)) <= 1e-10 * r);
		CHECK(Distance(heart->SurfacePoint(0.0), Vec2(r, 0)) <= 1e-15 * r);
		CHECK(Distance(heart->SurfacePoint(kPi), Vec2(-r, 0)) <= 1e-15 * r);
		for (double L : {0.01, 0.5, 4.0, 100.0})
		{
			CHECK(RelativeError(heart->RadiusAt(Vec2(0, 1), L), std::sqrt(L)) < 1e-15);
			CHECK(RelativeError(heart->RadiusAt(Vec2(0, -1), L), std::sqrt(L)) < 1e-15);
			CHECK(RelativeError(heart->RadiusAt(Vec2(1, 0), L), std::sqrt(L)) < 1e-15);
		}
		// The notch is a local minimum of the radius over angle, the lobes reach beyond it.
		CHECK(heart->RadiusAt(Vec2(0, 1), alpha) < heart->RadiusAt(Normalize(Vec2(0.1, 1)), alpha));
		CHECK(heart->RadiusAt(Vec2(0, 1), alpha) < heart->RadiusAt(Normalize(Vec2(-0.1, 1)), alpha));
	}
}

TEST_CASE("heart: on the axis x = 0 the derivatives drop the singular terms (documented convention)")
{
	const auto heart = MakeHeart(1.0);
	for (double y : {-1.3, -0.5, 0.0, 0.25, 1.0, 2.0})
	{
		CAPTURE(y);
		const LevelDerivatives d = heart->Derivatives(Vec2(0.0, y));
		CHECK(d.value == y * y);
		CHECK(d.gradient.x == 0.0);
		CHECK(d.gradient.y == 2.0 * y);
		CHECK(d.hessian.xx == 2.0);
		CHECK(d.hessian.xy == 0.0);
		CHECK(d.hessian.yy == 2.0);
		// ∂/∂y is continuous across the axis (2y − |x|^{2/3} → 2y) ...
		CHECK(std::fabs(heart->Gradient(Vec2(1e-12, y)).y - 2.0 * y) < 1e-7);
		if (y != 0.0)
		{
			// ... but ∂/∂x = 2x − (2/3) sgn(x)|x|^{−1/3} y jumps from +∞ to −∞ (times sgn y):
			// the convention is a choice, not a limit.
			const double gx = heart->Gradient(Vec2(1e-12, y)).x;
			CHECK(gx == doctest::Approx(-(2.0 / 3.0) * 1e4 * y).epsilon(1e-9));
			CHECK(heart->Gradient(Vec2(-1e-12, y)).x == doctest::Approx(-gx).epsilon(1e-12));
		}
	}
}

TEST_CASE("heart: mirror symmetric about the axis x = 0")
{
	const auto heart = MakeHeart(1.3);
	Random rng(62);
	for (int i = 0; i < 500; ++i)
	{
		const Vec2 x(rng.Uniform(0.01, 2), rng.Uniform(-2, 2));
		const Vec2 m(-x.x, x.y);
		const LevelDerivatives d = heart->Derivatives(x), e = heart->Derivatives(m);
		CHECK(d.value == e.value);
		CHECK(d.gradient.x == -e.gradient.x);
		CHECK(d.gradient.y == e.gradient.y);
		CHECK(d.hessian.xx == e.hessian.xx);
		CHECK(d.hessian.xy == -e.hessian.xy);
		CHECK(d.hessian.yy == e.hessian.yy);
		const double t = rng.Uniform(-0.5 * kPi, 0.5 * kPi);
		const Vec2 p = heart->SurfacePoint(t), q = heart->SurfacePoint(kPi - t);
		CHECK(Distance(p, Vec2(-q.x, q.y)) <= 1e-15 * 2.0);
	}
	CHECK(std::fabs(heart->Mass().centroid.x) < 1e-14);
	CHECK(std::fabs(heart->Mass().Ixy) < 1e-14 * heart->Mass().polarMoment);
}

namespace
{
// Radius of the heart (x²+y²−α)³ = x²y³ along the direction (c, s), by bisection on the
// implicit function itself: F(t) = (t² − α)³ − t⁵ c² s³, negative at 0, with one positive root.
double HeartRadiusByBisection(double alpha, double c, double s)
{
	auto F = [&](double t) {
		const double w = t * t - alpha;
		return w * w * w - t * t * t * t * t * c * c * s * s * s;
	};
	double lo = 0.0, hi = std::sqrt(alpha);
	while (F(hi) <= 0.0) hi *= 2.0;
	for (int it = 0; it < 200; ++it)
	{
		const double mid = 0.5 * (lo + hi);
		if (mid <= lo || mid >= hi) break;
		(F(mid) > 0.0 ? hi : lo) = mid;
	}
	return 0.5 * (lo + hi);
}

// ∫ over the heart of (1, x, y, x², y², xy) by the polar formulas ∫R²/2, ∫R³cos/3, ...
// with the midpoint rule on [−π/2, π/2] and [π/2, 3π/2] (the cusps are the interval ends,
// where the integrand behaves like |θ ∓ π/2|^{2/3}: the midpoint rule still converges as h^{5/3}).
std::array<long double, 6> HeartMomentsPolar(double alpha, int perHalf)
{
	std::array<long double, 6> sum{};
	const double h = kPi / perHalf;
	for (int half = 0; half < 2; ++half)
		for (int k = 0; k < perHalf; ++k)
		{
			const double t = -0.5 * kPi + half * kPi + (k + 0.5) * h;
			const double c = std::cos(t), s = std::sin(t);
			const long double R = HeartRadiusByBisection(alpha, c, s);
			const long double R2 = R * R, R3 = R2 * R, R4 = R2 * R2;
			sum[0] += R2 / 2;
			sum[1] += R3 * c / 3;
			sum[2] += R3 * s / 3;
			sum[3] += R4 * c * c / 4;
			sum[4] += R4 * s * s / 4;
			sum[5] += R4 * c * s / 4;
		}
	for (auto& v : sum) v *= h;
	return sum;
}
} // namespace

TEST_CASE("heart: area and moments agree with an independent polar integral and a grid count")
{
	for (double alpha : {1.0, 2.5})
	{
		CAPTURE(alpha);
		const auto heart = MakeHeart(alpha);
		const MassProperties& mp = heart->Mass();

		// Polar integral with our own bisection radius and midpoint rule, 2^15 points per half.
		// Its error comes from the cusps and falls like h^{5/3} to h^{7/3} (measured against the
		// library while halving h from 2^14 to 2^18 points: area 2e-11 → 3e-14, centroid 2e-8 →
		// 2e-10, Ixx 4e-8 → 4e-10; Iyy, whose x² weight vanishes at the cusps, 4e-16 throughout).
		// Tolerances are about 10× the 2^15 discrepancy.
		const auto m = HeartMomentsPolar(alpha, 1 << 15);
		const double area = double(m[0]);
		const double cx = double(m[1] / m[0]), cy = double(m[2] / m[0]);
		const double Iyy = double(m[3] - m[0] * cx * cx);
		const double Ixx = double(m[4] - m[0] * cy * cy);
		CHECK(RelativeError(mp.area, area) < 5e-11);
		CHECK(std::fabs(mp.centroid.y - cy) < 1e-7 * std::sqrt(alpha));
		CHECK(std::fabs(cx) < 1e-13 * std::sqrt(alpha)); // ∫x dA = 0 by symmetry
		CHECK(RelativeError(mp.Iyy, Iyy) < 1e-13);
		CHECK(RelativeError(mp.Ixx, Ixx) < 1e-7);
		CHECK(std::fabs(double(m[5])) < 1e-12 * Iyy); // ∫xy dA = 0

		// Grid count: cell centres of a 2000 × 2000 grid over [−2√α, 2√α]² with G(x, α) ≤ 0.
		// The ~3000 boundary cells each err by less than one cell area (4e-6 α) and largely
		// cancel: 1e-3 relative is a generous but independent bound.
		const int n = 2000;
		const double half = 2.0 * std::sqrt(alpha), cell = 2.0 * half / n;
		long count = 0;
		for (int i = 0; i < n; ++i)
			for (int j = 0; j < n; ++j)
				if (HeartG(Vec2(-half + (i + 0.5) * cell, -half + (j + 0.5) * cell), alpha) <= 0.0) ++count;
		CHECK(RelativeError(mp.area, count * cell * cell) < 1e-3);
	}
}

namespace
{
// A random disc for the bound tests: centre uniform within ±spread on each axis, radius
// log-uniform in [rMin, rMax], and the least and greatest level over it (DiscLevelRange's rings).
struct Disc
{
	Vec2 centre;
	double radius, lowest, highest;
};
Disc RandomDisc(Random& rng, const Shape& h, double spread, double rMin, double rMax)
{
	Disc d;
	d.centre = Vec2(rng.Uniform(-spread, spread), rng.Uniform(-spread, spread));
	d.radius = rng.LogUniform(rMin, rMax);
	DiscLevelRange([&](Vec2 x) { return h.Level(x); }, d.centre, d.radius, d.lowest, d.highest);
	return d;
}
} // namespace

TEST_CASE("heart: LevelLowerBound and LevelUpperBound bracket the level everywhere on the disc, and are close where the disc is far")
{
	// Reference: the smallest and largest levels over 40 rings of 120 points covering the disc,
	// and its centre.
	Random rng(31);
	for (double alpha : {0.3, 1.0, 4.0})
	{
		const auto h = MakeHeart(alpha);
		const double R = h->BoundingRadius();
		for (int i = 0; i < 300; ++i)
		{
			const Disc d = RandomDisc(rng, *h, 3.0 * R, 1e-3 * R, R);
			const Vec2 c = d.centre;
			const double r = d.radius, lowest = d.lowest, highest = d.highest;
			const double lower = h->LevelLowerBound(c, r), upper = h->LevelUpperBound(c, r);
			INFO("alpha ", alpha, ", disc (", c.x, ", ", c.y, ") of radius ", r);
			CHECK(lower <= lowest + 1e-12 * std::fabs(lowest));
			CHECK(upper >= highest - 1e-12 * std::fabs(highest));
			// Small discs far from the centre: within a few radii of the truth (α ~ |x|², so a
			// bound loses about 2|c|r + the cube-root term's spread).
			if (r < 0.01 * R && Length(c) > R)
			{
				CHECK(lowest - lower <= 10.0 * r * (Length(c) + 1.0));
				CHECK(upper - highest <= 10.0 * r * (Length(c) + 1.0));
			}
		}
	}
	// A disc of radius 0 is its centre: the bounds bracket its level within the cube root's
	// bounds (2e-3 of the cusp term) and the lower bound's margin for rounding (|c| taken 1e-15
	// low: 2e-15 of |c|²). The default shape has no upper bound.
	const auto h = MakeHeart(1.0);
	for (Vec2 c : {Vec2(0.3, -0.2), Vec2(-0.4, 0.7), Vec2(1.5, 0.0)})
	{
		const double level = h->Level(c), cusp = std::cbrt(c.x * c.x) * std::fabs(c.y);
		CHECK(h->LevelLowerBound(c, 0.0) <= level);
		CHECK(h->LevelUpperBound(c, 0.0) >= level);
		CHECK(h->LevelUpperBound(c, 0.0) - h->LevelLowerBound(c, 0.0) <= 2.1e-3 * cusp + 3e-15 * std::fabs(level));
	}
	CHECK(MakeSuperellipse(1.0, 0.5, 4.0, 4.0)->LevelUpperBound(Vec2(), 0.1) == std::numeric_limits<double>::infinity());
}

TEST_CASE("heart: TightLevelLowerBound is below the level on the box, tighter than LevelLowerBound on the disc around it, tighter for thinner boxes, and none near the axis")
{
	// Reference: the smallest level over an 81 × 81 lattice on the box. Boxes of 1e-4 to 0.3 of
	// the heart in length, of any orientation, as wide as long down to a hundredth of that (a
	// run of the grid's samples is a tenth to a fiftieth), off the heart's axis (where the bound
	// applies), and some across it (where it must say none, −∞).
	Random rng(33);
	double slackTight = 0.0, slackApart = 0.0;
	int applied = 0, tighter = 0, thinner = 0;
	for (double alpha : {0.3, 1.0, 4.0})
	{
		const auto h = MakeHeart(alpha);
		const double R = h->BoundingRadius();
		for (int i = 0; i < 400; ++i)
		{
			OrientedBox box;
			box.centre = Vec2(rng.Uniform(-1.5 * R, 1.5 * R), rng.Uniform(-1.5 * R, 1.5 * R));
			const double angle = rng.Angle();
			box.axis = Vec2(std::cos(angle), std::sin(angle));
			box.halfLength = rng.LogUniform(1e-4 * R, 0.3 * R);
			box.halfWidth = box.halfLength * rng.LogUniform(0.01, 1.0);
			const double lowest = BoxLevelLowest([&](Vec2 x) { return h->Level(x); }, box);
			const double radius = std::hypot(box.halfLength, box.halfWidth);
			const Vec2 c = box.centre;
			const double tight = h->TightLevelLowerBound(box), apart = h->LevelLowerBound(c, radius);
			INFO("alpha ", alpha, ", box (", c.x, ", ", c.y, ") along (", box.axis.x, ", ", box.axis.y, "), ", box.halfLength, " by ",
			     box.halfWidth);
			CHECK(tight <= lowest + 1e-12 * std::fabs(lowest));
			if (std::fabs(c.x) < 2.0 * radius)
			{
				CHECK(tight == -std::numeric_limits<double>::infinity()); // off the axis only
				continue;
			}
			if (std::fabs(c.x) < 2.0 * radius * (1.0 + 1e-6))
				continue; // (t = ρ/|cx| at 1/2, within rounding of where it stops applying)
			REQUIRE(std::isfinite(tight));
			++applied;
			tighter += tight > apart;
			slackTight += lowest - tight;
			slackApart += lowest - apart;
			// The same box square (as wide as long) holds it, so bounds no higher.
			OrientedBox square = box;
			square.halfWidth = box.halfLength;
			const double squareBound = h->TightLevelLowerBound(square);
			CHECK(squareBound <= tight + 1e-15 * std::fabs(tight));
			thinner += squareBound < tight;
		}
	}
	CAPTURE(applied);
	CAPTURE(tighter);
	CAPTURE(thinner);
	CAPTURE(slackTight);
	CAPTURE(slackApart);
	CHECK(applied > 600);                 // (measured: 1133 of the 1200 boxes)
	CHECK(tighter >= 0.95 * applied);     // (measured: all but two)
	CHECK(thinner >= 0.95 * applied);     // (measured: all)
	CHECK(slackTight < 0.1 * slackApart); // (measured: 0.032 of the slack)
	// The default shape has none.
	OrientedBox box;
	box.centre = Vec2(1.0, 0.5);
	box.halfLength = box.halfWidth = 0.1;
	CHECK(MakeSuperellipse(1.0, 0.5, 4.0, 4.0)->TightLevelLowerBound(box) == -std::numeric_limits<double>::infinity());
}

TEST_CASE("heart: CurvatureBounds holds the Hessian's eigenvalues over the disc, closely on small discs, and none near the axis")
{
	// Reference: the Hessian by central differences of the long-double level (HeartLevelRef,
	// steps of 1e-4 of |x|: errors near 1e-8 of it), its eigenvalues over 10 rings of 24
	// points covering the disc, and its centre. Discs of 1e-4 to 0.3 of the heart.
	Random rng(37);
	int applied = 0;
	const std::shared_ptr<HeartShape> hearts[] = {MakeHeart(0.3), MakeHeart(1.0), MakeHeart(4.0)};
	for (int i = 0; i < 900; ++i)
	{
		const HeartShape* h = hearts[i % 3].get();
		const double alpha = h->SurfaceLevel(), R = h->BoundingRadius();
		const Vec2 c(rng.Uniform(-1.5 * R, 1.5 * R), rng.Uniform(-1.5 * R, 1.5 * R));
		const double r = rng.LogUniform(1e-4 * R, 0.3 * R);
		double lowest = 0.0, highest = 0.0;
		const bool has = h->CurvatureBounds(c, r, lowest, highest);
		INFO("alpha ", alpha, ", disc (", c.x, ", ", c.y, ") of radius ", r);
		if (std::fabs(c.x) < 2.0 * r)
		{
			CHECK_FALSE(has); // off the axis only
			continue;
		}
		if (std::fabs(c.x) < 2.0 * r * (1.0 + 1e-6))
			continue; // (ρ/|cx| at 1/2, within rounding of where it stops applying)
		REQUIRE(has);
		++applied;
		double least = 1e300, most = -1e300;
		for (int ring = 0; ring <= 10; ++ring)
			for (int k = 0; k < (ring == 0 ? 1 : 24); ++k)
			{
				const double t = 2.0 * kPi * k / 24.0;
				const Vec2 x = c + (r * ring / 10.0) * Vec2(std::cos(t), std::sin(t));
				const long double e = 1e-4L * std::hypot(x.x, x.y);
				auto L = [&](long double dx, long double dy) { return (long double)HeartLevelRef(Vec2(double(x.x + dx), double(x.y + dy))); };
				const long double l0 = L(0, 0);
				const long double xx = (L(e, 0) - 2 * l0 + L(-e, 0)) / (e * e), yy = (L(0, e) - 2 * l0 + L(0, -e)) / (e * e);
				const long double xy = (L(e, e) - L(e, -e) - L(-e, e) + L(-e, -e)) / (4 * e * e);
				const long double mid = 0.5L * (xx + yy), half = std::sqrt(0.25L * (xx - yy) * (xx - yy) + xy * xy);
				least = std::min(least, double(mid - half));
				most = std::max(most, double(mid + half));
			}
		const double tol = 1e-6 * (std::fabs(least) + std::fabs(most) + 1.0);
		CHECK(lowest <= least + tol);
		CHECK(highest >= most - tol);
		// Small discs: the bounds are the eigenvalues' own bounds at the centre (2 + min(a, 0)
		// − e and 2 + max(a, 0) + e, which differ from them by at most e) within the disc's
		// spread of them.
		if (r < 1e-3 * std::fabs(c.x))
		{
			const double a = (2.0 / 9.0) * c.y / std::pow(std::fabs(c.x), 4.0 / 3.0), e = (2.0 / 3.0) / std::cbrt(std::fabs(c.x));
			CHECK(lowest >= least - e - 0.01 * (std::fabs(a) + e) - 1e-9);
			CHECK(highest <= most + e + 0.01 * (std::fabs(a) + e) + 1e-9);
		}
	}
	CAPTURE(applied);
	CHECK(applied > 500); // (measured: 853 of the 900 discs)
	// The default shape has none.
	double lowest = 0.0, highest = 0.0;
	CHECK_FALSE(MakeSuperellipse(1.0, 0.5, 4.0, 4.0)->CurvatureBounds(Vec2(1.0, 0.5), 0.1, lowest, highest));
}

TEST_CASE("heart: LevelSmoothOver is the discs off the axis")
{
	// α = x² + y² − |x|^{2/3} y is smooth wherever x ≠ 0 and has its kink on the axis.
	const auto h = MakeHeart(1.0);
	CHECK(h->LevelSmoothOver(Vec2(0.5, -0.3), 0.4));
	CHECK_FALSE(h->LevelSmoothOver(Vec2(0.5, -0.3), 0.6));
	CHECK_FALSE(h->LevelSmoothOver(Vec2(-0.01, -1.0), 0.02)); // the tip
	CHECK(h->LevelSmoothOver(Vec2(-0.03, -1.0), 0.02));
}

TEST_CASE("heart: LevelLowerBounds, two discs at a time, is LevelLowerBound bit for bit, and the default's is too")
{
	// The grid bounds its groups and runs through LevelLowerBounds, which the heart evaluates in
	// pairs of SSE2 lanes. Reference: LevelLowerBound, one disc at a time. Discs from 1e-150 to
	// 1e150 across, above and below the axis, on it (the cube root's argument 0), of radius 0,
	// and pairs with one disc non-finite or beyond the ranges where the pair path applies.
	const auto heart = MakeHeart(0.8);
	Random rng(32);
	std::vector<Vec2> centres;
	std::vector<double> radii;
	for (int i = 0; i < 2000; ++i)
	{
		const double scale = rng.LogUniform(1e-150, 1e150), angle = rng.Angle();
		centres.emplace_back(scale * std::cos(angle), scale * std::sin(angle));
		radii.push_back(i % 7 == 0 ? 0.0 : scale * rng.LogUniform(1e-6, 3.0));
	}
	const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
	const Vec2 odd[] = {Vec2(0.0, -0.5), Vec2(0.0, 0.5), Vec2(0.0, 0.0), Vec2(1e-160, 0.2), Vec2(1e160, 1.0), Vec2(inf, 0.0), Vec2(nan, 0.1)};
	for (const Vec2 c : odd)
		for (int order = 0; order < 2; ++order)
		{
			centres.push_back(order ? c : Vec2(0.3, -0.4));
			radii.push_back(0.1);
			centres.push_back(order ? Vec2(-0.6, 0.2) : c);
			radii.push_back(c.x == 0.0 ? 0.0 : 0.05);
		}
	std::vector<double> out(centres.size());
	heart->LevelLowerBounds(centres.data(), radii.data(), int(centres.size()), out.data());
	for (size_t i = 0; i < centres.size(); ++i)
	{
		CAPTURE(centres[i].x);
		CAPTURE(centres[i].y);
		CAPTURE(radii[i]);
		const double one = heart->LevelLowerBound(centres[i], radii[i]);
		if (std::isnan(one))
			CHECK(std::isnan(out[i]));
		else
			CHECK(out[i] == one);
	}
	// A shape without bounds of its own has none to give (the searches then bound nothing), and
	// the default loop answers −∞ for each disc.
	CHECK(MakeUserShape(UserHeartDef(0.8))->Bounds() == nullptr);
	struct NoBounds : LevelBounds
	{
	} plain;
	std::vector<double> none(3, 0.0);
	plain.LevelLowerBounds(centres.data(), radii.data(), 3, none.data());
	for (double b : none)
		CHECK(b == -std::numeric_limits<double>::infinity());
}

TEST_CASE("heart: Support's tip cone and tangency Newton agree with the sampled search of Shape::Support")
{
	// The reference is the generic search (best sample, then a bracketed root of the slope to
	// 1e-10 rad): on the smooth outline the values agree to rounding (the support value is flat
	// at its maximum), the points to the reference's angle tolerance times the size. At the tip
	// the reference closes on the corner only to its angle tolerance, below the exact tip.
	Random rng(47);
	for (double alpha : {0.02, 0.2, 1.0, 1.7, 40.0})
	{
		CAPTURE(alpha);
		const auto heart = MakeHeart(alpha);
		const double size = heart->BoundingRadius();
		int tips = 0;
		for (int i = 0; i < 2000; ++i)
		{
			const Vec2 d = Rotate(Rot(i < 8 ? i * 0.25 * kPi : rng.Angle()), Vec2(1.0, 0.0));
			CAPTURE(d.x);
			CAPTURE(d.y);
			const Vec2 p = heart->Support(d), ref = heart->Shape::Support(d);
			const bool tip = p.x == 0.0;
			CHECK(Dot(p, d) >= Dot(ref, d) - 1e-15 * size);
			CHECK(Dot(p, d) - Dot(ref, d) <= (tip ? 1e-10 : 1e-14) * size);
			CHECK(Length(p - ref) <= 1e-8 * size);
			CHECK(std::fabs(heart->Level(p) - alpha) <= 1e-14 * alpha);
			tips += p.x == 0.0 ? 1 : 0;
		}
		CHECK(tips > 200); // the tip's normal cone is a sizeable share of the directions
	}
}

TEST_CASE("heart: SupportBounds enclose the support value of an independent dense outline, closely")
{
	// Reference h(d): the outline in polar form, r² − r^{5/3} |cos θ|^{2/3} sin θ = α, its
	// outermost root on each of 20000 rays by bisection (scanned in from 3√α), the best
	// ray then refined by golden-section search between its neighbours, and the tip. Below the
	// true h by the search's tolerance alone.
	for (double alpha : {0.02, 0.2, 1.7})
	{
		CAPTURE(alpha);
		const auto heart = MakeHeart(alpha);
		const double size = heart->BoundingRadius();
		auto radius = [&](double t) {
			const double c = std::pow(std::fabs(std::cos(t)), 2.0 / 3.0), s = std::sin(t);
			auto f = [&](double r) { return r * r - std::pow(r, 5.0 / 3.0) * c * s - alpha; };
			const double step = 0.01 * std::sqrt(alpha);
			double lo = 3.0 * std::sqrt(alpha);
			for (int it = 0; it < 300 && f(lo) > 0.0; ++it)
				lo -= step;
			double hi = lo + step;
			for (int it = 0; it < 100; ++it)
			{
				const double mid = 0.5 * (lo + hi);
				(f(mid) > 0.0 ? hi : lo) = mid;
			}
			return Vec2(lo * std::cos(t), lo * std::sin(t));
		};
		const int rays = 20000;
		std::vector<Vec2> outline(rays);
		for (int k = 0; k < rays; ++k)
			outline[size_t(k)] = radius(2.0 * kPi * k / rays);
		Random rng(71);
		double widest = 0.0;
		for (int i = 0; i < 300; ++i)
		{
			const Vec2 d = rng.LogUniform(1e-1, 1e1) * Rotate(Rot(i < 8 ? i * 0.25 * kPi : rng.Angle()), Vec2(1.0, 0.0));
			CAPTURE(d.x);
			CAPTURE(d.y);
			int best = 0;
			for (int k = 1; k < rays; ++k)
				if (Dot(outline[size_t(k)], d) > Dot(outline[size_t(best)], d))
					best = k;
			// (The tip (0, −√α), a corner, where the search closes on the kink only to its angle
			// tolerance, 1e-11 of the size below.)
			const double h = std::max(GoldenMax([&](double t) { return Dot(radius(t), d); }, 2.0 * kPi * (best - 1) / rays,
			                                    2.0 * kPi * (best + 1) / rays),
			                          Dot(Vec2(0.0, -std::sqrt(alpha)), d));
			double lower = 0.0, upper = 0.0;
			heart->SupportBounds(d, lower, upper);
			CHECK_MESSAGE(lower <= h, "excess " << (lower - h) / (size * Length(d)));
			CHECK(h <= upper + 1e-13 * size * Length(d));
			// They hold the computed support value too (the separating-axis skips rely on it).
			const double computed = heart->SupportValue(d);
			CHECK(lower <= computed);
			CHECK(computed <= upper);
			widest = std::max(widest, (upper - lower) / (size * Length(d)));
		}
		// Close enough to decide most separating axes without a support: within 1e-3 of the size.
		CHECK(widest < 1e-3);
		CHECK(widest > 0.0);
	}
}

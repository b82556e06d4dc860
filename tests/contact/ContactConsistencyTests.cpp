// The contact's own consistency, against independent verdicts:
//  - touching == (separation ≤ 0) == (level ≤ own level), for convex pairs across separated,
//    overlapping and near-tangent placements, and the verdict agrees with an independent
//    long-double touching test;
//  - pointA and pointB lie on their particles' surfaces and on the line through `point` along
//    the normal, or, where that line misses a far-away particle, on the ray from its centre
//    towards `point` (the documented radial fallback), which never happens to touching pairs.
//
// Independent verdict: two convex particles touch exactly when A's centre lies in B or the
// smallest level of A over B's own surface is ≤ 1 (ContactReference.h: dense sampling of a
// closed-form parametrisation of B's surface plus golden-section/derivative polishing in long
// double). Near-tangent placements are built from the reference alone: the tangency distance
// along a ray is found by bisecting that verdict, then the pair is placed at (1 ± 1e-7) of it,
// far beyond both the reference's (~1e-15) and the solvers' (~1e-13) resolution.
//
// Surface tolerance: the points are Brent roots of λ − λ₀ along a line (or closed-form radial
// points), exact to a few ulps of their world coordinates. A coordinate error δ = 8·eps·(distance
// from the origin) changes the level by |∇λ|·δ, which is ~1e-15 for sizes ~1 near the origin
// (the brief's 1e-12 holds there) but grows with the distance and with a thin semi-axis (far
// apart, 2000 units away, semi-axis 0.05: ~1e-11). The heart's level r² − |x|^{2/3}·y is not
// Lipschitz on its axis: at its tip and notch a coordinate error δ moves the level by δ^{2/3}
// (1e-16 → 2e-11), an intrinsic limit of the shape function, not of the solver.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"
#include "ContactChecks.h"
#include "ContactPairs.h"
#include "ContactReference.h"

#include <limits>
#include <vector>

using namespace b2a;
using namespace b2a::test;
using ref::LD;
using ref::V;

namespace
{
// Reference copy of a library shape (superellipse family and hearts).
ref::RefShape RefOf(const Shape& s)
{
	if (const auto* se = dynamic_cast<const SuperellipseShape*>(&s))
		return ref::RefShape::Super(se->A(), se->B(), se->N(), se->M());
	if (const auto* h = dynamic_cast<const HeartShape*>(&s))
		return ref::RefShape::Heart(h->Alpha());
	FAIL("no reference for " << s.Describe());
	return {};
}

// Independent touching verdict for convex particles.
bool TouchingRef(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, LD* minLevel = nullptr)
{
	const ref::RefShape ra = RefOf(a), rb = RefOf(b);
	const ref::RefPose qa = ref::Of(pa), qb = ref::Of(pb);
	if (rb.Level(ref::ToBodyL(qb, qa.p)) <= rb.Own())
		return true;
	const LD m = ref::SurfaceMin(ra, qa, rb, qb, rb.Own(), 1024, 3).value / ra.Own();
	if (minLevel) *minLevel = m;
	return m <= 1.0L;
}

// Outcome of the point checks: how the points were placed.
struct PointCheck
{
	bool fallbackA = false, fallbackB = false;
};

// Tolerance on |λ(p)/λ₀ − 1| for a world point p of a posed shape (see the header comment).
double SurfaceTolerance(const Shape& s, const Pose& pose, Vec2 p)
{
	const double eps = std::numeric_limits<double>::epsilon();
	const double delta = 8.0 * eps * (Length(p) + Length(pose.p) + s.BoundingRadius());
	if (dynamic_cast<const HeartShape*>(&s))
		return 1e-12 + std::pow(delta, 2.0 / 3.0) / std::sqrt(s.SurfaceLevel());
	double gradient = 2.0 / s.BoundingRadius(); // user shapes: ellipse-like
	if (const auto* se = dynamic_cast<const SuperellipseShape*>(&s))
		gradient = std::max(se->N() / se->A(), se->M() / se->B());
	if (const auto* us = dynamic_cast<const UserShape*>(&s))
		gradient = 4.0 / std::min(us->Mass().area / us->BoundingRadius(), us->BoundingRadius());
	return 1e-12 + delta * gradient;
}

// pointA/pointB on their surfaces, and on the normal line through `point` or on the radial
// fallback ray; separation = (pointB − pointA)·normal up to the documented rounding fix-ups.
PointCheck CheckPoints(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const ContactResult& r)
{
	PointCheck out;
	const double size = a.BoundingRadius() + b.BoundingRadius();
	CHECK(std::fabs(RelativeLevel(a, pa, r.pointA) - 1.0) <= SurfaceTolerance(a, pa, r.pointA));
	CHECK(std::fabs(RelativeLevel(b, pb, r.pointB) - 1.0) <= SurfaceTolerance(b, pb, r.pointB));
	CHECK(std::fabs(Length(r.normal) - 1.0) <= 1e-14);
	auto onLine = [&](Vec2 p) { return std::fabs(Cross(p - r.point, r.normal)) <= 1e-9 * (size + Distance(p, r.point)); };
	auto onRay = [&](Vec2 p, Vec2 centre) {
		const Vec2 u = r.point - centre, w = p - centre;
		return std::fabs(Cross(w, u)) <= 1e-9 * Length(w) * Length(u) && Dot(w, u) > 0.0;
	};
	if (!onLine(r.pointA))
	{
		out.fallbackA = true;
		CHECK(onRay(r.pointA, pa.p));
	}
	if (!onLine(r.pointB))
	{
		out.fallbackB = true;
		CHECK(onRay(r.pointB, pb.p));
	}
	const double projected = Dot(r.pointB - r.pointA, r.normal);
	if (std::fabs(projected) > 1e-12 * size)
		CHECK(std::fabs(r.separation - projected) <= 1e-12 * size);
	else
		CHECK(std::fabs(r.separation) <= 1e-12 * size); // the documented rounding fix-up (0 or denorm_min)
	return out;
}

std::vector<std::pair<std::string, std::pair<ShapePtr, ShapePtr>>> ConvexPairs()
{
	return {
		{"circle-ellipse", {MakeCircle(0.6), MakeEllipse(1.6, 0.3)}},
		{"ellipse-ellipse", {MakeEllipse(2.0, 0.25), MakeEllipse(0.8, 1.3)}},
		{"superellipse-ellipse", {MakeSuperellipse(1.2, 0.8, 4.0, 6.0), MakeEllipse(1.0, 0.6)}},
		{"superellipse-superellipse", {MakeSuperellipse(1.0, 1.5, 2.5, 9.3), MakeSuperellipse(0.9, 0.6, 12.0, 3.0)}},
		{"cornered-ellipse", {MakeSuperellipse(1.0, 0.7, 1.5, 1.2), MakeEllipse(1.2, 0.5)}},
		{"diamond-superellipse", {MakeSuperellipse(1.0, 1.0, 1.0, 1.0), MakeSuperellipse(0.8, 1.2, 4.0, 4.0)}},
	};
}
} // namespace

TEST_CASE("convex pairs: touching == (separation <= 0) == (level <= 1), agreeing with an independent verdict, near tangency too")
{
	int cases = 0, touching = 0;
	for (const auto& item : ConvexPairs())
	{
		const auto& name = item.first;
		const auto& shapes = item.second;
		const auto& a = shapes.first;
		const auto& b = shapes.second;
		for (double dir : {0.4, 2.0, -2.6})
		{
			const Pose pa(Vec2(0.2, -0.1), 0.3 + dir), pb0(Vec2(0.0, 0.0), -0.7 + 2.0 * dir);
			const Vec2 u(std::cos(dir), std::sin(dir));
			auto placeB = [&](double d) { return Pose(pa.p + d * u, pb0.q.Angle()); };
			// Tangency distance along u by bisection of the independent verdict.
			double lo = 0.0, hi = 2.0 * (a->BoundingRadius() + b->BoundingRadius());
			for (int i = 0; i < 36; ++i) // 2^-36 ≈ 1.5e-11 of the bracket: ≪ the 1e-7 offsets below
			{
				const double mid = 0.5 * (lo + hi);
				(TouchingRef(*a, pa, *b, placeB(mid)) ? lo : hi) = mid;
			}
			const double tangent = 0.5 * (lo + hi);
			for (double f : {0.3, 0.8, 1.0 - 1e-7, 1.0 + 1e-7, 1.2, 3.0})
			{
				const Pose pb = placeB(f * tangent);
				const bool want = f < 1.0;
				CHECK(TouchingRef(*a, pa, *b, pb) == want); // the bisection itself
				INFO(name << " dir=" << dir << " f=" << f);
				for (MethodChoice m : {MethodChoice::automatic, MethodChoice::newton, MethodChoice::grid})
				{
					if (m == MethodChoice::newton && !(a->IsSmoothConvex() && b->IsSmoothConvex()))
						continue;
					INFO("method " << int(m));
					const ContactResult r = ComputeContact(*a, pa, *b, pb, m);
					REQUIRE(r.Ok());
					CHECK(AllFinite(r));
					CHECK(r.touching == want);
					CHECK(r.touching == (r.separation <= 0.0));
					CHECK(r.touching == (r.level <= 1.0));
					// The common-level solvers (not the one-sided grid) report C itself.
					if (m != MethodChoice::grid && a->IsSmoothConvex() && b->IsSmoothConvex())
					{
						const LevelResult level = SolveCommonLevel(*a, pa, *b, pb, m);
						REQUIRE(level.Ok());
						CHECK((level.level <= 1.0) == want);
					}
				}
				++cases;
				touching += want;
			}
		}
	}
	CHECK(cases == 6 * 3 * 6);
	CHECK(touching == 6 * 3 * 3);
}

TEST_CASE("every family: pointA and pointB lie on the surfaces, on the normal line or the documented radial fallback")
{
	const auto pairs = FamilyPairs();
	int fallbacks = 0, checked = 0;
	for (const PlacedPair& c : Place(pairs, {0.3, 0.7, 0.95, 1.5, 4.0}))
	{
		const ShapePair& p = *c.pair;
		INFO(p.name << " f=" << c.factor << " pb=(" << c.pb.p.x << "," << c.pb.p.y << ")");
		for (MethodChoice m : {MethodChoice::automatic, MethodChoice::grid})
		{
			INFO("method " << int(m));
			const ContactResult r = ComputeContact(*p.a, c.pa, *p.b, c.pb, m);
			REQUIRE(r.Ok());
			CHECK(AllFinite(r));
			CHECK(r.touching == (r.separation <= 0.0));
			const PointCheck pc = CheckPoints(*p.a, c.pa, *p.b, c.pb, r);
			// The fallback is for far-away particles only: a touching pair's point lies inside
			// both (or on both surfaces), so the line always leaves each particle.
			if (r.touching)
			{
				CHECK_FALSE(pc.fallbackA);
				CHECK_FALSE(pc.fallbackB);
			}
			fallbacks += pc.fallbackA + pc.fallbackB;
			++checked;
		}
	}
	CHECK(checked == int(pairs.size()) * 15 * 2);
	CHECK(fallbacks > 0); // the far placements (4 × the reach) exercise the fallback branch of CheckPoints
}

TEST_CASE("far-apart thin particles: the radial fallback puts the points on the surfaces, on the rays towards the common point")
{
	// Long thin ellipses far apart: the line through the common point along the normal misses a
	// particle, and the documented fallback applies. Both ways (line or ray) are checked by
	// CheckPoints; here the fallback must actually occur, and the separation stays positive.
	const auto thin = MakeEllipse(10.0, 0.05), other = MakeEllipse(0.05, 6.0);
	int fallbacks = 0;
	for (double angle : {0.3, 1.1, 2.0, 2.8})
		for (double dist : {200.0, 2000.0})
		{
			const Pose pa(Vec2(0.0, 0.0), 0.1), pb(dist * Vec2(std::cos(angle), std::sin(angle)), 0.7 - angle);
			INFO("angle=" << angle << " dist=" << dist);
			const ContactResult r = ComputeContact(*thin, pa, *other, pb);
			REQUIRE(r.Ok());
			CHECK_FALSE(r.touching);
			CHECK(r.separation > 0.0);
			const PointCheck pc = CheckPoints(*thin, pa, *other, pb, r);
			fallbacks += pc.fallbackA + pc.fallbackB;
		}
	CHECK(fallbacks > 0);
}

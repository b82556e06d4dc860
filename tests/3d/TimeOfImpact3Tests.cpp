// 3D time of impact for constant linear and angular velocities, against independent first
// contacts: the spheres' quadratic root in long double; for ellipsoids Perram–Wertheim's common
// level in long double with the poses moved in long double (Rodrigues), stepped and bisected;
// for superellipsoids a bracketing search (uniform steps, then bisection) on the contact's sign,
// and the long-double polish of the common level at the answer. And the paper's Figure 17.
#include <doctest/doctest.h>

#include "b2analytic/3d/SuperellipsoidShape.h"
#include "b2analytic/3d/TimeOfImpact3.h"
#include "Reference3.h"
#include "3d/Random3.h"

#include <cmath>
#include <functional>

using namespace b2a;
using namespace b2a::test;
namespace r3 = b2a::test::ref3;
using r3::LD;

namespace
{

// First t in [0, tMax] with touching(t): `steps` equal steps to the first touching one, then
// bisection to `resolution`; −1 when none.
LD FirstContact(const std::function<bool(LD)>& touching, LD tMax, int steps, LD resolution)
{
	if (touching(0.0L))
		return 0.0L;
	LD prev = 0.0L;
	for (int k = 1; k <= steps; ++k)
	{
		const LD t = tMax * k / steps;
		if (touching(t))
		{
			LD lo = prev, hi = t;
			while (hi - lo > resolution)
			{
				const LD mid = 0.5L * (lo + hi);
				(touching(mid) ? hi : lo) = mid;
			}
			return hi;
		}
		prev = t;
	}
	return -1.0L;
}

// Two bodies that meet within t ∈ [0, 1]: B starts away from A and heads for it, both turning.
void MovingPair(Random& rng, const Shape3& a, const Shape3& b, Motion3& ma, Motion3& mb)
{
	const double reach = a.BoundingRadius() + b.BoundingRadius();
	ma.pose = Pose3(Vec3(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)), RandomRotation(rng));
	const Vec3 away = RandomUnit(rng);
	mb.pose = Pose3(ma.pose.p + 2.0 * reach * away, RandomRotation(rng));
	ma.velocity = 0.2 * reach * RandomUnit(rng);
	mb.velocity = ma.velocity - 2.5 * reach * away + 0.3 * reach * RandomUnit(rng);
	ma.angularVelocity = rng.Uniform(0, 3) * RandomUnit(rng);
	mb.angularVelocity = rng.Uniform(0, 3) * RandomUnit(rng);
}
} // namespace

TEST_CASE("3D time of impact: spheres against the quadratic root")
{
	Random rng(3);
	for (int k = 0; k < 50; ++k)
	{
		const auto a = MakeSphere(rng.Uniform(0.2, 2)), b = MakeSphere(rng.Uniform(0.2, 2));
		Motion3 ma, mb;
		MovingPair(rng, *a, *b, ma, mb);
		const TimeOfImpactResult3 r = TimeOfImpact(*a, ma, *b, mb, 1.0);
		REQUIRE(r.Ok());
		// |d + w t| = ra + rb, the smaller root, in long double.
		const r3::V3 d = r3::From(mb.pose.p - ma.pose.p), w = r3::From(mb.velocity - ma.velocity);
		const LD R = LD(a->BoundingRadius()) + b->BoundingRadius();
		const LD A = r3::Dot(w, w), B = r3::Dot(d, w), C = r3::Dot(d, d) - R * R;
		const LD disc = B * B - A * C;
		const bool hits = disc >= 0.0L && (-B - std::sqrt(disc)) / A <= 1.0L && (-B + std::sqrt(disc)) >= 0.0L;
		CHECK(r.hit == hits);
		if (hits)
		{
			const LD t = std::max(0.0L, (-B - std::sqrt(disc)) / A);
			CHECK(std::fabs(r.time - double(t)) < 1e-12);
			CHECK(r.contact.touching);
			CHECK(std::fabs(r.contact.separation) < 1e-9);
		}
	}
}

TEST_CASE("3D time of impact: turning ellipsoids against Perram-Wertheim stepped in long double")
{
	Random rng(5);
	for (int k = 0; k < 12; ++k)
	{
		const auto a = MakeEllipsoid(rng.Uniform(0.5, 2), rng.Uniform(0.2, 1), rng.Uniform(0.1, 1));
		const auto b = MakeEllipsoid(rng.Uniform(0.5, 3), rng.Uniform(0.2, 1), rng.Uniform(0.3, 1));
		Motion3 ma, mb;
		MovingPair(rng, *a, *b, ma, mb);
		const TimeOfImpactResult3 r = TimeOfImpact(*a, ma, *b, mb, 1.0);
		REQUIRE(r.Ok());
		const r3::Shape A(*a), B(*b);
		auto touching = [&](LD t) {
			const r3::Pose pa = r3::Pose::Moving(ma.pose, ma.velocity, ma.angularVelocity, t);
			const r3::Pose pb = r3::Pose::Moving(mb.pose, mb.velocity, mb.angularVelocity, t);
			return r3::PerramWertheim(A, pa, B, pb).level <= 1.0L;
		};
		const LD ref = FirstContact(touching, 1.0L, 2000, 1e-15L);
		CHECK(r.hit == (ref >= 0.0L));
		if (r.hit && ref >= 0.0L)
			CHECK(std::fabs(r.time - double(ref)) < 1e-9);
	}
}

TEST_CASE("3D time of impact: superellipsoids against a bracketing search")
{
	Random rng(7);
	for (int k = 0; k < 12; ++k)
	{
		const auto a = MakeSuperellipsoid(rng.Uniform(0.5, 2), rng.Uniform(0.5, 2), rng.Uniform(0.5, 2), rng.Uniform(2, 12),
		                                  rng.Uniform(2, 12), rng.Uniform(2, 12));
		const auto b = MakeSuperellipsoid(rng.Uniform(0.5, 2), rng.Uniform(0.5, 2), rng.Uniform(0.5, 2), rng.Uniform(2, 12),
		                                  rng.Uniform(2, 12), rng.Uniform(2, 12));
		Motion3 ma, mb;
		MovingPair(rng, *a, *b, ma, mb);
		const TimeOfImpactResult3 r = TimeOfImpact(*a, ma, *b, mb, 1.0);
		REQUIRE(r.Ok());
		auto touching = [&](LD t) { return ComputeContact(*a, ma.At(double(t)), *b, mb.At(double(t))).touching; };
		const LD ref = FirstContact(touching, 1.0L, 4000, 1e-14L);
		CHECK(r.hit == (ref >= 0.0L));
		if (r.hit && ref >= 0.0L)
		{
			CHECK(std::fabs(r.time - double(ref)) < 1e-11);
			// The common level at the answer is 1, in long double.
			const r3::Shape A(*a), B(*b);
			const Pose3 pa = ma.At(r.time), pb = mb.At(r.time);
			const r3::Pose la(pa), lb(pb);
			const r3::V3 X = r3::From(r.contact.point);
			const r3::V3 ga = la.Rotate(A.Gradient(la.ToBody(X))), gb = lb.Rotate(B.Gradient(lb.ToBody(X)));
			const r3::SurfaceMinimum m = r3::Polish(A, la, B, lb, X, -r3::Dot(ga, gb) / r3::Dot(gb, gb));
			CHECK(std::fabs(double(m.level) - 1.0) < 1e-11);
		}
	}
}

TEST_CASE("3D time of impact: the paper's Figure 17 touches at 0.1924 ms")
{
	// |x/4|^6 + |y/4|^6 + |z/4|^12 and |x/2|^8 + |y/3|^8 + |z/2|^8, lengths in mm, time in ms,
	// z-x-z Euler angles, angular velocities in rad/ms about the world axes.
	const auto a = MakeSuperellipsoid(4, 4, 4, 6, 6, 12), b = MakeSuperellipsoid(2, 3, 2, 8, 8, 8);
	Motion3 ma{Pose3(Vec3(-10, -15, -10), EulerZXZ(kPi / 9, kPi / 8, kPi / 7)), Vec3(-20, -10, -15), Vec3(20, -30, 2)};
	Motion3 mb{Pose3(Vec3(-20, -25, -20), EulerZXZ(kPi / 6, kPi / 5, kPi / 4)), Vec3(10, 20, 15), Vec3(-10, 20, -2)};
	const TimeOfImpactResult3 r = TimeOfImpact(*a, ma, *b, mb, 1.0);
	REQUIRE(r.Ok());
	REQUIRE(r.hit);
	CHECK(std::fabs(r.time - 0.1924) < 1e-3);
	auto touching = [&](LD t) { return ComputeContact(*a, ma.At(double(t)), *b, mb.At(double(t))).touching; };
	const LD ref = FirstContact(touching, 0.3L, 3000, 1e-15L);
	CHECK(std::fabs(r.time - double(ref)) < 1e-9 * 0.1924);
	CHECK(r.contact.level == doctest::Approx(1.0).epsilon(1e-11));
	CHECK(std::fabs(r.contact.separation) < 1e-9);
	// The common level there is 1 in long double, with the poses moved in long double.
	{
		const r3::Shape A(*a), B(*b);
		const r3::Pose la = r3::Pose::Moving(ma.pose, ma.velocity, ma.angularVelocity, r.time);
		const r3::Pose lb = r3::Pose::Moving(mb.pose, mb.velocity, mb.angularVelocity, r.time);
		const r3::V3 X = r3::From(r.contact.point);
		const r3::V3 ga = la.Rotate(A.Gradient(la.ToBody(X))), gb = lb.Rotate(B.Gradient(lb.ToBody(X)));
		const r3::SurfaceMinimum m = r3::Polish(A, la, B, lb, X, -r3::Dot(ga, gb) / r3::Dot(gb, gb));
		CHECK(std::fabs(double(m.level) - 1.0) < 1e-11);
	}
	// The particles had not touched at any earlier step of a fine scan (first contact, not any).
	for (int k = 0; k < 1000; ++k)
		CHECK_FALSE(ComputeContact(*a, ma.At(r.time * k / 1000.0), *b, mb.At(r.time * k / 1000.0)).touching);
}

TEST_CASE("3D time of impact: misses, touching at the start, bad input")
{
	const auto a = MakeSuperellipsoid(1, 1, 1, 4, 4, 4), b = MakeEllipsoid(1, 0.5, 0.5);
	Motion3 ma{Pose3(Vec3(0, 0, 0), Quat()), Vec3(), Vec3(0, 0, 1)};
	Motion3 mb{Pose3(Vec3(5, 0, 0), Quat()), Vec3(0, 1, 0), Vec3(1, 0, 0)};
	TimeOfImpactResult3 r = TimeOfImpact(*a, ma, *b, mb, 10.0);
	REQUIRE(r.Ok());
	CHECK_FALSE(r.hit);
	CHECK(r.time == 10.0);
	mb.pose.p = Vec3(1.5, 0, 0);
	r = TimeOfImpact(*a, ma, *b, mb, 10.0);
	REQUIRE(r.Ok());
	CHECK(r.hit);
	CHECK(r.time == 0.0);
	CHECK_FALSE(TimeOfImpact(*a, ma, *b, mb, -1.0).Ok());
	CHECK_FALSE(TimeOfImpact(*a, ma, *b, mb, NAN).Ok());
	mb.velocity = Vec3(NAN, 0, 0);
	CHECK(std::string(TimeOfImpact(*a, ma, *b, mb, 1.0).failure) == "motions must be finite, with unit quaternions");
}

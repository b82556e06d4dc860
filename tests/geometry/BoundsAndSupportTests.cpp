// Support points, world AABBs and bounding radii against brute-force extremes over the surface.
#include <doctest/doctest.h>

#include "GeometryReference.h"
#include "TestSupport.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>

using namespace b2a;
using namespace b2a::test;

namespace
{
// Reference extremes come from a dense surface polygon (100000 points; 20000 for user shapes,
// whose surface points are nested root solves) refined by golden-section search between the
// neighbours of the best polygon vertex. Built once per shape.
const DenseSurface& Dense(const ShapeCase& c)
{
	static std::map<std::string, std::unique_ptr<DenseSurface>> cache;
	auto& slot = cache[c.name];
	if (!slot)
		slot = std::make_unique<DenseSurface>(*c.shape, dynamic_cast<const UserShape*>(c.shape.get()) ? 20000 : 100000);
	return *slot;
}

// Tolerance of a refined extreme, relative to the shape's size: the golden-section reference
// and the library's support are both exact to a few ulps (observed ≤ 5e-15 of the size; the
// heart's cusp tip by its closed form, Extreme), so 1e-12 leaves a wide margin while still catching any support
// that is only sample-accurate (≈ maxDeviation, 1e-5 at 1024 samples).
const double kExtremeTol = 1e-12;

// The refined extreme of g over the surface, and for a heart no less than g at its exact tip
// (0, −√α) (the level there is y²): the dense reference meets the cusp only at the polar angle
// nearest −π/2, whose cosine 6e-17 puts it (6e-17)^{2/3}/2 ≈ 1e-11 of the size above the tip.
double Extreme(const ShapeCase& c, const std::function<double(Vec2)>& g, double* polygonMax = nullptr)
{
	const double dense = Dense(c).Max(g, polygonMax);
	if (const auto* heart = dynamic_cast<const HeartShape*>(c.shape.get()))
		return std::max(dense, g(Vec2(0.0, -std::sqrt(heart->Alpha()))));
	return dense;
}

const char* const kAabbShapes[] = {"ellipse 1000:1 a=0.1 b=100", "ellipse a=3 b=0.8", "heart alpha=1", "heart alpha=2.5",
                                   "superellipse n=3 m=5", "superellipse n=m=1.5", "superellipse n=1 m=3", "superellipse n=m=60",
                                   "zeta form zeta=0.8", "user heart alpha=1.3 (analytic G derivatives)"};
} // namespace

TEST_CASE("AABB: contains every surface sample and touches the shape on all four sides")
{
	for (const char* name : kAabbShapes)
	{
		const ShapeCase& c = FindShapeCase(name);
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		const auto smp = s.Samples(1024);
		const double size = s.BoundingRadius();
		Random rng(81);
		for (int i = 0; i < 12; ++i)
		{
			// Axis-aligned poses first (the support directions are then the body axes), then random.
			const double angle = i < 4 ? i * 0.5 * kPi : rng.Angle();
			const Pose pose(Vec2(rng.Uniform(-50, 50), rng.Uniform(-50, 50)), angle);
			CAPTURE(angle);
			const Box box = s.ComputeAABB(pose);
			const double tol = kExtremeTol * size + 1e-15 * Length(pose.p); // world coordinates round at |p|
			// Contains every sample.
			double gap[4] = {1e300, 1e300, 1e300, 1e300};
			for (const Vec2& b : smp->point)
			{
				const Vec2 w = ToWorld(pose, b);
				CHECK(w.x <= box.upper.x + tol);
				CHECK(w.x >= box.lower.x - tol);
				CHECK(w.y <= box.upper.y + tol);
				CHECK(w.y >= box.lower.y - tol);
				gap[0] = std::min(gap[0], box.upper.x - w.x);
				gap[1] = std::min(gap[1], w.x - box.lower.x);
				gap[2] = std::min(gap[2], box.upper.y - w.y);
				gap[3] = std::min(gap[3], w.y - box.lower.y);
			}
			// Touches: the point where a side touches lies on the arc between two consecutive
			// samples, whose length is at most chord + 2 × deviation, so some sample is that close.
			for (double g : gap)
				CHECK(g <= smp->maxSpacing + 2.0 * smp->maxDeviation);
			// Exactly: each side equals the brute-force extreme of the surface in world coordinates.
			auto wx = [&](Vec2 b) { return ToWorld(pose, b).x; };
			auto wy = [&](Vec2 b) { return ToWorld(pose, b).y; };
			double poly = 0.0;
			const double ux = Extreme(c, wx, &poly);
			CHECK(box.upper.x >= poly - tol);
			CHECK(std::fabs(box.upper.x - ux) <= tol);
			CHECK(std::fabs(box.lower.x + Extreme(c, [&](Vec2 b) { return -wx(b); })) <= tol);
			CHECK(std::fabs(box.upper.y - Extreme(c, wy)) <= tol);
			CHECK(std::fabs(box.lower.y + Extreme(c, [&](Vec2 b) { return -wy(b); })) <= tol);
		}
	}
}

TEST_CASE("AABB: ellipses match the closed-form half extents")
{
	// An ellipse rotated by θ has half extents √(a²cos²θ + b²sin²θ) and √(a²sin²θ + b²cos²θ).
	Random rng(82);
	for (const auto& ab : {std::pair{0.1, 100.0}, std::pair{3.0, 0.8}, std::pair{1.7, 1.7}})
	{
		const double a = ab.first, b = ab.second;
		const auto s = a == b ? MakeCircle(a) : MakeEllipse(a, b);
		for (int i = 0; i < 200; ++i)
		{
			const Pose pose(Vec2(rng.Uniform(-1e3, 1e3), rng.Uniform(-1e3, 1e3)), rng.Angle());
			const double c = pose.q.c, sn = pose.q.s;
			const double hx = std::sqrt(a * a * c * c + b * b * sn * sn), hy = std::sqrt(a * a * sn * sn + b * b * c * c);
			const Box box = s->ComputeAABB(pose);
			const double tol = 1e-14 * std::max(a, b) + 4e-16 * Length(pose.p);
			CHECK(std::fabs(box.upper.x - (pose.p.x + hx)) <= tol);
			CHECK(std::fabs(box.lower.x - (pose.p.x - hx)) <= tol);
			CHECK(std::fabs(box.upper.y - (pose.p.y + hy)) <= tol);
			CHECK(std::fabs(box.lower.y - (pose.p.y - hy)) <= tol);
		}
	}
}

TEST_CASE("Support: the value is the maximum over the boundary and the point is on the surface")
{
	// Convex shapes, and the heart (whose support is that of its convex hull).
	for (const ShapeCase& c : AllShapeKinds())
	{
		if (!c.shape->IsConvex() && !dynamic_cast<const HeartShape*>(c.shape.get())) continue;
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		const double size = s.BoundingRadius(), tol = kExtremeTol * size;
		Random rng(83);
		for (int i = 0; i < 40; ++i)
		{
			const Vec2 dir = i < 4 ? Rotate(Rot(i * 0.5 * kPi), Vec2(1, 0)) : Rotate(Rot(rng.Angle()), Vec2(1, 0));
			CAPTURE(dir.x);
			CAPTURE(dir.y);
			const Vec2 p = s.Support(dir);
			CHECK(RelativeError(s.Level(p), s.SurfaceLevel()) < 1e-12);
			double poly = 0.0;
			const double ref = Extreme(c, [&](Vec2 b) { return Dot(b, dir); }, &poly);
			CHECK(Dot(p, dir) >= poly - 1e-15 * size);
			CHECK(std::fabs(Dot(p, dir) - ref) <= tol);
			// d need not be unit: any positive scale gives the same support value.
			for (double scale : {1e-150, 1e-3, 1e3, 1e150})
			{
				CAPTURE(scale);
				CHECK(std::fabs(Dot(s.Support(scale * dir), dir) - Dot(p, dir)) <= tol);
			}
		}
	}
}

TEST_CASE("BoundingRadius: equals the largest distance from the origin to the surface")
{
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		double poly = 0.0;
		const double ref = Dense(c).Max([](Vec2 b) { return Length(b); }, &poly);
		CHECK(c.shape->BoundingRadius() >= poly * (1.0 - 1e-15));
		CHECK(RelativeError(c.shape->BoundingRadius(), ref) < kExtremeTol);
	}
	// Closed forms: max(a, b) for ellipses and for n, m ≤ 2 (the shape then lies inside the
	// ellipse with the same axes); a·2^{1/2 − 1/n} on the diagonal for a = b, n = m ≥ 2.
	CHECK(MakeCircle(1.7)->BoundingRadius() == 1.7);
	CHECK(MakeEllipse(0.1, 100.0)->BoundingRadius() == 100.0);
	CHECK(MakeEllipse(3.0, 0.8)->BoundingRadius() == 3.0);
	CHECK(MakeSuperellipse(1.0, 2.0, 1.5, 2.0)->BoundingRadius() == 2.0);
	CHECK(MakeSuperellipse(2.0, 1.0, 1.0, 1.0)->BoundingRadius() == 2.0);
	for (double n : {3.0, 4.0, 7.5, 60.0})
	{
		CAPTURE(n);
		CHECK(RelativeError(MakeSuperellipse(1.3, 1.3, n, n)->BoundingRadius(), 1.3 * std::pow(2.0, 0.5 - 1.0 / n)) < 1e-13);
	}
}

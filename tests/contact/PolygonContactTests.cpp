// ComputePolygonContact (an analytic particle against a Box2D polygon or segment, by the
// separating axis) against independent references.
//
// Circle: for a centre c outside a convex polygon P the largest separating-axis gap is the
// signed distance |c − P| − r, along the direction from c to its nearest point of P.
// Ellipse: the gap along n is min over P's vertices of v·n minus the ellipse's support value
// c·n + |(a·n_body.x, b·n_body.y)|; its maximum over n is found here by brute force (4096 angles,
// then golden-section search between the best one's neighbours), never exceeding the true one.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
// Distance from p to the segment [u, v].
double SegmentDistance(Vec2 p, Vec2 u, Vec2 v)
{
	const Vec2 e = v - u;
	const double t = std::clamp(Dot(p - u, e) / LengthSquared(e), 0.0, 1.0);
	return Length(p - (u + t * e));
}

// Largest gap over directions between a shape, given by its world support value along a unit
// direction, and world vertices w, by brute force: `samples` angles, then golden-section search
// between the best one's neighbours. Never exceeds the true maximum; `angle` is the maximiser.
template <typename SupportValue>
double GapByScan(const SupportValue& support, const std::vector<Vec2>& w, int samples, double& angle)
{
	auto gap = [&](double t) {
		const Vec2 n(std::cos(t), std::sin(t));
		double lowest = std::numeric_limits<double>::infinity();
		for (const Vec2& v : w)
			lowest = std::min(lowest, Dot(v, n));
		return lowest - support(n);
	};
	std::vector<double> g(static_cast<size_t>(samples));
	for (int k = 0; k < samples; ++k)
		g[size_t(k)] = gap(2.0 * kPi * k / samples);
	int best = 0;
	for (int k = 1; k < samples; ++k)
		best = g[size_t(k)] > g[size_t(best)] ? k : best;
	double lo = 2.0 * kPi * (best - 1) / samples, hi = 2.0 * kPi * (best + 1) / samples;
	const double r = 0.6180339887498949;
	double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo), g1 = gap(x1), g2 = gap(x2);
	for (int it = 0; it < 200 && hi - lo > 1e-15; ++it)
	{
		if (g1 < g2) { lo = x1; x1 = x2; g1 = g2; x2 = lo + r * (hi - lo); g2 = gap(x2); }
		else { hi = x2; x2 = x1; g2 = g1; x1 = hi - r * (hi - lo); g1 = gap(x1); }
	}
	angle = 0.5 * (lo + hi);
	return std::max(g1, g2);
}

// A 2 x 1 box and a long segment, alternately, turned by a small random angle about the origin,
// and a random place along the top face: the face-contact scans below share them.
struct FaceCase
{
	const Vec2* v = nullptr;
	int count = 0;
	Pose pb;
	double along = 0.0;  // where along the top face the particle is put
	double top = 0.0;    // the top face's height in the polygon's frame
	std::vector<Vec2> w; // the vertices in the world
};

FaceCase MakeFaceCase(int i, Random& rng, double alongRange)
{
	static const Vec2 box[] = {{-1.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}, {-1.0, 0.5}};
	static const Vec2 segment[] = {{-2.0, 0.0}, {2.0, 0.0}};
	FaceCase f;
	const bool isBox = i % 2 == 0;
	f.v = isBox ? box : segment;
	f.count = isBox ? 4 : 2;
	f.pb = Pose(Vec2(), rng.Uniform(-0.3, 0.3));
	f.along = rng.Uniform(-alongRange, alongRange);
	f.top = isBox ? 0.5 : 0.0;
	for (int j = 0; j < f.count; ++j)
		f.w.push_back(ToWorld(f.pb, f.v[j]));
	return f;
}
} // namespace

TEST_CASE("polygon contact: a circle against boxes and segments gets the signed distance to the polygon")
{
	const auto circle = MakeCircle(0.4);
	const Vec2 box[] = {{-1.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}, {-1.0, 0.5}};
	const Vec2 segment[] = {{-2.0, 0.0}, {2.0, 0.0}};
	Random rng(61);
	for (int i = 0; i < 400; ++i)
	{
		const bool isBox = i % 2 == 0;
		const Vec2* v = isBox ? box : segment;
		const int count = isBox ? 4 : 2;
		const Pose pb(Vec2(rng.Uniform(-0.5, 0.5), rng.Uniform(-0.5, 0.5)), rng.Angle());
		// A centre outside the polygon: from resting on a face (most of the cases a scene has)
		// to beyond the corners, touching or apart.
		Vec2 c;
		double distance = 0.0;
		do
		{
			c = Vec2(rng.Uniform(-2.6, 2.6), rng.Uniform(-1.6, 1.6));
			c = ToWorld(pb, c);
			distance = std::numeric_limits<double>::infinity();
			for (int j = 0; j < count; ++j)
				distance = std::min(distance, SegmentDistance(c, ToWorld(pb, v[j]), ToWorld(pb, v[(j + 1) % count])));
		} while (isBox && InvRotate(pb.q, c - pb.p).x > -1.0 && InvRotate(pb.q, c - pb.p).x < 1.0 &&
		         std::fabs(InvRotate(pb.q, c - pb.p).y) < 0.5);
		if (!(distance > 1e-6))
			continue;
		const Pose pa(c, rng.Angle());
		CAPTURE(i);
		CAPTURE(c.x);
		CAPTURE(c.y);
		const ContactResult r = ComputePolygonContact(*circle, pa, v, count, pb);
		REQUIRE(r.Ok());
		CHECK(std::fabs(r.separation - (distance - 0.4)) <= 1e-10);
		CHECK(r.touching == (distance - 0.4 <= 0.0));
		// The normal points from the centre to its nearest point of the polygon.
		CHECK(Distance(pa.p + distance * r.normal, r.pointA + r.separation * r.normal) <= 1e-8);
	}
}

TEST_CASE("polygon contact: an ellipse against boxes and segments matches the brute-force largest gap")
{
	const double a = 0.7, b = 0.25;
	const auto ellipse = MakeEllipse(a, b);
	Random rng(62);
	int resting = 0;
	for (int i = 0; i < 300; ++i)
	{
		// Above the top face, from a clearance of 0.3 down to an overlap of 0.1, anywhere along it
		// and past its ends; tilted from flat to upright.
		const FaceCase f = MakeFaceCase(i, rng, 2.6);
		const double along = f.along;
		const double tilt = rng.Uniform(-kPi, kPi) * (i % 3 == 0 ? 0.02 : 1.0);
		const double rise = std::hypot(a * std::sin(tilt), b * std::cos(tilt)); // support along y
		const Pose pa(ToWorld(f.pb, Vec2(along, f.top + rise + rng.Uniform(-0.1, 0.3))), Rot(tilt + f.pb.q.Angle()));
		auto support = [&](Vec2 n) {
			const Vec2 nb = InvRotate(pa.q, n);
			return Dot(pa.p, n) + std::hypot(a * nb.x, b * nb.y);
		};
		double angle = 0.0;
		const double reference = GapByScan(support, f.w, 4096, angle);
		CAPTURE(i);
		CAPTURE(along);
		CAPTURE(tilt);
		const ContactResult r = ComputePolygonContact(*ellipse, pa, f.v, f.count, f.pb);
		REQUIRE(r.Ok());
		// The reference never exceeds the true maximum; golden search leaves it ~1e-15 below.
		CHECK(r.separation >= reference - 1e-12);
		CHECK(r.separation <= reference + 1e-9);
		CHECK(std::fabs(Cross(r.normal, Vec2(std::cos(angle), std::sin(angle)))) <= 1e-6);
		if (std::fabs(along) < 0.5 && std::fabs(tilt) < 0.05)
			++resting;
	}
	CHECK(resting > 10); // the resting-on-a-face case (a face normal as the answer) is exercised
}

TEST_CASE("polygon contact: a heart against boxes and segments matches the brute-force largest gap")
{
	// The heart's hull has a flat between its lobes and a corner at its tip, so a face normal
	// is taken as the answer only where the heart's support there is one point. Reference: the
	// gap over 1024 directions with the generic support search (Shape::Support, independent of
	// the heart's own), then golden-section search between the best one's neighbours.
	const auto heart = MakeHeart(0.2);
	Random rng(63);
	int resting = 0;
	for (int i = 0; i < 120; ++i)
	{
		// Upright, upside down (on both lobes) or at any angle; above the top face from a
		// clearance of 0.2 down to an overlap of 0.05.
		const FaceCase f = MakeFaceCase(i, rng, 2.4);
		const double along = f.along;
		const double tilt = i % 3 == 0 ? rng.Uniform(-0.02, 0.02) : i % 3 == 1 ? kPi + rng.Uniform(-0.02, 0.02) : rng.Angle();
		const Rot q(tilt + f.pb.q.Angle());
		const Vec2 up = Rotate(f.pb.q, Vec2(0.0, 1.0));
		const double rise = -Dot(Rotate(q, heart->Shape::Support(InvRotate(q, -1.0 * up))), up);
		const Pose pa(ToWorld(f.pb, Vec2(along, f.top + rise + rng.Uniform(-0.05, 0.2))), q);
		auto support = [&](Vec2 n) { return Dot(ToWorld(pa, heart->Shape::Support(InvRotate(pa.q, n))), n); };
		double angle = 0.0;
		const double reference = GapByScan(support, f.w, 1024, angle);
		CAPTURE(i);
		CAPTURE(along);
		CAPTURE(tilt);
		const ContactResult c = ComputePolygonContact(*heart, pa, f.v, f.count, f.pb);
		REQUIRE(c.Ok());
		// The generic support reaches the tip only to 1e-11 of the size (the reference's gap is
		// then that much larger); golden search leaves the reference ~1e-15 below its maximum.
		CHECK(c.separation >= reference - 1e-10);
		CHECK(c.separation <= reference + 1e-9);
		CHECK(std::fabs(Cross(c.normal, Vec2(std::cos(angle), std::sin(angle)))) <= 1e-6);
		if (std::fabs(along) < 0.8 && i % 3 != 2)
			++resting;
	}
	CHECK(resting > 10); // the resting-on-a-face cases (tip or lobes on the face) are exercised
}

namespace
{
// A superellipse under another class: every query forwarded, but SupportBounds left exact (the
// default) and SupportBoundsCheap not declared, so SeparatingAxisContact takes every candidate's
// support, as it did before its superellipses skipped those their bounds rule out.
class PlainForwarding final : public Shape
{
public:
	explicit PlainForwarding(ShapePtr inner)
		: Shape(inner->Kind(), inner->SurfaceLevel(), inner->IsConvex(), inner->IsSmoothConvex(), inner->LevelPower()),
		  m_inner(std::move(inner))
	{
		Finalize(m_inner->BoundingRadius(), &m_inner->Mass());
	}
	std::string Describe() const override { return "forwarding " + m_inner->Describe(); }
	double Level(Vec2 x) const override { return m_inner->Level(x); }
	LevelDerivatives Derivatives(Vec2 x) const override { return m_inner->Derivatives(x); }
	double RadiusAt(Vec2 u, double level) const override { return m_inner->RadiusAt(u, level); }
	Vec2 Support(Vec2 d) const override { return m_inner->Support(d); }
	double SupportValue(Vec2 d) const override { return m_inner->SupportValue(d); }

private:
	ShapePtr m_inner;
};

// A user's shape of a kind of its own, registered at run time: the ellipse (x/a)² + (y/b)² ≤ 1
// with its closed-form support h(d) = |(a·dx, b·dy)| and cheap bounds of it, max(|a·dx|, |b·dy|)
// ≤ h ≤ |a·dx| + |b·dy| (no square root), which it declares cheap (SupportBoundsCheap) only when
// `cheap` is set.
class BoundedEllipse final : public Shape
{
public:
	BoundedEllipse(double a, double b, bool cheap) : Shape(RegisteredKind(), 1.0, true, true, 1.0), m_a(a), m_b(b)
	{
		if (cheap)
			SetSupportBoundsCheap();
		Finalize(std::max(a, b), nullptr);
	}
	std::string Describe() const override { return "bounded ellipse(a=" + FormatNumber(m_a) + ", b=" + FormatNumber(m_b) + ")"; }
	double Level(Vec2 x) const override { return (x.x / m_a) * (x.x / m_a) + (x.y / m_b) * (x.y / m_b); }
	LevelDerivatives Derivatives(Vec2 x) const override
	{
		LevelDerivatives d;
		d.value = Level(x);
		d.gradient = Vec2(2.0 * x.x / (m_a * m_a), 2.0 * x.y / (m_b * m_b));
		d.hessian.xx = 2.0 / (m_a * m_a);
		d.hessian.yy = 2.0 / (m_b * m_b);
		return d;
	}
	Vec2 Support(Vec2 d) const override
	{
		const Vec2 e(m_a * d.x, m_b * d.y);
		return Vec2(m_a * e.x, m_b * e.y) / Length(e);
	}
	void SupportBounds(Vec2 d, double& lower, double& upper) const override
	{
		const double ex = std::fabs(m_a * d.x), ey = std::fabs(m_b * d.y);
		lower = std::max(ex, ey) * (1.0 - 1e-12);
		upper = (ex + ey) * (1.0 + 1e-12);
	}
	static ShapeKind RegisteredKind()
	{
		const ShapeKind found = FindShapeKind("test_bounded_ellipse");
		return found.Valid() ? found : RegisterShapeKind("test_bounded_ellipse", 2, SolverClass::smoothConvex);
	}

private:
	double m_a, m_b;
};

// SeparatingAxisContact of `shape` and of `twin` (the same particle, taking every candidate's
// support) against a box and a segment, alternately, in 200 random poses: resting flat (a third),
// tilted or at any angle; from 0.1 into the face to 0.4 above it, anywhere along it and past its
// ends. Normal, separation and points must agree bit for bit, with no more gap evaluations;
// `fewer` adds up the evaluations saved. Where `ellipse` gives the particle's semi-axes, the
// separation must also match the largest gap by scanning directions (GapByScan).
void CompareSkipped(const Shape& shape, const Shape& twin, Random& rng, long& fewer, long& calls, const Vec2* ellipse = nullptr)
{
	const Vec2 box[] = {{-1.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}, {-1.0, 0.5}};
	const Vec2 segment[] = {{-2.0, 0.0}, {2.0, 0.0}};
	for (int i = 0; i < 200; ++i)
	{
		const bool isBox = i % 2 == 0;
		const Vec2* v = isBox ? box : segment;
		const int count = isBox ? 4 : 2;
		const Pose pb(Vec2(rng.Uniform(-3.0, 3.0), rng.Uniform(-3.0, 3.0)), rng.Uniform(-0.3, 0.3));
		const double tilt = i % 3 == 0 ? rng.Uniform(-0.01, 0.01) : rng.Angle();
		const Rot q(tilt + pb.q.Angle());
		const Vec2 up = Rotate(pb.q, Vec2(0.0, 1.0));
		const double rise = shape.SupportValue(InvRotate(q, -1.0 * up));
		const Pose pa(ToWorld(pb, Vec2(rng.Uniform(-2.6, 2.6), (isBox ? 0.5 : 0.0) + rng.Uniform(-0.1, 0.4))) + rise * up, q);
		const Vec2 guess = Rotate(pb.q, Vec2(rng.Uniform(-0.2, 0.2), -1.0));
		CAPTURE(shape.Describe());
		CAPTURE(i);
		const ContactResult r = SeparatingAxisContact(shape, pa, v, count, pb, i % 4 == 1 ? &guess : nullptr);
		const ContactResult t = SeparatingAxisContact(twin, pa, v, count, pb, i % 4 == 1 ? &guess : nullptr);
		REQUIRE(r.Ok());
		REQUIRE(t.Ok());
		CHECK(r.separation == t.separation);
		CHECK(r.normal.x == t.normal.x);
		CHECK(r.normal.y == t.normal.y);
		CHECK(r.pointA.x == t.pointA.x);
		CHECK(r.pointA.y == t.pointA.y);
		CHECK(r.pointB.x == t.pointB.x);
		CHECK(r.pointB.y == t.pointB.y);
		CHECK(r.iterations <= t.iterations);
		if (ellipse)
		{
			auto support = [&](Vec2 n) {
				const Vec2 nb = InvRotate(pa.q, n);
				return Dot(pa.p, n) + std::hypot(ellipse->x * nb.x, ellipse->y * nb.y);
			};
			std::vector<Vec2> w;
			for (int j = 0; j < count; ++j)
				w.push_back(ToWorld(pb, v[j]));
			double angle = 0.0;
			const double reference = GapByScan(support, w, 4096, angle);
			// The reference never exceeds the true maximum; golden search leaves it ~1e-15 below.
			CHECK(r.separation >= reference - 1e-12);
			CHECK(r.separation <= reference + 1e-9);
		}
		fewer += t.iterations - r.iterations;
		++calls;
	}
}
} // namespace

TEST_CASE("polygon contact: a superellipse's skipped candidates change no bit of the answer")
{
	// SeparatingAxisContact skips a candidate axis whose gap with the superellipse's closed-form
	// lower bound on the support value cannot beat the best found. Reference: the same shape
	// behind PlainForwarding, whose candidates all take their supports.
	const std::vector<ShapePtr> shapes = {MakeSuperellipse(0.5, 0.3, 4.0, 4.0), MakeSuperellipse(0.7, 0.2, 2.5, 2.5),
	                                      MakeSuperellipse(0.4, 0.4, 8.0, 8.0), MakeSuperellipse(0.6, 0.3, 4.0, 8.0),
	                                      MakeSuperellipse(0.5, 0.3, 1.5, 1.5), MakeEllipse(0.5, 0.25)};
	Random rng(64);
	long fewer = 0, calls = 0;
	for (const ShapePtr& shape : shapes)
	{
		CHECK(shape->SupportBoundsCheap());
		const PlainForwarding twin(shape);
		CHECK_FALSE(twin.SupportBoundsCheap());
		CompareSkipped(*shape, twin, rng, fewer, calls);
	}
	// The skip is exercised: most of the 16 even directions and the far side of each face go.
	CHECK(fewer > 10 * calls);
}

TEST_CASE("polygon contact: a user shape kind that declares its support bounds cheap skips candidates, bit for bit")
{
	// The skip is the shape's to claim (SupportBoundsCheap), not the built-in classes': a shape
	// of a kind registered at run time declares it and skips as a superellipse does. Reference:
	// the same shape undeclared, and the ellipse's gap by scanning directions. A heart declares
	// it too; a UserShape, whose SupportBounds is Support itself, does not.
	CHECK(MakeHeart(1.0)->SupportBoundsCheap());
	UserShapeDef def;
	def.function = [](Vec2 x, double level) { return x.x * x.x + 4.0 * x.y * x.y - level; };
	def.convex = def.smooth = true;
	CHECK_FALSE(MakeUserShape(def)->SupportBoundsCheap());
	Random rng(44);
	long fewer = 0, calls = 0;
	for (const Vec2 axes : {Vec2(0.5, 0.25), Vec2(0.3, 0.3), Vec2(0.8, 0.1)})
	{
		const BoundedEllipse cheap(axes.x, axes.y, true), plain(axes.x, axes.y, false);
		REQUIRE(cheap.SupportBoundsCheap());
		REQUIRE_FALSE(plain.SupportBoundsCheap());
		CompareSkipped(cheap, plain, rng, fewer, calls, &axes);
	}
	CHECK(fewer > 10 * calls);
}

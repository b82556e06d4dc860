// b2analytic tests: ray casts, point tests and AABB queries through Box2D answer for the true
// shape of every kind, at any rotation, position and scale.
//
// Reference: each shape's level function written out in long double (GeometryReference.h: the
// superellipse's |x/a|^n + |y/b|^m, the heart's r² − cbrt(x² y³)), placed at the body's float
// position and angle (cosine and sine of the float angle in long double, not Box2D's float
// b2Rot), and a crossing search of its own: 4000 samples along the ray, then bisection. Box2D's
// float angle, positions and output fraction make a boundary ambiguous by about 1e-7 of the
// size, so every check is made against the shape shrunk and grown by a factor 1 ∓ ε (ε a few
// 1e-6): a hit must lie between the two surfaces with nothing of the shrunk shape before it, a
// miss must miss the shrunk shape, a point inside the shrunk shape must test inside and one
// outside the grown shape outside. A sliver of the shrunk shape thinner than the sample step
// could hide from the reference (the check is then weaker, never wrong).
#include "SceneSupport.h"
#include "GeometryReference.h"

#include "b2analytic/Box2DConversions.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <string>

using namespace b2a;
using namespace b2a::test;

namespace
{
// A shape with its reference level (body frame) and own level; the level of the shape scaled
// by s at x is the level at x/s.
struct Subject
{
	std::string name;
	ShapePtr shape;
	std::function<long double(Vec2)> level;
	double own = 1.0;
	double size = 1.0; // a length to scale the ambiguity by (the bounding radius)
	// Body points where the reference normal is not defined (corners, the heart's axis).
	std::function<bool(Vec2)> corner;
};

// Shapes of every kind, sizes log-uniform in [smallest, largest] (bounding radius about that).
std::vector<Subject> Subjects(Random& rng, double smallest = 0.02, double largest = 50.0)
{
	std::vector<Subject> out;
	auto superellipse = [&](const std::string& name, double a, double b, double n, double m) {
		Subject s;
		s.name = name;
		s.shape = n == 2.0 && m == 2.0 && a == b ? ShapePtr(MakeCircle(a)) : ShapePtr(MakeSuperellipse(a, b, n, m));
		s.level = [=](Vec2 x) { return SuperellipseLevelRef(x, a, b, n, m); };
		// Exponents below 2 turn the normal sharply at the axes.
		s.corner = [=](Vec2 x) { return (n < 2.0 && std::fabs(x.y) < 0.02 * b) || (m < 2.0 && std::fabs(x.x) < 0.02 * a); };
		out.push_back(s);
	};
	for (int k = 0; k < 3; ++k)
	{
		const double r = rng.LogUniform(smallest, largest), aspect = rng.LogUniform(1.0, 8.0);
		superellipse("circle", r, r, 2.0, 2.0);
		superellipse("ellipse", r, r / aspect, 2.0, 2.0);
		superellipse("superellipse n = 4", r, r / aspect, 4.0, 4.0);
		superellipse("superellipse n = 8, m = 3", r, r / aspect, 8.0, 3.0);
		superellipse("superellipse n = 1.5", r, r / aspect, 1.5, 1.5);
		const double alpha = r * r;
		Subject heart;
		heart.name = "heart";
		heart.shape = MakeHeart(alpha);
		heart.level = [](Vec2 x) { return HeartLevelRef(x); };
		heart.own = alpha;
		heart.corner = [=](Vec2 x) { return std::fabs(x.x) < 0.05 * r; };
		out.push_back(heart);
	}
	// User shapes (levels by root solves, no bounds): a heart and an ellipse.
	Subject user = out.back();
	user.name = "user heart";
	user.shape = MakeUserShape(UserHeartDef(user.own));
	out.push_back(user);
	Subject ellipse;
	ellipse.name = "user ellipse";
	ellipse.shape = MakeUserShape(UserEllipseDef(0.7, 0.3));
	ellipse.level = [](Vec2 x) { return (long double)x.x * x.x / 0.49L + (long double)x.y * x.y / 0.09L; };
	ellipse.corner = [](Vec2) { return false; };
	out.push_back(ellipse);
	for (Subject& s : out)
		s.size = s.shape->BoundingRadius();
	return out;
}

// The reference placement: the body's float position and angle, in long double.
struct Placement
{
	long double px, py, c, s;
	explicit Placement(const b2Body* body)
		: px(body->GetPosition().x), py(body->GetPosition().y), c(std::cos((long double)body->GetAngle())),
		  s(std::sin((long double)body->GetAngle()))
	{
	}
	Vec2 ToBodyFrame(long double x, long double y) const
	{
		const long double dx = x - px, dy = y - py;
		return Vec2(double(c * dx + s * dy), double(-s * dx + c * dy));
	}
};

// Whether the world point lies in the subject scaled by `scale` at the placement.
bool Inside(const Subject& s, const Placement& at, long double x, long double y, double scale)
{
	const Vec2 b = at.ToBodyFrame(x, y);
	return s.level(Vec2(b.x / scale, b.y / scale)) <= s.own;
}

// The first fraction in [0, maxFraction] at which the ray p1 → p2 is inside the scaled subject
// (4000 samples, then bisection), or −1.
double FirstInside(const Subject& s, const Placement& at, b2Vec2 p1, b2Vec2 p2, double maxFraction, double scale)
{
	const long double dx = (long double)p2.x - p1.x, dy = (long double)p2.y - p1.y;
	auto in = [&](long double t) { return Inside(s, at, p1.x + t * dx, p1.y + t * dy, scale); };
	const int samples = 4000;
	long double before = 0.0L;
	if (in(0.0L))
		return 0.0;
	for (int k = 1; k <= samples; ++k)
	{
		long double t = maxFraction * (long double)k / samples;
		if (!in(t))
		{
			before = t;
			continue;
		}
		for (int it = 0; it < 80; ++it)
		{
			const long double mid = 0.5L * (before + t);
			(in(mid) ? t : before) = mid;
		}
		return double(t);
	}
	return -1.0;
}

// A random float angle: anywhere in ±40 rad, and the angles where a circle's ray casts failed.
float RandomAngle(Random& rng, int trial)
{
	const float special[] = {2.0f, -4.0f, 30.0f, 0.7f};
	return trial < 4 ? special[trial] : float(rng.Uniform(-40.0, 40.0));
}

b2Body* PlaceBody(b2World& world, const Subject& s, Random& rng, int trial)
{
	b2BodyDef def;
	def.position.Set(float(rng.Uniform(-100.0, 100.0)), float(rng.Uniform(-100.0, 100.0)));
	def.angle = RandomAngle(rng, trial);
	b2Body* body = world.CreateBody(&def);
	CreateAnalyticFixture(body, s.shape, 0.0f);
	return body;
}

// A ray around the body: from 1.1 to 4 sizes away, aimed within 1.3 sizes of the centre (most
// hit, many graze) or anywhere, 0.5 to 8 sizes long.
void RandomRay(Random& rng, const b2Body* body, double size, b2RayCastInput& in)
{
	const Vec2 c = ToVec2(body->GetPosition());
	const double from = rng.Uniform(0.0, 2.0 * kPi), d = size * rng.Uniform(1.1, 4.0);
	const Vec2 p1 = c + d * Vec2(std::cos(from), std::sin(from));
	const Vec2 aim = c + size * rng.Uniform(0.0, 1.3) * Vec2(std::cos(rng.Angle()), std::sin(rng.Angle()));
	const Vec2 dir = rng.Uniform(0.0, 1.0) < 0.8 ? Normalize(aim - p1) : Vec2(std::cos(rng.Angle()), std::sin(rng.Angle()));
	in.p1 = ToB2Vec2(p1);
	in.p2 = ToB2Vec2(p1 + size * rng.Uniform(0.5, 8.0) * dir);
	in.maxFraction = float(rng.Uniform(0.3, 1.0));
}

// The reference's outward normal at a world point: its level's gradient by central differences.
Vec2 ReferenceNormal(const Subject& s, const Placement& at, Vec2 p)
{
	const Vec2 b = at.ToBodyFrame(p.x, p.y);
	const double h = 1e-6 * s.size;
	const Vec2 g(double(s.level(b + Vec2(h, 0.0)) - s.level(b - Vec2(h, 0.0))),
	             double(s.level(b + Vec2(0.0, h)) - s.level(b - Vec2(0.0, h))));
	const Vec2 body = Normalize(g);
	return Vec2(double(at.c * body.x - at.s * body.y), double(at.s * body.x + at.c * body.y));
}
} // namespace

TEST_CASE("b2Fixture::RayCast is exact for every shape kind at any rotation, position and scale")
{
	Random rng(46);
	b2World world(b2Vec2(0.0f, 0.0f));
	int hits = 0, misses = 0, normals = 0;
	for (const Subject& s : Subjects(rng))
	{
		const int trials = s.name.rfind("user", 0) == 0 ? 40 : 150;
		for (int trial = 0; trial < trials; ++trial)
		{
			b2Body* body = PlaceBody(world, s, rng, trial % 8);
			const Placement at(body);
			b2RayCastInput in;
			RandomRay(rng, body, s.size, in);
			const double length = b2Distance(in.p1, in.p2);
			const double eps = 4e-6 + 1e-6 * length / s.size; // the float fraction's rounding
			CAPTURE(s.name);
			CAPTURE(s.shape->Describe());
			CAPTURE(trial);
			b2RayCastOutput out;
			const bool hit = body->GetFixtureList()->RayCast(&out, in, 0);
			if (Inside(s, at, in.p1.x, in.p1.y, 1.0 + eps))
			{
				// Starts inside (or within the ambiguity): Box2D's shapes report no hit from inside.
				if (Inside(s, at, in.p1.x, in.p1.y, 1.0 - eps))
					CHECK_FALSE(hit);
				world.DestroyBody(body);
				continue;
			}
			const double shrunk = FirstInside(s, at, in.p1, in.p2, in.maxFraction, 1.0 - eps);
			if (hit)
			{
				++hits;
				const double f = out.fraction;
				const Vec2 p = ToVec2(in.p1) + f * (ToVec2(in.p2) - ToVec2(in.p1));
				CHECK(f >= 0.0);
				CHECK(f <= in.maxFraction);
				CHECK(Inside(s, at, p.x, p.y, 1.0 + eps));                 // on the surface,
				CHECK_FALSE(Inside(s, at, p.x, p.y, 1.0 - eps));           // within the ambiguity,
				CHECK((shrunk < 0.0 || shrunk >= f - eps * s.size / length)); // and nothing before it
				// The normal: unit, facing the ray, and the reference's away from corners.
				const Vec2 n = ToVec2(out.normal);
				CHECK(std::fabs(Length(n) - 1.0) < 1e-6);
				CHECK(Dot(n, ToVec2(in.p2) - ToVec2(in.p1)) <= 0.0);
				if (!s.corner(at.ToBodyFrame(p.x, p.y)))
				{
					++normals;
					CHECK(Length(n - ReferenceNormal(s, at, p)) < 1e-3);
				}
			}
			else
			{
				++misses;
				CHECK(shrunk < 0.0); // a miss misses the shrunk shape
			}
			world.DestroyBody(body);
		}
	}
	// The rays are a mix: most hit, many miss, most hits away from corners.
	CHECK(hits > 800);
	CHECK(misses > 200);
	CHECK(normals > 600);
}

TEST_CASE("b2Fixture::TestPoint and the world's QueryAABB find every point of the true shape")
{
	Random rng(4646);
	b2World world(b2Vec2(0.0f, 0.0f));
	int inside = 0, outside = 0;
	for (const Subject& s : Subjects(rng))
	{
		const int trials = s.name.rfind("user", 0) == 0 ? 10 : 30;
		for (int trial = 0; trial < trials; ++trial)
		{
			b2Body* body = PlaceBody(world, s, rng, trial % 8);
			b2Fixture* fixture = body->GetFixtureList();
			const Placement at(body);
			const b2AABB box = fixture->GetAABB(0);
			const double eps = 4e-6;
			CAPTURE(s.name);
			CAPTURE(trial);
			for (int k = 0; k < 60; ++k)
			{
				// Points around the particle, many near its surface.
				const Vec2 c = ToVec2(body->GetPosition());
				const double r = s.size * (k % 2 == 0 ? rng.Uniform(0.0, 1.2) : rng.Uniform(0.9, 1.05));
				const b2Vec2 p = ToB2Vec2(c + r * Vec2(std::cos(rng.Angle()), std::sin(rng.Angle())));
				const bool tested = fixture->TestPoint(p);
				if (Inside(s, at, p.x, p.y, 1.0 - eps))
				{
					++inside;
					CHECK(tested);
					// In the fixture's tight AABB, and found by the world's query at the point.
					CHECK(box.lowerBound.x <= p.x);
					CHECK(box.lowerBound.y <= p.y);
					CHECK(box.upperBound.x >= p.x);
					CHECK(box.upperBound.y >= p.y);
					struct Found : b2QueryCallback
					{
						const b2Fixture* wanted = nullptr;
						b2Vec2 point;
						bool found = false;
						bool ReportFixture(b2Fixture* f) override
						{
							found = found || (f == wanted && f->TestPoint(point));
							return true;
						}
					} query;
					query.wanted = fixture;
					query.point = p;
					b2AABB around;
					around.lowerBound = around.upperBound = p;
					world.QueryAABB(&query, around);
					CHECK(query.found);
				}
				else if (!Inside(s, at, p.x, p.y, 1.0 + eps))
				{
					++outside;
					CHECK_FALSE(tested);
				}
			}
			world.DestroyBody(body);
		}
	}
	CHECK(inside > 3000);
	CHECK(outside > 3000);
}

TEST_CASE("b2World::RayCast reports the nearest true shape among many, circles at every angle included")
{
	// 80 particles of every kind at random poses, overlapping or not; 400 rays through them.
	// The nearest hit Box2D's ray cast reports must be the reference's nearest entry over all
	// particles (within the ambiguity), and a ray that reports nothing must miss them all.
	Random rng(146);
	b2World world(b2Vec2(0.0f, 0.0f));
	const std::vector<Subject> kinds = Subjects(rng, 0.1, 3.0);
	std::vector<const Subject*> subjects;
	std::vector<b2Body*> bodies;
	for (int i = 0; i < 80; ++i)
	{
		const Subject& s = kinds[i % (kinds.size() - 2)]; // (not the slow user shapes)
		b2BodyDef def;
		def.position.Set(float(rng.Uniform(-20.0, 20.0)), float(rng.Uniform(-20.0, 20.0)));
		def.angle = float(rng.Uniform(-40.0, 40.0));
		bodies.push_back(world.CreateBody(&def));
		CreateAnalyticFixture(bodies.back(), s.shape, 0.0f);
		subjects.push_back(&s);
	}
	struct Nearest : b2RayCastCallback
	{
		const b2Fixture* fixture = nullptr;
		float fraction = -1.0f;
		float ReportFixture(b2Fixture* f, const b2Vec2&, const b2Vec2&, float fr) override
		{
			fixture = f;
			fraction = fr;
			return fr;
		}
	};
	int hits = 0;
	for (int k = 0; k < 400; ++k)
	{
		const b2Vec2 p1(float(rng.Uniform(-60.0, 60.0)), float(rng.Uniform(-60.0, 60.0)));
		const b2Vec2 p2(float(rng.Uniform(-25.0, 25.0)), float(rng.Uniform(-25.0, 25.0)));
		CAPTURE(k);
		Nearest nearest;
		world.RayCast(&nearest, p1, p2);
		const double length = b2Distance(p1, p2);
		double shrunkFirst = -1.0;
		bool startsInside = false;
		for (size_t i = 0; i < bodies.size(); ++i)
		{
			const Placement at(bodies[i]);
			const Subject& s = *subjects[i];
			const double eps = 4e-6 + 1e-6 * length / s.size;
			// (Only where the ray passes the bounding circle: elsewhere nothing can be inside.)
			const Vec2 c = ToVec2(bodies[i]->GetPosition());
			if (DistanceToSegment(c, ToVec2(p1), ToVec2(p2)) > 1.01 * s.size)
				continue;
			startsInside = startsInside || Inside(s, at, p1.x, p1.y, 1.0 + eps);
			const double a = FirstInside(s, at, p1, p2, 1.0, 1.0 - eps);
			if (a >= 0.0 && (shrunkFirst < 0.0 || a < shrunkFirst))
				shrunkFirst = a;
		}
		if (startsInside)
			continue; // Box2D then reports the particles the ray enters later: not this test's subject
		if (nearest.fraction < 0.0f)
		{
			CHECK(shrunkFirst < 0.0);
			continue;
		}
		// The hit lies on the reported particle's surface, and no particle is entered before it.
		// (Not: the reference's nearest entry of the grown particles lies there too; a ray that
		// clips a heart's tip can enter it over less than the reference's sample step.)
		++hits;
		const size_t i = size_t(std::find_if(bodies.begin(), bodies.end(), [&](const b2Body* b) { return b->GetFixtureList() == nearest.fixture; }) -
		                        bodies.begin());
		REQUIRE(i < bodies.size());
		const Placement at(bodies[i]);
		const double eps = 4e-6 + 1e-6 * length / subjects[i]->size;
		const Vec2 p = ToVec2(p1) + double(nearest.fraction) * (ToVec2(p2) - ToVec2(p1));
		CHECK(Inside(*subjects[i], at, p.x, p.y, 1.0 + eps));
		CHECK_FALSE(Inside(*subjects[i], at, p.x, p.y, 1.0 - eps));
		const double tol = 2e-6; // the float fraction's rounding and the references' bisection
		CHECK((shrunkFirst < 0.0 || nearest.fraction <= shrunkFirst + tol));
	}
	CHECK(hits > 100);
}

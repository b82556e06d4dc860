// b2analytic tests: creating analytic fixtures, their mass data, queries, drawing and lifetime.
#include "SceneSupport.h"

#include "b2analytic/Box2DConversions.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("an analytic fixture honours its b2FixtureDef and sets the body's mass from the analytic shape")
{
	b2World world(b2Vec2(0.0f, -10.0f));
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	b2Body* body = world.CreateBody(&bd);
	int userBody = 7;
	body->GetUserData().pointer = reinterpret_cast<uintptr_t>(&userBody);

	b2FixtureDef fd;
	fd.density = 2.5f;
	fd.friction = 0.3f;
	fd.restitution = 0.4f;
	fd.restitutionThreshold = 0.25f;
	fd.filter.categoryBits = 0x0004;
	fd.filter.maskBits = 0x00F0;
	fd.filter.groupIndex = -3;
	fd.isSensor = false;
	int userFixture = 11;
	fd.userData.pointer = reinterpret_cast<uintptr_t>(&userFixture);
	AnalyticFixtureDef ad;
	ad.shape = MakeEllipse(2.0, 0.5);
	ad.local = Pose(Vec2(1.0, -0.5), 0.3);
	b2Fixture* f = CreateAnalyticFixture(body, fd, ad);

	CHECK(f->GetFriction() == 0.3f);
	CHECK(f->GetRestitution() == 0.4f);
	CHECK(f->GetRestitutionThreshold() == 0.25f);
	CHECK(f->GetDensity() == 2.5f);
	CHECK(f->GetFilterData().categoryBits == 0x0004);
	CHECK(f->GetFilterData().maskBits == 0x00F0);
	CHECK(f->GetFilterData().groupIndex == -3);
	CHECK(f->GetUserData().pointer == reinterpret_cast<uintptr_t>(&userFixture));
	CHECK(body->GetUserData().pointer == reinterpret_cast<uintptr_t>(&userBody));
	CHECK(GetAnalyticShape(f) == ad.shape.get());

	// Closed forms: area πab, polar moment about the centroid πab(a² + b²)/4, shifted to the
	// body origin by the parallel-axis theorem (the local pose puts the centroid at (1, −0.5)).
	const double area = kPi * 2.0 * 0.5;
	const double mass = 2.5 * area;
	const double Ic = 2.5 * kPi * 2.0 * 0.5 * (4.0 + 0.25) / 4.0;
	CHECK(body->GetMass() == doctest::Approx(mass).epsilon(1e-6));
	CHECK(body->GetLocalCenter().x == doctest::Approx(1.0).epsilon(1e-6));
	CHECK(body->GetLocalCenter().y == doctest::Approx(-0.5).epsilon(1e-6));
	CHECK(body->GetInertia() == doctest::Approx(Ic + mass * 1.25).epsilon(1e-6));

	// A heart's mass comes from its own (numerically integrated) centroid, not the body origin.
	b2Body* hb = world.CreateBody(&bd);
	CreateAnalyticFixture(hb, MakeHeart(1.0), 1.0f);
	const MassProperties hm = MakeHeart(1.0)->Mass();
	CHECK(hb->GetMass() == doctest::Approx(hm.area).epsilon(1e-6));
	CHECK(hb->GetLocalCenter().y == doctest::Approx(hm.centroid.y).epsilon(1e-5));
	CHECK(hb->GetLocalCenter().y > 0.25); // the heart's lobes put its centroid above its origin
}

TEST_CASE("bad arguments give clear errors, never a Box2D assertion")
{
	b2World world(b2Vec2(0.0f, -10.0f));
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	b2Body* body = world.CreateBody(&bd);
	b2FixtureDef fd;
	AnalyticFixtureDef ad;

	auto message = [&](auto&& call) -> std::string {
		try
		{
			call();
		}
		catch (const std::exception& e)
		{
			return e.what();
		}
		return "";
	};
	CHECK(message([&] { CreateAnalyticFixture(body, fd, ad); }).find("field 'shape' is null") != std::string::npos);
	ad.shape = MakeCircle(1.0);
	CHECK(message([&] { CreateAnalyticFixture(nullptr, fd, ad); }).find("body is null") != std::string::npos);
	b2CircleShape other;
	fd.shape = &other;
	CHECK(message([&] { CreateAnalyticFixture(body, fd, ad); }).find("'def.shape' must be null") != std::string::npos);
	fd.shape = nullptr;
	ad.patchTolerance = -1.0;
	CHECK(message([&] { CreateAnalyticFixture(body, fd, ad); }).find("patchTolerance") != std::string::npos);
	ad.patchTolerance = 0.001;
	ad.shape = MakeCircle(0.001); // below Box2D's linear slop
	CHECK(message([&] { CreateAnalyticFixture(body, fd, ad); }).find("smaller length units") != std::string::npos);
	CHECK(body->GetFixtureList() == nullptr);

	// Inside a world callback the world is locked: a clear error instead of Box2D's assert.
	struct Creator : b2ContactListener
	{
		b2Body* body = nullptr;
		std::string error;
		void BeginContact(b2Contact*) override
		{
			try
			{
				CreateAnalyticFixture(body, MakeCircle(0.5), 1.0f);
			}
			catch (const MisuseError& e)
			{
				error = e.what();
			}
		}
	} creator;
	creator.body = body;
	world.SetContactListener(&creator);
	MakeFloor(world);
	body->SetTransform(b2Vec2(0.0f, 0.4f), 0.0f);
	CreateAnalyticFixture(body, MakeCircle(0.5), 1.0f);
	for (int i = 0; i < 30 && creator.error.empty(); ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	CHECK(creator.error.find("world is locked") != std::string::npos);
}

TEST_CASE("ray casts and point tests answer for the true shape")
{
	b2World world(b2Vec2(0.0f, 0.0f));
	b2BodyDef bd;
	bd.position.Set(1.0f, 2.0f);
	bd.angle = 0.5f;
	b2Body* body = world.CreateBody(&bd);
	const auto shape = MakeSuperellipse(2.0, 1.0, 4.0, 4.0);
	b2Fixture* f = CreateAnalyticFixture(body, shape, 1.0f);

	// Point tests against the level function directly (independent of the proxy polygon): a
	// corner point of the bounding box lies outside, the inscribed proxy's complement inside.
	const Pose pose(Vec2(1.0, 2.0), 0.5);
	Random rng(5);
	int disagreements = 0;
	for (int i = 0; i < 2000; ++i)
	{
		const Vec2 x(rng.Uniform(-2.2, 2.2), rng.Uniform(-1.2, 1.2));
		const Vec2 w = ToWorld(pose, x);
		const bool inside = std::pow(std::fabs(x.x / 2.0), 4) + std::pow(std::fabs(x.y), 4) <= 1.0;
		// Points within float rounding of the surface may go either way.
		if (std::fabs(std::pow(std::fabs(x.x / 2.0), 4) + std::pow(std::fabs(x.y), 4) - 1.0) < 1e-5)
			continue;
		disagreements += f->TestPoint(b2Vec2(float(w.x), float(w.y))) != inside;
	}
	CHECK(disagreements == 0);

	// A ray along the body's x axis from outside hits the tip (2, 0) of the superellipse.
	const Vec2 from = ToWorld(pose, Vec2(-5.0, 0.0)), to = ToWorld(pose, Vec2(0.0, 0.0));
	struct Closest : b2RayCastCallback
	{
		float fraction = -1.0f;
		b2Vec2 point, normal;
		float ReportFixture(b2Fixture*, const b2Vec2& p, const b2Vec2& n, float fr) override
		{
			fraction = fr;
			point = p;
			normal = n;
			return fr;
		}
	} closest;
	world.RayCast(&closest, b2Vec2(float(from.x), float(from.y)), b2Vec2(float(to.x), float(to.y)));
	REQUIRE(closest.fraction >= 0.0f);
	CHECK(closest.fraction == doctest::Approx(3.0 / 5.0).epsilon(1e-6));
	const Vec2 n = Rotate(pose.q, Vec2(-1.0, 0.0));
	CHECK(closest.normal.x == doctest::Approx(n.x).epsilon(1e-5));
	CHECK(closest.normal.y == doctest::Approx(n.y).epsilon(1e-5));

	// A ray that passes through the tight AABB but misses the rounded corner reports nothing:
	// along the body line x = 1.95 the superellipse reaches |y| = (1 − (0.975)^4)^(1/4) ≈ 0.56.
	const Vec2 a = ToWorld(pose, Vec2(1.95, 3.0)), b = ToWorld(pose, Vec2(1.95, 0.7));
	b2RayCastOutput out;
	b2RayCastInput in;
	in.p1.Set(float(a.x), float(a.y));
	in.p2.Set(float(b.x), float(b.y));
	in.maxFraction = 1.0f;
	CHECK_FALSE(f->RayCast(&out, in, 0));
	in.p2 = b2Vec2(float(ToWorld(pose, Vec2(1.95, 0.0)).x), float(ToWorld(pose, Vec2(1.95, 0.0)).y));
	REQUIRE(f->RayCast(&out, in, 0));
	const double yHit = std::pow(1.0 - std::pow(0.975, 4.0), 0.25);
	CHECK(out.fraction == doctest::Approx((3.0 - yHit) / 3.0).epsilon(1e-5));

	// The fixture's AABB (which the broad phase fattens by its margin) is the shape's tight box,
	// rounded outwards to float: it contains the shape and is within float rounding of it.
	const b2AABB box = f->GetAABB(0);
	const Box tight = shape->ComputeAABB(Pose(Vec2(body->GetPosition().x, body->GetPosition().y), double(body->GetAngle())));
	CHECK(box.lowerBound.x <= tight.lower.x);
	CHECK(box.lowerBound.y <= tight.lower.y);
	CHECK(box.upperBound.x >= tight.upper.x);
	CHECK(box.upperBound.y >= tight.upper.y);
	CHECK(box.lowerBound.x == doctest::Approx(tight.lower.x).epsilon(1e-6));
	CHECK(box.upperBound.y == doctest::Approx(tight.upper.y).epsilon(1e-6));
}

TEST_CASE("the broad phase's box holds the shape and stays within 3 % of Box2D's margin of tight at every pose")
{
	// ComputeAABB answers from the exact box at an anchor pose, moved and widened by the turn
	// since (up to 3 % of b2_aabbExtension), and recomputes past that. Along random walks of
	// small steps (the anchored path) with jumps (recomputations), every box holds 1024 points of
	// the surface at the pose and the exact tight box, and lies within twice that of it.
	const double reach = 0.03 * double(b2_aabbExtension);
	const std::vector<std::pair<const char*, ShapePtr>> shapes = {
		{"ellipse", MakeEllipse(1.0, 0.33)}, {"superellipse n=4", MakeSuperellipse(1.0, 0.625, 4.0, 4.0)},
		{"superellipse n=2.7", MakeSuperellipse(0.8, 0.5, 2.7, 2.7)}, {"circle", MakeCircle(0.4)}, {"heart", MakeHeart(0.2)}};
	std::mt19937 random(42);
	std::uniform_real_distribution<double> unit(-1.0, 1.0);
	for (const auto& [name, shape] : shapes)
	{
		CAPTURE(name);
		b2World world(b2Vec2(0.0f, 0.0f));
		b2BodyDef bd;
		bd.type = b2_dynamicBody;
		b2Body* body = world.CreateBody(&bd);
		b2FixtureDef fd;
		AnalyticFixtureDef ad;
		ad.shape = shape;
		ad.local = Pose(Vec2(0.3, -0.2), 0.7); // off the body origin: the turn moves the shape too
		const b2Shape* proxy = CreateAnalyticFixture(body, fd, ad)->GetShape();
		const double level = shape->SurfaceLevel();
		double x = 0.0, y = 0.0, angle = 0.0, worstLoose = 0.0;
		int anchored = 0, exact = 0, outside = 0;
		for (int step = 0; step < 2000; ++step)
		{
			if (step % 500 == 0) // a jump: past the anchor's reach
			{
				x = 50.0 * unit(random);
				y = 50.0 * unit(random);
				angle = 3.0 * unit(random);
			}
			else
			{
				x += 0.01 * unit(random);
				y += 0.01 * unit(random);
				angle += 0.001 * unit(random);
			}
			const b2Transform xf{b2Vec2(float(x), float(y)), b2Rot(float(angle))};
			b2AABB box;
			proxy->ComputeAABB(&box, xf, 0);
			const Pose body2 = ToPose(xf);
			const Pose pose(ToWorld(body2, ad.local.p), Mul(body2.q, ad.local.q));
			const Box tight = shape->ComputeAABB(pose);
			outside += box.lowerBound.x <= tight.lower.x && box.lowerBound.y <= tight.lower.y && box.upperBound.x >= tight.upper.x &&
			                   box.upperBound.y >= tight.upper.y
			               ? 0
			               : 1;
			for (int k = 0; k < 1024; ++k)
			{
				const Vec2 p = ToWorld(pose, shape->SurfacePoint(-kPi + 2.0 * kPi * k / 1024.0, level));
				outside += p.x >= box.lowerBound.x && p.x <= box.upperBound.x && p.y >= box.lowerBound.y && p.y <= box.upperBound.y ? 0 : 1;
			}
			const double loose = std::max({tight.lower.x - box.lowerBound.x, tight.lower.y - box.lowerBound.y,
			                               box.upperBound.x - tight.upper.x, box.upperBound.y - tight.upper.y});
			worstLoose = std::max(worstLoose, loose);
			// Float rounding of a box 50 units from the origin: a few 1e-6.
			(loose > 1e-5 ? anchored : exact) += 1;
		}
		CHECK(outside == 0);
		CHECK(worstLoose <= 2.0 * reach + 1e-5);
		CHECK(worstLoose >= 0.5 * reach); // the anchored path was taken, and loosened as far as it may
		CHECK(anchored > 1000);
		CHECK(exact > 5);
	}
}

TEST_CASE("debug drawing shows the true outlines, hearts included, through the user's b2Draw")
{
	struct Recorder : b2Draw
	{
		std::vector<std::vector<b2Vec2>> polygons;
		int segments = 0, circles = 0;
		void DrawPolygon(const b2Vec2* v, int32 n, const b2Color&) override { polygons.emplace_back(v, v + n); }
		void DrawSolidPolygon(const b2Vec2* v, int32 n, const b2Color&) override { polygons.emplace_back(v, v + n); }
		void DrawCircle(const b2Vec2&, float, const b2Color&) override { ++circles; }
		void DrawSolidCircle(const b2Vec2&, float, const b2Vec2&, const b2Color&) override { ++circles; }
		void DrawSegment(const b2Vec2&, const b2Vec2&, const b2Color&) override { ++segments; }
		void DrawTransform(const b2Transform&) override {}
		void DrawPoint(const b2Vec2&, float, const b2Color&) override {}
	} draw;
	draw.SetFlags(b2Draw::e_shapeBit);
	b2World world(b2Vec2(0.0f, -10.0f));
	MakeFloor(world);
	const auto heart = MakeHeart(1.0);
	MakeParticle(world, heart, 0.0f, 3.0f, 0.25f);
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	b2CircleShape ball;
	ball.m_radius = 0.5f;
	world.CreateBody(&bd)->CreateFixture(&ball, 1.0f);

	DrawWorld(&world, &draw, 64);
	REQUIRE(draw.polygons.size() == 1);
	CHECK(draw.segments == 1);
	CHECK(draw.circles == 1);
	// Every outline vertex lies on the heart's surface at its pose (float rounding aside).
	const Pose pose(Vec2(0.0, 3.0), 0.25f);
	CHECK(draw.polygons[0].size() >= 64);
	for (const b2Vec2& v : draw.polygons[0])
		CHECK(heart->Level(ToBody(pose, Vec2(v.x, v.y))) == doctest::Approx(1.0).epsilon(1e-5));
}

TEST_CASE("destroying fixtures, bodies and worlds releases the analytic data")
{
	// The shape's use count tells whether the adapter still holds it (LeakSanitizer checks the rest
	// in the sanitizer build).
	const auto shape = MakeSuperellipse(0.5, 0.3, 4.0, 4.0);
	{
		b2World world(b2Vec2(0.0f, -10.0f));
		MakeFloor(world);
		b2Body* a = MakeParticle(world, shape, 0.0f, 0.3f);
		b2Body* b = MakeParticle(world, shape, 0.0f, 1.0f);
		b2Body* c = MakeParticle(world, shape, 2.0f, 0.3f);
		CHECK(shape.use_count() == 4);
		for (int i = 0; i < 30; ++i)
			world.Step(1.0f / 60.0f, 8, 3);
		a->DestroyFixture(a->GetFixtureList());
		CHECK(shape.use_count() == 3);
		world.DestroyBody(b);
		CHECK(shape.use_count() == 2);
		world.Step(1.0f / 60.0f, 8, 3);
		(void)c;
	}
	CHECK(shape.use_count() == 1); // the world's destructor destroyed the last fixture
}

// b2analytic tests: what the world fuzzer (tests/fuzz, b2a_fuzz_world) found in the adapter.
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("fuzz regression: a plain polygon holding stale proxy bytes in its unused slot stays a plain polygon")
{
	// b2PolygonShape leaves m_vertices[7] and m_normals[7] uninitialised, and the adapter marks
	// its proxies with a tag in m_vertices[7] and a data pointer in m_normals[7]. A box built
	// where a proxy lived before (CreateAnalyticFixture's temporary on the stack, as in the
	// fuzzer's fixture helper) inherited both, Box2D's clone copied them, and the adapter took the
	// box for an analytic fixture of someone else's shape (UBSan: "downcast of address ... which
	// does not point to an object of type 'const b2a::AnalyticProxyShape'"). Here the stale bytes
	// are put there on purpose, copied from a live analytic fixture.
	b2World world(b2Vec2(0.0f, -10.0f));
	b2Body* ball = MakeParticle(world, MakeEllipse(0.5, 0.25), 0.0f, 3.0f);
	b2Fixture* analytic = ball->GetFixtureList();
	const b2PolygonShape* proxy = static_cast<const b2PolygonShape*>(analytic->GetShape());
	REQUIRE(GetAnalyticShape(analytic) != nullptr);

	b2PolygonShape box;
	box.SetAsBox(4.0f, 0.5f);
	box.m_vertices[7] = proxy->m_vertices[7];
	box.m_normals[7] = proxy->m_normals[7];
	b2BodyDef groundDef;
	b2Body* ground = world.CreateBody(&groundDef);
	b2Fixture* plain = ground->CreateFixture(&box, 0.0f);

	CHECK(GetAnalyticShape(plain) == nullptr);
	CHECK(!ComputeFixtureContact(plain, analytic).Ok());
	CHECK_THROWS_AS(GetAnalyticPose(plain), InvalidParameter);

	// And Box2D's box it stays: the ellipse lands on its top face (y = 0.5) and rests there on its
	// minor semi-axis, 0.25 above it, within Box2D's linear slop (taken for the ellipse, the box
	// would have held it at 0.5).
	for (int i = 0; i < 180; ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	CHECK(std::fabs(ball->GetPosition().y - 0.75f) <= 2.0f * b2_linearSlop);
}

TEST_CASE("fuzz regression: a particle too thin for float or for its samples is refused by name, and the world goes on")
{
	// The world fuzzer (CI, seed 1) found an integer division by zero in the proxy builder: a
	// superellipse 1e-237 wide and 0.57 long has one distinct surface sample (every sample lies
	// within 1e-237 of the centre), the proxy polygon shrank to one vertex, and the convex hull
	// of that one vertex was empty (its samples on the axes, exact since, now reach its tips, and
	// its float proxy is a segment). With density 0 no mass check stands in the way. (The input's
	// bytes were not kept; the shape is one of that class, found by a search over such needles.)
	// With density 1 the same needle, and an ellipse 6.6e-40 wide, have a mass below float's
	// normal range, where Box2D's ResetMassData asserted (the fuzzer's second find).
	struct Case
	{
		ShapePtr shape;
		float density;
	};
	const Case cases[] = {
		{MakeSuperellipse(4.2688566718624014e-237, 0.56933335768778381, 1.2776451293969946, 1.8744627534479257), 0.0f},
		{MakeSuperellipse(4.2688566718624014e-237, 0.56933335768778381, 1.2776451293969946, 1.8744627534479257), 1.0f},
		{MakeSuperellipse(8.1620300692310041e-296, 0.13915336571400536, 1.0, 1.0), 0.0f},
		{MakeEllipse(0.49941661749807853, 6.5732409498342358e-40), 1.0f},
	};
	b2World world(b2Vec2(0.0f, -10.0f));
	MakeFloor(world);
	b2BodyDef bodyDef;
	bodyDef.type = b2_dynamicBody;
	bodyDef.position.Set(0.0f, 3.0f);
	b2Body* body = world.CreateBody(&bodyDef);
	for (const Case& c : cases)
	{
		b2FixtureDef def;
		def.density = c.density;
		AnalyticFixtureDef analytic;
		analytic.shape = c.shape;
		std::string message;
		try
		{
			CreateAnalyticFixture(body, def, analytic);
		}
		catch (const InvalidParameter& e)
		{
			message = e.what();
		}
		CAPTURE(c.shape->Describe());
		CHECK(message.find("'shape'") != std::string::npos);
		CHECK(body->GetFixtureList() == nullptr);
	}
	// The body takes a proper particle afterwards, which falls onto the floor (its top at y = 0)
	// and rests on its radius.
	CreateAnalyticFixture(body, MakeCircle(0.25), 1.0f);
	for (int i = 0; i < 180; ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	CHECK(std::fabs(body->GetPosition().y - 0.25f) <= 2.0f * b2_linearSlop);
}

TEST_CASE("a small particle far from its body's centre is refused by 'local' only where Box2D's float moment is lost")
{
	// CreateFixture's b2Body::ResetMassData computes I − m·|c|² in float and asserts it positive.
	// A 0.1 circle 300 from the origin of an otherwise empty body has no moment left after that
	// (Box2D would assert): refused, by 'local'. The same circle on a body whose centre stays near
	// the origin (a 2 × 2 box there, then a second circle opposite) keeps its moment, and the body
	// gets the closed-form mass data.
	b2World world(b2Vec2(0.0f, 0.0f));
	b2BodyDef bodyDef;
	bodyDef.type = b2_dynamicBody;
	auto circleAt = [](double x) {
		AnalyticFixtureDef analytic;
		analytic.shape = MakeCircle(0.1);
		analytic.local = Pose(Vec2(x, 0.0), 0.0);
		return analytic;
	};
	b2FixtureDef def;
	def.density = 1.0f;

	b2Body* lone = world.CreateBody(&bodyDef);
	std::string message;
	try
	{
		CreateAnalyticFixture(lone, def, circleAt(300.0));
	}
	catch (const InvalidParameter& e)
	{
		message = e.what();
	}
	CHECK(message.find("'local'") != std::string::npos);
	CHECK(lone->GetFixtureList() == nullptr);

	b2Body* dumbbell = world.CreateBody(&bodyDef);
	b2PolygonShape box;
	box.SetAsBox(1.0f, 1.0f);
	dumbbell->CreateFixture(&box, 1.0f);
	CreateAnalyticFixture(dumbbell, def, circleAt(300.0));
	CreateAnalyticFixture(dumbbell, def, circleAt(-300.0));
	const double area = kPi * 0.01; // each circle's; the box: mass 4, moment 8/3
	CHECK(double(dumbbell->GetMass()) == doctest::Approx(4.0 + 2.0 * area).epsilon(1e-6));
	CHECK(std::fabs(dumbbell->GetLocalCenter().x) < 1e-3f);
	CHECK(double(dumbbell->GetInertia()) == doctest::Approx(8.0 / 3.0 + 2.0 * area * (300.0 * 300.0 + 0.005)).epsilon(1e-5));
}

TEST_CASE("fuzz regression: fixture contacts between superellipses on turned bodies have unit normals")
{
	// The world fuzzer (CI, seed 1, b2a_fuzz_world) found a fixture contact whose normal was off
	// unit length by more than 1e-9: two n = 4 superellipses (a = b = 1.5567) overlapping on
	// turned bodies. A body's b2Rot holds a float cosine and sine, so the pose built from it is
	// off unit length by up to about 6e-8, and the raw-level finish turned its normal into the
	// world with that rotation. (The input's bytes were not kept; these are poses of that class.)
	b2World world(b2Vec2(0.0f, 0.0f));
	const ShapePtr square = MakeSuperellipse(1.55672533409036, 1.55672533409036, 4.0, 4.0);
	double worstRotation = 0.0, worstNormal = 0.0;
	int contacts = 0;
	for (int k = 0; k < 24; ++k)
	{
		b2Body* a = MakeParticle(world, square, 0.3f * float(k), 0.0f, 0.37f * float(k) - 3.0f);
		b2Body* b = MakeParticle(world, square, 0.3f * float(k) + 2.0f, 0.4f, 0.23f * float(k) + 1.0f);
		const b2Rot q = a->GetTransform().q;
		worstRotation = std::max(worstRotation, std::fabs(std::hypot(double(q.c), double(q.s)) - 1.0));
		const ContactResult c = ComputeFixtureContact(a->GetFixtureList(), b->GetFixtureList());
		REQUIRE(c.Ok());
		++contacts;
		worstNormal = std::max(worstNormal, std::fabs(Length(c.normal) - 1.0));
		world.DestroyBody(a);
		world.DestroyBody(b);
	}
	CAPTURE(worstRotation);
	CAPTURE(worstNormal);
	CHECK(contacts == 24);
	CHECK(worstRotation > 1e-8); // float rotations, as Box2D keeps them
	CHECK(worstNormal <= 1e-15);
}

TEST_CASE("fuzz regression: particles too large for float positions are refused, and Box2D's time of impact never meets them")
{
	// The world fuzzer (CI's re-run, seed 1; tests/fuzz/corpus/world/crash-huge_particles_time_of_impact)
	// made b2TimeOfImpact assert (b2SeparationFunction::Initialize, 0 < count < 3): two bullet
	// bodies in one place, one holding a superellipse 0.028 by 1e12, the other a circle of radius
	// 1e8. At those sizes a float coordinate is far coarser than Box2D's linear slop. Both are now
	// refused by 'shape'; the decoded scene then steps as it should (here, 40 steps as the input's).
	b2World world(b2Vec2(-9.0f, -9.0f));
	auto bullet = [&] {
		b2BodyDef def;
		def.type = b2_dynamicBody;
		def.position.Set(-9.80392f, -9.80392f);
		def.angle = -1.54f;
		def.linearVelocity.Set(-24.5098f, -24.5098f);
		def.angularVelocity = -14.7059f;
		def.bullet = true;
		return world.CreateBody(&def);
	};
	auto add = [](b2Body* body, ShapePtr shape, Pose local, float density) {
		b2FixtureDef def;
		def.density = density;
		AnalyticFixtureDef analytic;
		analytic.shape = std::move(shape);
		analytic.local = local;
		try
		{
			CreateAnalyticFixture(body, def, analytic);
		}
		catch (const InvalidParameter& e)
		{
			return std::string(e.what());
		}
		return std::string();
	};
	b2Body* first = bullet();
	const std::string needle = add(first, MakeSuperellipse(0.02794076275822616, 1e12, 9.0, 9.0), Pose(Vec2(7.6e-5, -0.905), 1.4e-4), 1.27451f);
	CHECK(add(first, SuperellipseShape::FromZeta(0.50551551379430748, 0.027477254378009516, 1.9019607843137254),
	          Pose(Vec2(-0.490196, -0.490196), -1.54), 0.00488289f)
	          .empty());
	b2Body* second = bullet();
	const std::string huge = add(second, MakeCircle(1e8), Pose(Vec2(0.601343, -0.56408), 0.891784), 1.27527f);
	CAPTURE(needle);
	CAPTURE(huge);
	CHECK(needle.find("'shape'") != std::string::npos);
	CHECK(huge.find("'shape'") != std::string::npos);
	CHECK(second->GetFixtureList() == nullptr);
	b2CircleShape ball; // a Box2D circle in the refused one's place, so that the bullets meet
	ball.m_radius = 0.5f;
	second->CreateFixture(&ball, 1.0f);
	for (int i = 0; i < 40; ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	CHECK(std::isfinite(first->GetPosition().x));
	CHECK(std::isfinite(second->GetPosition().x));
}

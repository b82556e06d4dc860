// b2analytic tests: misuse of the adapter gives clear errors and leaves the world usable; what
// the adapter allows (shared shapes, density changes, lookups on any fixture) works.
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <limits>
#include <string>

using namespace b2a;
using namespace b2a::test;

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// The message of what `call` throws as `E` ("" when it throws nothing; other exceptions escape).
template <typename E, typename F>
std::string Thrown(F&& call)
{
	try
	{
		call();
	}
	catch (const E& e)
	{
		return e.what();
	}
	return "";
}

bool Has(const std::string& text, const std::string& part)
{
	return text.find(part) != std::string::npos;
}

b2Body* MakeDynamicBody(b2World& world, float x, float y)
{
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	bd.position.Set(x, y);
	return world.CreateBody(&bd);
}
} // namespace

TEST_CASE("a bad shape cannot be built, so no fixture ever sees one")
{
	// Every factory checks its parameters and names the field (the geometry tests check each rule).
	CHECK(Has(Thrown<InvalidParameter>([] { MakeSuperellipse(-1.0, 1.0, 4.0, 4.0); }), "'a'"));
	CHECK(Has(Thrown<InvalidParameter>([] { MakeSuperellipse(1.0, kNaN, 4.0, 4.0); }), "'b'"));
	CHECK(Has(Thrown<InvalidParameter>([] { MakeSuperellipse(1.0, 1.0, 0.5, 4.0); }), "'n'"));
	CHECK(Has(Thrown<InvalidParameter>([] { MakeEllipse(1.0, kInf); }), "'b'"));
	CHECK(Has(Thrown<InvalidParameter>([] { MakeCircle(0.0); }), "'r'"));
	CHECK(Has(Thrown<InvalidParameter>([] { MakeHeart(-2.0); }), "'alpha'"));
}

TEST_CASE("bad fixture definitions are refused with the field and value named; the body and world stay untouched")
{
	b2World world(b2Vec2(0.0f, -10.0f));
	MakeFloor(world);
	b2Body* body = MakeDynamicBody(world, 0.0f, 2.0f);
	const auto shape = MakeEllipse(0.6, 0.3);

	struct Case
	{
		const char* field;
		void (*spoil)(b2FixtureDef&, AnalyticFixtureDef&);
	};
	const Case cases[] = {
		{"'local'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.local = Pose(Vec2(kNaN, 0.0), 0.0); }},
		{"'local'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.local = Pose(Vec2(0.0, 0.0), kInf); }},
		{"'density'", [](b2FixtureDef& d, AnalyticFixtureDef&) { d.density = -1.0f; }},
		{"'density'", [](b2FixtureDef& d, AnalyticFixtureDef&) { d.density = float(kNaN); }},
		{"'friction'", [](b2FixtureDef& d, AnalyticFixtureDef&) { d.friction = -0.5f; }},
		{"'friction'", [](b2FixtureDef& d, AnalyticFixtureDef&) { d.friction = float(kInf); }},
		{"'restitution'", [](b2FixtureDef& d, AnalyticFixtureDef&) { d.restitution = -0.1f; }},
		{"'restitutionThreshold'", [](b2FixtureDef& d, AnalyticFixtureDef&) { d.restitutionThreshold = float(kNaN); }},
		{"'patchTolerance'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.patchTolerance = kNaN; }},
		{"'patchMinWidth'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.patchMinWidth = -1.0; }},
		{"'shape'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.shape = MakeCircle(1e-3); }},
		{"'shape'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.shape = nullptr; }},
		// A particle too large for Box2D's float mass data (the mass would overflow to inf).
		{"'shape'", [](b2FixtureDef& d, AnalyticFixtureDef& a) { a.shape = MakeCircle(1e18); d.density = 1.0f; }},
		// Particles reaching farther from the body origin than Box2D's float positions resolve its
		// slop (4194 length units): a circle of radius 5000, a needle 1e12 long, and a small
		// ellipse 4200 from the origin (the first two made b2TimeOfImpact assert in the world
		// fuzzer, next to a circle of radius 1e8).
		{"'shape'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.shape = MakeCircle(5000.0); }},
		{"'shape'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.shape = MakeSuperellipse(0.02794076275822616, 1e12, 9.0, 9.0); }},
		{"'local'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.local = Pose(Vec2(4200.0, 0.0), 0.0); }},
		// A needle so thin that its mass underflows float (Box2D's ResetMassData asserted; found by
		// the world fuzzer).
		{"'shape'", [](b2FixtureDef&, AnalyticFixtureDef& a) { a.shape = MakeEllipse(0.49941661749807853, 6.5732409498342358e-40); }},
	};
	for (const Case& c : cases)
	{
		b2FixtureDef fd;
		fd.density = 1.0f;
		AnalyticFixtureDef ad;
		ad.shape = shape;
		c.spoil(fd, ad);
		const std::string message = Thrown<InvalidParameter>([&] { CreateAnalyticFixture(body, fd, ad); });
		CAPTURE(message);
		CHECK(Has(message, c.field));
		CHECK(body->GetFixtureList() == nullptr);
	}

	// Within the reach a large particle is taken: a static circle of radius 4000 (Box2D's own
	// advice is at most 50 length units for static shapes, but its float positions still resolve
	// a tenth of the slop there).
	{
		b2World big(b2Vec2(0.0f, -10.0f));
		b2BodyDef groundDef;
		b2Body* ground = big.CreateBody(&groundDef);
		CHECK(CreateAnalyticFixture(ground, MakeCircle(4000.0), 0.0f) != nullptr);
		AnalyticFixtureDef near;
		near.shape = MakeCircle(1.0);
		near.local = Pose(Vec2(4190.0, 0.0), 0.0);
		b2FixtureDef fd;
		CHECK(CreateAnalyticFixture(ground, fd, near) != nullptr);
	}

	// A body whose own pose is not finite (set by the user) cannot get a fixture: its AABB
	// would poison Box2D's broad phase.
	b2Body* lost = MakeDynamicBody(world, 0.0f, 5.0f);
	lost->SetTransform(b2Vec2(float(kNaN), 0.0f), 0.0f);
	const std::string message = Thrown<InvalidParameter>([&] { CreateAnalyticFixture(lost, shape, 1.0f); });
	CAPTURE(message);
	CHECK(Has(message, "'body'"));
	CHECK(lost->GetFixtureList() == nullptr);
	world.DestroyBody(lost);

	// After all the refusals the world is intact: a proper fixture falls onto the floor and rests
	// there, its centre a semi-axis above it.
	CreateAnalyticFixture(body, shape, 1.0f);
	for (int i = 0; i < 120; ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	CHECK(body->GetPosition().y == doctest::Approx(0.3).epsilon(0.03));
	CHECK(std::fabs(body->GetLinearVelocity().y) < 0.05f);
}

TEST_CASE("creating analytic fixtures inside any callback of Step is refused and the step goes on")
{
	// Box2D locks the world during Step; its own CreateFixture would assert. Every listener
	// callback runs inside Step.
	struct Creator : b2ContactListener
	{
		b2Body* body = nullptr;
		int calls = 0, refused = 0;
		void TryCreate()
		{
			++calls;
			const std::string m = Thrown<MisuseError>([&] { CreateAnalyticFixture(body, MakeCircle(0.2), 1.0f); });
			refused += Has(m, "world is locked");
		}
		void BeginContact(b2Contact*) override { TryCreate(); }
		void EndContact(b2Contact*) override { TryCreate(); }
		void PreSolve(b2Contact*, const b2Manifold*) override { TryCreate(); }
		void PostSolve(b2Contact*, const b2ContactImpulse*) override { TryCreate(); }
	} creator;
	b2World world(b2Vec2(0.0f, -10.0f));
	world.SetContactListener(&creator);
	MakeFloor(world);
	b2Body* ball = MakeParticle(world, MakeSuperellipse(0.5, 0.3, 4.0, 4.0), 0.0f, 1.0f, 0.3f, 1.0f, 0.6f, 0.5f);
	creator.body = MakeDynamicBody(world, 5.0f, 5.0f);
	for (int i = 0; i < 240; ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	CHECK(creator.calls > 10);
	CHECK(creator.refused == creator.calls);
	CHECK(creator.body->GetFixtureList() == nullptr);
	// The scene itself was not disturbed: the particle came to rest on the floor.
	CHECK(ball->GetPosition().y > 0.25f);
	CHECK(ball->GetPosition().y < 0.55f);
	CHECK(ball->GetLinearVelocity().Length() < 0.05f);
	// Between steps the same call succeeds.
	CHECK(CreateAnalyticFixture(creator.body, MakeCircle(0.2), 1.0f) != nullptr);
}

TEST_CASE("lookups on null and plain fixtures answer or throw clearly")
{
	b2World world(b2Vec2(0.0f, 0.0f));
	b2Body* body = MakeDynamicBody(world, 0.0f, 0.0f);
	b2CircleShape circle;
	circle.m_radius = 0.5f;
	b2Fixture* plain = body->CreateFixture(&circle, 1.0f);
	b2Fixture* analytic = CreateAnalyticFixture(MakeDynamicBody(world, 3.0f, 0.0f), MakeCircle(0.5), 1.0f);

	CHECK(GetAnalyticShape(nullptr) == nullptr);
	CHECK(GetAnalyticShape(plain) == nullptr);
	CHECK(GetAnalyticShape(analytic) != nullptr);
	CHECK(Has(Thrown<InvalidParameter>([&] { GetAnalyticPose(plain); }), "'fixture'"));
	CHECK(Has(Thrown<InvalidParameter>([&] { GetAnalyticPose(nullptr); }), "'fixture'"));
	CHECK(GetAnalyticPose(analytic).p.x == doctest::Approx(3.0));
	for (const auto& pair : {std::make_pair(plain, analytic), std::make_pair(analytic, plain), std::make_pair(analytic, (b2Fixture*)nullptr),
	                         std::make_pair((b2Fixture*)nullptr, (b2Fixture*)nullptr)})
	{
		const ContactResult r = ComputeFixtureContact(pair.first, pair.second);
		CHECK(r.status == SolveStatus::failed);
		CHECK(Has(r.failure, "two analytic fixtures"));
	}
	// Two analytic unit circles 3 apart: separation 2 (the lookup works for pairs Box2D has no
	// contact for).
	b2Fixture* other = CreateAnalyticFixture(MakeDynamicBody(world, 0.0f, 3.0f), MakeCircle(0.5), 1.0f);
	CHECK(ComputeFixtureContact(analytic, other).separation == doctest::Approx(3.0 * std::sqrt(2.0) - 1.0).epsilon(1e-9));

	struct NoDraw : b2Draw
	{
		void DrawPolygon(const b2Vec2*, int32, const b2Color&) override {}
		void DrawSolidPolygon(const b2Vec2*, int32, const b2Color&) override {}
		void DrawCircle(const b2Vec2&, float, const b2Color&) override {}
		void DrawSolidCircle(const b2Vec2&, float, const b2Vec2&, const b2Color&) override {}
		void DrawSegment(const b2Vec2&, const b2Vec2&, const b2Color&) override {}
		void DrawTransform(const b2Transform&) override {}
		void DrawPoint(const b2Vec2&, float, const b2Color&) override {}
	} draw;
	CHECK(Has(Thrown<MisuseError>([&] { DrawWorld(nullptr, &draw); }), "must not be null"));
	CHECK(Has(Thrown<MisuseError>([&] { DrawWorld(&world, nullptr); }), "must not be null"));
}

TEST_CASE("shapes outlive the bodies and worlds that used them; fixtures are alive in SayGoodbye")
{
	const auto shape = MakeHeart(0.4);
	const Vec2 probe(0.0, 0.1); // inside the heart (its level there is below α)
	const double level = shape->Level(probe);
	REQUIRE(level < shape->SurfaceLevel());

	// Box2D tells a destruction listener about each fixture before freeing it: the analytic data
	// is still there, so user clean-up may read it.
	struct Goodbye : b2DestructionListener
	{
		int analytic = 0;
		void SayGoodbye(b2Joint*) override {}
		void SayGoodbye(b2Fixture* f) override { analytic += GetAnalyticShape(f) != nullptr && GetAnalyticShape(f)->Mass().area > 0.0; }
	} goodbye;
	{
		b2World world(b2Vec2(0.0f, -10.0f));
		world.SetDestructionListener(&goodbye);
		MakeFloor(world);
		b2Body* a = MakeParticle(world, shape, 0.0f, 1.0f);
		b2Body* b = MakeParticle(world, shape, 0.3f, 2.5f);
		for (int i = 0; i < 60; ++i)
			world.Step(1.0f / 60.0f, 8, 3);
		CHECK(shape.use_count() == 3);
		world.DestroyBody(a); // while in contact with the floor and maybe with b
		CHECK(goodbye.analytic == 1);
		CHECK(shape.use_count() == 2);
		for (int i = 0; i < 60; ++i) // the contacts of the destroyed body went with it
			world.Step(1.0f / 60.0f, 8, 3);
		CHECK(b->GetPosition().y < 1.0f);
		// The world's destructor frees the rest without calling listeners (as Box2D documents).
	}
	CHECK(shape.use_count() == 1);
	CHECK(shape->Level(probe) == level); // the shape itself is untouched and usable
	CHECK(goodbye.analytic == 1);
}

TEST_CASE("what is allowed: one shape in several worlds, density changes, sensors, static analytic bodies")
{
	const auto shape = MakeSuperellipse(0.5, 0.25, 4.0, 4.0);
	b2World w1(b2Vec2(0.0f, -10.0f)), w2(b2Vec2(0.0f, -10.0f));
	MakeFloor(w1);
	// In w2 the floor is itself an analytic fixture on a static body: a wide flat superellipse.
	b2BodyDef sd;
	sd.position.Set(0.0f, -0.5f);
	CreateAnalyticFixture(w2.CreateBody(&sd), MakeSuperellipse(20.0, 0.5, 8.0, 8.0), 0.0f);
	b2Body* b1 = MakeParticle(w1, shape, 0.0f, 1.0f);
	b2Body* b2 = MakeParticle(w2, shape, 0.0f, 1.0f);
	for (int i = 0; i < 180; ++i)
	{
		w1.Step(1.0f / 60.0f, 8, 3);
		w2.Step(1.0f / 60.0f, 8, 3);
	}
	// Both rest flat on their floors (top of the static superellipse at y = 0).
	CHECK(b1->GetPosition().y == doctest::Approx(0.25).epsilon(0.04));
	CHECK(b2->GetPosition().y == doctest::Approx(0.25).epsilon(0.04));

	// Density changes follow Box2D's rules: SetDensity then ResetMassData; the mass comes from the
	// analytic area.
	b2Fixture* f = b1->GetFixtureList();
	f->SetDensity(3.0f);
	b1->ResetMassData();
	CHECK(b1->GetMass() == doctest::Approx(3.0 * shape->Mass().area).epsilon(1e-6));

	// A sensor analytic fixture reports overlaps and never pushes.
	struct Counter : b2ContactListener
	{
		int begins = 0;
		void BeginContact(b2Contact* c) override { begins += c->GetFixtureA()->IsSensor() || c->GetFixtureB()->IsSensor(); }
	} counter;
	w1.SetContactListener(&counter);
	b2Body* ghost = MakeDynamicBody(w1, 0.2f, 0.5f);
	b2FixtureDef fd;
	fd.isSensor = true;
	fd.density = 1.0f;
	AnalyticFixtureDef ad;
	ad.shape = MakeCircle(0.4);
	CreateAnalyticFixture(ghost, fd, ad);
	const b2Vec2 resting = b1->GetPosition();
	for (int i = 0; i < 60; ++i)
		w1.Step(1.0f / 60.0f, 8, 3);
	CHECK(counter.begins >= 1);
	CHECK(ghost->GetPosition().y < -1.0f); // fell through the particle and the floor
	CHECK(b2Distance(b1->GetPosition(), resting) < 1e-3f); // which it never pushed
}

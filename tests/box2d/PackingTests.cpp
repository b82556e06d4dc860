// b2analytic tests: a random packing settles to mechanical equilibrium; millimetre scenes behave.
#include "SceneSupport.h"

#include <doctest/doctest.h>

using namespace b2a;
using namespace b2a::test;

namespace
{
// A box of static edges: floor y = 0 from −w to w, walls up to height h, frictionless walls
// (so that the floor alone carries the weight) and a rough floor. Box2D mixes restitution
// thresholds by their minimum, so a millimetre scene raises the walls' threshold too.
b2Body* MakeBox(b2World& world, float w, float h, float floorFriction, float restitutionThreshold = 1.0f)
{
	b2BodyDef def;
	b2Body* box = world.CreateBody(&def);
	b2EdgeShape edge;
	b2FixtureDef fd;
	fd.shape = &edge;
	fd.friction = floorFriction;
	fd.restitutionThreshold = restitutionThreshold;
	edge.SetTwoSided(b2Vec2(-w, 0.0f), b2Vec2(w, 0.0f));
	box->CreateFixture(&fd);
	fd.friction = 0.0f;
	edge.SetTwoSided(b2Vec2(-w, 0.0f), b2Vec2(-w, h));
	box->CreateFixture(&fd);
	edge.SetTwoSided(b2Vec2(w, 0.0f), b2Vec2(w, h));
	box->CreateFixture(&fd);
	return box;
}
} // namespace

TEST_CASE("a random packing of 200 superellipses in a box settles to mechanical equilibrium")
{
	// Superellipses of random sizes, exponents and orientations fall into a box and settle.
	// Mechanical equilibrium: no kinetic energy left (below 1e-6 of the potential energy the fall
	// released) and the floor carries the weight (its normal force, from PostSolve impulses over
	// time, within 1 % of m·g; the walls are frictionless so they carry none).
	const float g = 10.0f;
	b2World world(b2Vec2(0.0f, -g));
	world.SetAllowSleeping(false); // measure the settled pile, not frozen bodies
	b2Body* box = MakeBox(world, 6.0f, 40.0f, 0.6f);
	ImpulseMeter meter;
	meter.fixture = box->GetFixtureList()->GetNext()->GetNext(); // the floor (Box2D lists fixtures newest first)
	world.SetContactListener(&meter);
	Random rng(2022);
	for (int i = 0; i < 200; ++i)
	{
		const double a = rng.Uniform(0.25, 0.4), b = rng.Uniform(0.2, 0.3);
		const double n = rng.Uniform(2.0, 6.0), m = rng.Uniform(2.0, 6.0);
		const float x = -5.2f + 0.8f * float(i % 14), y = 0.5f + 0.8f * float(i / 14);
		MakeParticle(world, MakeSuperellipse(a, b, n, m), x, y, float(rng.Angle()), 1.0f, 0.5f);
	}
	double weight = 0.0;
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
		weight += b->GetMass() * g;
	const double pe0 = PotentialEnergy(world, g);
	const float dt = 1.0f / 60.0f;
	for (int i = 0; i < 600; ++i) // 10 s to fall and settle
		world.Step(dt, 8, 3);
	meter.impulse = 0.0;
	const int window = 120;
	for (int i = 0; i < window; ++i) // then 2 s of measurement
		world.Step(dt, 8, 3);
	const double released = pe0 - PotentialEnergy(world, g);
	const double ke = KineticEnergy(world);
	const double floorForce = meter.impulse / (window * dt);
	INFO("kinetic " << ke << ", released " << released << ", floor force " << floorForce << ", weight " << weight);
	REQUIRE(released > 0.0);
	CHECK(ke < 1e-6 * released);
	CHECK(std::fabs(floorForce - weight) < 0.01 * weight);
	// Nobody left the box.
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
		if (b->GetType() == b2_dynamicBody)
		{
			CHECK(std::fabs(b->GetPosition().x) < 6.0f);
			CHECK(b->GetPosition().y > 0.0f);
		}
}

TEST_CASE("a 2 x 0.66 mm ellipse in a millimetre scene lands, rocks down onto its side, and rests")
{
	// docs/design.md, "Units": 1 length unit = 1 mm, gravity 9810 mm/s², a step small enough that
	// nothing moves more than 2 units per step, and the restitution threshold raised from 1 unit/s
	// (1 mm/s here) to Box2D's default in metres, 1000 mm/s. The paper's ellipse (major axis 2 mm,
	// minor 0.66 mm) falls 10 mm.
	const float g = 9810.0f;
	auto makeWorld = [&](b2World& world) {
		world.SetAllowSleeping(false);
		MakeBox(world, 10.0f, 20.0f, 0.5f, 1000.0f);
	};
	auto makeEllipse = [&](b2World& world, float y, float angle) {
		b2BodyDef bd;
		bd.type = b2_dynamicBody;
		bd.position.Set(0.0f, y);
		bd.angle = angle;
		b2Body* body = world.CreateBody(&bd);
		b2FixtureDef fd;
		fd.density = 1e-3f; // g/mm²: masses in grams
		fd.friction = 0.5f;
		fd.restitution = 0.3f;
		fd.restitutionThreshold = 1000.0f; // mm/s
		AnalyticFixtureDef ad;
		ad.shape = MakeEllipse(1.0, 0.33);
		CreateAnalyticFixture(body, fd, ad);
		return body;
	};
	const float dt = 2e-4f; // the impact speed √(2·9810·10) ≈ 443 mm/s moves 0.09 mm per step
	{
		b2World world(b2Vec2(0.0f, -g));
		makeWorld(world);
		b2Body* body = makeEllipse(world, 10.0f, 0.6f);
		auto energy = [&] {
			const b2Vec2 v = body->GetLinearVelocity();
			const double w = body->GetAngularVelocity();
			return 0.5 * body->GetMass() * b2Dot(v, v) + 0.5 * body->GetInertia() * w * w + body->GetMass() * g * body->GetPosition().y;
		};
		const double e0 = energy();
		double maxEnergy = e0, lowest = 1e9;
		float maxSpeed = 0.0f;
		for (int i = 0; i < 10000; ++i) // 2 s
		{
			world.Step(dt, 8, 3);
			maxSpeed = std::max(maxSpeed, body->GetLinearVelocity().Length());
			maxEnergy = std::max(maxEnergy, energy());
			lowest = std::min(lowest, WorldSupport(*GetAnalyticShape(body->GetFixtureList()), GetAnalyticPose(body->GetFixtureList()), Vec2(0.0, -1.0)).y);
		}
		CHECK(maxSpeed < 1.05f * std::sqrt(2.0f * g * 10.0f)); // no faster than the fall
		CHECK(maxEnergy <= e0 * (1.0 + 1e-6));                  // the impact only takes energy away
		CHECK(lowest > -0.02);                                  // never through the floor
		CHECK(energy() < 0.05 * e0);                            // most of the fall's energy is gone
		// It lies on its side, rocking a little: centre below half the major axis.
		CHECK(body->GetPosition().y < 0.6f);
		CHECK(std::fabs(std::sin(body->GetAngle())) < 0.5f);
	}
	{
		// Placed at rest on its side, it stays: the contact settles at the slop and nothing creeps.
		b2World world(b2Vec2(0.0f, -g));
		makeWorld(world);
		b2Body* body = makeEllipse(world, 0.33f + b2_polygonRadius - b2_linearSlop, 0.0f);
		for (int i = 0; i < 1000; ++i)
			world.Step(dt, 8, 3);
		const b2Vec2 rest = body->GetPosition();
		for (int i = 0; i < 5000; ++i) // 1 s
			world.Step(dt, 8, 3);
		CHECK(b2Distance(body->GetPosition(), rest) < 1e-5f);
		CHECK(std::fabs(body->GetAngle()) < 1e-5f);
		CHECK(body->GetPosition().y == doctest::Approx(0.33 + b2_polygonRadius - b2_linearSlop).epsilon(1e-4));
	}
}

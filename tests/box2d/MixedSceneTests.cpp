// b2analytic tests: analytic particles among Box2D's own shapes (chains, polygons, circles).
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <set>
#include <string>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("analytic particles rest in a chain container, on a Box2D box and under a Box2D ball")
{
	b2World world(b2Vec2(0.0f, -10.0f));
	world.SetAllowSleeping(false);
	// A U-shaped chain container, wound so that its one-sided links face inwards (a Box2D chain
	// link's solid side is its right-hand side, normal (e.y, −e.x)), with ghost vertices.
	b2BodyDef gd;
	b2Body* ground = world.CreateBody(&gd);
	const b2Vec2 u[4] = {b2Vec2(4.0f, 8.0f), b2Vec2(4.0f, 0.0f), b2Vec2(-4.0f, 0.0f), b2Vec2(-4.0f, 8.0f)};
	b2ChainShape chain;
	chain.CreateChain(u, 4, b2Vec2(4.0f, 9.0f), b2Vec2(-4.0f, 9.0f));
	b2Fixture* container = ground->CreateFixture(&chain, 0.0f);
	// A Box2D box standing on the floor, and analytic particles next to and on top of it.
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	bd.position.Set(2.5f, 0.5f);
	b2Body* box = world.CreateBody(&bd);
	b2PolygonShape square;
	square.SetAsBox(0.5f, 0.5f);
	box->CreateFixture(&square, 1.0f);
	b2Body* block = MakeParticle(world, MakeSuperellipse(0.5, 0.4, 6.0, 6.0), 2.5f, 1.45f);          // on the box
	b2Body* ellipse = MakeParticle(world, MakeEllipse(0.6, 0.3), -2.0f, 0.305f, 0.0f);               // lying on the chain floor
	b2Body* heart = MakeParticle(world, MakeHeart(0.2), 0.5f, 1.0f, 0.0f);                           // on the chain floor
	b2Body* leaning = MakeParticle(world, MakeSuperellipse(0.3, 0.6, 4.0, 4.0), -3.6f, 0.7f, 0.0f);  // against the wall
	// A Box2D ball dropped onto the block. (Balanced on the block's convex top it is in an
	// unstable equilibrium and starts, very slowly, to roll off: it is not part of the energy
	// check below.)
	bd.position.Set(2.5f, 2.6f);
	b2Body* ball = world.CreateBody(&bd);
	b2CircleShape circle;
	circle.m_radius = 0.3f;
	ball->CreateFixture(&circle, 1.0f);

	for (int i = 0; i < 300; ++i)
		world.Step(1.0f / 60.0f, 8, 3);

	// Every pair type the adapter handles has a touching contact: analytic with chain, polygon
	// and circle (and the plain box with the chain as Box2D does it).
	std::set<std::pair<b2Shape::Type, b2Shape::Type>> touching;
	for (b2Contact* c = world.GetContactList(); c; c = c->GetNext())
		if (c->IsTouching())
		{
			const b2Fixture* a = c->GetFixtureA();
			const b2Fixture* b = c->GetFixtureB();
			auto type = [](const b2Fixture* f) { return GetAnalyticShape(f) ? b2Shape::e_typeCount : f->GetType(); };
			touching.insert(std::minmax(type(a), type(b)));
		}
	const b2Shape::Type analytic = b2Shape::e_typeCount; // a marker for "analytic fixture"
	CHECK(touching.count(std::minmax(b2Shape::e_chain, analytic)));
	CHECK(touching.count(std::minmax(b2Shape::e_polygon, analytic)));
	CHECK(touching.count(std::minmax(b2Shape::e_circle, analytic)));
	CHECK(touching.count(std::minmax(b2Shape::e_chain, b2Shape::e_polygon)));

	// Everything came to rest inside the container, the ball on the block on the box.
	std::string motion;
	for (b2Body* b : {block, ellipse, heart, leaning, ball, box})
		motion += std::to_string(b->GetLinearVelocity().Length()) + "/" + std::to_string(b->GetAngularVelocity()) + " ";
	INFO("speeds/spins of block, ellipse, heart, leaning block, ball, box: " << motion);
	const double ke = KineticEnergy(world) - 0.5 * ball->GetMass() * b2Dot(ball->GetLinearVelocity(), ball->GetLinearVelocity()) -
	                  0.5 * ball->GetInertia() * ball->GetAngularVelocity() * ball->GetAngularVelocity();
	CHECK(ke < 1e-6);
	CHECK(std::fabs(ball->GetLinearVelocity().y) < 1e-3f);
	for (b2Body* b : {block, ellipse, heart, leaning, ball, box})
	{
		CHECK(std::fabs(b->GetPosition().x) < 4.0f);
		CHECK(b->GetPosition().y > 0.0f);
	}
	CHECK(ball->GetPosition().y > block->GetPosition().y + 0.4f);
	CHECK(block->GetPosition().y > box->GetPosition().y + 0.8f);
	// The ellipse lies flat on the chain floor: resting height b + chain skin − slop.
	CHECK(ellipse->GetPosition().y == doctest::Approx(0.3 + b2_polygonRadius - b2_linearSlop).epsilon(2e-3));
	CHECK(std::fabs(std::sin(ellipse->GetAngle())) < 1e-3f);
	(void)container;
}

TEST_CASE("a one-sided chain lets a particle through from behind, as Box2D's chains do")
{
	// A horizontal chain link facing up (collisions on its upper, right-hand side when wound
	// right to left): a particle thrown up from below passes it and falls back onto it; one falling from above rests
	// on it.
	b2World world(b2Vec2(0.0f, -10.0f));
	b2BodyDef gd;
	b2Body* ground = world.CreateBody(&gd);
	const b2Vec2 v[2] = {b2Vec2(5.0f, 0.0f), b2Vec2(-5.0f, 0.0f)};
	b2ChainShape chain;
	chain.CreateChain(v, 2, b2Vec2(6.0f, 0.0f), b2Vec2(-6.0f, 0.0f));
	ground->CreateFixture(&chain, 0.0f);
	b2Body* rising = MakeParticle(world, MakeEllipse(0.4, 0.2), -2.0f, -1.0f);
	rising->SetLinearVelocity(b2Vec2(0.0f, 8.0f));
	b2Body* falling = MakeParticle(world, MakeEllipse(0.4, 0.2), 2.0f, 1.0f);
	for (int i = 0; i < 120; ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	CHECK(falling->GetPosition().y > 0.15f); // resting on top
	CHECK(falling->GetPosition().y < 0.25f);
	// The rising one passed the link from behind (a two-sided edge would have stopped it below),
	// rose about 3 units, fell back and now rests on top as well.
	CHECK(rising->GetPosition().y > 0.15f);
	CHECK(rising->GetPosition().y < 0.25f);
}

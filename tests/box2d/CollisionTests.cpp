// b2analytic tests: collisions conserve what physics says, and fast particles do not tunnel.
#include "SceneSupport.h"

#include <doctest/doctest.h>

using namespace b2a;
using namespace b2a::test;

namespace
{
double KineticEnergy(b2Body* b)
{
	const b2Vec2 v = b->GetLinearVelocity();
	const double w = b->GetAngularVelocity();
	const double Ic = b->GetInertia() - b->GetMass() * b2Dot(b->GetLocalCenter(), b->GetLocalCenter());
	return 0.5 * b->GetMass() * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * Ic * w * w;
}
} // namespace

TEST_CASE("two ellipses colliding elastically without friction conserve momentum and energy")
{
	// Off-centre impact of two ellipses with spin: restitution 1, no friction, no gravity.
	// Momentum is conserved by every impulse pair; kinetic energy by an elastic impact.
	for (int substeps : {1, 4})
	{
		CAPTURE(substeps);
		b2World world(b2Vec2(0.0f, 0.0f));
		b2Body* a = MakeParticle(world, MakeEllipse(1.0, 0.5), -3.0f, 0.0f, 0.3f, 1.0f, 0.0f, 1.0f);
		b2Body* b = MakeParticle(world, MakeEllipse(0.8, 0.4), 3.0f, 0.4f, -0.7f, 1.5f, 0.0f, 1.0f);
		a->SetLinearVelocity(b2Vec2(5.0f, 0.0f));
		b->SetLinearVelocity(b2Vec2(-6.0f, 0.5f));
		b->SetAngularVelocity(1.0f);
		auto momentum = [&] {
			return b2Vec2(a->GetMass() * a->GetLinearVelocity().x + b->GetMass() * b->GetLinearVelocity().x,
			              a->GetMass() * a->GetLinearVelocity().y + b->GetMass() * b->GetLinearVelocity().y);
		};
		const b2Vec2 p0 = momentum();
		const double e0 = KineticEnergy(a) + KineticEnergy(b);
		const b2Vec2 va0 = a->GetLinearVelocity();
		for (int i = 0; i < 120 * substeps; ++i)
			world.Step(1.0f / (60.0f * substeps), 8, 3);
		CHECK(b2Distance(a->GetLinearVelocity(), va0) > 1.0f); // they did collide
		const b2Vec2 p1 = momentum();
		CHECK(b2Distance(p0, p1) / p0.Length() < 1e-4);
		const double e1 = KineticEnergy(a) + KineticEnergy(b);
		CHECK(std::fabs(e1 - e0) / e0 < 0.01);
	}
}

TEST_CASE("fast particles do not pass through thin static walls")
{
	// A zero-thickness edge wall at x = 0. Particles thrown at it at Box2D's speed limit (2 length
	// units per step: 120 per second at 60 Hz) cross several of their own sizes per step, so only
	// continuous collision stops them. Box2D's TOI works on the inscribed proxy polygon, which
	// never reaches the wall before the true shape does; when it stops the particle the true
	// shapes touch and the analytic contact holds it on the near side.
	const ShapePtr shapes[] = {MakeEllipse(0.4, 0.1), MakeSuperellipse(0.3, 0.2, 8.0, 8.0), MakeHeart(0.05), MakeCircle(0.15),
	                           MakeEllipse(0.5, 0.05)};
	int thrown = 0;
	for (const ShapePtr& shape : shapes)
		for (float angle : {0.0f, 0.5f, 1.3f, 2.2f})
			for (float speed : {30.0f, 80.0f, 119.0f})
			{
				CAPTURE(shape->Describe());
				CAPTURE(angle);
				CAPTURE(speed);
				b2World world(b2Vec2(0.0f, 0.0f));
				b2BodyDef gd;
				b2Body* ground = world.CreateBody(&gd);
				b2EdgeShape wall;
				wall.SetTwoSided(b2Vec2(0.0f, -100.0f), b2Vec2(0.0f, 100.0f)); // long: particles may slide along it
				ground->CreateFixture(&wall, 0.0f);
				b2Body* p = MakeParticle(world, shape, -3.0f, 0.2f, angle);
				p->SetLinearVelocity(b2Vec2(speed, 3.0f));
				p->SetAngularVelocity(7.0f);
				const Shape& s = *shape;
				double deepest = -1e9;
				for (int i = 0; i < 60; ++i)
				{
					world.Step(1.0f / 60.0f, 8, 3);
					// The centre never crosses; a spinning particle may dig into the wall for a step
					// or two while the solver resolves the impact, never through it.
					CHECK(p->GetPosition().x < 0.0f);
					deepest = std::max(deepest, WorldSupport(s, GetAnalyticPose(p->GetFixtureList()), Vec2(1.0, 0.0)).x);
				}
				CHECK(deepest < 0.5 * s.BoundingRadius() + 0.1);
				// A second later the whole particle is back on the near side, moving away or at rest
				// against the wall (a heart that came to lie on both lobes: 2e-7 m/s left over).
				CHECK(WorldSupport(s, GetAnalyticPose(p->GetFixtureList()), Vec2(1.0, 0.0)).x < 0.0);
				CHECK(p->GetLinearVelocity().x <= 1e-5f);
				++thrown;
			}
	CHECK(thrown == 60);
}

TEST_CASE("fast particles do not pass through each other")
{
	// Two thin ellipses (0.1 thick) shot at each other at the speed limit, one of them a bullet
	// (Box2D runs continuous collision between dynamic bodies only for bullets). Without it they
	// would cross in a step; with it they collide: their approach stops, and at no step do the
	// true shapes overlap by half their thickness.
	for (float angle : {0.0f, 0.7f, 1.57f})
	{
		CAPTURE(angle);
		b2World world(b2Vec2(0.0f, 0.0f));
		const auto needle = MakeEllipse(0.5, 0.05);
		b2Body* a = MakeParticle(world, needle, -3.0f, 0.0f, angle);
		b2Body* b = MakeParticle(world, needle, 3.0f, 0.1f, 1.57f - angle);
		a->SetBullet(true);
		a->SetLinearVelocity(b2Vec2(110.0f, 0.0f));
		b->SetLinearVelocity(b2Vec2(-110.0f, 0.0f));
		double deepest = 1e9;
		for (int i = 0; i < 10; ++i)
		{
			world.Step(1.0f / 60.0f, 8, 3);
			deepest = std::min(deepest, ComputeFixtureContact(a->GetFixtureList(), b->GetFixtureList()).separation);
		}
		CHECK(deepest > -0.05);
		CHECK(a->GetLinearVelocity().x - b->GetLinearVelocity().x < 0.2f * 220.0f); // the approach was stopped
	}
}

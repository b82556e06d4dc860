// b2analytic tests: small helpers for Box2D scenes.
#pragma once

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/b2analytic.h"
#include "TestSupport.h"

#include <box2d/box2d.h>

#include <cmath>
#include <vector>

namespace b2a::test
{

/// A static floor edge along y = 0 from x = −halfWidth to +halfWidth.
inline b2Body* MakeFloor(b2World& world, float halfWidth = 50.0f)
{
	b2BodyDef def;
	b2Body* ground = world.CreateBody(&def);
	b2EdgeShape edge;
	edge.SetTwoSided(b2Vec2(-halfWidth, 0.0f), b2Vec2(halfWidth, 0.0f));
	ground->CreateFixture(&edge, 0.0f);
	return ground;
}

/// A dynamic body at (x, y, angle) with one analytic fixture.
inline b2Body* MakeParticle(b2World& world, ShapePtr shape, float x, float y, float angle = 0.0f, float density = 1.0f,
                            float friction = 0.6f, float restitution = 0.0f)
{
	b2BodyDef def;
	def.type = b2_dynamicBody;
	def.position.Set(x, y);
	def.angle = angle;
	b2Body* body = world.CreateBody(&def);
	b2FixtureDef fd;
	fd.density = density;
	fd.friction = friction;
	fd.restitution = restitution;
	AnalyticFixtureDef ad;
	ad.shape = std::move(shape);
	CreateAnalyticFixture(body, fd, ad);
	return body;
}

/// Translational plus rotational kinetic energy of every dynamic body.
inline double KineticEnergy(b2World& world)
{
	double e = 0.0;
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
	{
		if (b->GetType() != b2_dynamicBody)
			continue;
		const b2Vec2 v = b->GetLinearVelocity();
		const double w = b->GetAngularVelocity();
		e += 0.5 * b->GetMass() * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * b->GetInertia() * w * w -
		     0.5 * b->GetMass() * double(b2Dot(b->GetLocalCenter(), b->GetLocalCenter())) * w * w;
	}
	return e;
}

/// Gravitational potential energy m·g·y of every dynamic body's centre of mass (g > 0 downwards).
inline double PotentialEnergy(b2World& world, double g)
{
	double e = 0.0;
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
		if (b->GetType() == b2_dynamicBody)
			e += b->GetMass() * g * b->GetWorldCenter().y;
	return e;
}

/// Sum of the vertical components of the normal impulses of every PostSolve on contacts that
/// involve `fixture` (a floor): over time, the floor's normal force.
struct ImpulseMeter : b2ContactListener
{
	b2Fixture* fixture = nullptr;
	double impulse = 0.0;
	void PostSolve(b2Contact* contact, const b2ContactImpulse* impulses) override
	{
		if (contact->GetFixtureA() != fixture && contact->GetFixtureB() != fixture)
			return;
		b2WorldManifold wm;
		contact->GetWorldManifold(&wm);
		for (int32 i = 0; i < impulses->count; ++i)
			impulse += impulses->normalImpulses[i] * std::fabs(wm.normal.y);
	}
};

} // namespace b2a::test

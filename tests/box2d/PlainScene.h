// b2analytic tests: a scene of Box2D's own shapes only, to compare with and without the adapter.
#pragma once

#include <box2d/box2d.h>

#include <cstdio>
#include <string>

namespace b2a::test
{

/// Boxes, polygons and circles falling into a chain container onto an edge floor: every pair type
/// the adapter registers for ((polygon, polygon), (polygon, circle), (edge, polygon), (chain,
/// polygon)) and those it leaves alone. Returns every body's final position, angle and velocity
/// as hexadecimal floats, so that equal strings mean bit-identical states.
inline std::string RunPlainScene(int steps)
{
	b2World world(b2Vec2(0.0f, -10.0f));
	b2BodyDef gd;
	b2Body* ground = world.CreateBody(&gd);
	b2EdgeShape floor;
	floor.SetTwoSided(b2Vec2(-8.0f, 0.0f), b2Vec2(8.0f, 0.0f));
	ground->CreateFixture(&floor, 0.0f);
	b2Vec2 wall[4] = {b2Vec2(-7.0f, 20.0f), b2Vec2(-7.0f, 0.5f), b2Vec2(7.0f, 0.5f), b2Vec2(7.0f, 20.0f)};
	b2ChainShape chain;
	chain.CreateChain(wall, 4, b2Vec2(-7.0f, 21.0f), b2Vec2(7.0f, 21.0f));
	ground->CreateFixture(&chain, 0.0f);

	for (int i = 0; i < 60; ++i)
	{
		b2BodyDef bd;
		bd.type = b2_dynamicBody;
		bd.position.Set(-5.0f + 0.9f * float(i % 12), 2.0f + 1.1f * float(i / 12));
		bd.angle = 0.37f * float(i);
		b2Body* body = world.CreateBody(&bd);
		b2FixtureDef fd;
		fd.density = 1.0f + 0.1f * float(i % 3);
		fd.friction = 0.5f;
		b2PolygonShape box;
		b2CircleShape ball;
		b2PolygonShape tri;
		switch (i % 3)
		{
		case 0:
			box.SetAsBox(0.35f, 0.25f);
			fd.shape = &box;
			break;
		case 1:
			ball.m_radius = 0.3f;
			fd.shape = &ball;
			break;
		default:
		{
			const b2Vec2 v[3] = {b2Vec2(-0.4f, -0.3f), b2Vec2(0.4f, -0.3f), b2Vec2(0.0f, 0.4f)};
			tri.Set(v, 3);
			fd.shape = &tri;
		}
		}
		body->CreateFixture(&fd);
	}
	for (int s = 0; s < steps; ++s)
		world.Step(1.0f / 60.0f, 8, 3);

	std::string out;
	char line[256];
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
	{
		std::snprintf(line, sizeof(line), "%a %a %a %a %a %a\n", double(b->GetPosition().x), double(b->GetPosition().y),
		              double(b->GetAngle()), double(b->GetLinearVelocity().x), double(b->GetLinearVelocity().y),
		              double(b->GetAngularVelocity()));
		out += line;
	}
	return out;
}

} // namespace b2a::test

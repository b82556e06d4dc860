// A minimal program of a Box2D user: a world from Box2D, an analytic particle from b2analytic.
#include <b2analytic/AnalyticFixture.h>
#include <b2analytic/b2analytic.h>
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>

int main()
{
	b2World world(b2Vec2(0.0f, -10.0f));
	b2BodyDef groundDef;
	b2Body* ground = world.CreateBody(&groundDef);
	b2EdgeShape floor;
	floor.SetTwoSided(b2Vec2(-10.0f, 0.0f), b2Vec2(10.0f, 0.0f));
	ground->CreateFixture(&floor, 0.0f);

	// An ellipse of semi-axes 1 and 0.5 dropped from 2 units up lands on its side.
	b2BodyDef def;
	def.type = b2_dynamicBody;
	def.position.Set(0.0f, 2.0f);
	b2Body* body = world.CreateBody(&def);
	b2a::CreateAnalyticFixture(body, b2a::MakeEllipse(1.0, 0.5), 1.0f);
	for (int i = 0; i < 180; ++i)
		world.Step(1.0f / 60.0f, 8, 3);

	// Resting height: semi-axis 0.5, plus the edge's skin, less Box2D's slop.
	const float y = body->GetPosition().y;
	std::printf("ellipse at rest at y = %.5f (mass %.5f, expected pi/2)\n", double(y), double(body->GetMass()));
	const bool ok = std::fabs(y - (0.5f + b2_polygonRadius - b2_linearSlop)) < 1e-3f &&
	                std::fabs(body->GetMass() - 3.14159265f / 2.0f) < 1e-5f;
	return ok ? 0 : 1;
}

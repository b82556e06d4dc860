// A minimal program of a Box2D user: a world from Box2D, a contact from b2analytic.
#include <b2analytic/b2analytic.h>
#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>

int main()
{
	b2World world(b2Vec2(0.0f, -10.0f));
	b2BodyDef def;
	def.type = b2_dynamicBody;
	b2Body* body = world.CreateBody(&def);
	b2CircleShape ball;
	ball.m_radius = 0.5f;
	body->CreateFixture(&ball, 1.0f);
	for (int i = 0; i < 10; ++i)
		world.Step(1.0f / 60.0f, 8, 3);

	// Two unit circles 3 apart: separated by 1 (closed form).
	const auto circle = b2a::MakeCircle(1.0);
	const b2a::ContactResult c = b2a::ComputeContact(*circle, b2a::Pose({0, 0}, 0.0), *circle, b2a::Pose({3, 0}, 0.0));
	std::printf("separation %.17g, body y %.6f\n", c.separation, double(body->GetPosition().y));
	return (c.Ok() && std::fabs(c.separation - 1.0) < 1e-14 && body->GetPosition().y < 0.0f) ? 0 : 1;
}

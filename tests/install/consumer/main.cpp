// A minimal program of a Box2D user: a world from Box2D, an analytic particle from b2analytic.
#include <b2analytic/3d/b2analytic3d.h>
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

	// The 3D core from the same package: the paper's Figure 17 first touches at 0.1923 ms.
	using b2a::kPi;
	const auto i = b2a::MakeSuperellipsoid(4, 4, 4, 6, 6, 12), j = b2a::MakeSuperellipsoid(2, 3, 2, 8, 8, 8);
	const b2a::Motion3 mi{b2a::Pose3({-10, -15, -10}, b2a::EulerZXZ(kPi / 9, kPi / 8, kPi / 7)), {-20, -10, -15}, {20, -30, 2}};
	const b2a::Motion3 mj{b2a::Pose3({-20, -25, -20}, b2a::EulerZXZ(kPi / 6, kPi / 5, kPi / 4)), {10, 20, 15}, {-10, 20, -2}};
	const b2a::TimeOfImpactResult3 hit = b2a::TimeOfImpact(*i, mi, *j, mj, 1.0);
	std::printf("superellipsoids of Figure 17 first touch at t = %.6f ms\n", hit.time);
	return ok && hit.hit && std::fabs(hit.time - 0.1923) < 1e-3 ? 0 : 1;
}

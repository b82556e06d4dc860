// b2analytic tests: game scenes in Box2D's testbed settings (metres, g = 10 m/s², 60 Hz, 8
// velocity and 3 position iterations, sleeping on) against the same scenes of Box2D's own
// shapes and the textbook: a pyramid of blocks, a block landing tilted, a heart on both lobes,
// a ramp.
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
const float kStep = 1.0f / 60.0f;

bool AllAsleep(b2World& world)
{
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
		if (b->GetType() == b2_dynamicBody && b->IsAwake())
			return false;
	return true;
}

// Box2D's testbed pyramid, 10 rows of 1 m blocks 1.125 m apart, each row offset by half that,
// stacked on the one below with Box2D's slop of overlap, on a ground edge (density 5, friction
// 0.2): superellipses |2x|^8 + |2y|^8 ≤ 1, whose shoulders meet at 2 y(0.5625/2) with
// y(x) = 0.5 (1 − |2x|^8)^(1/8), or boxes of half-width `box`. The top block's height at every
// step for 5 s, and when everything slept.
struct Pyramid
{
	std::vector<float> top;
	float asleepAt = -1.0f;
	int onePoint = 0, twoPoints = 0;
};

Pyramid RunPyramid(bool analytic, float box = 0.5f - b2_polygonRadius)
{
	b2World world(b2Vec2(0.0f, -10.0f));
	MakeFloor(world, 20.0f);
	const ShapePtr block = MakeSuperellipse(0.5, 0.5, 8.0, 8.0);
	const double offset = 0.5625, shoulder = 0.5 * std::pow(1.0 - std::pow(offset, 8.0), 1.0 / 8.0);
	const double spacing = (analytic ? 2.0 * shoulder : 1.0) - b2_linearSlop;
	b2Body* top = nullptr;
	for (int row = 0; row < 10; ++row)
		for (int k = row; k < 10; ++k)
		{
			b2BodyDef def;
			def.type = b2_dynamicBody;
			def.position.Set(float(-7.0 + offset * row + 1.125 * (k - row)), float(0.75 + spacing * row));
			top = world.CreateBody(&def);
			if (analytic)
				CreateAnalyticFixture(top, block, 5.0f, 0.2f);
			else
			{
				b2PolygonShape shape;
				shape.SetAsBox(box, box);
				top->CreateFixture(&shape, 5.0f)->SetFriction(0.2f);
			}
		}
	Pyramid p;
	for (int step = 1; step <= 300; ++step)
	{
		world.Step(kStep, 8, 3);
		p.top.push_back(top->GetPosition().y);
		if (p.asleepAt < 0.0f && AllAsleep(world))
			p.asleepAt = step * kStep;
	}
	for (b2Contact* c = world.GetContactList(); c; c = c->GetNext())
		if (c->IsTouching())
			(c->GetManifold()->pointCount == 2 ? p.twoPoints : p.onePoint) += 1;
	return p;
}
} // namespace

TEST_CASE("a pyramid of blocky superellipses stands as stiff as one of boxes and falls asleep as soon")
{
	// Boxes of 1 x 1 m outline (Box2D adds its 1 cm skin to SetAsBox(0.49, 0.49)), the same
	// pyramid: the top blocks' heights within 5 cm at every step after 1 s (the superellipses'
	// shoulders drop 0.6 mm each: 1.2 cm over ten rows), asleep within 1.5 times the boxes' time,
	// and the contacts two-point (the half-offset ones where the shoulders meet included).
	const Pyramid a = RunPyramid(true), b = RunPyramid(false);
	float worst = 0.0f;
	for (size_t k = 60; k < a.top.size(); ++k)
		worst = std::max(worst, std::fabs(a.top[k] - b.top[k]));
	CHECK(worst < 0.05f);
	REQUIRE(a.asleepAt > 0.0f);
	REQUIRE(b.asleepAt > 0.0f);
	CHECK(a.asleepAt <= 1.5f * b.asleepAt);
	CHECK(a.twoPoints >= 90);
	CHECK(a.onePoint + a.twoPoints == 100);
	// Against boxes of SetAsBox(0.5, 0.5), 1.02 m with their skin (the testbed's): asleep within
	// 1.5 times their time too.
	const Pyramid c = RunPyramid(false, 0.5f);
	REQUIRE(c.asleepAt > 0.0f);
	CHECK(a.asleepAt <= 1.5f * c.asleepAt);
}

TEST_CASE("a blocky superellipse landing tilted turns flat and sleeps, as a box does")
{
	// The face belongs to the body: landing tilted, the block stands on the lower end of its face
	// and gravity turns it flat, until both ends touch within Box2D's slop: a tilt below the slop
	// over the face's width (0.67 m: 0.0075 rad), as a box of the same outline ends with, and
	// asleep within 1.5 times the box's time.
	auto drop = [](bool analytic, float tilt, float& angle, float& height) {
		b2World world(b2Vec2(0.0f, -10.0f));
		MakeFloor(world);
		b2Body* block = nullptr;
		if (analytic)
			block = MakeParticle(world, MakeSuperellipse(0.5, 0.5, 8.0, 8.0), 0.0f, 0.8f, tilt, 1.0f, 0.6f);
		else
		{
			b2BodyDef def;
			def.type = b2_dynamicBody;
			def.position.Set(0.0f, 0.8f);
			def.angle = tilt;
			block = world.CreateBody(&def);
			b2PolygonShape box;
			box.SetAsBox(0.5f - b2_polygonRadius, 0.5f - b2_polygonRadius);
			block->CreateFixture(&box, 1.0f)->SetFriction(0.6f);
		}
		int step = 0;
		for (; step < 300 && !AllAsleep(world); ++step)
			world.Step(kStep, 8, 3);
		angle = block->GetAngle();
		height = block->GetPosition().y;
		return step;
	};
	for (float tilt : {0.02f, 0.08f, -0.15f, 0.3f})
	{
		CAPTURE(tilt);
		float angle = 0.0f, height = 0.0f, boxAngle = 0.0f, boxHeight = 0.0f;
		const int steps = drop(true, tilt, angle, height), boxSteps = drop(false, tilt, boxAngle, boxHeight);
		CHECK(steps <= 1.5 * boxSteps);
		CHECK(std::fabs(angle) < b2_linearSlop / 0.667f);
		CHECK(std::fabs(boxAngle) < b2_linearSlop / 0.98f);
		CHECK(std::fabs(height - (0.5f + b2_polygonRadius - b2_linearSlop)) < 0.003f);
	}
}

TEST_CASE("a heart upside down on a block's face rests on both lobes, whichever fixture Box2D takes first")
{
	for (bool blockFirst : {true, false})
	{
		CAPTURE(blockFirst);
		b2World world(b2Vec2(0.0f, -10.0f));
		world.SetAllowSleeping(false);
		auto makeBlock = [&] {
			b2BodyDef def;
			def.position.Set(0.0f, -0.5f);
			CreateAnalyticFixture(world.CreateBody(&def), MakeSuperellipse(3.0, 0.5, 8.0, 8.0), 0.0f, 0.6f);
		};
		if (blockFirst)
			makeBlock();
		b2Body* heart = MakeParticle(world, MakeHeart(0.2), 0.05f, 0.7f, 3.14159f + 0.05f, 1.0f, 0.6f);
		if (!blockFirst)
			makeBlock();
		double motion = 0.0;
		for (int step = 1; step <= 300; ++step)
		{
			world.Step(kStep, 8, 3);
			if (step > 120)
				motion = std::max(motion, double(heart->GetLinearVelocity().Length()) + 0.5 * std::fabs(heart->GetAngularVelocity()));
		}
		CHECK(motion < 1e-5); // still from 2 s on (one point hopping between the lobes: 0.13 m/s)
		REQUIRE(heart->GetContactList() != nullptr);
		const b2Contact* contact = heart->GetContactList()->contact;
		CHECK(contact->GetManifold()->pointCount == 2);
		b2WorldManifold wm;
		contact->GetWorldManifold(&wm);
		CHECK(std::fabs(wm.points[0].x - wm.points[1].x) > 0.5f); // one point a lobe
	}
}

TEST_CASE("on a 30-degree ramp a block sticks or slides and a disc rolls at the textbook rates")
{
	// Friction 0.6 > tan 30° holds the block; at 0.4 it slides at g (sin θ − μ cos θ); a disc
	// rolls without slipping at (2/3) g sin θ. The ramp has the body's friction (Box2D mixes
	// them as the root of the product). Accelerations from the positions at 0.1 and 1.1 s and the
	// velocity at 0.1 s.
	const double theta = kPi / 6.0, g = 10.0;
	const Vec2 down(std::cos(theta), -std::sin(theta)), normal(std::sin(theta), std::cos(theta));
	struct Case
	{
		ShapePtr shape;
		float friction;
		double expected;
	};
	const Case cases[] = {{MakeSuperellipse(0.5, 0.5, 8.0, 8.0), 0.6f, 0.0},
	                      {MakeSuperellipse(0.5, 0.5, 8.0, 8.0), 0.4f, g * (std::sin(theta) - 0.4 * std::cos(theta))},
	                      {MakeCircle(0.4), 0.6f, 2.0 / 3.0 * g * std::sin(theta)}};
	for (const Case& c : cases)
	{
		CAPTURE(c.shape->Describe());
		CAPTURE(c.friction);
		b2World world(b2Vec2(0.0f, -10.0f));
		b2BodyDef gd;
		b2EdgeShape ramp;
		ramp.SetTwoSided(b2Vec2(float(-6.0 * down.x), float(-6.0 * down.y)), b2Vec2(float(6.0 * down.x), float(6.0 * down.y)));
		world.CreateBody(&gd)->CreateFixture(&ramp, 0.0f)->SetFriction(c.friction);
		const double half = -c.shape->Support(Vec2(0.0, -1.0)).y;
		const Vec2 start = -4.0 * down + (half + b2_polygonRadius - b2_linearSlop) * normal;
		b2Body* body = MakeParticle(world, c.shape, float(start.x), float(start.y), float(-theta), 1.0f, c.friction);
		double s0 = 0.0, v0 = 0.0;
		for (int step = 1; step <= 66; ++step)
		{
			world.Step(kStep, 8, 3);
			if (step == 6)
			{
				s0 = Dot(Vec2(body->GetPosition().x, body->GetPosition().y), down);
				v0 = Dot(Vec2(body->GetLinearVelocity().x, body->GetLinearVelocity().y), down);
			}
		}
		const double s1 = Dot(Vec2(body->GetPosition().x, body->GetPosition().y), down);
		const double a = 2.0 * (s1 - s0 - v0 * 1.0);
		if (c.expected == 0.0)
			CHECK(std::fabs(s1 - s0) < 1e-3);
		else
			CHECK(a == doctest::Approx(c.expected).epsilon(0.01));
	}
}

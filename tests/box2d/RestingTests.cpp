// b2analytic tests: particles at rest stay at rest; stacks stand or topple as physics says.
#include "SceneSupport.h"

#include <doctest/doctest.h>

using namespace b2a;
using namespace b2a::test;

namespace
{
// Separations Box2D sees for every touching contact of a body (its world manifold).
std::vector<float> Separations(b2Body* body)
{
	std::vector<float> out;
	for (b2ContactEdge* e = body->GetContactList(); e; e = e->next)
	{
		if (!e->contact->IsTouching())
			continue;
		b2WorldManifold wm;
		e->contact->GetWorldManifold(&wm);
		for (int32 i = 0; i < e->contact->GetManifold()->pointCount; ++i)
			out.push_back(wm.separations[i]);
	}
	return out;
}
} // namespace

TEST_CASE("an ellipse and a blocky superellipse resting on the ground settle at the slop without drift or creep")
{
	b2World world(b2Vec2(0.0f, -10.0f));
	world.SetAllowSleeping(false); // sleeping would freeze them: we want to see any creep
	MakeFloor(world);
	b2Body* ellipse = MakeParticle(world, MakeEllipse(1.0, 0.5), -3.0f, 0.52f);
	b2Body* block = MakeParticle(world, MakeSuperellipse(0.5, 0.5, 8.0, 8.0), 3.0f, 0.52f);
	for (int i = 0; i < 60; ++i) // 1 s to land and settle
		world.Step(1.0f / 60.0f, 8, 3);
	const b2Vec2 e0 = ellipse->GetPosition(), s0 = block->GetPosition();
	const float ae0 = ellipse->GetAngle(), as0 = block->GetAngle();
	for (int i = 0; i < 600; ++i) // then 10 s
	{
		world.Step(1.0f / 60.0f, 8, 3);
		for (b2Body* b : {ellipse, block})
			for (float s : Separations(b))
			{
				// Box2D's position solver stops correcting at −slop; contacts rest there.
				CHECK(s < 0.0f);
				CHECK(s > -2.0f * b2_linearSlop);
			}
	}
	CHECK(Separations(ellipse).size() == 1); // curved: one point
	CHECK(Separations(block).size() == 2);   // flat: two points with one normal
	for (float s : Separations(ellipse))
		CHECK(s == doctest::Approx(-b2_linearSlop).epsilon(0.02));
	for (float s : Separations(block))
		CHECK(s == doctest::Approx(-b2_linearSlop).epsilon(0.02));
	// No drift or creep over 10 s: positions and angles hold to a millionth of the size.
	CHECK(std::fabs(ellipse->GetPosition().x - e0.x) < 1e-6f);
	CHECK(std::fabs(ellipse->GetPosition().y - e0.y) < 1e-6f);
	CHECK(std::fabs(ellipse->GetAngle() - ae0) < 1e-6f);
	CHECK(std::fabs(block->GetPosition().x - s0.x) < 1e-6f);
	CHECK(std::fabs(block->GetPosition().y - s0.y) < 1e-6f);
	CHECK(std::fabs(block->GetAngle() - as0) < 1e-6f);
	// Resting heights: semi-axis (0.5) plus the floor edge's skin radius, less the slop.
	CHECK(ellipse->GetPosition().y == doctest::Approx(0.5 + b2_polygonRadius - b2_linearSlop).epsilon(1e-4));
	CHECK(std::fabs(ellipse->GetAngle()) < 1e-4f);
}

TEST_CASE("a stack of ten blocky superellipses stands for 10 s")
{
	b2World world(b2Vec2(0.0f, -10.0f));
	world.SetAllowSleeping(false);
	MakeFloor(world);
	const auto block = MakeSuperellipse(0.5, 0.5, 8.0, 8.0);
	std::vector<b2Body*> stack;
	for (int i = 0; i < 10; ++i) // placed touching (1 − slop apart)
		stack.push_back(MakeParticle(world, block, 0.0f, 0.5f + (1.0f - b2_linearSlop) * float(i)));
	const float placed = stack.back()->GetPosition().y;
	for (int i = 0; i < 60; ++i) // 1 s for the ten contacts to take up the load
		world.Step(1.0f / 60.0f, 8, 3);
	// Taking up the load sinks each contact by about the slop (plus a little under the weight).
	CHECK(placed - stack.back()->GetPosition().y < 10.0f * 4.0f * b2_linearSlop);
	const b2Vec2 top0 = stack.back()->GetPosition();
	float maxShift = 0.0f;
	for (int i = 0; i < 600; ++i)
	{
		world.Step(1.0f / 60.0f, 8, 3);
		maxShift = std::max(maxShift, b2Distance(stack.back()->GetPosition(), top0));
	}
	// Then, over 10 s, the top particle moves less than 1 % of its size (1).
	CHECK(maxShift < 0.01f * 1.0f);
	CHECK(std::fabs(stack.back()->GetAngle()) < 1e-3f);
	for (size_t i = 1; i < stack.size(); ++i)
		CHECK(Separations(stack[i]).size() >= 2);
}

TEST_CASE("an ellipse balanced on an ellipse stays or rolls off as the rocking criterion says")
{
	// A convex body resting on a convex surface is stable for rolling without slipping when its
	// centre of mass lies below h* = ρ₁ρ₂/(ρ₁ + ρ₂) above the contact (ρ the radii of curvature).
	// Two equal ellipses x²/a² + y²/b² ≤ 1 lying flat, one on the other: ρ = a²/b at the contact
	// and h = b, so they are stable when b < a²/(2b), i.e. a/b > √2, and unstable below.
	auto run = [](double aspect) {
		b2World world(b2Vec2(0.0f, -10.0f));
		world.SetAllowSleeping(false);
		b2BodyDef bd; // the lower ellipse is fixed in place
		b2Body* base = world.CreateBody(&bd);
		b2FixtureDef fd;
		fd.friction = 1.0f; // rolling, not slipping
		AnalyticFixtureDef ad;
		ad.shape = MakeEllipse(aspect, 1.0);
		CreateAnalyticFixture(base, fd, ad);
		b2Body* top = MakeParticle(world, ad.shape, 0.0f, 2.0f - b2_linearSlop, 0.02f, 1.0f, 1.0f);
		float maxAngle = 0.0f;
		for (int i = 0; i < 600; ++i)
		{
			world.Step(1.0f / 60.0f, 8, 3);
			maxAngle = std::max(maxAngle, std::fabs(top->GetAngle()));
		}
		return maxAngle;
	};
	CHECK(run(2.0) < 0.1f);  // stable: it rocks about the balance, tilted a little
	CHECK(run(1.7) < 0.1f);
	CHECK(run(1.25) > 0.5f); // unstable: the small tilt grows and it rolls off
	CHECK(run(1.1) > 0.5f);
}

TEST_CASE("a stack of ellipses standing on their tips topples")
{
	b2World world(b2Vec2(0.0f, -10.0f));
	MakeFloor(world);
	const auto needle = MakeEllipse(0.3, 1.0); // long axis vertical
	std::vector<b2Body*> stack;
	for (int i = 0; i < 4; ++i)
		stack.push_back(MakeParticle(world, needle, 0.001f * float(i), 1.0f + 2.0f * float(i), 0.0f));
	for (int i = 0; i < 600; ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	// Standing on a tip is unstable (the tip's radius of curvature 0.09 is below the height 1 of
	// the centre): the stack falls over, and the top ellipse ends low and tilted.
	CHECK(stack.back()->GetPosition().y < 2.0f);
	CHECK(std::fabs(std::sin(stack.back()->GetAngle())) > 0.5f);
}

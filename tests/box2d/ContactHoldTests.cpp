// b2analytic tests: a touching contact keeps touching across a gap of up to kContactHoldGap
// (AnalyticFixture.h), so that a grazing contact jittering about zero separation does not wake
// its bodies at every step, and one between two hearts across kNonConvexHoldGap; a contact that
// did not touch starts at separation zero.
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace b2a;
using namespace b2a::test;

namespace
{
// The contact between the two bodies of the world (null where Box2D has none).
b2Contact* OnlyContact(b2World& world)
{
	return world.GetContactList();
}

// Two particles on the x axis, B at x = `touch` + gap (its surface `gap` from A's: for two circles
// of radius 0.4, touch = 0.8), at rest, no gravity; one step, then B's manifold: touching,
// points, the separation.
struct Probe
{
	bool touching = false;
	int points = 0;
	float separation = 0.0f;
};

Probe StepAt(b2World& world, b2Body* b, double gap, double touch = 0.8)
{
	b->SetTransform(b2Vec2(float(touch + gap), 0.0f), 0.0f);
	b->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
	b->SetAngularVelocity(0.0f);
	world.Step(1.0f / 60.0f, 8, 3);
	Probe p;
	b2Contact* c = OnlyContact(world);
	if (!c)
		return p;
	p.touching = c->IsTouching();
	p.points = c->GetManifold()->pointCount;
	if (p.points > 0)
	{
		b2WorldManifold wm;
		c->GetWorldManifold(&wm);
		p.separation = wm.separations[0];
	}
	return p;
}
} // namespace

TEST_CASE("a touching contact keeps one point across a gap up to kContactHoldGap, and a new one starts at zero")
{
	b2World world(b2Vec2(0.0f, 0.0f));
	const ShapePtr circle = MakeCircle(0.4);
	b2Body* a = MakeParticle(world, circle, 0.0f, 0.0f);
	b2Body* b = MakeParticle(world, circle, 0.8f, 0.0f);
	a->SetType(b2_staticBody);
	const double hold = kContactHoldGap;
	// Above the 1e-5 m jitter of a creeping pile, below the slop that resting contacts overlap by.
	REQUIRE(hold > 1e-5);
	REQUIRE(hold < b2_linearSlop);

	// Not touching before: a gap of half the hold gap is no contact.
	Probe p = StepAt(world, b, 0.5 * hold);
	CHECK_FALSE(p.touching);
	CHECK(p.points == 0);
	// Overlapping by 1 mm: touching, separation the overlap (the circles' exact distance).
	p = StepAt(world, b, -1e-3);
	CHECK(p.touching);
	REQUIRE(p.points == 1);
	CHECK(std::fabs(p.separation - -1e-3) < 2e-6);
	// Apart by half the hold gap: still touching, its one point at that positive separation.
	p = StepAt(world, b, 0.5 * hold);
	CHECK(p.touching);
	REQUIRE(p.points == 1);
	CHECK(std::fabs(p.separation - 0.5 * hold) < 2e-6);
	// Beyond the hold gap: no longer touching, and back within it: still not (it starts at zero).
	p = StepAt(world, b, 2.0 * hold);
	CHECK_FALSE(p.touching);
	p = StepAt(world, b, 0.5 * hold);
	CHECK_FALSE(p.touching);
	CHECK(p.points == 0);
}

TEST_CASE("a grazing contact jittering about zero separation does not wake its bodies")
{
	// A circle resting on a floor edge (touching: the edge's skin b2_polygonRadius is its
	// surface), then moved up and down by 1e-5 m about a gap of zero every step, as a creeping pile's grazing contacts did: its sleep timer (which
	// Box2D zeroes when a contact starts or stops touching) runs on, and the body sleeps after
	// b2_timeToSleep, as it does when left still.
	b2World world(b2Vec2(0.0f, 0.0f));
	MakeFloor(world);
	const ShapePtr circle = MakeCircle(0.4);
	const double rest = 0.4 + b2_polygonRadius; // the circle's centre at zero gap
	b2Body* b = MakeParticle(world, circle, 0.0f, float(rest));
	int steps = 0;
	for (; steps < 120 && b->IsAwake(); ++steps)
	{
		b->SetTransform(b2Vec2(0.0f, float(rest + (steps % 2 == 0 ? -1e-5 : 1e-5))), 0.0f);
		world.Step(1.0f / 60.0f, 8, 3);
	}
	CHECK_FALSE(b->IsAwake());
	// Box2D's own test: asleep once the timer reaches b2_timeToSleep (0.5 s: 30 steps of 1/60 s).
	CHECK(steps <= 32);
}

TEST_CASE("a contact between hearts keeps touching across a gap up to kNonConvexHoldGap, not beyond")
{
	// Two hearts (alpha 0.2) side by side, upright: A's widest point and B's lie at the same
	// height with vertical tangents, so the surfaces' gap is B's offset past the widths. A
	// heart leaning on another in a settled pile drifts apart by a few tenths of a millimetre a
	// second while it carries load; across the convex pairs' gap of 0.25 mm the contact ended,
	// woke the pile and dropped the load for a step.
	b2World world(b2Vec2(0.0f, 0.0f));
	const ShapePtr heart = MakeHeart(0.2);
	const double width = heart->SupportValue(Vec2(1.0, 0.0)); // half the width, by symmetry
	b2Body* a = MakeParticle(world, heart, 0.0f, 0.0f);
	b2Body* b = MakeParticle(world, heart, float(2.0 * width + 0.1), 0.0f);
	a->SetType(b2_staticBody);
	const double hold = kNonConvexHoldGap;
	REQUIRE(hold >= 4.0 * kContactHoldGap);
	REQUIRE(hold <= b2_linearSlop);

	Probe p = StepAt(world, b, 0.5 * hold, 2.0 * width);
	CHECK_FALSE(p.touching);
	// Overlapping by 1 mm: touching, its separation the overlap.
	p = StepAt(world, b, -1e-3, 2.0 * width);
	CHECK(p.touching);
	REQUIRE(p.points >= 1);
	CHECK(std::fabs(p.separation - -1e-3) < 2e-5);
	// Apart by four convex hold gaps (1 mm, half the non-convex one): still touching, one point
	// at that positive separation (the convex pairs' hold ends it).
	p = StepAt(world, b, 4.0 * kContactHoldGap, 2.0 * width);
	CHECK(p.touching);
	REQUIRE(p.points == 1);
	CHECK(std::fabs(p.separation - 4.0 * kContactHoldGap) < 2e-5);
	// Apart by 0.9 of the hold gap: still touching.
	p = StepAt(world, b, 0.9 * hold, 2.0 * width);
	CHECK(p.touching);
	// Beyond it: no longer, and back within it: still not (a new contact starts at zero).
	p = StepAt(world, b, 1.5 * hold, 2.0 * width);
	CHECK_FALSE(p.touching);
	p = StepAt(world, b, 0.5 * hold, 2.0 * width);
	CHECK_FALSE(p.touching);
	CHECK(p.points == 0);
}

TEST_CASE("a contact between a heart and a convex particle keeps the convex pairs' hold gap")
{
	// A circle of radius 0.4 beside an upright heart's widest point: held across kContactHoldGap
	// alone, as between two convex particles.
	b2World world(b2Vec2(0.0f, 0.0f));
	const ShapePtr heart = MakeHeart(0.2);
	const double touch = heart->SupportValue(Vec2(1.0, 0.0)) + 0.4;
	b2Body* a = MakeParticle(world, heart, 0.0f, 0.0f);
	b2Body* b = MakeParticle(world, MakeCircle(0.4), float(touch + 0.1), 0.0f);
	a->SetType(b2_staticBody);
	// The circle's centre level with the heart's widest point: the gap is the offset past it.
	const double y = heart->Support(Vec2(1.0, 0.0)).y;
	a->SetTransform(b2Vec2(0.0f, float(-y)), 0.0f);
	Probe p = StepAt(world, b, -1e-3, touch);
	CHECK(p.touching);
	REQUIRE(p.points == 1);
	CHECK(std::fabs(p.separation - -1e-3) < 2e-5);
	p = StepAt(world, b, 0.5 * kContactHoldGap, touch);
	CHECK(p.touching);
	p = StepAt(world, b, 4.0 * kContactHoldGap, touch);
	CHECK_FALSE(p.touching);
}

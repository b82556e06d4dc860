// b2analytic tests: the user's contact listener sees events that follow the true shapes.
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <regex>
#include <string>

using namespace b2a;
using namespace b2a::test;

namespace
{
// Logs every event with the step it happened in and the analytic separation at that moment.
struct LoggingListener : b2ContactListener
{
	struct Event
	{
		char kind; // B, E, P (PreSolve), S (PostSolve)
		int step;
		double separation;
		int points;
	};
	std::vector<Event> events;
	int step = 0;
	void Log(char kind, b2Contact* c)
	{
		const ContactResult r = ComputeFixtureContact(c->GetFixtureA(), c->GetFixtureB());
		events.push_back({kind, step, r.separation, c->GetManifold()->pointCount});
	}
	void BeginContact(b2Contact* c) override { Log('B', c); }
	void EndContact(b2Contact* c) override { Log('E', c); }
	void PreSolve(b2Contact* c, const b2Manifold*) override { Log('P', c); }
	void PostSolve(b2Contact* c, const b2ContactImpulse*) override { Log('S', c); }
};
} // namespace

TEST_CASE("contact events come in Box2D's order and mean that the true shapes touch")
{
	// No gravity: B glides past A, grazing it, so the pair touches for a while and separates.
	b2World world(b2Vec2(0.0f, 0.0f));
	LoggingListener log;
	world.SetContactListener(&log);
	const auto shape = MakeSuperellipse(1.0, 0.5, 4.0, 4.0);
	b2Body* a = MakeParticle(world, shape, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f);
	b2Body* b = MakeParticle(world, shape, -4.0f, 0.9f, 0.0f, 1.0f, 0.0f);
	a->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
	b->SetLinearVelocity(b2Vec2(3.0f, 0.0f));
	for (log.step = 0; log.step < 180; ++log.step)
		world.Step(1.0f / 60.0f, 8, 3);

	std::string order;
	for (const auto& e : log.events)
		order += e.kind;
	INFO("events: " << order);
	REQUIRE(order.find('B') != std::string::npos);
	REQUIRE(order.find('E') != std::string::npos);
	// Each touching episode is one Begin, PreSolve/PostSolve pairs (one per step while touching),
	// one End: the log is (B (PS)+ E)+. A graze may give more than one episode.
	CHECK(std::regex_match(order, std::regex("(B(PS)+E)+")));
	// Analytic meaning: Begin happens with the true shapes overlapping (Box2D reports a point only
	// at separation ≤ 0), every PreSolve with them overlapping or apart by at most
	// kContactHoldGap (a touching contact keeps touching across that gap), with 1 or 2 manifold
	// points; at End they are apart by more than the hold gap.
	for (const auto& e : log.events)
	{
		if (e.kind == 'B' || e.kind == 'P')
		{
			CHECK(e.separation <= (e.kind == 'B' ? 0.0 : kContactHoldGap));
			CHECK((e.points == 1 || e.points == 2));
		}
		if (e.kind == 'E')
		{
			CHECK(e.separation > kContactHoldGap);
			CHECK(e.points == 0);
		}
	}
	// The grazing pushed A down and B up (normal impulses only: no friction).
	CHECK(a->GetLinearVelocity().y < 0.0f);
	CHECK(b->GetLinearVelocity().y > 0.0f);
}

TEST_CASE("overlapping proxies without touching shapes give no event and no impulse")
{
	// Two thin ellipses turned by ±45°, side by side: their bounding boxes overlap (so Box2D's
	// broad phase makes a contact) but the true shapes are far apart.
	b2World world(b2Vec2(0.0f, 0.0f));
	LoggingListener log;
	world.SetContactListener(&log);
	const auto needle = MakeEllipse(2.0, 0.1);
	b2Body* a = MakeParticle(world, needle, 0.0f, 0.0f, float(kPi / 4));
	b2Body* b = MakeParticle(world, needle, 1.8f, -1.8f, float(kPi / 4));
	b->SetLinearVelocity(b2Vec2(0.1f, 0.1f)); // drifting along the line that keeps them apart
	const ContactResult truth = ComputeFixtureContact(a->GetFixtureList(), b->GetFixtureList());
	REQUIRE(truth.separation > 1.0);
	for (int i = 0; i < 60; ++i)
		world.Step(1.0f / 60.0f, 8, 3);
	CHECK(world.GetContactCount() == 1); // the broad phase paired them
	CHECK_FALSE(world.GetContactList()->IsTouching());
	CHECK(log.events.empty());
	CHECK(a->GetLinearVelocity().x == 0.0f);
	CHECK(a->GetLinearVelocity().y == 0.0f);
	CHECK(a->GetAngularVelocity() == 0.0f);
	CHECK(b->GetLinearVelocity().x == 0.1f);
}

TEST_CASE("warm starting carries impulses across steps and lowers the solver's residual on a resting pile")
{
	// A pile of 30 superellipses on the floor, run with and without Box2D's warm starting. With
	// impulses carried between steps (stable point ids), the few velocity iterations converge
	// further, so the pile's residual motion after settling is smaller.
	auto run = [](bool warm, double& carried) {
		b2World world(b2Vec2(0.0f, -10.0f));
		world.SetAllowSleeping(false);
		world.SetWarmStarting(warm);
		MakeFloor(world);
		const auto block = MakeSuperellipse(0.5, 0.35, 4.0, 4.0);
		for (int i = 0; i < 30; ++i)
			MakeParticle(world, block, -2.5f + float(i % 6), 0.4f + 0.75f * float(i / 6), 0.0f);
		struct Carried : b2ContactListener
		{
			double sum = 0.0;
			void PreSolve(b2Contact* c, const b2Manifold*) override
			{
				// After id matching and before solving: the impulses Box2D starts from.
				for (int32 i = 0; i < c->GetManifold()->pointCount; ++i)
					sum += c->GetManifold()->points[i].normalImpulse;
			}
		} listener;
		world.SetContactListener(&listener);
		for (int i = 0; i < 180; ++i)
			world.Step(1.0f / 60.0f, 4, 3);
		double residual = 0.0;
		listener.sum = 0.0;
		for (int i = 0; i < 60; ++i)
		{
			world.Step(1.0f / 60.0f, 4, 3);
			for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
				residual += b2Dot(b->GetLinearVelocity(), b->GetLinearVelocity());
		}
		carried = listener.sum;
		return std::sqrt(residual / (60.0 * 30.0));
	};
	double carriedWarm = 0.0, carriedCold = 0.0;
	const double warm = run(true, carriedWarm), cold = run(false, carriedCold);
	INFO("rms velocity with warm starting " << warm << ", without " << cold);
	CHECK(carriedWarm > 0.0); // the matched ids brought last step's impulses along
	CHECK(warm < 0.1 * cold);
}

TEST_CASE("Box2D's contact touches exactly when the true shapes overlap or a touching pair stays within the hold gap, while pairs pass, graze and drift apart")
{
	// The adapter skips the solve when the last normal or the line between the centres separates
	// the particles, and skips those tests for a pair its last solve found touching. Here pairs inside each other's bounding circles pass at various offsets and
	// spins; before every step the true contact is computed directly, and after the step (whose
	// collide phase saw the same transforms) Box2D's contact must agree with it.
	struct Pair
	{
		ShapePtr a, b;
	};
	const Pair pairs[] = {{MakeEllipse(1.0, 0.33), MakeEllipse(1.0, 0.33)},
	                      {MakeSuperellipse(1.0, 0.6, 4.0, 4.0), MakeSuperellipse(0.8, 0.5, 4.0, 4.0)},
	                      {MakeEllipse(1.5, 0.2), MakeSuperellipse(0.7, 0.7, 8.0, 8.0)}};
	int touchingSteps = 0, apartSteps = 0, checked = 0, heldSteps = 0;
	for (const Pair& p : pairs)
	{
		for (int run = 0; run < 6; ++run)
		{
			CAPTURE(run);
			b2World world(b2Vec2(0.0f, 0.0f));
			b2Body* a = MakeParticle(world, p.a, 0.0f, 0.0f, 0.3f * run, 1.0f, 0.0f);
			b2Body* b = MakeParticle(world, p.b, -3.0f, 0.25f * run - 0.4f, -0.5f * run, 1.0f, 0.0f);
			b->SetLinearVelocity(b2Vec2(2.0f, 0.0f));
			b->SetAngularVelocity(0.7f * (run % 3 - 1));
			for (int step = 0; step < 200; ++step)
			{
				const ContactResult truth = ComputeFixtureContact(a->GetFixtureList(), b->GetFixtureList());
				REQUIRE(truth.Ok());
				const bool wasTouching = world.GetContactList() != nullptr && world.GetContactList()->IsTouching();
				world.Step(1.0f / 60.0f, 8, 3);
				const b2Contact* contact = world.GetContactList();
				const bool boxTouching = contact != nullptr && contact->IsTouching();
				if (contact == nullptr)
					continue; // the broad phase has not paired them: far apart
				++checked;
				CAPTURE(step);
				CAPTURE(truth.separation);
				// Touching where the shapes overlap, and where a contact that touched stays within
				// the hold gap (AnalyticFixture.h, kContactHoldGap).
				const bool held = wasTouching && truth.separation <= kContactHoldGap;
				CHECK(boxTouching == (truth.touching || held));
				(truth.touching ? touchingSteps : apartSteps)++;
				heldSteps += held && !truth.touching;
			}
		}
	}
	// The runs must exercise both sides: contacts apart inside the broad phase, and touching.
	CHECK(touchingSteps > 50);
	CHECK(apartSteps > 200);
	CHECK(checked == touchingSteps + apartSteps);
	// and pairs drifting apart through the hold gap.
	CHECK(heldSteps > 0);
}

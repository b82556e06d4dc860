// PrepareContacts: the analytic contacts of a step computed on several threads before Step.
// Reference: the same world stepped by b2World::Step alone. Every contact is computed from its
// own state exactly as the step would, so the worlds must stay bit-identical, on any number of
// threads; and the prepared manifolds must actually be used (the step's own shape evaluations
// drop by what the preparation did).
#include <doctest/doctest.h>

#include "b2analytic/ParallelContacts.h"
#include "SceneSupport.h"

#include <atomic>
#include <cstring>
#include <random>
#include <string>
#include <thread>

using namespace b2a;
using namespace b2a::test;

namespace
{
std::atomic<long> g_calls{0}; // level evaluations of the counting user shape, on every thread

// A unit-ish superellipse (n = 4) given as a user shape whose level function counts its calls.
ShapePtr CountingBlock()
{
	UserShapeDef def;
	def.name = "counting block";
	auto level = [](Vec2 x) {
		++g_calls;
		const double X = x.x / 0.5, Y = x.y / 0.3;
		return X * X * X * X + Y * Y * Y * Y;
	};
	def.levelOf = level;
	def.function = [level](Vec2 x, double L) { return level(x) - L; };
	// Exact derivatives (not counted): the solvers need no difference quotients.
	def.gradient = [](Vec2 x, double) {
		const double X = x.x / 0.5, Y = x.y / 0.3;
		return Vec2(4.0 * X * X * X / 0.5, 4.0 * Y * Y * Y / 0.3);
	};
	def.hessian = [](Vec2 x, double) {
		const double X = x.x / 0.5, Y = x.y / 0.3;
		return Sym22{12.0 * X * X / 0.25, 0.0, 12.0 * Y * Y / 0.09};
	};
	def.convex = def.smooth = true;
	def.levelPower = 2.0;
	def.lengthScale = 0.5;
	return MakeUserShape(def);
}

// A box with a ramp, a Box2D ball and a Box2D box inside, and a lattice of particles of five
// kinds (ellipses, blocky superellipses, counting user blocks, hearts, circles) falling in.
void BuildScene(b2World& world, int count)
{
	b2BodyDef groundDef;
	b2Body* ground = world.CreateBody(&groundDef);
	b2ChainShape box;
	const b2Vec2 corners[4] = {b2Vec2(-6, 12), b2Vec2(-6, 0), b2Vec2(6, 0), b2Vec2(6, 12)};
	box.CreateChain(corners, 4, b2Vec2(-6, 13), b2Vec2(6, 13));
	ground->CreateFixture(&box, 0.0f);
	b2PolygonShape ramp;
	ramp.SetAsBox(2.0f, 0.1f, b2Vec2(2.5f, 3.0f), 0.3f);
	ground->CreateFixture(&ramp, 0.0f);
	b2CircleShape ball;
	ball.m_radius = 0.4f;
	ball.m_p.Set(-3.0f, 2.0f);
	ground->CreateFixture(&ball, 0.0f);

	const ShapePtr kinds[] = {MakeEllipse(0.4, 0.2), MakeSuperellipse(0.35, 0.25, 4.0, 4.0), CountingBlock(), MakeHeart(0.3),
	                          MakeCircle(0.22)};
	std::mt19937 rng(7);
	std::uniform_real_distribution<float> jitter(-0.05f, 0.05f), angle(-3.0f, 3.0f);
	for (int i = 0; i < count; ++i)
	{
		const float x = -5.0f + 1.0f * float(i % 11) + jitter(rng);
		const float y = 4.0f + 0.9f * float(i / 11);
		MakeParticle(world, kinds[i % 5], x, y, angle(rng), 1.0f, 0.5f, 0.1f);
	}
}

bool SameState(b2World& a, b2World& b)
{
	for (b2Body *p = a.GetBodyList(), *q = b.GetBodyList(); p || q; p = p->GetNext(), q = q->GetNext())
	{
		if (!p || !q)
			return false;
		const b2Transform& x = p->GetTransform();
		const b2Transform& y = q->GetTransform();
		const b2Vec2 v = p->GetLinearVelocity(), w = q->GetLinearVelocity();
		const float s = p->GetAngularVelocity(), t = q->GetAngularVelocity();
		if (std::memcmp(&x, &y, sizeof x) != 0 || std::memcmp(&v, &w, sizeof v) != 0 || std::memcmp(&s, &t, sizeof s) != 0)
			return false;
	}
	return true;
}
} // namespace

TEST_CASE("contacts prepared on 1, 2 and 3 threads step bit-identically to b2World::Step alone, and are used")
{
	const int count = 88;
	b2World plain(b2Vec2(0.0f, -10.0f)), one(b2Vec2(0.0f, -10.0f)), two(b2Vec2(0.0f, -10.0f)), three(b2Vec2(0.0f, -10.0f));
	for (b2World* w : {&plain, &one, &two, &three})
		BuildScene(*w, count);
	long prepareCalls = 0, preparedStepCalls = 0, plainStepCalls = 0;
	int prepared = 0, maxThreads = 0, firstDifference = -1;
	for (int step = 0; step < 150; ++step)
	{
		g_calls = 0;
		plain.Step(1.0f / 60.0f, 8, 3);
		plainStepCalls += g_calls;

		g_calls = 0;
		prepared += PrepareContacts(&one, 1).prepared;
		prepareCalls += g_calls;
		g_calls = 0;
		one.Step(1.0f / 60.0f, 8, 3);
		preparedStepCalls += g_calls;

		maxThreads = std::max(maxThreads, StepWithPreparedContacts(&two, 1.0f / 60.0f, 8, 3, 2).threads);
		StepWithPreparedContacts(&three, 1.0f / 60.0f, 8, 3, 3);
		if (firstDifference < 0 && !(SameState(plain, one) && SameState(plain, two) && SameState(plain, three)))
			firstDifference = step;
	}
	CHECK(firstDifference == -1);
	CHECK(maxThreads == 2);
	// The particles piled up: many contacts were prepared (about two per particle at the end).
	CHECK(prepared > 150 * count / 2);
	// The evaluations moved out of the step: what the plain world spent in its steps, the
	// prepared one spent in preparation plus its steps (AABBs, TOI sub-steps), exactly: each
	// prepared contact was evaluated once, by the preparation, and none was prepared in vain.
	// The preparation's share is 48 % (the counted user shape's AABBs, by sampled supports, stay
	// in the step; touching pairs ask for no separating-axis supports).
	CAPTURE(prepareCalls);
	CAPTURE(preparedStepCalls);
	CHECK(prepareCalls > plainStepCalls * 2 / 5);
	CHECK(preparedStepCalls + prepareCalls == plainStepCalls);
	// The scene did something: the lattice (top row at 10.3) fell and piled up in the box.
	double highest = 0.0;
	for (b2Body* b = plain.GetBodyList(); b; b = b->GetNext())
		if (b->GetType() == b2_dynamicBody)
			highest = std::max(highest, double(b->GetPosition().y));
	CHECK(highest < 7.0);
}

TEST_CASE("two threads that prepare two worlds at once, each on 2 threads, step as b2World::Step alone")
{
	// The helper threads serve one call at a time; the call that finds them busy computes its
	// contacts alone. Either way each world must step as the plain one does.
	const int count = 55;
	b2World plain(b2Vec2(0.0f, -10.0f)), a(b2Vec2(0.0f, -10.0f)), b(b2Vec2(0.0f, -10.0f));
	for (b2World* w : {&plain, &a, &b})
		BuildScene(*w, count);
	const int steps = 120;
	int preparedA = 0, preparedB = 0;
	std::thread other([&] {
		for (int step = 0; step < steps; ++step)
			preparedB += StepWithPreparedContacts(&b, 1.0f / 60.0f, 8, 3, 2).prepared;
	});
	for (int step = 0; step < steps; ++step)
		preparedA += StepWithPreparedContacts(&a, 1.0f / 60.0f, 8, 3, 2).prepared;
	other.join();
	for (int step = 0; step < steps; ++step)
		plain.Step(1.0f / 60.0f, 8, 3);
	CHECK(SameState(plain, a));
	CHECK(SameState(plain, b));
	CHECK(preparedA == preparedB);
	CHECK(preparedA > steps * count / 2);
}

TEST_CASE("PrepareContacts refuses a null world, negative threads and a locked world by name")
{
	CHECK_THROWS_WITH_AS(PrepareContacts(nullptr, 2), doctest::Contains("'world'"), InvalidParameter);
	b2World world(b2Vec2(0.0f, -10.0f));
	BuildScene(world, 11);
	CHECK_THROWS_WITH_AS(PrepareContacts(&world, -1), doctest::Contains("'threads'"), InvalidParameter);
	struct Caller : b2ContactListener
	{
		b2World* world = nullptr;
		int calls = 0, refused = 0;
		void PreSolve(b2Contact*, const b2Manifold*) override
		{
			++calls;
			try
			{
				PrepareContacts(world, 2);
			}
			catch (const MisuseError& e)
			{
				refused += std::string(e.what()).find("locked") != std::string::npos;
			}
		}
	} caller;
	caller.world = &world;
	world.SetContactListener(&caller);
	for (int i = 0; i < 200; ++i)
		StepWithPreparedContacts(&world, 1.0f / 60.0f, 8, 3, 0);
	CHECK(caller.calls > 0);
	CHECK(caller.refused == caller.calls);
}

// b2analytic fuzzing: Box2D worlds with analytic fixtures, stepped and torn down.
//
// From the bytes: gravity, up to 8 bodies (static, kinematic or dynamic, some bullets) with one or
// two fixtures each, analytic ones (any shape of FuzzShapes.h, sizes around Box2D's limits so
// that CreateAnalyticFixture sometimes rejects them) mixed with Box2D circles, boxes, edges and
// chains; then up to 40 steps with velocity kicks, fixture and body removals, ray casts, AABB
// queries, fixture contacts and debug drawing between them; then the bodies destroyed in an
// order from the bytes. Every body position and velocity must stay finite, and nothing may crash,
// hang, leak or trip a sanitizer. Box2D is single precision and meant for metre-sized scenes, so
// positions stay within ±20 and sizes within [0.005, 4].
#include "FuzzShapes.h"

#include "b2analytic/AnalyticFixture.h"

#include <box2d/box2d.h>

#include <cstddef>
#include <cstdint>
#include <vector>

using namespace b2a;
using namespace b2a::fuzz;

namespace
{
bool Finite(b2Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// A b2Draw that only checks what it is given.
struct CheckingDraw final : b2Draw
{
	void DrawPolygon(const b2Vec2* v, int32 n, const b2Color&) override { Check(v, n); }
	void DrawSolidPolygon(const b2Vec2* v, int32 n, const b2Color&) override { Check(v, n); }
	void DrawCircle(const b2Vec2& c, float r, const b2Color&) override { B2A_FUZZ_CHECK(Finite(c) && std::isfinite(r)); }
	void DrawSolidCircle(const b2Vec2& c, float r, const b2Vec2& axis, const b2Color&) override
	{
		B2A_FUZZ_CHECK(Finite(c) && std::isfinite(r) && Finite(axis));
	}
	void DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color&) override { B2A_FUZZ_CHECK(Finite(p1) && Finite(p2)); }
	void DrawTransform(const b2Transform& xf) override { B2A_FUZZ_CHECK(Finite(xf.p)); }
	void DrawPoint(const b2Vec2& p, float, const b2Color&) override { B2A_FUZZ_CHECK(Finite(p)); }
	static void Check(const b2Vec2* v, int32 n)
	{
		B2A_FUZZ_CHECK(n >= 2);
		for (int32 i = 0; i < n; ++i)
			B2A_FUZZ_CHECK(Finite(v[i]));
	}
};

// Counts ray hits and checks each.
struct RayCheck final : b2RayCastCallback
{
	float ReportFixture(b2Fixture*, const b2Vec2& point, const b2Vec2& normal, float fraction) override
	{
		B2A_FUZZ_CHECK(Finite(point) && Finite(normal) && fraction >= 0.0f && fraction <= 1.0f);
		return fraction; // the closest hit, as a game would ask
	}
};

// Collects fixtures in an AABB.
struct QueryCollect final : b2QueryCallback
{
	std::vector<b2Fixture*> found;
	bool ReportFixture(b2Fixture* f) override
	{
		found.push_back(f);
		return found.size() < 16;
	}
};

// One fixture: analytic (kinds 0–2) or Box2D's circle, box, edge or chain.
void AddFixture(FuzzInput& in, b2Body* body)
{
	b2FixtureDef def;
	def.density = float(in.Uniform(0.0, 5.0));
	def.friction = float(in.Uniform(0.0, 1.0));
	def.restitution = float(in.Uniform(0.0, 1.0));
	def.isSensor = in.Byte() < 16;
	const int kind = in.Int(0, 6);
	if (kind <= 2)
	{
		AnalyticFixtureDef analytic;
		analytic.shape = DecodeShape(in, 0.005, 4.0); // below 0.01 CreateAnalyticFixture must refuse
		analytic.local = Pose(Vec2(in.Uniform(-1.0, 1.0), in.Uniform(-1.0, 1.0)), in.Uniform(-kPi, kPi));
		if (in.Bool())
			analytic.solver.gridSamples = 8 << in.Int(0, 6);
		CreateAnalyticFixture(body, def, analytic);
		return;
	}
	const b2Vec2 c(float(in.Uniform(-1.0, 1.0)), float(in.Uniform(-1.0, 1.0)));
	if (kind == 3)
	{
		b2CircleShape circle;
		circle.m_radius = float(in.LogUniform(0.02, 4.0));
		circle.m_p = c;
		def.shape = &circle;
		body->CreateFixture(&def);
	}
	else if (kind == 4)
	{
		b2PolygonShape box;
		box.SetAsBox(float(in.LogUniform(0.02, 4.0)), float(in.LogUniform(0.02, 4.0)), c, float(in.Uniform(-kPi, kPi)));
		def.shape = &box;
		body->CreateFixture(&def);
	}
	else if (kind == 5)
	{
		b2EdgeShape edge;
		edge.SetTwoSided(c, c + b2Vec2(float(in.Uniform(0.1, 10.0)), float(in.Uniform(-10.0, 10.0))));
		def.shape = &edge;
		body->CreateFixture(&def);
	}
	else
	{
		// A zigzag floor (a chain needs vertices farther apart than b2_linearSlop).
		b2Vec2 v[6];
		const int n = in.Int(2, 6);
		for (int i = 0; i < n; ++i)
			v[i] = c + b2Vec2(2.0f * float(i), float(in.Uniform(-1.0, 1.0)));
		b2ChainShape chain;
		chain.CreateChain(v, n, v[0] - b2Vec2(1.0f, 0.0f), v[n - 1] + b2Vec2(1.0f, 0.0f));
		def.shape = &chain;
		body->CreateFixture(&def);
	}
}

b2Body* AddBody(FuzzInput& in, b2World& world)
{
	b2BodyDef def;
	def.type = b2BodyType(in.Int(0, 2));
	def.position.Set(float(in.Uniform(-20.0, 20.0)), float(in.Uniform(-20.0, 20.0)));
	def.angle = float(in.Uniform(-kPi, kPi));
	def.linearVelocity.Set(float(in.Uniform(-50.0, 50.0)), float(in.Uniform(-50.0, 50.0)));
	def.angularVelocity = float(in.Uniform(-30.0, 30.0));
	def.bullet = in.Bool();
	b2Body* body = world.CreateBody(&def);
	const int fixtures = in.Int(1, 2);
	for (int i = 0; i < fixtures; ++i)
	{
		try
		{
			AddFixture(in, body);
		}
		catch (const InvalidParameter&)
		{
			// A shape the constructors or CreateAnalyticFixture reject (too small for Box2D's
			// tolerances, bad parameters): the body stays as it was.
		}
	}
	return body;
}

void CheckBodies(b2World& world)
{
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
	{
		B2A_FUZZ_CHECK(Finite(b->GetPosition()) && std::isfinite(b->GetAngle()));
		B2A_FUZZ_CHECK(Finite(b->GetLinearVelocity()) && std::isfinite(b->GetAngularVelocity()));
	}
}

// Something between two steps: a kick, a removal, a query, a drawing.
void BetweenSteps(FuzzInput& in, b2World& world, std::vector<b2Body*>& bodies)
{
	const int op = in.Int(0, 9);
	if (bodies.empty())
		return;
	b2Body* body = bodies[in.Byte() % bodies.size()];
	switch (op)
	{
	case 0:
		body->SetLinearVelocity(b2Vec2(float(in.Uniform(-100.0, 100.0)), float(in.Uniform(-100.0, 100.0))));
		body->SetAngularVelocity(float(in.Uniform(-50.0, 50.0)));
		break;
	case 1:
		body->ApplyLinearImpulseToCenter(b2Vec2(float(in.Uniform(-10.0, 10.0)), float(in.Uniform(-10.0, 10.0))), true);
		break;
	case 2:
		if (b2Fixture* f = body->GetFixtureList())
			body->DestroyFixture(f);
		break;
	case 3:
	{
		const size_t k = in.Byte() % bodies.size();
		world.DestroyBody(bodies[k]);
		bodies.erase(bodies.begin() + long(k));
		break;
	}
	case 4:
	{
		RayCheck ray;
		const b2Vec2 p1(float(in.Uniform(-25.0, 25.0)), float(in.Uniform(-25.0, 25.0)));
		const b2Vec2 p2(float(in.Uniform(-25.0, 25.0)), float(in.Uniform(-25.0, 25.0)));
		if (p1 != p2) // Box2D's precondition (it asserts)
			world.RayCast(&ray, p1, p2);
		break;
	}
	case 5:
	{
		QueryCollect query;
		const b2Vec2 p(float(in.Uniform(-20.0, 20.0)), float(in.Uniform(-20.0, 20.0)));
		b2AABB box;
		box.lowerBound = p - b2Vec2(2.0f, 2.0f);
		box.upperBound = p + b2Vec2(2.0f, 2.0f);
		world.QueryAABB(&query, box);
		for (b2Fixture* f : query.found)
			(void)f->TestPoint(p);
		for (size_t i = 0; i + 1 < query.found.size(); ++i)
		{
			const ContactResult c = ComputeFixtureContact(query.found[i], query.found[i + 1]);
			if (GetAnalyticShape(query.found[i]) && GetAnalyticShape(query.found[i + 1]))
				CheckContact(c, !in.AnyExtreme());
		}
		break;
	}
	case 6:
	{
		CheckingDraw draw;
		draw.SetFlags(b2Draw::e_shapeBit | (in.Bool() ? b2Draw::e_aabbBit | b2Draw::e_centerOfMassBit : 0u));
		DrawWorld(&world, &draw, in.Int(3, 64));
		break;
	}
	case 7:
		body->SetType(b2BodyType(in.Int(0, 2)));
		break;
	case 8:
		body->SetTransform(b2Vec2(float(in.Uniform(-20.0, 20.0)), float(in.Uniform(-20.0, 20.0))), float(in.Uniform(-kPi, kPi)));
		break;
	default:
		break; // just step
	}
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	FuzzInput in(data, size);
	Context().clear();
	b2World world(b2Vec2(float(in.Uniform(-20.0, 20.0)), float(in.Uniform(-20.0, 20.0))));
	std::vector<b2Body*> bodies;
	const int count = in.Int(1, 8);
	for (int i = 0; i < count; ++i)
		bodies.push_back(AddBody(in, world));
	Trace("decoded");

	const int steps = in.Int(1, 40);
	for (int s = 0; s < steps; ++s)
	{
		BetweenSteps(in, world, bodies);
		Trace("between steps");
		const float dt = float(in.Uniform(1.0 / 480.0, 1.0 / 30.0));
		world.Step(dt, in.Int(1, 10), in.Int(1, 5));
		Trace("step");
		CheckBodies(world);
	}

	// Tear down in an order from the bytes; the world's destructor frees the rest.
	while (!bodies.empty() && in.Bool())
	{
		const size_t k = in.Byte() % bodies.size();
		world.DestroyBody(bodies[k]);
		bodies.erase(bodies.begin() + long(k));
	}
	return 0;
}

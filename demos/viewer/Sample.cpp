// b2a_viewer: the sample base (Box2D testbed's Sample, with analytic fixtures).
#include "Sample.h"

#include "common/GranularScene.h"

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/Box2DConversions.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace b2a::viewer
{

// What a polygon fixture replaced, to put it back.
struct Sample::SwitchedFixture
{
	ShapePtr shape;
	Pose local;
	b2FixtureDef def;
};

namespace
{
// The first dynamic body whose fixture contains the point (the testbed's QueryCallback).
class PointQuery : public b2QueryCallback
{
public:
	explicit PointQuery(b2Vec2 p) : m_point(p) {}
	bool ReportFixture(b2Fixture* fixture) override
	{
		if (fixture->GetBody()->GetType() != b2_dynamicBody || !fixture->TestPoint(m_point))
			return true;
		found = fixture;
		return false;
	}
	b2Fixture* found = nullptr;

private:
	b2Vec2 m_point;
};

b2Vec2 ToB2(Vec2 v)
{
	return b2Vec2(float(v.x), float(v.y));
}
} // namespace

SampleDefaults MetreScene(b2Vec2 viewLo, b2Vec2 viewHi, float margin)
{
	SampleDefaults d;
	d.viewLo = viewLo;
	d.viewHi = viewHi;
	const b2Vec2 size = viewHi - viewLo;
	d.boundsLo = viewLo - margin * size;
	d.boundsHi = viewHi + margin * size;
	return d;
}

Sample::Sample() = default;

Sample::~Sample()
{
	if (m_world)
		m_world->SetDestructionListener(nullptr);
}

b2World* Sample::MakeWorld(b2Vec2 gravity)
{
	m_ownedWorld = std::make_unique<b2World>(gravity);
	UseWorld(m_ownedWorld.get());
	return m_world;
}

void Sample::UseWorld(b2World* world)
{
	m_world = world;
	m_world->SetDestructionListener(this);
}

b2Body* Sample::GroundBody()
{
	if (!m_ground)
	{
		b2BodyDef bd;
		m_ground = m_world->CreateBody(&bd);
	}
	return m_ground;
}

b2Fixture* Sample::AddGroundEdge(b2Vec2 a, b2Vec2 b, float friction)
{
	b2EdgeShape edge;
	edge.SetTwoSided(a, b);
	b2FixtureDef fd;
	fd.shape = &edge;
	fd.friction = friction;
	return GroundBody()->CreateFixture(&fd);
}

void Sample::RememberShape(const ShapePtr& shape)
{
	m_shapes[shape.get()] = shape;
}

b2Body* Sample::AddParticle(const ShapePtr& shape, b2Vec2 position, float angle, float density, float friction,
                            float restitution)
{
	RememberShape(shape);
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	bd.position = position;
	bd.angle = angle;
	b2Body* body = m_world->CreateBody(&bd);
	b2FixtureDef fd;
	fd.density = density;
	fd.friction = friction;
	fd.restitution = restitution;
	AnalyticFixtureDef af;
	af.shape = shape;
	b2Fixture* f = CreateAnalyticFixture(body, fd, af);
	if (m_polygons) // made while the scene shows 8-gons: one too
		SwitchToPolygon(f);
	return body;
}

void Sample::StepWorld(float dt, int velocityIterations, int positionIterations)
{
	m_world->Step(dt, velocityIterations, positionIterations);
}

void Sample::Step(const StepSettings& s, bool paused, bool singleStep)
{
	m_world->SetAllowSleeping(s.sleep);
	m_world->SetWarmStarting(s.warmStarting);
	m_world->SetContinuousPhysics(s.continuous);
	m_world->SetSubStepping(false);
	const int steps = singleStep ? 1 : paused ? 0 : s.stepsPerFrame;
	const float dt = float(1.0 / s.hertz);
	for (int i = 0; i < steps; ++i)
	{
		StepWorld(dt, s.velocityIterations, s.positionIterations);
		m_profile = m_world->GetProfile();
		m_time += dt;
		++m_stepCount;
		AfterStep();
	}
	// A bomb that left the scene is gone (it would otherwise count as an escaped body).
	if (m_bomb)
	{
		const SampleDefaults d = Defaults();
		const b2Vec2 p = m_bomb->GetPosition();
		if (p.x < d.boundsLo.x || p.y < d.boundsLo.y || p.x > d.boundsHi.x || p.y > d.boundsHi.y)
		{
			m_world->DestroyBody(m_bomb);
			m_bomb = nullptr;
		}
	}
}

void Sample::Draw(DrawBatch& batch, const DrawSettings& draw)
{
	const SampleDefaults d = Defaults();
	uint32 flags = 0;
	flags |= draw.shapes ? b2Draw::e_shapeBit : 0;
	flags |= draw.joints ? b2Draw::e_jointBit : 0;
	flags |= draw.aabbs ? b2Draw::e_aabbBit : 0;
	flags |= draw.centresOfMass ? b2Draw::e_centerOfMassBit : 0;
	batch.SetFlags(flags);
	batch.SetAxisLength(0.4f * d.bodySize);
	DrawWorld(m_world, &batch, batch.OutlineVertices());

	if (draw.contactPoints || draw.contactNormals || draw.contactImpulses)
	{
		float maxImpulse = 0.0f;
		for (b2Contact* c = m_world->GetContactList(); c; c = c->GetNext())
			for (int32 i = 0; i < c->GetManifold()->pointCount; ++i)
				maxImpulse = std::max(maxImpulse, c->GetManifold()->points[i].normalImpulse);
		for (b2Contact* c = m_world->GetContactList(); c; c = c->GetNext())
		{
			if (!c->IsTouching())
				continue;
			b2WorldManifold wm;
			c->GetWorldManifold(&wm);
			const b2Manifold* m = c->GetManifold();
			for (int32 i = 0; i < m->pointCount; ++i)
			{
				const b2Vec2 p = wm.points[i];
				if (draw.contactPoints)
					batch.DrawPoint(p, 6.0f, b2Color(0.3f, 0.3f, 0.95f));
				if (draw.contactNormals)
					batch.DrawSegment(p, p + 0.5f * d.bodySize * wm.normal, b2Color(0.9f, 0.9f, 0.9f));
				if (draw.contactImpulses && maxImpulse > 0.0f)
					batch.DrawSegment(p, p + (1.5f * d.bodySize * m->points[i].normalImpulse / maxImpulse) * wm.normal,
					                  b2Color(0.9f, 0.9f, 0.3f));
			}
		}
	}
	if (m_mouseJoint)
	{
		const b2Vec2 p1 = m_mouseJoint->GetAnchorB(), p2 = m_mouseJoint->GetTarget();
		batch.DrawPoint(p1, 4.0f, b2Color(0.0f, 1.0f, 0.0f));
		batch.DrawPoint(p2, 4.0f, b2Color(0.0f, 1.0f, 0.0f));
		batch.DrawSegment(p1, p2, b2Color(0.8f, 0.8f, 0.8f));
	}
	if (m_aimingBomb)
	{
		batch.DrawPoint(m_bombStart, 4.0f, b2Color(0.0f, 0.0f, 1.0f));
		batch.DrawSegment(m_mouse, m_bombStart, b2Color(0.8f, 0.8f, 0.8f));
	}
}

void Sample::Status(std::vector<std::string>& lines) const
{
	char line[160];
	std::snprintf(line, sizeof(line), "t = %.4f s, step %d%s", m_time, m_stepCount, m_polygons ? ", Box2D 8-gons" : "");
	lines.push_back(line);
}

bool Sample::Keyboard(int key)
{
	if (key == GLFW_KEY_SPACE)
	{
		LaunchRandomBomb();
		return true;
	}
	return false;
}

bool Sample::MouseDown(b2Vec2 p)
{
	m_mouse = p;
	if (m_mouseJoint)
		return false;
	b2AABB box;
	const b2Vec2 e(1e-3f * Defaults().bodySize, 1e-3f * Defaults().bodySize);
	box.lowerBound = p - e;
	box.upperBound = p + e;
	PointQuery query(p);
	m_world->QueryAABB(&query, box);
	if (!query.found)
		return false;
	const SampleDefaults d = Defaults();
	b2Body* body = query.found->GetBody();
	b2MouseJointDef jd;
	jd.bodyA = GroundBody();
	jd.bodyB = body;
	jd.target = p;
	// The testbed's 1000 m/s² at most, in the scene's units.
	jd.maxForce = 1000.0f * d.metre * body->GetMass();
	b2LinearStiffness(jd.stiffness, jd.damping, d.mouseHertz, 0.7f, jd.bodyA, jd.bodyB);
	m_mouseJoint = static_cast<b2MouseJoint*>(m_world->CreateJoint(&jd));
	body->SetAwake(true);
	return true;
}

void Sample::MouseUp(b2Vec2 p)
{
	if (m_mouseJoint)
	{
		m_world->DestroyJoint(m_mouseJoint);
		m_mouseJoint = nullptr;
	}
	if (m_aimingBomb)
	{
		// The testbed's launch: 30 times the drag, per second.
		LaunchBomb(m_bombStart, 30.0f * (m_bombStart - p));
		m_aimingBomb = false;
	}
}

void Sample::MouseMove(b2Vec2 p)
{
	m_mouse = p;
	if (m_mouseJoint)
		m_mouseJoint->SetTarget(p);
}

void Sample::ShiftMouseDown(b2Vec2 p)
{
	m_mouse = p;
	if (m_mouseJoint)
		return;
	m_aimingBomb = true;
	m_bombStart = p;
}

void Sample::LaunchBomb(b2Vec2 position, b2Vec2 velocity)
{
	const SampleDefaults d = Defaults();
	if (m_bomb)
	{
		m_world->DestroyBody(m_bomb);
		m_bomb = nullptr;
	}
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	bd.position = position;
	bd.bullet = true;
	m_bomb = m_world->CreateBody(&bd);
	m_bomb->SetLinearVelocity(velocity);
	b2CircleShape circle;
	circle.m_radius = 0.3f * d.bodySize;
	b2FixtureDef fd;
	fd.shape = &circle;
	fd.density = d.bombDensity;
	fd.restitution = 0.0f;
	fd.restitutionThreshold = 1.0f * d.metre;
	m_bomb->CreateFixture(&fd);
}

void Sample::LaunchRandomBomb()
{
	const SampleDefaults d = Defaults();
	static std::mt19937 rng(1);
	std::uniform_real_distribution<float> u(d.viewLo.x, d.viewHi.x);
	const b2Vec2 p(u(rng), d.viewHi.y);
	LaunchBomb(p, -5.0f * d.metre * b2Vec2(0.0f, 1.0f));
}

void Sample::SwitchToPolygon(b2Fixture* f)
{
	b2Body* b = f->GetBody();
	auto rec = std::make_unique<SwitchedFixture>();
	rec->shape = m_shapes[GetAnalyticShape(f)];
	// The shape's pose in the body frame: the body's inverse transform of its world pose.
	const Pose world = GetAnalyticPose(f);
	const b2Vec2 lp = b2MulT(b->GetTransform(), ToB2(world.p));
	rec->local = Pose(Vec2(lp.x, lp.y), world.q.Angle() - double(b->GetAngle()));
	b2FixtureDef& def = rec->def;
	def.density = f->GetDensity();
	def.friction = f->GetFriction();
	def.restitution = f->GetRestitution();
	def.restitutionThreshold = f->GetRestitutionThreshold();
	def.filter = f->GetFilterData();
	def.isSensor = f->IsSensor();
	def.userData = f->GetUserData();
	b2PolygonShape polygon = MakeInscribedPolygon(*rec->shape, m_polygonVertices);
	b2Vec2 v[b2_maxPolygonVertices];
	const b2Transform local(lp, b2Rot(float(rec->local.q.Angle())));
	for (int32 i = 0; i < polygon.m_count; ++i)
		v[i] = b2Mul(local, polygon.m_vertices[i]);
	polygon.Set(v, polygon.m_count);
	b2FixtureDef pd = def;
	pd.shape = &polygon;
	b2Fixture* made = b->CreateFixture(&pd);
	b->DestroyFixture(f);
	m_switched[made] = std::move(rec);
}

void Sample::SwitchToPolygons(bool polygons, int vertices)
{
	if (polygons == m_polygons)
		return;
	m_polygonVertices = vertices;
	if (polygons)
	{
		for (b2Body* b = m_world->GetBodyList(); b; b = b->GetNext())
		{
			std::vector<b2Fixture*> analytic;
			for (b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext())
				if (GetAnalyticShape(f) && m_shapes.count(GetAnalyticShape(f)))
					analytic.push_back(f);
			for (b2Fixture* f : analytic)
				SwitchToPolygon(f);
		}
	}
	else
	{
		for (auto& [polygon, rec] : m_switched)
		{
			b2Body* b = polygon->GetBody();
			AnalyticFixtureDef af;
			af.shape = rec->shape;
			af.local = rec->local;
			CreateAnalyticFixture(b, rec->def, af);
			b->DestroyFixture(polygon);
		}
		m_switched.clear();
	}
	m_polygons = polygons;
}

void Sample::SayGoodbye(b2Joint* joint)
{
	if (joint == m_mouseJoint)
		m_mouseJoint = nullptr;
}

void Sample::SayGoodbye(b2Fixture* fixture)
{
	m_switched.erase(fixture);
}

} // namespace b2a::viewer

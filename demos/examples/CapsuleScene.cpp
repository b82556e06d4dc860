// Example: the capsule scene.
#include "CapsuleScene.h"

#include "common/Svg.h"

#include "b2analytic/AnalyticFixture.h"

#include <algorithm>
#include <cmath>
#include <random>

using namespace b2a;

namespace example
{

namespace
{
const double kHalfWidth = 3.0, kWallHeight = 6.0; // the container (m)
} // namespace

CapsuleScene::CapsuleScene(const CapsuleSceneConfig& config) : m_config(config)
{
	m_world = std::make_unique<b2World>(b2Vec2(0.0f, -10.0f));
	// The container: one chain, its links one-sided with their fronts facing in (right wall
	// down, floor right to left, left wall up).
	b2BodyDef groundDef;
	b2Body* ground = m_world->CreateBody(&groundDef);
	const float w = float(kHalfWidth), h = float(kWallHeight);
	const b2Vec2 walls[4] = {b2Vec2(w, h), b2Vec2(w, 0.0f), b2Vec2(-w, 0.0f), b2Vec2(-w, h)};
	b2ChainShape chain;
	chain.CreateChain(walls, 4, b2Vec2(w, h + 1.0f), b2Vec2(-w, h + 1.0f));
	b2FixtureDef wallDef;
	wallDef.shape = &chain;
	wallDef.friction = 0.4f;
	ground->CreateFixture(&wallDef);
	// A tilted box across the middle, which the particles slide off.
	b2PolygonShape ramp;
	ramp.SetAsBox(1.2f, 0.1f, b2Vec2(0.6f, 1.2f), 0.35f);
	wallDef.shape = &ramp;
	ground->CreateFixture(&wallDef);

	std::mt19937_64 rng(config.seed);
	auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
	const int columns = 10;
	for (int i = 0; i < config.particles; ++i)
	{
		b2BodyDef bd;
		bd.type = b2_dynamicBody;
		const double x = -kHalfWidth + 0.55 * (0.5 + i % columns) + uniform(-0.05, 0.05);
		const double y = 2.0 + 0.6 * (i / columns) + uniform(-0.05, 0.05);
		bd.position.Set(float(x), float(y));
		bd.angle = float(uniform(-kPi, kPi));
		b2Body* body = m_world->CreateBody(&bd);
		b2FixtureDef fd;
		fd.density = 1.0f;
		fd.friction = 0.4f;
		fd.restitution = 0.1f;
		AnalyticFixtureDef analytic;
		switch (i % 4)
		{
		case 0:
		case 2:
			analytic.shape = MakeCapsule(uniform(0.08, 0.16), uniform(0.07, 0.1));
			break;
		case 1:
		{
			const double a = uniform(0.14, 0.2);
			analytic.shape = MakeSuperellipse(a, a / 1.5, 4.0, 4.0);
			break;
		}
		default:
			if (i % 8 == 3)
				analytic.shape = MakeCircle(uniform(0.09, 0.13));
			break;
		}
		if (analytic.shape)
		{
			CreateAnalyticFixture(body, fd, analytic);
		}
		else
		{
			b2CircleShape circle; // a Box2D circle: the table's circle kind meets the capsules
			circle.m_radius = float(uniform(0.09, 0.13));
			fd.shape = &circle;
			body->CreateFixture(&fd);
		}
	}
	m_closedFormAtStart = g_closedFormContacts.load();
}

std::string CapsuleScene::KindOf(const b2Fixture* f)
{
	if (const Shape* s = GetAnalyticShape(f))
		return KindName(s->Kind());
	if (f->GetBody()->GetType() == b2_staticBody)
		return "wall";
	return "box2d_circle";
}

void CapsuleScene::Step()
{
	m_world->Step(float(m_config.dt), 8, 3);
	++m_report.steps;
	m_report.time += m_config.dt;
	Tally();
}

void CapsuleScene::Tally()
{
	m_report.lastPenetration = 0.0;
	for (b2Contact* c = m_world->GetContactList(); c; c = c->GetNext())
	{
		if (!c->IsTouching())
			continue;
		std::string ka = KindOf(c->GetFixtureA()), kb = KindOf(c->GetFixtureB());
		if (kb < ka)
			std::swap(ka, kb);
		++m_report.contacts[ka + "-" + kb];
		b2WorldManifold wm;
		c->GetWorldManifold(&wm);
		for (int k = 0; k < c->GetManifold()->pointCount; ++k)
			m_report.lastPenetration = std::max(m_report.lastPenetration, -double(wm.separations[k]));
	}
	m_report.maxPenetration = std::max(m_report.maxPenetration, m_report.lastPenetration);
}

CapsuleSceneReport CapsuleScene::Report() const
{
	CapsuleSceneReport r = m_report;
	r.closedFormContacts = g_closedFormContacts.load() - m_closedFormAtStart;
	r.nonFinite = r.escaped = 0;
	r.kineticEnergy = 0.0;
	for (const b2Body* b = m_world->GetBodyList(); b; b = b->GetNext())
	{
		if (b->GetType() != b2_dynamicBody)
			continue;
		const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity();
		const double angle = b->GetAngle(), omega = b->GetAngularVelocity();
		if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(angle) || !std::isfinite(v.x) || !std::isfinite(v.y) ||
		    !std::isfinite(omega))
		{
			++r.nonFinite;
			continue;
		}
		if (std::fabs(p.x) > kHalfWidth || p.y < 0.0)
			++r.escaped;
		r.kineticEnergy += 0.5 * b->GetMass() * double(b2Dot(v, v)) + 0.5 * b->GetInertia() * omega * omega;
	}
	return r;
}

std::string CapsuleScene::Svg(const std::string& title) const
{
	demo::SvgCanvas svg(Vec2(-kHalfWidth - 0.2, -0.3), Vec2(kHalfWidth + 0.2, 0.5 * kWallHeight + 0.5), 900.0);
	auto styleOf = [](const std::string& kind) {
		demo::Style s;
		s.stroke = "#333333";
		s.opacity = 0.85;
		s.fill = kind == "capsule" ? "#e15759" : kind == "superellipse" ? "#4e79a7" : "#f2b134";
		return s;
	};
	for (const b2Body* b = m_world->GetBodyList(); b; b = b->GetNext())
	{
		const b2Transform& xf = b->GetTransform();
		Rot q;
		q.c = xf.q.c;
		q.s = xf.q.s;
		const Pose body(Vec2(xf.p.x, xf.p.y), q);
		for (const b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext())
		{
			if (const Shape* s = GetAnalyticShape(f))
			{
				svg.Polygon(demo::Outline(*s, GetAnalyticPose(f), 0.0 / 0.0, 96), styleOf(KindName(s->Kind())));
			}
			else if (f->GetType() == b2Shape::e_circle)
			{
				const auto* c = static_cast<const b2CircleShape*>(f->GetShape());
				demo::Style s = styleOf("circle");
				s.fill = "#59a14f"; // Box2D's own circles
				svg.Circle(ToWorld(body, Vec2(c->m_p.x, c->m_p.y)), c->m_radius, s);
			}
			else if (f->GetType() == b2Shape::e_polygon)
			{
				const auto* p = static_cast<const b2PolygonShape*>(f->GetShape());
				std::vector<Vec2> points;
				for (int k = 0; k < p->m_count; ++k)
					points.push_back(ToWorld(body, Vec2(p->m_vertices[k].x, p->m_vertices[k].y)));
				demo::Style s;
				s.fill = "#bab0ac";
				svg.Polygon(points, s);
			}
			else if (f->GetType() == b2Shape::e_chain)
			{
				const auto* c = static_cast<const b2ChainShape*>(f->GetShape());
				std::vector<Vec2> points;
				for (int k = 0; k < c->m_count; ++k)
					points.push_back(ToWorld(body, Vec2(c->m_vertices[k].x, c->m_vertices[k].y)));
				demo::Style s;
				s.width = 3.0;
				svg.Polyline(points, s);
			}
		}
	}
	svg.Label(10.0, 22.0, title, 16.0);
	svg.Label(10.0, 44.0, "capsules (red): kind \"capsule\", registered by the example; superellipses (blue), analytic circles "
	                      "(yellow), Box2D circles (green)",
	          12.0);
	// A scale bar of 1 m.
	svg.Polyline({Vec2(-kHalfWidth + 0.1, -0.15), Vec2(-kHalfWidth + 1.1, -0.15)}, demo::Style{"none", "black", 2.0, "", 1.0});
	svg.Text(Vec2(-kHalfWidth + 0.45, -0.1), "1 m", 12.0);
	return svg.Finish();
}

} // namespace example

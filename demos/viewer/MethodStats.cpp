// b2a_viewer: contacts counted by method, with the mean time per contact.
#include "MethodStats.h"

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/Contact.h"
#include "b2analytic/PolygonContact.h"
#include "b2analytic/SuperellipseShape.h"

#include <box2d/box2d.h>

#include <chrono>
#include <vector>

namespace b2a::viewer
{
namespace
{
using Clock = std::chrono::steady_clock;

double Micros(Clock::time_point t0)
{
	return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

Pose ToPose(const b2Transform& xf)
{
	Rot q;
	q.c = xf.q.c;
	q.s = xf.q.s;
	return Pose(Vec2(xf.p.x, xf.p.y), q);
}

// The plain fixture's child as vertices in its body frame: a polygon, an edge or a chain link
// (2 or more vertices); false for circles.
bool PlainVertices(const b2Fixture* f, int child, std::vector<Vec2>& out)
{
	out.clear();
	const b2Shape* s = f->GetShape();
	if (s->GetType() == b2Shape::e_polygon)
	{
		const b2PolygonShape* p = static_cast<const b2PolygonShape*>(s);
		for (int32 i = 0; i < p->m_count; ++i)
			out.push_back(Vec2(p->m_vertices[i].x, p->m_vertices[i].y));
		return true;
	}
	b2EdgeShape edge;
	if (s->GetType() == b2Shape::e_edge)
		edge = *static_cast<const b2EdgeShape*>(s);
	else if (s->GetType() == b2Shape::e_chain)
		static_cast<const b2ChainShape*>(s)->GetChildEdge(&edge, child);
	else
		return false;
	out.push_back(Vec2(edge.m_vertex1.x, edge.m_vertex1.y));
	out.push_back(Vec2(edge.m_vertex2.x, edge.m_vertex2.y));
	return true;
}

// Box2D's own narrow phase for a plain pair, timed; its tally's name.
const char* CollidePlain(b2Contact* c, double& micros, bool& touching)
{
	const b2Fixture *fa = c->GetFixtureA(), *fb = c->GetFixtureB();
	const b2Transform &xa = fa->GetBody()->GetTransform(), &xb = fb->GetBody()->GetTransform();
	const b2Shape *sa = fa->GetShape(), *sb = fb->GetShape();
	b2Manifold m;
	const char* name = "box2d_other";
	const auto t0 = Clock::now();
	const b2Shape::Type ta = sa->GetType(), tb = sb->GetType();
	if (ta == b2Shape::e_polygon && tb == b2Shape::e_polygon)
	{
		b2CollidePolygons(&m, static_cast<const b2PolygonShape*>(sa), xa, static_cast<const b2PolygonShape*>(sb), xb);
		name = "box2d_polygons";
	}
	else if (ta == b2Shape::e_circle && tb == b2Shape::e_circle)
	{
		b2CollideCircles(&m, static_cast<const b2CircleShape*>(sa), xa, static_cast<const b2CircleShape*>(sb), xb);
		name = "box2d_circles";
	}
	else if (ta == b2Shape::e_polygon && tb == b2Shape::e_circle)
	{
		b2CollidePolygonAndCircle(&m, static_cast<const b2PolygonShape*>(sa), xa, static_cast<const b2CircleShape*>(sb), xb);
		name = "box2d_polygon_circle";
	}
	else if ((ta == b2Shape::e_edge || ta == b2Shape::e_chain) && (tb == b2Shape::e_polygon || tb == b2Shape::e_circle))
	{
		b2EdgeShape edge;
		if (ta == b2Shape::e_edge)
			edge = *static_cast<const b2EdgeShape*>(sa);
		else
			static_cast<const b2ChainShape*>(sa)->GetChildEdge(&edge, c->GetChildIndexA());
		if (tb == b2Shape::e_polygon)
			b2CollideEdgeAndPolygon(&m, &edge, xa, static_cast<const b2PolygonShape*>(sb), xb);
		else
			b2CollideEdgeAndCircle(&m, &edge, xa, static_cast<const b2CircleShape*>(sb), xb);
		name = tb == b2Shape::e_polygon ? "box2d_edge_polygon" : "box2d_edge_circle";
	}
	else
		m.pointCount = 0;
	micros = Micros(t0);
	touching = m.pointCount > 0;
	return name;
}
} // namespace

double MethodStats::TotalMicroseconds() const
{
	double t = 0.0;
	for (const auto& [name, tally] : methods)
		t += tally.microseconds;
	return t;
}

MethodStats CountMethods(b2World* world)
{
	MethodStats stats;
	std::vector<Vec2> vertices;
	for (b2Contact* c = world->GetContactList(); c; c = c->GetNext())
	{
		++stats.pairs;
		b2Fixture *fa = c->GetFixtureA(), *fb = c->GetFixtureB();
		int childB = c->GetChildIndexB(), childA = c->GetChildIndexA();
		if (!GetAnalyticShape(fa) && GetAnalyticShape(fb))
		{
			std::swap(fa, fb);
			std::swap(childA, childB);
		}
		const Shape* sa = GetAnalyticShape(fa);
		if (!sa)
		{
			double micros = 0.0;
			bool touching = false;
			MethodTally& t = stats.methods[CollidePlain(c, micros, touching)];
			++t.contacts;
			t.touching += touching;
			t.microseconds += micros;
			continue;
		}
		ContactResult r;
		const auto t0 = Clock::now();
		if (GetAnalyticShape(fb))
			r = ComputeFixtureContact(fa, fb);
		else if (PlainVertices(fb, childB, vertices))
			r = ComputePolygonContact(*sa, GetAnalyticPose(fa), vertices.data(), int(vertices.size()),
			                          ToPose(fb->GetBody()->GetTransform()));
		else // a Box2D circle: the analytic circle the adapter stands in for it
		{
			const b2CircleShape* circle = static_cast<const b2CircleShape*>(fb->GetShape());
			static thread_local std::map<float, ShapePtr> circles;
			ShapePtr& shape = circles[circle->m_radius];
			if (!shape)
				shape = MakeCircle(circle->m_radius);
			const b2Vec2 centre = b2Mul(fb->GetBody()->GetTransform(), circle->m_p);
			r = ComputeContact(*sa, GetAnalyticPose(fa), *shape, Pose(Vec2(centre.x, centre.y), 0.0));
		}
		const double micros = Micros(t0);
		if (!r.Ok())
		{
			++stats.failed;
			continue;
		}
		MethodTally& t = stats.methods[MethodName(r.method)];
		++t.contacts;
		t.touching += r.touching;
		t.microseconds += micros;
	}
	return stats;
}

} // namespace b2a::viewer

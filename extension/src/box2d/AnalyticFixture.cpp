// b2analytic: creating analytic fixtures, looking them up, drawing them.
#include "b2analytic/AnalyticFixture.h"

#include "box2d/AnalyticContact.h"
#include "box2d/AnalyticProxyShape.h"

#include "b2analytic/Contact.h"
#include "b2analytic/PolygonContact.h"

#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_world.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace b2a
{

namespace
{
// Exactly the same point (for std::unique: repeated proxy points).
bool SamePoint(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

// Convex hull (Andrew's monotone chain), counter-clockwise, of up to a few points.
std::vector<Vec2> ConvexHull(std::vector<Vec2> p)
{
	std::sort(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
	p.erase(std::unique(p.begin(), p.end(), SamePoint), p.end());
	if (p.size() < 3)
		return p; // a point or a segment (the chain below would drop a lone point)
	std::vector<Vec2> h(2 * p.size());
	size_t k = 0;
	for (size_t i = 0; i < p.size(); ++i)
	{
		while (k >= 2 && Cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0.0) --k;
		h[k++] = p[i];
	}
	for (size_t i = p.size() - 1, t = k + 1; i-- > 0;)
	{
		while (k >= t && Cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0.0) --k;
		h[k++] = p[i];
	}
	h.resize(k > 0 ? k - 1 : 0);
	return h;
}

// The vertices of the rounded polygon (core `poly`, counter-clockwise, plus a disk of radius
// `skin`) whose boundary leaves the shape: points along each edge moved out by the skin and on
// each corner's arc, tested against the level function; and the ends of the edge nearest to any
// surface sample that lies within the rounded polygon (a cusp between the edge points).
std::vector<int> VerticesOutside(const Shape& shape, const std::vector<Vec2>& poly, double skin)
{
	const int n = int(poly.size());
	std::vector<int> out;
	skin *= 1.0 - 1e-6; // a smooth convex surface touches the skin's disk: no rounding either way
	auto outside = [&](Vec2 x) { return !(shape.Level(x) <= shape.SurfaceLevel()); };
	auto normal = [&](int i) {
		const Vec2 e = poly[(i + 1) % n] - poly[i];
		return Normalize(Vec2(e.y, -e.x));
	};
	for (int i = 0; i < n; ++i)
	{
		const int j = (i + 1) % n;
		const Vec2 m = normal(i), next = normal(j);
		bool edge = false, corner = false;
		for (int k = 0; k <= 16 && !edge; ++k)
			edge = outside(poly[i] + (k / 16.0) * (poly[j] - poly[i]) + skin * m);
		for (int k = 1; k < 8 && !corner && skin > 0.0; ++k)
			corner = outside(poly[j] + skin * Normalize((1.0 - k / 8.0) * m + (k / 8.0) * next));
		if (edge)
			out.push_back(i);
		if (edge || corner)
			out.push_back(j);
	}
	// The cusp test is for non-convex shapes. In a convex one, an offset edge whose two ends lie
	// inside lies inside (no cusp can hide between its test points), and a corner's arc bulges
	// past the chords between its test points by skin·(1 − cos(turn/16)), at most 0.02 skins
	// (1e-4 at Box2D's skin, a fiftieth of its linear slop). So a convex shape's fixture needs
	// no default samples, only its proxy's seven.
	if (!shape.IsConvex())
	{
		for (Vec2 p : shape.Samples()->point)
		{
			double nearest = 1e300;
			int edge = 0;
			bool inCore = true;
			for (int i = 0; i < n; ++i)
			{
				const Vec2 a = poly[i], e = poly[(i + 1) % n] - a;
				const double ee = Dot(e, e); // 0 for a repeated vertex: its nearest point is the vertex
				const double t = ee > 0.0 ? std::clamp(Dot(p - a, e) / ee, 0.0, 1.0) : 0.0;
				const double d = Length(p - (a + t * e));
				if (d < nearest)
				{
					nearest = d;
					edge = i;
				}
				inCore = inCore && Cross(e, p - a) > 0.0;
			}
			if (inCore || nearest < skin)
			{
				out.push_back(edge);
				out.push_back((edge + 1) % n);
			}
		}
	}
	std::sort(out.begin(), out.end());
	out.erase(std::unique(out.begin(), out.end()), out.end());
	return out;
}

const AnalyticProxyShape* Proxy(const b2Fixture* fixture)
{
	return fixture ? AnalyticProxyShape::From(fixture->GetShape()) : nullptr;
}

b2Vec2 F(Vec2 v) { return b2Vec2(float(v.x), float(v.y)); }

// CreateAnalyticFixture's checks of its arguments, in the order their errors are reported: the
// body and the world, the shapes, the local pose, the material, the body's pose, the patch
// parameters.
void CheckFixtureArguments(b2Body* body, const b2FixtureDef& def, const AnalyticFixtureDef& analytic)
{
	if (!body)
		throw MisuseError("CreateAnalyticFixture: the body is null");
	if (body->GetWorld()->IsLocked())
		throw MisuseError("CreateAnalyticFixture: the world is locked (inside Step or a world callback); "
		                  "create fixtures between steps");
	if (!analytic.shape)
		throw InvalidParameter("CreateAnalyticFixture: field 'shape' is null (an analytic shape is required)", "shape");
	if (def.shape)
		throw InvalidParameter("CreateAnalyticFixture: field 'def.shape' must be null (the analytic shape takes its place)", "def.shape");
	const Pose& local = analytic.local;
	if (!IsFinite(local.p) || !std::isfinite(local.q.c) || !std::isfinite(local.q.s))
		throw InvalidParameter("CreateAnalyticFixture", "local", "must be a finite pose", local.p.x + local.p.y + local.q.c + local.q.s);
	// Box2D checks none of these: a negative density gives a negative mass (its assertions, or
	// silently wrong dynamics), a negative friction NaN mixed friction (sqrt of a product).
	const std::pair<const char*, float> material[] = {{"density", def.density},
	                                                   {"friction", def.friction},
	                                                   {"restitution", def.restitution},
	                                                   {"restitutionThreshold", def.restitutionThreshold}};
	for (const auto& [field, value] : material)
		if (!std::isfinite(value) || value < 0.0f)
			throw InvalidParameter("CreateAnalyticFixture", field, "must be finite and >= 0", value);
	const b2Transform& xf = body->GetTransform();
	if (!std::isfinite(xf.p.x) || !std::isfinite(xf.p.y) || !std::isfinite(xf.q.c) || !std::isfinite(xf.q.s))
		throw InvalidParameter("CreateAnalyticFixture", "body", "must have a finite position and angle, position x + y",
		                       double(xf.p.x) + double(xf.p.y));
	if (!std::isfinite(analytic.patchTolerance) || analytic.patchTolerance < 0.0)
		throw InvalidParameter("CreateAnalyticFixture", "patchTolerance", "must be finite and >= 0", analytic.patchTolerance);
	if (!std::isfinite(analytic.patchMinWidth) || analytic.patchMinWidth < 0.0)
		throw InvalidParameter("CreateAnalyticFixture", "patchMinWidth", "must be finite and >= 0", analytic.patchMinWidth);
}

// The particle's size and reach against Box2D's absolute tolerances and float positions and mass
// data; its own mass data (about the body origin) when it fits.
b2MassData CheckFitsBox2DFloats(const Shape& shape, const Pose& local, float density)
{
	// Box2D's tolerances are absolute (linear slop 0.005 length units): a smaller particle
	// cannot be resolved; the fix is a smaller length unit (see the README on millimetres).
	if (!(shape.BoundingRadius() >= 2.0 * b2_linearSlop))
		throw InvalidParameter("CreateAnalyticFixture", "shape", "must be at least 2 * b2_linearSlop (0.01 length units) in bounding radius "
		                       "(use smaller length units), bounding radius",
		                       shape.BoundingRadius());
	// Box2D's positions, proxies and distance queries are float: beyond reach·FLT_EPSILON = 0.1 of
	// its linear slop (4194 length units from the body origin) a float coordinate of the particle
	// is coarser than its tolerances, and its time of impact breaks (a 0.028 × 1e12 needle beside
	// a circle of radius 1e8 made b2TimeOfImpact assert, found by the world fuzzer).
	const double reach = shape.BoundingRadius() + Length(local.p);
	const double farthest = 0.1 * double(b2_linearSlop) / double(FLT_EPSILON);
	if (!(shape.BoundingRadius() <= farthest))
		throw InvalidParameter("CreateAnalyticFixture", "shape",
		                       "is too large for Box2D's float positions (the bounding radius must be at most "
		                       "0.1 * b2_linearSlop / FLT_EPSILON, 4194 length units: use larger length units), bounding radius",
		                       shape.BoundingRadius());
	if (!(reach <= farthest))
		throw InvalidParameter("CreateAnalyticFixture", "local",
		                       "puts the particle too far from the body origin for Box2D's float positions (bounding "
		                       "radius plus |local.p| must be at most 0.1 * b2_linearSlop / FLT_EPSILON, 4194 length "
		                       "units), bounding radius plus |local.p|",
		                       reach);
	// Box2D keeps mass data in float: mass and the moment about the body origin must not overflow.
	const double moment = double(density) * shape.Mass().area * reach * reach;
	const double most = std::numeric_limits<float>::max(); // compared in double: a cast out of range is undefined
	if (!(reach < most && moment < most))
		throw InvalidParameter("CreateAnalyticFixture", "shape", "is too large for Box2D's float mass data, bounding radius",
		                       shape.BoundingRadius());
	// Nor underflow: a mass below float's normal range keeps few bits (an ellipse 6.6e-40 wide,
	// found by the world fuzzer), and its inverse overflows.
	const b2MassData own = AnalyticMassData(shape, local, density);
	if (density > 0.0f)
	{
		const float moment = float(double(density) * shape.Mass().polarMoment); // about the centroid
		if (!(own.mass >= std::numeric_limits<float>::min() && moment >= std::numeric_limits<float>::min()))
			throw InvalidParameter("CreateAnalyticFixture", "shape",
			                       "is too thin (or 'density' too low) for Box2D's float mass data: its mass or moment "
			                       "is below float's normal range, mass",
			                       double(density) * shape.Mass().area);
	}
	return own;
}

// The body's float moment about its centre, with this fixture added, checked before Box2D
// asserts on it.
void CheckMomentAboutCentre(const b2Body* body, const b2FixtureDef& def, const b2MassData& own, const Shape& shape,
                            const Pose& local)
{
	// b2Body::ResetMassData, which CreateFixture calls, moves the body's float moment about its
	// origin to its centre (I − m·|c|²) and asserts that it stays positive. Far from the body's
	// centre a small particle's own moment is lost in that difference (as a Box2D circle's is), so
	// the sums are done here first, in float as Box2D does them, with this fixture added.
	if (body->GetType() == b2_dynamicBody && !body->IsFixedRotation() && def.density > 0.0f)
	{
		float mass = 0.0f, moment = 0.0f;
		b2Vec2 centre(0.0f, 0.0f);
		auto add = [&](const b2MassData& m) {
			mass += m.mass;
			centre += m.mass * m.center;
			moment += m.I;
		};
		for (const b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext())
		{
			if (f->GetDensity() == 0.0f)
				continue;
			b2MassData m;
			f->GetMassData(&m);
			add(m);
		}
		add(own);
		centre *= 1.0f / mass;
		if (!(moment - mass * b2Dot(centre, centre) > 0.0f))
			throw InvalidParameter("CreateAnalyticFixture", "local",
			                       "puts the particle so far from the body's centre that Box2D's float moment of inertia "
			                       "about it is lost to rounding (move the body origin nearer), distance",
			                       Length(ToWorld(local, shape.Mass().centroid)));
	}
}

// The proxy polygon's vertices in the body frame of the shape, before they are fitted inside
// it; `insetFits`: whether they are the surface points moved in by Box2D's skin (else the
// surface points themselves).
std::vector<Vec2> ProxyCore(const Shape& shape, bool& insetFits)
{
	// The proxy: Box2D's time of impact stops bodies when proxy cores come within
	// totalRadius − 3·slop and expects its position solver to leave them at totalRadius − slop,
	// so the proxy needs a skin like Box2D's polygons (b2_polygonRadius). Its core is the polygon
	// through surface points moved inwards by that skin along their normals, or towards the
	// origin (shapes are star-shaped about it) where the normal is no use: at a cusp such as the
	// heart's, the gradient points anywhere.
	const double skin = b2_polygonRadius;
	const auto samples = shape.Samples(AnalyticProxyShape::kMaxProxyVertices);
	std::vector<Vec2> points;
	insetFits = true;
	auto inside = [&](Vec2 q, Vec2 p) { return shape.Level(q) < shape.SurfaceLevel() && Dot(q, p) > 0.0; };
	for (Vec2 p : samples->point)
	{
		Vec2 q = p - skin * Normalize(shape.Gradient(p));
		if (!inside(q, p))
			q = p - skin * Normalize(p);
		insetFits = insetFits && inside(q, p);
		points.push_back(q);
	}
	if (!insetFits)
	{
		// Thinner than two skins somewhere: the surface points themselves, without a skin.
		points.clear();
		for (Vec2 p : samples->point)
			points.push_back(p);
	}
	if (!shape.IsConvex())
		points = ConvexHull(points);
	// Repeated points (samples that coincide on a degenerate user shape) would give edges
	// without a normal; fewer than three left means the samples span no area.
	points.erase(std::unique(points.begin(), points.end(), SamePoint), points.end());
	while (points.size() > 1 && SamePoint(points.back(), points.front()))
		points.pop_back();
	// The proxy's vertices are float: a needle thinner than float resolves (1e-237 wide, its
	// samples now reaching its tips) is a segment there, which spans no area either.
	double twiceArea = 0.0;
	for (size_t i = 0; i < points.size(); ++i)
	{
		const Vec2 p = points[i], q = points[(i + 1) % points.size()];
		twiceArea += Cross(Vec2(double(float(p.x)), double(float(p.y))), Vec2(double(float(q.x)), double(float(q.y))));
	}
	if (points.size() < 3 || !(twiceArea > 0.0))
		throw InvalidParameter("CreateAnalyticFixture", "shape",
		                       "has surface samples that span no area in float (the proxy polygon needs 3 distinct vertices "
		                       "around an area), vertices",
		                       double(points.size()));
	return points;
}

// Pull the vertices of `points` (the proxy's core, rounded by `radius`) whose edges or corners
// leave the shape towards the origin until the rounded polygon lies inside it (at most 200
// rounds).
void FitProxyInside(const Shape& shape, std::vector<Vec2>& points, double radius)
{
	// The rounded proxy must lie inside the true shape: Box2D drops a time of impact whose
	// contact is not touching when it gets there (b2World::SolveTOI), so a proxy reaching past
	// the true shape lets fast particles pass. Convex shapes fit as built; a hull bridges concave
	// parts (the heart's notch), so pull the vertices of edges that leave the shape towards the
	// origin until it fits.
	for (int iteration = 0; iteration < 200; ++iteration)
	{
		const std::vector<int> outside = VerticesOutside(shape, points, radius);
		if (outside.empty())
			break;
		for (int i : outside)
			points[i] = 0.99 * points[i];
		points = ConvexHull(points);
	}
}
} // namespace

b2Fixture* CreateAnalyticFixture(b2Body* body, const b2FixtureDef& def, const AnalyticFixtureDef& analytic)
{
	AnalyticContact::Install(); // also links the registration into every program that creates one
	CheckFixtureArguments(body, def, analytic);
	const Pose& local = analytic.local;
	const Shape& shape = *analytic.shape;
	const b2MassData own = CheckFitsBox2DFloats(shape, local, def.density);
	CheckMomentAboutCentre(body, def, own, shape, local);

	bool insetFits = true;
	std::vector<Vec2> points = ProxyCore(shape, insetFits);
	const double radius = insetFits ? b2_polygonRadius : 0.0;
	FitProxyInside(shape, points, radius);
	for (Vec2& p : points)
		p = ToWorld(local, p);
	auto* data = new AnalyticFixtureData;
	data->shape = analytic.shape;
	data->local = local;
	data->patchTolerance = analytic.patchTolerance;
	data->patchMinWidth = analytic.patchMinWidth * shape.BoundingRadius();
	data->solver = analytic.solver;
	AnalyticProxyShape proxy(data); // owns the first reference; the fixture's clone adds its own
	proxy.m_radius = float(radius);
	const int count = std::min(int(points.size()), AnalyticProxyShape::kMaxProxyVertices);
	proxy.m_count = count;
	for (int i = 0; i < count; ++i)
	{
		proxy.m_vertices[i] = F(points[i]);
		const Vec2 e = points[(i + 1) % count] - points[i];
		proxy.m_normals[i] = F(Normalize(Vec2(e.y, -e.x)));
	}
	proxy.m_centroid = F(ToWorld(local, shape.Mass().centroid));

	b2FixtureDef d = def;
	d.shape = &proxy;
	return body->CreateFixture(&d);
}

b2Fixture* CreateAnalyticFixture(b2Body* body, ShapePtr shape, float density)
{
	b2FixtureDef def;
	def.density = density;
	AnalyticFixtureDef analytic;
	analytic.shape = std::move(shape);
	return CreateAnalyticFixture(body, def, analytic);
}

b2Fixture* CreateAnalyticFixture(b2Body* body, ShapePtr shape, float density, float friction, float restitution)
{
	AnalyticFixtureDef analytic;
	analytic.shape = std::move(shape);
	return CreateAnalyticFixture(body, analytic, density, friction, restitution);
}

b2Fixture* CreateAnalyticFixture(b2Body* body, const AnalyticFixtureDef& analytic, float density, float friction, float restitution)
{
	b2FixtureDef def;
	def.density = density;
	def.friction = friction;
	def.restitution = restitution;
	return CreateAnalyticFixture(body, def, analytic);
}

const Shape* GetAnalyticShape(const b2Fixture* fixture)
{
	const AnalyticProxyShape* p = Proxy(fixture);
	return p ? p->Data().shape.get() : nullptr;
}

Pose GetAnalyticPose(const b2Fixture* fixture)
{
	const AnalyticProxyShape* p = Proxy(fixture);
	if (!p)
		throw InvalidParameter("GetAnalyticPose: field 'fixture' is not an analytic fixture", "fixture");
	return p->WorldPose(fixture->GetBody()->GetTransform());
}

ContactResult ComputeFixtureContact(const b2Fixture* a, const b2Fixture* b)
{
	const AnalyticProxyShape* pa = Proxy(a);
	const AnalyticProxyShape* pb = Proxy(b);
	if (pa && pb)
		return ComputeContact(*pa->Data().shape, GetAnalyticPose(a), *pb->Data().shape, GetAnalyticPose(b));
	ContactResult failed;
	failed.failure = "ComputeFixtureContact needs two analytic fixtures";
	return failed;
}

void DrawWorld(b2World* world, b2Draw* draw, int outlineVertices)
{
	if (!world || !draw)
		throw MisuseError("DrawWorld: the world and the b2Draw must not be null");
	const uint32 flags = draw->GetFlags();
	if (flags & b2Draw::e_shapeBit)
	{
		std::vector<b2Vec2> outline;
		for (b2Body* b = world->GetBodyList(); b; b = b->GetNext())
		{
			const b2Transform& xf = b->GetTransform();
			// Box2D's own colour code for body states.
			b2Color color(0.9f, 0.7f, 0.7f);
			if (b->GetType() == b2_dynamicBody && b->GetMass() == 0.0f) color = b2Color(1.0f, 0.0f, 0.0f);
			else if (!b->IsEnabled()) color = b2Color(0.5f, 0.5f, 0.3f);
			else if (b->GetType() == b2_staticBody) color = b2Color(0.5f, 0.9f, 0.5f);
			else if (b->GetType() == b2_kinematicBody) color = b2Color(0.5f, 0.5f, 0.9f);
			else if (!b->IsAwake()) color = b2Color(0.6f, 0.6f, 0.6f);
			for (b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext())
			{
				if (const AnalyticProxyShape* p = Proxy(f))
				{
					const Shape& s = *p->Data().shape;
					const Pose pose = p->WorldPose(xf);
					const auto samples = s.Samples(std::max(8, outlineVertices));
					outline.clear();
					for (Vec2 v : samples->point)
						outline.push_back(F(ToWorld(pose, v)));
					draw->DrawSolidPolygon(outline.data(), int32(outline.size()), color);
					continue;
				}
				switch (f->GetType())
				{
				case b2Shape::e_circle:
				{
					const b2CircleShape* c = static_cast<const b2CircleShape*>(f->GetShape());
					draw->DrawSolidCircle(b2Mul(xf, c->m_p), c->m_radius, b2Mul(xf.q, b2Vec2(1.0f, 0.0f)), color);
					break;
				}
				case b2Shape::e_edge:
				{
					const b2EdgeShape* e = static_cast<const b2EdgeShape*>(f->GetShape());
					draw->DrawSegment(b2Mul(xf, e->m_vertex1), b2Mul(xf, e->m_vertex2), color);
					break;
				}
				case b2Shape::e_chain:
				{
					const b2ChainShape* c = static_cast<const b2ChainShape*>(f->GetShape());
					for (int32 i = 1; i < c->m_count; ++i)
						draw->DrawSegment(b2Mul(xf, c->m_vertices[i - 1]), b2Mul(xf, c->m_vertices[i]), color);
					break;
				}
				case b2Shape::e_polygon:
				{
					const b2PolygonShape* poly = static_cast<const b2PolygonShape*>(f->GetShape());
					b2Vec2 v[b2_maxPolygonVertices];
					for (int32 i = 0; i < poly->m_count; ++i)
						v[i] = b2Mul(xf, poly->m_vertices[i]);
					draw->DrawSolidPolygon(v, poly->m_count, color);
					break;
				}
				default:
					break;
				}
			}
		}
	}
	// Joints, AABBs, pairs and centres of mass: Box2D's own drawing without its shapes.
	if (flags & ~uint32(b2Draw::e_shapeBit))
	{
		world->SetDebugDraw(draw);
		draw->SetFlags(flags & ~uint32(b2Draw::e_shapeBit));
		world->DebugDraw();
		draw->SetFlags(flags);
	}
}

} // namespace b2a

// b2analytic: the analytic narrow phase inside Box2D's contact pipeline.
#include "box2d/AnalyticContact.h"

#include "box2d/AnalyticProxyShape.h"
#include "numerics/CodeLayout.h"

#include "b2analytic/AnalyticFixture.h"

#include "b2analytic/Contact.h"
#include "b2analytic/ContactManifold.h"
#include "b2analytic/PolygonContact.h"
#include "b2analytic/SurfaceQueries.h"
#include "b2analytic/SuperellipseShape.h"

#include <box2d/b2_block_allocator.h>
#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>

#include <map>
#include <cstring>
#include <mutex>
#include <new>
#include <type_traits>
#include <typeinfo>

namespace b2a
{

namespace
{
// Why Evaluate and not a PreSolve listener: Evaluate runs inside b2Contact::Update before Box2D
// matches point ids (so impulses carry over), decides touching (so Begin/EndContact follow the
// true shapes) and calls PreSolve (which stays the user's). It also runs in the TOI sub-steps.
// Registration must precede every contact of the four types anywhere in the process, because
// Box2D destroys a contact through the register of its shape types: so it runs during static
// initialisation, in the translation unit every adapter function lives in.
const bool g_installed = AnalyticContact::Install();

Vec2 V(const b2Vec2& v) { return Vec2(v.x, v.y); }
b2Vec2 F(Vec2 v) { return b2Vec2(float(v.x), float(v.y)); }

// Whether the axis n (unit, from A towards B) separates the particles: B's lowest point along n
// lies above A's highest, (cB − cA)·n − h_A(n) − h_B(−n) > 0 with h the support values in the
// body frames. The shapes' bounds on h decide most pairs (touching ones by the lower bounds,
// pairs well apart by the upper ones); two supports only in between. All against a solve.
bool SeparatedAlong(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Vec2 n)
{
	const Vec2 dA = InvRotate(pa.q, n), dB = InvRotate(pb.q, -n);
	const double gap = Dot(pb.p - pa.p, n);
	double lowA, highA, lowB, highB;
	a.SupportBounds(dA, lowA, highA);
	b.SupportBounds(dB, lowB, highB);
	if (!(gap - lowA - lowB > 0.0))
		return false;
	if (gap - highA - highB > 0.0)
		return true;
	return gap - a.SupportValue(dA) - b.SupportValue(dB) > 0.0;
}

// Write a manifold in Box2D's e_faceA form: normal and the point on A in A's frame, points on B
// in B's frame; or, where the manifold was built from B's side (`onB`: its normal points from B
// to A, its pointA lies on B and its points on A), in the e_faceB form, which Box2D reads the
// same way with the roles swapped. Ids 0 and 1 follow the patch's ends along the tangent, so they
// are stable while the contact persists and Box2D carries impulses between steps. Box2D subtracts
// each shape's m_radius from the separation; an analytic side's proxy has a skin (for the time of
// impact) that the true surface does not, so its point moves into the body by that skin, which
// Box2D's subtraction then cancels (skinA, skinB: 0 for plain shapes, whose skin is real).
void Write(const ContactManifold& m, b2Manifold* out, const b2Transform& xfA, const b2Transform& xfB, double skinA,
           double skinB, bool onB = false)
{
	out->pointCount = 0;
	if (m.count == 0)
		return;
	const b2Transform& reference = onB ? xfB : xfA;
	const b2Transform& incident = onB ? xfA : xfB;
	out->type = onB ? b2Manifold::e_faceB : b2Manifold::e_faceA;
	out->localNormal = b2MulT(reference.q, F(m.normal));
	out->localPoint = b2MulT(reference, F(m.pointA - (onB ? skinB : skinA) * m.normal));
	for (int k = 0; k < m.count; ++k)
	{
		b2ManifoldPoint& p = out->points[k];
		p.localPoint = b2MulT(incident, F(m.points[k].pointB + (onB ? skinA : skinB) * m.normal));
		p.normalImpulse = 0.0f;
		p.tangentImpulse = 0.0f;
		p.id.key = 0;
		p.id.cf.indexA = uint8(m.points[k].id);
		p.id.cf.typeA = b2ContactFeature::e_vertex;
	}
	out->pointCount = m.count;
}

// Analytic circles standing in for Box2D circle fixtures, one per radius for the whole process.
// A contact only borrows one: it must not own anything (see m_circle).
const Shape* CircleOfRadius(float radius)
{
	static std::mutex mutex;
	static std::map<float, ShapePtr> cache;
	std::lock_guard<std::mutex> lock(mutex);
	ShapePtr& circle = cache[radius];
	if (!circle)
		circle = MakeCircle(radius);
	return circle.get();
}

// Box2D polygon vertices (core, without skin) of a fixture's polygon.
int PolygonVertices(const b2PolygonShape* s, Vec2* v)
{
	for (int j = 0; j < s->m_count; ++j)
		v[j] = V(s->m_vertices[j]);
	return s->m_count;
}
} // namespace

static_assert(std::is_trivially_destructible<WarmStart>::value && std::is_trivially_destructible<ManifoldCache>::value,
              "Box2D does not run contact destructors when a world is destroyed");
// Box2D 2.4's block allocator serves blocks up to 640 bytes (b2_maxBlockSize, in
// b2_block_allocator.cpp); a larger contact would be a malloc and a free each.
static_assert(sizeof(AnalyticContact) <= 640, "AnalyticContact outgrew Box2D's largest block");

bool AnalyticContact::Install()
{
	static const bool done = [] {
		if (!s_initialized)
		{
			InitializeRegisters();
			s_initialized = true;
		}
		AddType(&Create<Kind::polygonPolygon>, &Destroy, b2Shape::e_polygon, b2Shape::e_polygon);
		AddType(&Create<Kind::polygonCircle>, &Destroy, b2Shape::e_polygon, b2Shape::e_circle);
		AddType(&Create<Kind::edgePolygon>, &Destroy, b2Shape::e_edge, b2Shape::e_polygon);
		AddType(&Create<Kind::chainPolygon>, &Destroy, b2Shape::e_chain, b2Shape::e_polygon);
		return true;
	}();
	return done;
}

AnalyticContact::AnalyticContact(b2Fixture* a, int32 indexA, b2Fixture* b, int32 indexB, Kind kind)
	: b2Contact(a, indexA, b, indexB), m_kind(kind)
{
	const AnalyticProxyShape* pa = AnalyticProxyShape::From(a->GetShape());
	const AnalyticProxyShape* pb = kind == Kind::polygonCircle ? nullptr : AnalyticProxyShape::From(b->GetShape());
	auto side = [](const AnalyticProxyShape* proxy) {
		Side s;
		if (proxy)
			s = Side{proxy->Data().shape.get(), proxy->Data().local, proxy->Data().shape->BoundingRadius(), proxy->m_radius};
		return s;
	};
	m_sideA = side(pa);
	m_sideB = side(pb);
	// Hearts against hearts or plain Box2D shapes hold across kNonConvexHoldGap; against a convex
	// particle (a Box2D circle included) across kContactHoldGap.
	auto convex = [](const Side& s) { return s.shape && s.shape->IsConvex(); };
	auto nonConvex = [](const Side& s) { return s.shape && !s.shape->IsConvex(); };
	m_nonConvex = (nonConvex(m_sideA) || nonConvex(m_sideB)) && !convex(m_sideA) && !convex(m_sideB) && kind != Kind::polygonCircle;
	if (pa && pb)
	{
		m_patchTolerance = std::min(pa->Data().patchTolerance, pb->Data().patchTolerance);
		m_patchMinWidth = std::min(pa->Data().patchMinWidth, pb->Data().patchMinWidth);
	}
	else if (pa || pb)
	{
		m_patchTolerance = (pa ? pa : pb)->Data().patchTolerance;
		m_patchMinWidth = (pa ? pa : pb)->Data().patchMinWidth;
	}
	if (pa)
		m_solver = &pa->Data().solver;
	if (kind == Kind::polygonCircle && pa)
	{
		const b2CircleShape* circle = static_cast<const b2CircleShape*>(b->GetShape());
		if (circle->m_radius > 0.0f)
			m_circle = CircleOfRadius(circle->m_radius);
	}
}

template <AnalyticContact::Kind kind>
b2Contact* AnalyticContact::Create(b2Fixture* a, int32 indexA, b2Fixture* b, int32 indexB, b2BlockAllocator* allocator)
{
	void* memory = allocator->Allocate(sizeof(AnalyticContact));
	return new (memory) AnalyticContact(a, indexA, b, indexB, kind);
}

void AnalyticContact::Destroy(b2Contact* contact, b2BlockAllocator* allocator)
{
	static_cast<AnalyticContact*>(contact)->~AnalyticContact();
	allocator->Free(contact, sizeof(AnalyticContact));
}

void AnalyticContact::EvaluatePlain(b2Manifold* manifold, const b2Transform& xfA, const b2Transform& xfB)
{
	const b2Shape* sa = m_fixtureA->GetShape();
	const b2Shape* sb = m_fixtureB->GetShape();
	switch (m_kind)
	{
	case Kind::polygonPolygon:
		b2CollidePolygons(manifold, static_cast<const b2PolygonShape*>(sa), xfA, static_cast<const b2PolygonShape*>(sb), xfB);
		break;
	case Kind::polygonCircle:
		b2CollidePolygonAndCircle(manifold, static_cast<const b2PolygonShape*>(sa), xfA, static_cast<const b2CircleShape*>(sb), xfB);
		break;
	case Kind::edgePolygon:
		b2CollideEdgeAndPolygon(manifold, static_cast<const b2EdgeShape*>(sa), xfA, static_cast<const b2PolygonShape*>(sb), xfB);
		break;
	case Kind::chainPolygon:
	{
		b2EdgeShape edge;
		static_cast<const b2ChainShape*>(sa)->GetChildEdge(&edge, m_indexA);
		b2CollideEdgeAndPolygon(manifold, &edge, xfA, static_cast<const b2PolygonShape*>(sb), xfB);
		break;
	}
	}
}

namespace
{
bool SameTransform(const b2Transform& x, const b2Transform& y)
{
	return std::memcmp(&x, &y, sizeof(b2Transform)) == 0;
}
} // namespace

AnalyticContact* AnalyticContact::FromAnalytic(b2Contact* contact)
{
	// The class is final: its exact type is what a dynamic_cast would accept, and the type
	// comparison costs a load and a compare where the cast walks the hierarchy (PrepareContacts
	// asks it of every contact of every step, on its serial path).
	if (!contact || typeid(*contact) != typeid(AnalyticContact))
		return nullptr;
	AnalyticContact* c = static_cast<AnalyticContact*>(contact);
	return c->m_sideA.shape || c->m_sideB.shape ? c : nullptr;
}

void AnalyticContact::Prepare()
{
	m_preparedA = m_fixtureA->GetBody()->GetTransform();
	m_preparedB = m_fixtureB->GetBody()->GetTransform();
	EvaluateAnalytic(&m_preparedManifold, m_preparedA, m_preparedB);
	m_prepared = true;
}

void AnalyticContact::Evaluate(b2Manifold* manifold, const b2Transform& xfA, const b2Transform& xfB)
{
	if (!m_sideA.shape && !m_sideB.shape)
	{
		EvaluatePlain(manifold, xfA, xfB);
		return;
	}
	// A manifold prepared at these very transforms is what the evaluation below would give
	// (Prepare ran it, warm start and patch cache included): use it once.
	const bool prepared = m_prepared && SameTransform(xfA, m_preparedA) && SameTransform(xfB, m_preparedB);
	m_prepared = false;
	if (prepared)
	{
		*manifold = m_preparedManifold;
		return;
	}
	EvaluateAnalytic(manifold, xfA, xfB);
}

const SolverOptions& AnalyticContact::Solver() const
{
	// A reference either way: a conditional between the member and a temporary would copy the
	// options at every evaluation.
	static constexpr SolverOptions kDefaults{};
	return m_solver ? *m_solver : kDefaults;
}

inline double AnalyticContact::HoldGap() const
{
	return m_nonConvex ? kNonConvexHoldGap : kContactHoldGap;
}

// (Forced inline: GCC keeps it out of line, and its call then takes the poses through memory at
// every evaluation.)
B2A_FORCE_INLINE
inline bool AnalyticContact::PairApart(const Pose& poseA, const Pose& poseB)
{
	// Bounding circles apart: no contact, and no solve. The tight AABBs of the broad phase
	// overlap for many pairs whose particles are apart (elongated ones especially).
	const Shape& shapeA = *m_sideA.shape;
	const Shape& shapeB = *m_sideB.shape;
	const double reach = m_sideA.radius + m_sideB.radius + (IsTouching() ? HoldGap() : 0.0);
	const Vec2 between = poseB.p - poseA.p;
	if (LengthSquared(between) > reach * reach)
	{
		m_wasTouching = false;
		return true;
	}
	// Separating axes before the solve: the last normal this contact found (the exact
	// separating direction then, and still one while the pair drifts apart or rests apart),
	// then the line between the centres. In a granular scene many of the pairs that reach
	// this point are apart, and most of them stop here. Their warm start is kept.
	// Not for a pair the last solve found touching: it almost always still touches, and then
	// both axes fail, after the exact support values wherever the shape's bounds are loose (a
	// superellipse n = 4 touches in its bounds' gap), at more cost than the few solves of
	// pairs that came apart. Such a pair's solve tells it as exactly (separation > 0: no
	// points).
	if (m_wasTouching)
		return false;
	if (m_hasNormal && SeparatedAlong(shapeA, poseA, shapeB, poseB, m_lastNormal))
		return true;
	const double distance = Length(between);
	return distance > 0.0 && SeparatedAlong(shapeA, poseA, shapeB, poseB, between / distance);
}

ContactResult AnalyticContact::PlainSideContact(const Pose& bodyA, const Pose& bodyB, ManifoldSide& sideA, ManifoldSide& sideB,
                                                double& radii, Vec2* vertices)
{
	if (m_sideA.shape && m_kind == Kind::polygonCircle)
	{
		// Analytic against a Box2D circle: the circle as an analytic circle at its centre, whose
		// pair the dispatch table decides as any other. Box2D subtracts the circle's radius
		// itself, so B's manifold point is the centre.
		if (!m_circle)
			return {};
		const b2CircleShape* circle = static_cast<const b2CircleShape*>(m_fixtureB->GetShape());
		const Pose poseA = Compose(bodyA, m_sideA.local);
		const Pose poseC(ToWorld(bodyB, V(circle->m_p)), bodyB.q);
		ContactResult c = ComputeContact(*m_sideA.shape, poseA, *m_circle, poseC, MethodChoice::automatic, Solver(), &m_warm);
		if (!c.Ok())
			return c;
		c.pointB = poseC.p;
		radii = circle->m_radius;
		sideA = {m_sideA.shape, poseA};
		sideB.point = true;
		return c;
	}
	// One analytic side against a Box2D polygon, edge or chain link: its core geometry's
	// vertices to the dispatch table's polygon column (ComputePolygonContact); Box2D adds the
	// skin radius.
	const bool analyticIsA = m_sideA.shape != nullptr;
	const Side& proxy = analyticIsA ? m_sideA : m_sideB;
	const b2Shape* sa = m_fixtureA->GetShape();
	const b2Shape* plain = analyticIsA ? m_fixtureB->GetShape() : sa;
	const Pose poseAnalytic = Compose(analyticIsA ? bodyA : bodyB, proxy.local);
	const Pose posePlain = analyticIsA ? bodyB : bodyA;
	int count = 0;
	if (m_kind == Kind::polygonPolygon)
	{
		count = PolygonVertices(static_cast<const b2PolygonShape*>(plain), vertices);
	}
	else
	{
		b2EdgeShape edge;
		if (m_kind == Kind::chainPolygon)
			static_cast<const b2ChainShape*>(sa)->GetChildEdge(&edge, m_indexA);
		else
			edge = *static_cast<const b2EdgeShape*>(sa);
		vertices[0] = V(edge.m_vertex1);
		vertices[1] = V(edge.m_vertex2);
		count = 2;
		if (edge.m_oneSided)
		{
			// One-sided edges (chain links) collide only with particles whose centroid lies on
			// their right side, as Box2D decides for its polygons (b2CollideEdgeAndPolygon). The
			// centroid, not the shape's origin: a heart's origin lies well below its centroid.
			const Vec2 e = vertices[1] - vertices[0];
			const Vec2 front(e.y, -e.x);
			const Vec2 centroid = ToWorld(poseAnalytic, proxy.shape->Mass().centroid);
			if (Dot(ToBody(posePlain, centroid) - vertices[0], front) < 0.0)
				return {};
		}
	}
	const Vec2* guess = m_hasNormal ? &m_lastNormal : nullptr;
	ContactResult c = ComputePolygonContact(*proxy.shape, poseAnalytic, vertices, count, posePlain, guess);
	if (!c.Ok())
		return c;
	m_lastNormal = c.normal;
	m_hasNormal = true;
	for (int j = 0; j < count; ++j)
		vertices[j] = ToWorld(posePlain, vertices[j]);
	radii = plain->m_radius;
	ManifoldSide analytic{proxy.shape, poseAnalytic};
	ManifoldSide polygon;
	polygon.vertices = vertices;
	polygon.count = count;
	if (analyticIsA)
	{
		sideA = analytic;
		sideB = polygon;
	}
	else
	{
		c = FlipContact(c);
		sideA = polygon;
		sideB = analytic;
	}
	return c;
}

void AnalyticContact::EvaluateAnalytic(b2Manifold* manifold, const b2Transform& xfA, const b2Transform& xfB)
{
	const Side& pa = m_sideA;
	const Side& pb = m_sideB;
	manifold->pointCount = 0;
	const Pose bodyA = ToPose(xfA), bodyB = ToPose(xfB);
	ManifoldSide sideA, sideB;
	double radii = 0.0;
	// The plain polygon's world vertices, for the polygon branch alone: left uninitialised (Vec2
	// zeroes itself), as most evaluations are of two analytic particles and never touch them.
	union VertexBuffer
	{
		VertexBuffer() {}
		Vec2 v[b2_maxPolygonVertices];
	} vertexBuffer;
	Vec2* const vertices = vertexBuffer.v;

	// Analytic against analytic: the contact core, warm-started from the last step, unless the
	// bounds part the pair first. Else one analytic side against a Box2D circle, polygon, edge or
	// chain link. The result is built in c itself (a returned prvalue, a conditional of two
	// initialises c directly): a result constructed first and assigned after cost its
	// construction and a copy at every evaluation.
	const bool pair = pa.shape && pb.shape;
	const Pose poseA = pair ? Compose(bodyA, pa.local) : bodyA, poseB = pair ? Compose(bodyB, pb.local) : bodyB;
	if (pair && PairApart(poseA, poseB))
		return;
	ContactResult c = pair ? ComputeContact(*pa.shape, poseA, *pb.shape, poseB, MethodChoice::automatic, Solver(), &m_warm)
	                       : PlainSideContact(bodyA, bodyB, sideA, sideB, radii, vertices);
	if (pair)
	{
		m_wasTouching = c.Ok() && c.separation <= HoldGap();
		if (c.Ok())
		{
			m_lastNormal = c.normal;
			m_hasNormal = true;
		}
		sideA = {pa.shape, poseA};
		sideB = {pb.shape, poseB};
	}
	if (!c.Ok())
		return; // a failed solve (never NaN) gives no contact this step
	// A non-convex particle against a face stands on its lobes (BuildContactManifold), found with
	// the face's side as the manifold's A: where that is the contact's B, the manifold is built
	// from B's side. (Which side is non-convex is fixed for the contact: its cache keeps its roles.)
	const bool fromB = sideA.shape && !sideA.shape->IsConvex() && !sideB.point && (!sideB.shape || sideB.shape->IsConvex());
	if (fromB)
		c = FlipContact(c);
	const ContactResult& oriented = c;
	// A contact that touched at the last step (b2Contact::Update still holds that flag while it
	// evaluates) and is now apart by at most the hold gap: its manifold is built as if the radii
	// were larger by the gap (faces and their ends as at touching, measured from the lifted
	// level), and Box2D, which measures separations from the points, sees the true, positive
	// gap: a face lifted by a fraction of a millimetre keeps its two points, as it would touching.
	// Box2D's velocity solver holds such a point at no approach and its position solver leaves
	// it alone (HoldGap; AnalyticFixture.h says why the contact is held).
	double held = 0.0;
	if (IsTouching())
	{
		const double gap = Dot(oriented.pointB - oriented.pointA, oriented.normal) - radii;
		if (gap > 0.0 && gap <= HoldGap())
			held = gap + 1e-12 * (1.0 + radii);
	}
	const ContactManifold m = fromB ? BuildContactManifold(oriented, sideB, sideA, m_patchTolerance, m_patchMinWidth, radii + held, &m_patch)
	                                : BuildContactManifold(oriented, sideA, sideB, m_patchTolerance, m_patchMinWidth, radii + held, &m_patch);
	Write(m, manifold, xfA, xfB, pa.skin, pb.skin, fromB);
}

} // namespace b2a

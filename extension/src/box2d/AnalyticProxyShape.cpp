// b2analytic: the proxy b2Shape of analytic fixtures: enclosing AABB, mass, point test, ray cast.
#include "box2d/AnalyticProxyShape.h"

#include "b2analytic/SurfaceQueries.h"
#include "numerics/FloatRounding.h"

#include <box2d/b2_block_allocator.h>
#include <box2d/b2_collision.h>

#include <cmath>
#include <cstring>
#include <new>
#include <typeinfo>

namespace b2a
{

namespace
{
// Tag in m_vertices[7]: two floats no polygon of ours ever has there.
const b2Vec2 kTag(-1.7014118e38f, 3.1415926e-30f);
} // namespace

AnalyticProxyShape::AnalyticProxyShape(AnalyticFixtureData* data)
{
	Store(data);
}

AnalyticProxyShape::AnalyticProxyShape(const AnalyticProxyShape& other) : b2PolygonShape(other)
{
	m_dataPointer()->references.fetch_add(1, std::memory_order_relaxed);
}

AnalyticProxyShape::~AnalyticProxyShape()
{
	AnalyticFixtureData* data = m_dataPointer();
	if (data->references.fetch_sub(1, std::memory_order_acq_rel) == 1)
		delete data;
}

void AnalyticProxyShape::Store(AnalyticFixtureData* data)
{
	std::memcpy(static_cast<void*>(&m_normals[7]), &data, sizeof(data));
	m_vertices[7] = kTag;
}

const AnalyticProxyShape* AnalyticProxyShape::From(const b2Shape* shape)
{
	if (!shape || shape->m_type != b2Shape::e_polygon)
		return nullptr;
	const b2PolygonShape* polygon = static_cast<const b2PolygonShape*>(shape);
	if (polygon->m_vertices[7].x != kTag.x || polygon->m_vertices[7].y != kTag.y)
		return nullptr;
	// The tag alone is not proof: a plain b2PolygonShape leaves slot 7 uninitialised, so one made
	// where a proxy lived before (CreateAnalyticFixture's on the stack, a freed block) can carry
	// the tag into its fixture's copy. The dynamic type decides (found by b2a_fuzz_world).
	if (typeid(*shape) != typeid(AnalyticProxyShape))
		return nullptr;
	return static_cast<const AnalyticProxyShape*>(shape);
}

b2Shape* AnalyticProxyShape::Clone(b2BlockAllocator* allocator) const
{
	// Same size as b2PolygonShape: Box2D frees it with that size.
	void* memory = allocator->Allocate(sizeof(b2PolygonShape));
	return new (memory) AnalyticProxyShape(*this);
}

Pose AnalyticProxyShape::WorldPose(const b2Transform& transform) const
{
	return Compose(ToPose(transform), Data().local);
}

bool AnalyticProxyShape::TestPoint(const b2Transform& transform, const b2Vec2& p) const
{
	return b2a::TestPoint(*Data().shape, WorldPose(transform), Vec2(p.x, p.y));
}

bool AnalyticProxyShape::RayCast(b2RayCastOutput* output, const b2RayCastInput& input, const b2Transform& transform, int32) const
{
	const RayHit hit = b2a::RayCast(*Data().shape, WorldPose(transform), Vec2(input.p1.x, input.p1.y),
	                                Vec2(input.p2.x, input.p2.y), input.maxFraction);
	if (!hit.hit)
		return false;
	output->fraction = float(hit.fraction);
	output->normal.Set(float(hit.normal.x), float(hit.normal.y));
	return true;
}

// How far a shape may turn from its anchor before ComputeAABB recomputes its exact box: the
// box grows by at most this on every side, 3 % of the margin by which Box2D fattens every proxy
// (b2_aabbExtension: 0.1 length units, 5 % of a 2 mm particle in the millimetre scenes), so the
// fat boxes and the pairs they make stay those of tight boxes to within that. (A tenth of the
// margin made 3 % more pairs in the packing scene for no fewer recomputations; docs/benchmarks.md.)
constexpr double kAnchorTurnFraction = 0.03;

void AnalyticProxyShape::ComputeAABB(b2AABB* aabb, const b2Transform& transform, int32) const
{
	AabbCache& cache = MutableData().box;
	if (cache.valid && std::memcmp(&transform, &cache.lastTransform, sizeof(b2Transform)) == 0)
	{
		*aabb = cache.lastBox;
		return;
	}
	const Pose pose = WorldPose(transform);
	if (cache.valid)
	{
		// A point x = a + Q u of the shape at the anchor (a, Q) is x' = a' + Q' u at the new pose,
		// x' − x = (a' − a) + (Q' − Q) u, and Q' − Q is the rotation-like matrix of (c' − c, s' − s),
		// whose norm is the length of that difference (2 |sin(Δθ/2)| ≤ |Δθ|). So the anchor's box
		// moved by a' − a and widened by |q' − q|·max|u| on every side holds the shape: no
		// support, no shape data. The sums carry a relative rounding of a few 1e-16, covered by
		// `rounding`, and round outwards to float.
		const Vec2 shift = pose.p - cache.anchor.p;
		const double dc = pose.q.c - cache.anchor.q.c, ds = pose.q.s - cache.anchor.q.s;
		const double turn = std::sqrt(dc * dc + ds * ds) * cache.radius;
		if (turn <= kAnchorTurnFraction * b2_aabbExtension)
		{
			const b2AABB& a = cache.anchorBox;
			const double size = std::fabs(a.lowerBound.x) + std::fabs(a.lowerBound.y) + std::fabs(a.upperBound.x) +
			                    std::fabs(a.upperBound.y) + std::fabs(shift.x) + std::fabs(shift.y) + cache.radius;
			const double widen = turn + 1e-14 * size;
			aabb->lowerBound.Set(FloatBelow(a.lowerBound.x + shift.x - widen), FloatBelow(a.lowerBound.y + shift.y - widen));
			aabb->upperBound.Set(FloatAbove(a.upperBound.x + shift.x + widen), FloatAbove(a.upperBound.y + shift.y + widen));
			cache.lastTransform = transform;
			cache.lastBox = *aabb;
			return;
		}
	}
	// The tight box of the true shape, rounded outward to float; the new anchor.
	const Shape& shape = *Data().shape;
	const Box box = shape.ComputeAABB(pose);
	aabb->lowerBound.Set(FloatBelow(box.lower.x), FloatBelow(box.lower.y));
	aabb->upperBound.Set(FloatAbove(box.upper.x), FloatAbove(box.upper.y));
	cache.anchor = pose;
	cache.anchorBox = *aabb;
	// The bounding radius is a maximum found by a Brent search (Shape::Finalize): a relative 1e-9
	// above it covers that search's tolerance.
	cache.radius = shape.BoundingRadius() * (1.0 + 1e-9);
	cache.lastTransform = transform;
	cache.lastBox = *aabb;
	cache.valid = true;
}

b2MassData AnalyticMassData(const Shape& shape, const Pose& local, float density)
{
	// Mass properties about the body origin: the centroid moves with the local pose; the polar
	// moment about the centroid is invariant under the local rotation (parallel-axis theorem).
	const MassProperties& mp = shape.Mass();
	const Vec2 centre = ToWorld(local, mp.centroid);
	b2MassData m;
	m.mass = float(density * mp.area);
	m.center.Set(float(centre.x), float(centre.y));
	m.I = float(density * (mp.polarMoment + mp.area * LengthSquared(centre)));
	return m;
}

void AnalyticProxyShape::ComputeMass(b2MassData* massData, float density) const
{
	*massData = AnalyticMassData(*Data().shape, Data().local, density);
}

} // namespace b2a

// b2analytic: the proxy b2Shape of analytic fixtures: exact AABB, mass, point test and ray cast.
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

AnalyticFixtureData* AnalyticProxyShape::m_dataPointer() const
{
	AnalyticFixtureData* data = nullptr;
	std::memcpy(&data, static_cast<const void*>(&m_normals[7]), sizeof(data));
	return data;
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

void AnalyticProxyShape::ComputeAABB(b2AABB* aabb, const b2Transform& transform, int32) const
{
	AnalyticFixtureData& data = MutableData();
	if (data.hasLastBox && std::memcmp(&transform, &data.lastTransform, sizeof(b2Transform)) == 0)
	{
		*aabb = data.lastBox; // (a heart's box is four supports)
		return;
	}
	// The tight box of the true shape, rounded outwards to float.
	const Box box = data.shape->ComputeAABB(WorldPose(transform));
	aabb->lowerBound.Set(FloatBelow(box.lower.x), FloatBelow(box.lower.y));
	aabb->upperBound.Set(FloatAbove(box.upper.x), FloatAbove(box.upper.y));
	data.lastTransform = transform;
	data.lastBox = *aabb;
	data.hasLastBox = true;
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

// b2analytic: the b2Shape an analytic fixture carries (internal to the adapter).
#pragma once

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/Box2DConversions.h"

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <atomic>
#include <cstring>

namespace b2a
{

/// What ComputeAABB keeps between calls, in one cache line: Box2D asks each moving body's
/// fixtures for the boxes at its last and new transforms every step (b2Fixture::Synchronize), so
/// the last is asked again (`lastTransform`, `lastBox`); and the exact box at an anchor pose,
/// from which a box at a nearby pose follows without the shape (see ComputeAABB).
struct alignas(64) AabbCache
{
	// First cache line: what every call reads.
	b2Transform lastTransform;
	b2AABB lastBox;
	b2AABB anchorBox;    ///< the shape's tight box at `anchor`, rounded outwards to float
	double radius = 0.0; ///< an upper bound on |x| over the shape in its own frame
	bool valid = false;
	// Second: the anchor itself.
	Pose anchor; ///< world pose of the shape where `anchorBox` was computed
};

/// What an analytic fixture knows beyond Box2D: shared by the fixture's shape and every copy of
/// it, counted, and released with the last copy (fixture destruction, body destruction and
/// world destruction all destroy the fixture's shape).
struct AnalyticFixtureData
{
	std::atomic<int> references{1};
	ShapePtr shape;
	Pose local;
	double patchTolerance = 0.0;
	double patchMinWidth = 0.0; // absolute: the fraction times the bounding radius
	SolverOptions solver;
	/// The broad phase's box cache (ComputeAABB). Box2D calls it from its own thread only (never
	/// from PrepareContacts').
	AabbCache box;
};

/// A b2PolygonShape whose virtual functions answer for the analytic shape, and whose vertices
/// with its skin radius (b2_polygonRadius, as Box2D's polygons) make a rounded polygon inside it
/// (for Box2D's time of impact and sensors). Box2D subtracts that skin from manifold
/// separations; the contact adds it back (see AnalyticContact).
///
/// Box2D frees a fixture's polygon with sizeof(b2PolygonShape), so this class adds no data
/// member: it keeps its data pointer in m_normals[7], a slot Box2D never reads because the
/// proxy has at most 7 vertices, and a tag in m_vertices[7] to recognise itself.
class AnalyticProxyShape final : public b2PolygonShape
{
public:
	/// Most vertices of the inscribed proxy polygon (slot 7 holds the data).
	static constexpr int kMaxProxyVertices = 7;

	/// A proxy for `data`, taking over the caller's reference.
	explicit AnalyticProxyShape(AnalyticFixtureData* data);
	/// Copy, sharing (and counting) the data.
	AnalyticProxyShape(const AnalyticProxyShape& other);
	AnalyticProxyShape& operator=(const AnalyticProxyShape&) = delete;
	~AnalyticProxyShape() override;

	b2Shape* Clone(b2BlockAllocator* allocator) const override;
	int32 GetChildCount() const override { return 1; }
	bool TestPoint(const b2Transform& transform, const b2Vec2& p) const override;
	bool RayCast(b2RayCastOutput* output, const b2RayCastInput& input, const b2Transform& transform, int32 childIndex) const override;
	void ComputeAABB(b2AABB* aabb, const b2Transform& transform, int32 childIndex) const override;
	void ComputeMass(b2MassData* massData, float density) const override;

	/// The shared analytic data.
	const AnalyticFixtureData& Data() const { return *m_dataPointer(); }
	/// The same, for the box cache.
	AnalyticFixtureData& MutableData() const { return *m_dataPointer(); }
	/// World pose of the analytic shape for a body transform.
	Pose WorldPose(const b2Transform& transform) const;
	/// The proxy if `shape` is one, else null.
	static const AnalyticProxyShape* From(const b2Shape* shape);

private:
	AnalyticFixtureData* m_dataPointer() const;
	void Store(AnalyticFixtureData* data);
};

inline AnalyticFixtureData* AnalyticProxyShape::m_dataPointer() const
{
	// Inline: ComputeAABB reads it for every fixture twice a step.
	AnalyticFixtureData* data = nullptr;
	std::memcpy(&data, static_cast<const void*>(&m_normals[7]), sizeof(data));
	return data;
}

static_assert(sizeof(AnalyticProxyShape) == sizeof(b2PolygonShape), "Box2D frees shapes with the base class size");
static_assert(sizeof(void*) <= sizeof(b2Vec2), "the data pointer must fit in one b2Vec2 slot");

/// Box2D's mass data of `shape` placed at `local` in its body's frame with `density`: what the
/// proxy's ComputeMass gives (CreateAnalyticFixture checks it before Box2D sees it).
b2MassData AnalyticMassData(const Shape& shape, const Pose& local, float density);

/// Composition: body pose times a local pose.
inline Pose Compose(const Pose& body, const Pose& local)
{
	return Pose(ToWorld(body, local.p), Mul(body.q, local.q));
}

} // namespace b2a

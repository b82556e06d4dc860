// b2analytic: the b2Contact that replaces Box2D's narrow phase (internal to the adapter).
#pragma once

#include "b2analytic/ContactManifold.h"
#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"

#include <box2d/b2_contact.h>

namespace b2a
{

/// Box2D's contact for (polygon, polygon), (polygon, circle), (edge, polygon) and (chain,
/// polygon) pairs, registered in place of Box2D's own. Pairs of plain shapes call exactly the
/// collision function Box2D's contact would; pairs with an analytic fixture get the analytic
/// contact as a b2Manifold (type e_faceA, one or two points, stable ids).
class AnalyticContact final : public b2Contact
{
public:
	/// Which of Box2D's contact types this one stands in for.
	enum class Kind
	{
		polygonPolygon,
		polygonCircle,
		edgePolygon,
		chainPolygon
	};

	/// Register with Box2D (idempotent). Runs before main(); calling it again is harmless.
	static bool Install();

	void Evaluate(b2Manifold* manifold, const b2Transform& xfA, const b2Transform& xfB) override;

	/// The contact if `contact` is one of ours with an analytic fixture, else null.
	static AnalyticContact* FromAnalytic(b2Contact* contact);
	/// Computes the manifold at the bodies' current transforms and keeps it for the next
	/// Evaluate at the same transforms (ParallelContacts.h). Touches only this contact and
	/// read-only shared data, so different contacts may be prepared on different threads.
	void Prepare();

private:
	AnalyticContact(b2Fixture* a, int32 indexA, b2Fixture* b, int32 indexB, Kind kind);
	template <Kind kind>
	static b2Contact* Create(b2Fixture* a, int32 indexA, b2Fixture* b, int32 indexB, b2BlockAllocator* allocator);
	static void Destroy(b2Contact* contact, b2BlockAllocator* allocator);

	// The plain Box2D path, exactly as Box2D's own contact classes do it.
	void EvaluatePlain(b2Manifold* manifold, const b2Transform& xfA, const b2Transform& xfB);
	// The analytic path (at least one analytic fixture).
	void EvaluateAnalytic(b2Manifold* manifold, const b2Transform& xfA, const b2Transform& xfB);
	// Two analytic particles at these poses parted by their bounding circles or a separating
	// axis (then no solve); where the circles part them, the contact no longer touches.
	bool PairApart(const Pose& poseA, const Pose& poseB);
	// One analytic side against a plain circle, polygon, edge or chain link: the contact, the
	// manifold's sides and radii, the plain polygon's world vertices in `vertices`; a failed
	// result where there is none.
	ContactResult PlainSideContact(const Pose& bodyA, const Pose& bodyB, ManifoldSide& sideA, ManifoldSide& sideB, double& radii,
	                               Vec2* vertices);

	// An analytic fixture's data as the contact needs it, copied when Box2D creates the contact:
	// a fixture's analytic data never changes and outlives its contacts, and reading it through
	// fixture, proxy shape and data block cost a cache miss per side on every step.
	struct Side
	{
		const Shape* shape = nullptr; // null: a plain Box2D shape
		Pose local;                   // the shape's pose in its body
		double radius = 0.0;          // its bounding radius
		double skin = 0.0;            // the proxy polygon's skin (b2_polygonRadius)
	};

	// The small members first, packed together: the contact must fit Box2D's largest block.
	Kind m_kind;
	bool m_hasNormal = false;    // m_lastNormal is set
	bool m_wasTouching = false;  // the last solve found the analytic pair touching (then no separating-axis tests)
	bool m_prepared = false;     // m_preparedManifold holds a manifold computed ahead of the step (Prepare)
	bool m_nonConvex = false;    // a heart against a heart or a plain shape: it holds across kNonConvexHoldGap
	// How far apart a touching contact may drift and stay touching (AnalyticFixture.h).
	double HoldGap() const;
	// A's solver options, or the defaults where A is a plain shape.
	const SolverOptions& Solver() const;
	Side m_sideA, m_sideB;
	double m_patchTolerance = 0.0, m_patchMinWidth = 0.0; // the analytic sides' (the smaller of two)
	// A's solver options, where A is analytic (its fixture's data, which outlives the contact;
	// a pointer, not a copy: the contact must fit Box2D's largest block).
	const SolverOptions* m_solver = nullptr;
	WarmStart m_warm;       // Newton's previous solution (analytic pairs)
	Vec2 m_lastNormal;      // previous normal, world (a guess against polygons, a separating axis to try between analytic particles)
	// Box2D frees contacts without running their destructors when a world is destroyed, so
	// every member here must be trivially destructible: the circle is borrowed from a cache.
	const Shape* m_circle = nullptr; // the analytic circle standing in for a Box2D circle fixture
	ManifoldCache m_patch;  // the faces last step's manifold found (BuildContactManifold)
	// A manifold computed ahead of the step (Prepare) and the transforms it belongs to.
	b2Transform m_preparedA, m_preparedB;
	b2Manifold m_preparedManifold;
};

} // namespace b2a

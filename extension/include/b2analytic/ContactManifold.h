// b2analytic: the points a contact solver needs: one, or two on a flat patch.
#pragma once

#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"

namespace b2a
{

/// One side of a contact: a convex analytic shape at a pose, or a convex polygon (count ≥ 3) or
/// segment (count = 2) in world coordinates. Anything else (a circle, a non-convex shape) is
/// `point` and never widens the patch.
struct ManifoldSide
{
	const Shape* shape = nullptr; ///< analytic shape, or null
	Pose pose;                    ///< pose of the analytic shape
	const Vec2* vertices = nullptr; ///< world vertices of a polygon or segment, or null
	int count = 0;                ///< number of vertices
	bool point = false;           ///< a side that only ever touches at one point
};

/// A point of a manifold: where B's surface is, and the separation from A's tangent plane.
struct ManifoldPoint
{
	Vec2 pointB;             ///< point on B's surface (world)
	double separation = 0.0; ///< (pointB − pointA)·normal − radii, ≤ 0 for every reported point
	int id = 0;              ///< 0 for the single point or the lower end of a patch, 1 for its upper end
};

/// A contact in the form Box2D's solver takes: one normal, one point on A (its tangent plane)
/// and one or two points on B.
struct ContactManifold
{
	Vec2 normal;         ///< unit normal from A to B
	Vec2 pointA;         ///< point on A's surface: A's tangent plane passes through it
	int count = 0;       ///< 0 (apart), 1 or 2
	ManifoldPoint points[2]; ///< the points
};

/// Where the flat stretches of a contact ended last time (polar angles in each shape's body
/// frame), so that the next step's search starts there. Keep one per persistent contact.
struct ManifoldCache
{
	double endsA[2] = {0.0, 0.0};   ///< ends of A's stretch
	double endsB[2] = {0.0, 0.0};   ///< ends of B's stretch
	double slopesA[2] = {0.0, 0.0}; ///< d(depth − tol)/d(angle) at A's ends (0: none), for the next step's secant
	double slopesB[2] = {0.0, 0.0}; ///< the same at B's ends
	bool validA = false;            ///< endsA holds a previous answer
	bool validB = false;            ///< endsB holds a previous answer
};

/// Build the manifold of a contact. Two particles that touch along a flat stretch (blocky
/// superellipses side by side, or on a floor) must get two points with one normal, as Box2D's
/// boxes do, or stacks rock and creep. The stretch ("patch") is where both surfaces lie within
/// `patchTolerance` of their extreme along the normal: the arc of A around its support point along
/// +normal and of B along −normal (a polygon's face, for a polygon). Where the two stretches
/// overlap along the tangent by more than `minPatchWidth`, the manifold has the overlap's two
/// ends (B's surface points there); otherwise it has the contact's own pointB. Curved contacts
/// (ellipses) stay single points: their stretch within the tolerance is narrow (about
/// 2·√(2ρ·tolerance) for a radius of curvature ρ), and two points there would hold up an
/// ellipse balanced on another that physics says must roll off. `radii` (Box2D skin
/// radii of non-analytic sides) is subtracted from every separation, and only points with
/// separation ≤ 0 are reported (Box2D 2.4 has no speculative contacts: a gap would hover).
ContactManifold BuildContactManifold(const ContactResult& contact, const ManifoldSide& a, const ManifoldSide& b,
                                     double patchTolerance, double minPatchWidth, double radii = 0.0,
                                     ManifoldCache* cache = nullptr);

} // namespace b2a

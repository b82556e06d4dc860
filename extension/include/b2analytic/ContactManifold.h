// b2analytic: the points a contact solver needs: one, or two on a flat patch.
#pragma once

#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"

#include <limits>

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
	/// 0 for the single point or the lower end of a patch, 1 for its upper end; a non-convex
	/// pair's lobes and parts of the overlap keep theirs while they last (0 to 3, ManifoldCache)
	int id = 0;
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

/// The faces a contact found last time (polar angles in each shape's body frame: the face's
/// flattest point, then its two ends), so that the next step takes them again without a search
/// while the contact stays on them; and where the contact was on none. Keep one per persistent
/// contact.
struct ManifoldCache
{
	double faceA[3] = {0.0, 0.0, 0.0}; ///< A's face
	double faceB[3] = {0.0, 0.0, 0.0}; ///< B's face
	/// Polar angle of A's contact point where it was found on no face (NaN: none): no search
	/// until the point has moved 0.01 rad from it.
	double offFaceA = std::numeric_limits<double>::quiet_NaN();
	double offFaceB = std::numeric_limits<double>::quiet_NaN(); ///< the same for B
	bool validA = false;               ///< faceA holds a face
	bool validB = false;               ///< faceB holds a face
	/// A's contact point lay on faceA at the last step: it stays on it until it lies farther than
	/// twice the tolerance from the face's tangent plane (hysteresis at the face's ends).
	bool onA = false;
	bool onB = false; ///< the same for B
	/// Points of a non-convex pair's last manifold (lobes on a face, or two parts of the overlap),
	/// whose ids the next manifold's points take by nearness: partCount of them.
	signed char partCount = 0;
	signed char partId[2] = {0, 1}; ///< their ids
	/// Their places on B's surface (B's body frame; a part's manifold point lies along the normal
	/// from its place, as far as the parts' plane is from it).
	float partB[2][2] = {{0.0f, 0.0f}, {0.0f, 0.0f}};
};

/// Build the manifold of a contact, as Box2D builds its polygons': two particles that touch face
/// to face (blocky superellipses side by side, on a floor, or offset by half their width as in
/// a pyramid or a wall) get two points with one normal, or stacks rock, creep and sag. A face is
/// a polygon's edge, or the arc of an analytic particle around a point whose radius of curvature
/// exceeds ten bounding radii (a blocky superellipse's side; not a circle, nor an ellipse of
/// aspect below ten), within `patchTolerance` of the tangent there: it belongs to the body (with
/// `cache`, a contact point that lay on its face at the last step stays on it while it lies
/// within twice the tolerance of the face's tangent plane, where both sides are convex). Where
/// both contact points lie on faces, A's face is the reference: the normal is its normal, and
/// where the two faces' extents along it overlap by more than max(2·patchTolerance,
/// minPatchWidth), the points are B's surface at the overlap's two ends (ids 0 and 1), those at
/// or below A's face plane (a tilted face lifts one end: the other alone), with their
/// separations from that plane, as Box2D measures a box's points against its reference face.
/// Otherwise, and where neither end touches, the manifold is the contact's own normal, pointA
/// and pointB (id 0): a curved contact keeps one point, as two on a curved surface would make a
/// foot and hold up an ellipse balanced on another that physics says must roll off.
/// Analytic particles with corners or infinite curvature on their axes (superellipse exponents
/// below 2) have no curvature to tell faces by: their face is the arc within the tolerance of
/// their extreme along the contact normal. `radii` (Box2D skin radii of non-analytic sides) is
/// subtracted from every separation, and only points with separation ≤ 0 are reported (Box2D 2.4
/// has no speculative contacts: a gap would hover).
ContactManifold BuildContactManifold(const ContactResult& contact, const ManifoldSide& a, const ManifoldSide& b,
                                     double patchTolerance, double minPatchWidth, double radii = 0.0,
                                     ManifoldCache* cache = nullptr);

} // namespace b2a

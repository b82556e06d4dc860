// b2analytic: the parts of two particles' overlap, for non-convex pairs' manifolds (internal).
#pragma once

#include "b2analytic/Shape.h"

namespace b2a
{

/// One connected part of the overlap of two particles: the deepest point of one particle's
/// surface inside the other, the other's outward normal there turned to point from A to B, and
/// the separation along it (negative).
struct OverlapPart
{
	Vec2 pointA, pointB, normal;
	double separation = 0.0;
};

/// A part that the caller discards: one whose point on inner's surface (world) lies within
/// `within` of `point` (the contact's own part, which the manifold already holds).
struct OverlapSkip
{
	Vec2 point;           ///< world point on inner's surface
	double within = 0.0;  ///< parts whose inner point lies at most this far from it are discarded
};

/// The parts of the overlap that the surface of `inner` shows inside `outer` (world): each local
/// minimum of outer's level along a run of inner's cached surface samples inside outer is one
/// part, refined between its neighbours (Brent's method on the polar angle, to 1e-10 rad). The
/// normal is outer's gradient there, or, between two non-convex particles, that and inner's
/// own normal weighted so that a corner of either (a heart's tip) gives way to the other's;
/// the depth is the distance along it to outer's surface.
/// `outerIsA` says which side outer is, for the normal's sense (from A to B) and the points. At
/// most `max` parts, the deepest kept; none where inner lies wholly inside outer.
///
/// Two shortcuts, neither changing what the caller keeps: with `fast`, outer's level is
/// evaluated only at the samples of runs whose disc outer's level bound (Shape::Bounds) does
/// not put at or above its surface (the others are outside, and their levels stand as +∞, which
/// orders them as their own would against any sample inside); and a part that `skip` names is
/// not refined where it surely lies within skip->within (its sample's arcs, widened by their
/// measured deviation, all do) and no more than `max` parts were found (so that it takes no
/// other part's place). `fast` false: every sample evaluated and every part refined.
int OverlapParts(const Shape& outer, const Pose& po, const Shape& inner, const Pose& pi, bool outerIsA, OverlapPart* out, int max,
                 const OverlapSkip* skip = nullptr, bool fast = true);

} // namespace b2a

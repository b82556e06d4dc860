// b2analytic: the contact between two posed shapes, dispatched per shape pair.
#pragma once

#include "b2analytic/CommonLevel.h"
#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"

namespace b2a
{

/// A contact function of the dispatch table. `warm` may be null.
using ContactFunction = ContactResult (*)(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                          const SolverOptions& options, WarmStart* warm);

/// The contact between A and B (see ContactResult for its meaning).
///  - automatic: the dispatch table: closed form for circle pairs; Perram and Wertheim's
///    one-dimensional form for ellipse pairs (EllipseContact); Newton on the common level
///    (warm-started from `warm`) with the min–max fallback for smooth, strictly convex pairs;
///    the grid method with refinement (GridContact) for non-smooth or non-convex shapes.
///  - newton: the common level by Newton alone (fails for shapes it cannot handle).
///  - grid: the grid method (GridContact) for any pair.
/// Coincident centres (no level point between them) get the axis of least overlap.
ContactResult ComputeContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                             MethodChoice method = MethodChoice::automatic, const SolverOptions& options = {},
                             WarmStart* warm = nullptr);

/// The contact built from a level solution. The normal is the mean of A's outward and B's
/// inward unit normals at the point (they agree at a tangency); where the point is a corner of
/// one shape (a heart's tip) the other's normal; and where both normals point the same way (one
/// centre inside the other) B's inward normal, with `pointOnB` saying the point lies on B's
/// surface (the grid method; `level.level` is then A's level at the point, as
/// SolveGridScale gives it). pointA is A's extreme point along the normal on the line through
/// the point, pointB is B's extreme point against it (or, where the line misses a far-away
/// particle, the surface point towards the level point), and the separation is measured along
/// the normal between them. `touching` is the level solve's verdict; where rounding makes the
/// separation's sign disagree with it (|separation| at rounding level), the separation is
/// reported as 0 or the smallest positive double.
ContactResult ContactFromLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const LevelResult& level,
                               bool touching, bool pointOnB = false);

/// The same contact seen from the other side: normal flipped, points swapped.
ContactResult FlipContact(const ContactResult& c);

/// Replace the dispatch table's entry for a pair of families (and the flipped entry, through
/// FlipContact). Call before any contact is computed; not thread-safe against running solves.
void RegisterContactFunction(ShapeFamily a, ShapeFamily b, ContactFunction function);

/// The dispatch table's current entry (for tests and tools).
ContactFunction GetContactFunction(ShapeFamily a, ShapeFamily b);

/// The table's building blocks, usable in a user's own registrations.
/// Closed form for two circles.
ContactResult CircleContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// Two plain ellipses (or an ellipse and a circle): Perram and Wertheim's one-dimensional
/// common level, points in closed form; the same answer as ConvexContact, sooner. Other shapes
/// and the rare cases it does not handle go to ConvexContact.
ContactResult EllipseContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// Two smooth superellipses (n, m ≥ 2, or one of them an ellipse or circle): the common level by
/// Newton with the levels evaluated inline; the same answer as ConvexContact, sooner. With
/// integer exponents the last Newton steps (all of them from a warm start) run on the raw levels
/// |x/a|^n + |y/b|^m, without the gauge's roots, and the points come from Halley steps along the
/// normal. Other shapes and the rare cases it does not finish go to ConvexContact.
ContactResult SuperellipseContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// Common level (Newton + min–max fallback) for smooth convex shapes; grid otherwise.
ContactResult ConvexContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// Which one-sided grid solves GridContact runs: one particle rescaled onto the other's surface
/// (its samples), or both ways.
enum class GridSide
{
	aOntoB,  ///< A rescaled onto B's surface
	bOntoA,  ///< B rescaled onto A's surface
	bothWays ///< both, the touching (else the deeper or nearer) answer taken
};

/// GridContact's choice, symmetric in A and B (swapping them swaps aOntoB and bOntoA). One side
/// decides whether the pair overlaps, exactly, when the rescaled particle's centre lies outside
/// the other (then it cannot lie inside the other, and it meets the other exactly where the
/// other's surface enters it, the other inside it included). Of two particles more than twice
/// the other's size the larger is rescaled (the samples must be dense against it); of similar
/// ones a convex particle before a non-convex one (its level is the cheaper and its bounds the
/// tighter), else the one whose centre lies deeper in the other's level (relative to its
/// surface level), ties by pose; the other side where that centre lies inside, and both ways
/// where each centre lies inside the other.
GridSide ChooseGridSide(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb);

/// The grid method with refinement, for any shapes: on the side ChooseGridSide picks, and both
/// ways where it picks both or where that side's answer fails a check (the rescaled particle
/// deep in the other, or a gap along the normal unlike the gap from the point to its surface:
/// a line that crossed a non-convex particle far from the point).
ContactResult GridContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);

} // namespace b2a

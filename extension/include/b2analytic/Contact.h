// b2analytic: the contact between two posed shapes, dispatched per pair of shape kinds.
#pragma once

#include "b2analytic/CommonLevel.h"
#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"
#include "b2analytic/ShapeKind.h"

namespace b2a
{

/// A contact function of the dispatch table. `warm` may be null. A function registered for a
/// pair of kinds is final for it: ComputeContact calls it for every pair of shapes of those
/// kinds, and nothing else decides.
using ContactFunction = ContactResult (*)(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                          const SolverOptions& options, WarmStart* warm);

/// The contact between A and B (see ContactResult for its meaning).
///  - automatic: the dispatch table's cell for the shapes' kinds (Shape::Kind): closed form for
///    circle pairs (CircleContact); Perram and Wertheim's one-dimensional form for ellipse pairs
///    (EllipseContact); the inline Newton for smooth superellipses (SuperellipseContact); Newton
///    on the common level (warm-started from `warm`) with the min–max fallback for other smooth,
///    strictly convex pairs (NewtonContact); the grid method with refinement (GridContact) for
///    non-smooth or non-convex shapes; a registered function where there is one.
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

/// Register `function` as the contact function of the pair of 2D kinds (a, b), in that order:
/// pairs (b, a) call it with the shapes swapped and flip its answer (FlipContact), without the
/// warm start. It replaces the cell's function (a built-in one, or the default by the kinds'
/// solver classes). Call before contacts of the pair are computed; not synchronised with
/// solves running on other threads. Throws InvalidParameter naming the field for a kind that
/// is not a registered 2D kind ('a', 'b') or a null function ('function').
void RegisterContactFunction(ShapeKind a, ShapeKind b, ContactFunction function);

/// The dispatch table's contact function for (a, b): the registered one (which may be stored for
/// (b, a) and called flipped), else the default by solver classes. Throws as
/// RegisterContactFunction for kinds that are not registered 2D kinds.
ContactFunction GetContactFunction(ShapeKind a, ShapeKind b);

/// The table's building blocks, usable in a user's own registrations. Each is a chain: its
/// solver, and the fixed fallback where that gives up; coincident centres (no level point
/// between them) get the axis of least overlap.
/// Closed form for two circles.
ContactResult CircleContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// Two plain ellipses (or an ellipse and a circle, kinds ellipse and circle): Perram and
/// Wertheim's one-dimensional common level, points in closed form; the same answer as
/// NewtonContact, sooner. Where it does not finish (and for shapes other than SuperellipseShape's
/// ellipses), the contact of the ellipse-pair level, then Newton's chain.
ContactResult EllipseContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// Two smooth superellipses on the raw level (kinds superellipse, ellipse, circle): the common
/// level by Newton with the levels evaluated inline; the same answer as NewtonContact, sooner.
/// With integer exponents the last Newton steps (all of them from a warm start) run on the raw
/// levels |x/a|^n + |y/b|^m, without the gauge's roots, and the points come from Halley steps
/// along the normal. Where it does not finish (and for the ζ-form), NewtonContact's chain.
ContactResult SuperellipseContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// Smooth, strictly convex pairs: the common level by Newton from the warm start, from the
/// geometric start where that fails, by min–max where both fail; the contact from the level.
ContactResult NewtonContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// By the shapes' own flags: NewtonContact for two smooth convex shapes, GridContact otherwise
/// (what the table's default cells give for kinds of those solver classes).
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

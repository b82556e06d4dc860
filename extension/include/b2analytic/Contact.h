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
///  - automatic: the dispatch table: closed form for circle pairs; Newton on the common level
///    (warm-started from `warm`) with the min–max fallback for smooth, strictly convex pairs;
///    the grid method with refinement, run both ways, for non-smooth or non-convex shapes.
///  - newton: the common level by Newton alone (fails for shapes it cannot handle).
///  - grid: the grid method both ways for any pair.
/// Coincident centres (no level point between them) get the axis of least overlap.
ContactResult ComputeContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                             MethodChoice method = MethodChoice::automatic, const SolverOptions& options = {},
                             WarmStart* warm = nullptr);

/// The contact built from a level solution: normal from the unit level gradients at the point
/// (the average of ∇λA/|∇λA| and −∇λB/|∇λB|, which agree at a tangency), points where the line
/// through the point along the normal meets each surface, separation along the normal.
/// `touching` is the level solve's verdict; where rounding makes the separation's sign disagree
/// with it (|separation| at rounding level), the separation is reported as 0 or the smallest
/// positive double.
ContactResult ContactFromLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const LevelResult& level,
                               bool touching);

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
/// Common level (Newton + min–max fallback) for smooth convex shapes; grid otherwise.
ContactResult ConvexContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);
/// Grid method both ways with refinement, for any shapes.
ContactResult GridContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options, WarmStart* warm);

} // namespace b2a

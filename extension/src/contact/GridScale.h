// b2analytic: the grid method's one-sided solve, handing back what the contact needs again (internal).
#pragma once

#include "b2analytic/CommonLevel.h"

namespace b2a
{

/// SolveGridScale, writing A's body-frame gradient at the answer's point into *bodyGradientA
/// (when the solve succeeds): the solve computes it for the normal, and the grid's contact
/// needs it again for its normal, its crossing and its one-side test.
LevelResult SolveGridScale(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                           double levelB, Vec2* bodyGradientA);

} // namespace b2a

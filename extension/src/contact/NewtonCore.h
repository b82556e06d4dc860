// b2analytic: the Newton iteration shared by the common-level solvers (internal).
#pragma once

#include "b2analytic/ContactResult.h"
#include "contact/PairFrame.h"

namespace b2a
{

/// Newton–Raphson on the common level from (ξ, m = log μ) in a PairFrame; `level` is λA there.
LevelResult RunNewton(const PairFrame& frame, Vec2 xi, double m, const SolverOptions& options);

/// The point between the centres where ψA = ψB, and μ balancing the gradients there.
/// Returns false when the centres coincide.
bool GeometricStart(const PairFrame& frame, Vec2& xi, double& mu);

} // namespace b2a

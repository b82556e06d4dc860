// b2analytic: the Newton iteration shared by the common-level and one-sided solvers (internal).
#pragma once

#include "b2analytic/ContactResult.h"
#include "contact/PairFrame.h"

namespace b2a
{

/// What the third equation of the Newton system holds fixed.
enum class NewtonMode
{
	common,  ///< ψA − ψB = 0, multiplier μ = e^m > 0
	oneSided ///< ψB − ψB(own) = 0, multiplier μ = m of either sign (B held at its surface)
};

/// Newton–Raphson from (ξ, m) in a PairFrame; `level` is λA at the answer.
LevelResult RunNewton(const PairFrame& frame, NewtonMode mode, Vec2 xi, double m, const SolverOptions& options);

/// The point between the centres where ψA = ψB, and μ balancing the gradients there.
/// Returns false when the centres coincide.
bool GeometricStart(const PairFrame& frame, Vec2& xi, double& mu);

} // namespace b2a

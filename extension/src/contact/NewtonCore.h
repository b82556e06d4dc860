// b2analytic: the Newton iteration shared by the common-level solvers (internal).
#pragma once

#include "b2analytic/ContactResult.h"
#include "contact/PairFrame.h"

namespace b2a
{

/// True when both shapes suit Newton (smooth, strictly convex); else fills `failure` with why.
inline bool NewtonApplies(const Shape& a, const Shape& b, LevelResult& failure)
{
	failure.method = SolveMethod::newton;
	if (a.IsSmoothConvex() && b.IsSmoothConvex())
		return true;
	failure.failure = "Newton needs smooth, strictly convex shapes (superellipse exponents >= 2)";
	return false;
}

/// Newton–Raphson on the common level from (ξ, m = log μ) in a PairFrame; `level` is λA there.
LevelResult RunNewton(const PairFrame& frame, Vec2 xi, double m, const SolverOptions& options);

/// The point between the centres where ψA = ψB, and μ balancing the gradients there.
/// Returns false when the centres coincide.
bool GeometricStart(const PairFrame& frame, Vec2& xi, double& mu);

} // namespace b2a

// b2analytic: solver pieces shared between the contact sources (internal).
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

class SuperellipseShape;
/// The shape as a plain ellipse or circle (n = m = 2, level f or f^1), else null.
const SuperellipseShape* AsPlainEllipse(const Shape& s);
/// The surface points of an ellipse pair on the line through the level point along the normal
/// (ContactFromLevel's pointA and pointB), where the level solve gives them at little cost.
struct EllipsePairPoints
{
	Vec2 a, b;          ///< on A's surface, on B's
	bool valid = false; ///< false: compute them as ContactFromLevel does
};
/// Common level of two plain ellipses by Halley's method on Perram–Wertheim's one-dimensional
/// form (EllipsePairLevel.cpp), warm-started from the previous multiplier; fills `points` when
/// given and the pair is solved in double (aspect ratios up to 4).
LevelResult SolveEllipsePairLevel(const SuperellipseShape& a, const Pose& pa, const SuperellipseShape& b, const Pose& pb,
                                  const WarmStart* warm, EllipsePairPoints* points = nullptr);

/// Newton–Raphson on the common level from (ξ, m = log μ) in a PairFrame; `level` is λA there.
LevelResult RunNewton(const PairFrame& frame, Vec2 xi, double m, const SolverOptions& options);

/// The point between the centres where ψA = ψB, and μ balancing the gradients there.
/// Returns false when the centres coincide.
bool GeometricStart(const PairFrame& frame, Vec2& xi, double& mu);

/// One-sided scale of A on B's surface by Newton (ScaleANewton.cpp).
LevelResult SolveScaleANewton(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options);

/// Common level of two circles in closed form; fails when the centres coincide exactly.
LevelResult CircleLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb);

} // namespace b2a

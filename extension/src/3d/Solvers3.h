// b2analytic: pieces shared between the 3D solver sources (internal).
#pragma once

#include "b2analytic/3d/Contact3.h"
#include "3d/PairFrame3.h"

namespace b2a
{

/// Newton on the common level from (ξ, ν = log μ) in a frame (Newton3.cpp); `level` is λA there.
LevelResult3 RunNewton3(const PairFrame3& frame, Vec3 xi, double nu, const SolverOptions& options);

/// Whether ξ solves the common level's conditions to the standard of a converged answer: the
/// gauges ψA, ψB within 1e-11 of each other, or ten times what the rounding of the point alone
/// leaves (the point known to ε times the largest world coordinate, moving each ψ by |∇ψ| that
/// much) up to 1e-9 of the level (the gauges to 1e-9/q); and the normals opposed to 1e-8 rad
/// (a normal's error is a few times this misalignment: 1.4e-6 rad at 4.6e-7 on a thin plate;
/// flat faces touching face to face leave 5e-10 that no step removes), or ten times the turn of
/// the normals within the point's rounding (each Hessian over its gradient times it), where
/// double precision does not determine them (centres within 1e-8 of the size of each other).
bool ConditionsHold3(const PairFrame3& frame, Vec3 xi);

/// ConditionsHold3 with both gauges already evaluated at ξ, Hessians included (a solver's own
/// last point: the test is then a comparison, not an evaluation).
bool ConditionsHold3(const PairFrame3& frame, Vec3 xi, const GaugeValue3& a, const GaugeValue3& b);

/// The point between the centres where ψA = ψB, and μ balancing the gradients there; false
/// when the centres coincide.
bool GeometricStart3(const PairFrame3& frame, Vec3& xi, double& mu);

/// True when both shapes suit Newton (smooth, strictly convex); else fills `failure`.
bool NewtonApplies3(const Shape3& a, const Shape3& b, LevelResult3& failure);

/// Common level of two spheres in closed form; fails where the centres coincide.
LevelResult3 SphereLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb);

/// Common level of two ellipsoids (spheres included) by Perram and Wertheim's one-dimensional
/// form (EllipsoidPairLevel.cpp). Fails for other shapes and where the centres coincide.
LevelResult3 SolveEllipsoidPairLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb);

/// Coincident centres: the contact along the axis of least overlap (the separating-axis depth,
/// the lowest of 256 directions refined by Nelder–Mead), Contact3.cpp.
ContactResult3 OverlapAxisContact3(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb);

/// Records a solved level as the next warm start (the point in both bodies' frames and μ); a
/// failed solve, or one without a positive multiplier, invalidates it.
void RecordWarmStart3(WarmStart3* warm, const Pose3& pa, const Pose3& pb, const LevelResult3& level);

} // namespace b2a

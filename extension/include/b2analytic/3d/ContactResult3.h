// b2analytic: results of the 3D contact solvers (the 2D statuses, methods and options).
#pragma once

#include "b2analytic/3d/Math3.h"
#include "b2analytic/ContactResult.h" // SolveStatus, SolveMethod, MethodChoice, SolverOptions

namespace b2a
{

/// Result of a 3D level solve: the common level of two particles, or the one-sided scale of A
/// (LevelResult's fields with 3-vectors). Points and normals are in world coordinates.
struct LevelResult3
{
	SolveStatus status = SolveStatus::failed; ///< outcome
	SolveMethod method = SolveMethod::none;   ///< solver that produced the answer
	const char* failure = "";                 ///< reason when failed (static text)
	int iterations = 0;                       ///< iterations of the solver
	double level = 0.0;                       ///< common level C, or A's level when B is held at its surface
	Vec3 point;                               ///< the touching point of the rescaled particles
	Vec3 normal;                              ///< unit direction of ∇λ_A at the point
	double multiplier = 0.0;                  ///< μ in ∇ψA + μ∇ψB = 0

	/// True unless the solve failed.
	bool Ok() const { return status != SolveStatus::failed; }
};

/// The contact a physics engine uses, for any pair of 3D shapes (world coordinates), with
/// ContactResult's meaning: the normal points from A to B; pointA and pointB lie on the unscaled
/// surfaces on the line through `point` along the normal (or, where that line misses a
/// far-away particle, on the ray from its centre towards `point`); separation =
/// (pointB − pointA)·normal, negative when the particles overlap; `touching` is separation ≤ 0,
/// which is "common level ≤ 1". Swapping A and B flips the normal and swaps the points.
struct ContactResult3
{
	SolveStatus status = SolveStatus::failed; ///< outcome
	SolveMethod method = SolveMethod::none;   ///< solver that produced the answer
	const char* failure = "";                 ///< reason when failed (static text)
	int iterations = 0;                       ///< iterations of the level solve
	double level = 0.0;                       ///< level value of the method used
	Vec3 point;                               ///< the level solve's touching point
	Vec3 normal{1.0, 0.0, 0.0};               ///< unit normal from A to B
	Vec3 pointA;                              ///< point on A's surface
	Vec3 pointB;                              ///< point on B's surface
	double separation = 0.0;                  ///< signed gap along the normal, < 0 when overlapping
	bool touching = false;                    ///< separation ≤ 0

	/// True unless the solve failed.
	bool Ok() const { return status != SolveStatus::failed; }
};

/// A previous solution to start Newton from (warm start across time steps): the touching point
/// in A's and in B's body frame, so that it follows both bodies, and the multiplier.
struct WarmStart3
{
	Vec3 localPoint;         ///< previous touching point in A's body frame
	Vec3 localPointB;        ///< the same point in B's body frame
	double multiplier = 1.0; ///< previous LevelResult3::multiplier
	bool valid = false;      ///< false: start from the geometric guess
};

} // namespace b2a

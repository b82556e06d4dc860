// b2analytic: results and options of the contact solvers.
#pragma once

#include "b2analytic/Math.h"

#include <cstdint>

namespace b2a
{

/// How a solve ended.
enum class SolveStatus : std::uint8_t
{
	converged,              ///< the requested solver converged
	convergedAfterFallback, ///< the first solver failed; a more robust one converged
	failed                  ///< no answer; `failure` says why (no field is NaN even then)
};

/// Which solver produced a result.
enum class SolveMethod : std::uint8_t
{
	none,       ///< nothing ran (invalid input)
	closedForm, ///< a closed form (circle pairs)
	newton,     ///< Newton–Raphson on the common level (paper eqs. 6–17)
	minMax,     ///< the min–max (Perram–Wertheim) characterisation C = max_μ min_X ψA + μψB
	grid,       ///< the grid method on surface samples with local refinement (paper section 3)
	overlapAxis,   ///< coincident centres: the axis of least overlap (no level point exists)
	separatingAxis, ///< analytic shape against a polygon: the best separating axis of the supports
	ellipsePair     ///< two ellipses: Newton on Perram and Wertheim's one-dimensional form (2×2 algebra)
};

/// Which solver the caller wants.
enum class MethodChoice : std::uint8_t
{
	automatic, ///< the dispatch table picks per shape pair
	newton,    ///< Newton only (smooth, strictly convex shapes); no fallback
	grid       ///< the grid method with refinement
};

/// "converged", "converged_after_fallback" or "failed".
const char* StatusName(SolveStatus status);
/// "closed_form", "newton", "min_max", "grid", "overlap_axis", "separating_axis" or "none".
const char* MethodName(SolveMethod method);

/// Result of a level solve: the common level of two particles, or the one-sided scale of A.
/// Points and normals are in world coordinates.
struct LevelResult
{
	SolveStatus status = SolveStatus::failed; ///< outcome
	SolveMethod method = SolveMethod::none;   ///< solver that produced the answer
	const char* failure = "";                 ///< reason when failed (static text)
	int iterations = 0;                       ///< iterations (Newton, outer min–max steps, grid refinement steps)
	double level = 0.0;                       ///< common level C, or A's level when B is held at its surface
	Vec2 point;                               ///< the touching point of the rescaled particles
	Vec2 normal;                              ///< unit direction of ∇λ_A at the point
	double multiplier = 0.0;                  ///< μ in ∇ψA + μ∇ψB = 0 (Newton's internal scaling)

	/// True unless the solve failed.
	bool Ok() const { return status != SolveStatus::failed; }
};

/// The contact the Box2D adapter uses, for any pair of shapes (world coordinates).
/// The normal points from A to B; pointA and pointB lie on the unscaled surfaces on the line
/// through `point` along the normal (or, where that line misses a far-away particle, on the
/// ray from its centre towards `point`), and separation = (pointB − pointA)·normal is negative
/// when the particles overlap. `touching` is separation ≤ 0, which is exactly "level ≤ the
/// particles' own level". Swapping A and B flips the normal and swaps the points.
struct ContactResult
{
	SolveStatus status = SolveStatus::failed; ///< outcome
	SolveMethod method = SolveMethod::none;   ///< solver that produced the answer
	const char* failure = "";                 ///< reason when failed (static text)
	int iterations = 0;                       ///< iterations of the level solve
	double level = 0.0;                       ///< level value of the method used
	Vec2 point;                               ///< the level solve's touching point
	Vec2 normal{1.0, 0.0};                    ///< unit normal from A to B
	Vec2 pointA;                              ///< point on A's surface
	Vec2 pointB;                              ///< point on B's surface
	double separation = 0.0;                  ///< signed gap along the normal, < 0 when overlapping
	bool touching = false;                    ///< separation ≤ 0

	/// True unless the solve failed.
	bool Ok() const { return status != SolveStatus::failed; }
};

/// A previous solution to start Newton from (warm start across time steps). `localPoint` is the
/// touching point in A's body frame, so it follows A when both particles move together;
/// `localPointB`, the same point in B's frame, lets a solver predict where the point went when B
/// moved relative to A. Where a solver records the slide, the point's first-order motion along
/// the level curves when B moves relative to A (from the curvatures of the two shapes' level
/// curves there), the next start follows the point also as it rolls. The slide is a hint for the
/// start only, kept in float so that a Box2D contact carrying it still fits Box2D's largest
/// allocator block.
struct WarmStart
{
	Vec2 localPoint;                 ///< previous touching point in A's body frame
	Vec2 localPointB;                ///< previous touching point in B's body frame
	double multiplier = 1.0;         ///< previous LevelResult::multiplier
	float normalA[2] = {0.0f, 0.0f}; ///< previous normal n (A's outward unit normal there) in A's body frame
	float normalB[2] = {0.0f, 0.0f}; ///< the same normal in B's body frame (turned with B, it shows B's turn relative to A since)
	/// ∂s/∂(ω, v·t, v·n): the point's move s along t = Perp(n) per turn ω of B relative to A
	/// (a length) and per move v of B's material point at the point (along t and along n).
	float slide[3] = {0.0f, 0.0f, 0.0f};
	bool valid = false;              ///< false: start from the geometric guess
	bool hasPointB = false;          ///< localPointB is set (solvers that do not record it clear this)
	bool hasSlide = false;           ///< normalA, normalB and slide are set (solvers that do not record them clear this)
};

/// Tuning of the solvers; the defaults suit every use in the library.
struct SolverOptions
{
	int maxIterations = 60;        ///< Newton iteration cap (the 3D min-max: 4 root steps each, at most 200)
	double stepTolerance = 1e-13;  ///< Newton stops when a full step moves the point less than this times the pair's size
	int gridSamples = 256;         ///< surface samples for the grid method (≥ 8)
	int gridCandidates = 4;        ///< local minima of the samples refined by the grid method
	bool gridRefine = true;        ///< refine the grid minimum between samples (false: the paper's plain
	                               ///< grid method, whose point is off by up to a sample spacing)
};

} // namespace b2a

// b2analytic: the level solvers (common level and one-sided scale) of docs/method.md ("Common-level contact", "Grid method").
#pragma once

#include "b2analytic/ContactResult.h"
#include "b2analytic/Shape.h"
#include "b2analytic/ShapeKind.h"

namespace b2a
{

/// Common level by Newton–Raphson (paper eqs. 6–17): finds X and μ > 0 with
///   ∇ψA(X) + μ∇ψB(X) = 0,  ψA(X) − ψB(X) = 0,
/// where ψ = (λ/λ₀)^{1/q}: each level in units of the shape's own level λ₀, raised to 1/q with
/// one q for the pair (the smaller LevelPower()). That map is the same for both shapes, so the
/// solution is the paper's, with better conditioning; the frame is normalised to the pair's
/// size. μ = e^ν keeps the multiplier positive, and before each step μ is reset to its
/// least-squares value at the current point when that lowers the residual. The Jacobian is
/// analytic and solved through its adjugate, with its exact condition number: a reciprocal
/// condition number below 1e-14 stops the solve as singular. Steps are limited (trust region of
/// half the pair's size, |Δν| ≤ 2) and damped by a backtracking line search on the row-weighted
/// residual. Starts from `warm` when given (its point moved with both bodies and by its slide
/// where recorded, WarmStart), else from the point between the centres where ψA = ψB. Both shapes must be
/// smooth and strictly convex (IsSmoothConvex). No fallback here; `level` is C in own-level units
/// (C ≤ 1 ⇔ touching; the superellipse family's own level is 1).
LevelResult SolveCommonLevelNewton(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                   const SolverOptions& options = {}, const WarmStart* warm = nullptr);

/// Common level by the min–max characterisation C = min_X max(λA, λB) = max_μ min_X (ψA + μψB)
/// (Perram–Wertheim): an outer bracketed root in ν = log μ of ψA(X(ν)) − ψB(X(ν)), which is
/// monotone, around an inner convex minimisation X(ν). Slower than Newton but it converges for
/// every pair of smooth convex shapes, so it is the fallback; a final Newton polish makes its
/// answer as exact as Newton's.
LevelResult SolveCommonLevelMinMax(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                   const SolverOptions& options = {});

/// Common level by the grid method: the fixed point C = g(C), where g(C) is the smallest level of
/// A on B's level-C surface (SolveGridScale). g decreases, so the fixed point is bracketed by 1
/// and g(1) and found by Brent's method. Works for any convex shapes, smooth or not; fails with a
/// clear reason for non-convex ones (use SolveScaleA).
LevelResult SolveCommonLevelGrid(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                 const SolverOptions& options = {});

/// Common level through the automatic path: the dispatch table's level function for the shapes'
/// kinds (closed form for circles, Perram–Wertheim for ellipses, Newton (warm-started when
/// `warm` is valid) with the min–max fallback for other smooth convex pairs, the grid fixed
/// point for other convex pairs, a registered function where there is one); fails with a clear
/// reason for non-convex shapes (use SolveScaleA). Updates `warm` on success.
LevelResult SolveCommonLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                             MethodChoice method = MethodChoice::automatic, const SolverOptions& options = {},
                             WarmStart* warm = nullptr);

/// A Newton answer's slide, kept for the next warm start (internal to the library: a level
/// function of the user's own leaves it alone).
struct LevelSlide;

/// A common-level function of the dispatch table: solves A and B's common level, starting from
/// `warm` where it is valid (it may be null), and fills `slide` where it computes one (it may be
/// null). SolveCommonLevel checks its answer and records it into the caller's warm start.
using LevelFunction = LevelResult (*)(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                      const SolverOptions& options, const WarmStart* warm, LevelSlide* slide);

/// Register `function` as the common-level function of the pair of 2D kinds (a, b), in that
/// order: pairs (b, a) call it swapped, without the warm start, and turn its answer back (normal
/// reversed, multiplier inverted). As RegisterContactFunction otherwise (set-up only; throws
/// InvalidParameter naming 'a', 'b' or 'function').
void RegisterLevelFunction(ShapeKind a, ShapeKind b, LevelFunction function);

/// The dispatch table's level function for (a, b) (see GetContactFunction).
LevelFunction GetLevelFunction(ShapeKind a, ShapeKind b);

/// Grid method (paper section 3): B held at its level `levelB` (its own surface level when NaN),
/// the smallest level of A over B's surface samples, then refined between the neighbouring
/// samples so that the answer is exact to rounding rather than to the sample spacing: Newton on
/// ∇λA + μ∇λB = 0, λB = levelB from the sample; at a corner of B the corner or a smooth minimum
/// beside it; where a corner ray of A (the heart's tip axis, a valley of λA) crosses the bracket,
/// the crossing; otherwise a bracketed root of d/dθ λA(X_B(θ)) or a Brent minimisation. The
/// lowest `gridCandidates` local minima are refined, so that shapes with several local minima
/// (the heart's cleft) get the global one. At B's own level, runs of samples whose disc A's
/// bounds (Shape::Bounds) put above the lowest level found are skipped (they cannot hold the
/// minimum), so a particle's far side costs one bound per run. `point` lies on B's surface.
LevelResult SolveGridScale(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                           const SolverOptions& options = {}, double levelB = 0.0 / 0.0);

/// The smallest level of A at which A touches B held at its own surface ("scale_a"): the grid
/// method (automatic for every pair, or asked for), or Newton on ∇ψA + μ∇ψB = 0, ψB = ψB(own)
/// for smooth convex pairs. `point` lies on B's surface.
LevelResult SolveScaleA(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                        MethodChoice method = MethodChoice::automatic, const SolverOptions& options = {});

} // namespace b2a

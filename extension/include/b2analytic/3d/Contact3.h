// b2analytic: the 3D level solvers and the contact between two posed 3D shapes.
#pragma once

#include "b2analytic/3d/ContactResult3.h"
#include "b2analytic/3d/Shape3.h"
#include "b2analytic/ShapeKind.h"

namespace b2a
{

/// Common level by Newton–Raphson on the four unknowns (X, μ):
///   ∇ψA(X) + μ∇ψB(X) = 0,  ψA(X) − ψB(X) = 0,
/// with ψ = (λ/λ₀)^{1/q} (one q for the pair, the smaller LevelPower) in a frame normalised to
/// the pair's size, μ = e^ν, the least-squares multiplier taken where it lowers the residual,
/// the exact condition number of the 4×4 Jacobian tested (below 1e-14: singular), a trust region
/// (half the pair's size, |Δν| ≤ 2) and a backtracking line search, as the 2D solver. Starts
/// from `warm` when valid (the point as both bodies carried it, their mean), else from the
/// point between the centres where ψA = ψB. Both shapes must be smooth and strictly convex; no
/// fallback here. `level` is C in own-level units (C ≤ 1 ⇔ touching).
LevelResult3 SolveCommonLevelNewton(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                                    const SolverOptions& options = {}, const WarmStart3* warm = nullptr);

/// Common level by the min–max characterisation C = min_X max(λA, λB) = max_μ min_X (ψA + μψB)
/// (Perram–Wertheim): a bracketed root in ν = log μ of the monotone ψA(X(ν)) − ψB(X(ν)) around
/// an inner convex minimisation X(ν) by damped Newton, then a Newton polish. Slower than Newton,
/// converges for every pair of smooth convex shapes: the fallback.
LevelResult3 SolveCommonLevelMinMax(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                                    const SolverOptions& options = {});

/// Grid method (paper section 3) in 3D: B held at its level `levelB` (its own level when NaN),
/// the smallest level of A over B's surface samples (SurfaceSamples3, about
/// options.gridSamples of them) and then, when options.gridRefine, the lowest
/// options.gridCandidates local minima of the grid refined to the exact minimum: Newton on
/// ∇ψA + μ∇ψB = 0, ψB = ψB(levelB) from the sample where both shapes are smooth, else a
/// Nelder–Mead minimisation of A's level over B's level surface in the directions around the
/// sample. `point` lies on B's level surface; `level` is A's level there.
LevelResult3 SolveGridScale(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                            const SolverOptions& options = {}, double levelB = 0.0 / 0.0);

/// Common level by the grid method: the fixed point C = g(C) of g(C), the smallest level of A on
/// B's level-C surface (SolveGridScale). g decreases, so the fixed point is bracketed by 1 and
/// g(1) and found by Brent's method. For any convex shapes, smooth or not.
LevelResult3 SolveCommonLevelGrid(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                                  const SolverOptions& options = {});

/// The smallest level of A at which it touches B held at its own surface ("scale_a"):
/// SolveGridScale with refinement.
LevelResult3 SolveScaleA(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                         MethodChoice method = MethodChoice::automatic, const SolverOptions& options = {});

/// A contact function of the 3D dispatch table. `warm` may be null.
using ContactFunction3 = ContactResult3 (*)(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                                            const SolverOptions& options, WarmStart3* warm);
/// A common-level function of the 3D dispatch table. `warm` may be null.
using LevelFunction3 = LevelResult3 (*)(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                                        const SolverOptions& options, const WarmStart3* warm);

/// Replace the 3D table's contact function for a pair of 3D kinds (registered, dimension 3;
/// the pair the other way round gets it flipped). Call before the pairs it changes are solved.
/// Throws InvalidParameter naming 'a', 'b' or 'function' for a kind that is not a registered 3D
/// kind or a null function.
void RegisterContactFunction(ShapeKind a, ShapeKind b, ContactFunction3 function);
/// The same for the common-level function (SolveCommonLevel's).
void RegisterLevelFunction(ShapeKind a, ShapeKind b, LevelFunction3 function);
/// The 3D table's contact function for a pair of 3D kinds (its default by solver classes where
/// none was registered).
ContactFunction3 GetContactFunction3(ShapeKind a, ShapeKind b);
/// The 3D table's common-level function for a pair of 3D kinds.
LevelFunction3 GetLevelFunction3(ShapeKind a, ShapeKind b);

/// Common level through the 3D dispatch table (Dispatch3.cpp, the same PairTable as 2D's): spheres in closed form; ellipsoids (and spheres) by
/// Newton on Perram and Wertheim's one-dimensional form; other smooth convex pairs by Newton
/// (warm-started from `warm` when valid, then cold) with the min–max fallback; pairs with an
/// exponent below 2 by the grid fixed point. `newton` and `grid` force one solver. Updates `warm`.
LevelResult3 SolveCommonLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                              MethodChoice method = MethodChoice::automatic, const SolverOptions& options = {},
                              WarmStart3* warm = nullptr);

/// The contact between A and B (ContactResult3) from the common level of SolveCommonLevel;
/// coincident centres (no level point between them) get the axis of least overlap.
ContactResult3 ComputeContact(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb,
                              MethodChoice method = MethodChoice::automatic, const SolverOptions& options = {},
                              WarmStart3* warm = nullptr);

/// The contact built from a level solution: the normal is the mean of A's outward and B's inward
/// unit normals at the point (they agree at a tangency; where they point the same way, one
/// centre inside the other, B's inward normal when `pointOnB`, else A's outward one); pointA is
/// A's far crossing along the normal on the line through the point, pointB B's against it (the
/// radial point where the line misses), and the separation is measured along the normal.
/// `touching` is the level solve's verdict; where rounding makes the separation's sign disagree,
/// the separation is reported as 0 or the smallest positive double.
ContactResult3 ContactFromLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const LevelResult3& level,
                                bool touching, bool pointOnB = false);

/// The same contact seen from the other side: normal flipped, points swapped.
ContactResult3 FlipContact(const ContactResult3& c);

} // namespace b2a

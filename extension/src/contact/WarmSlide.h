// b2analytic: where a warm start puts the common-level point after a small motion (internal).
// Inline: both Newton solvers call these once per contact, and a call was a visible part of it.
#pragma once

#include "contact/SolverCore.h"

#include <cmath>

namespace b2a
{

/// The slide's coefficients (LevelSlide::coefficients, validity) of an answer from both gauges'
/// Hessians at the point, in a frame whose length unit is `unit` world lengths: n is A's outward
/// unit normal there, μ the multiplier and gradA = |∇ψA| (at the root |∇ψB| = |∇ψA|/μ).
inline bool SlideCoefficients(const Sym22& hessA, const Sym22& hessB, Vec2 n, double mu, double gradA, double unit,
                              double coefficients[3])
{
	// Where the common-level point goes, to first order, when B moves relative to A by a small
	// rigid motion. At the point ξ, with A's outward normal n and tangent t = Perp(n), let B's
	// material point at ξ move by v and B turn by ω; the new point is ξ + s·t + h·n. The unit
	// normals of the gauges' level curves vary as dN = t·(tᵀ∇²ψ dx)/|∇ψ|, that is
	// t·(κ·dx·t + τ·dx·n) with the curve's curvature κ = tᵀ∇²ψ t/|∇ψ| and twist τ = tᵀ∇²ψ n/|∇ψ|
	// (the same for λ, whose Hessian differs from ψ's by a multiple of ∇λ∇λᵀ, zero on t). Along n
	// the levels stay equal, ψA + |∇ψA|·h = ψB + |∇ψB|·(v·n − h), so h = v·n/(1 + μ) with
	// μ = |∇ψA|/|∇ψB| (the plain warm start's weight). Along t the normals stay opposed: A's is
	// n + (κA·s + τA·h)·t, and B's, at its material point s − v·t along t and h − v·n along n,
	// turned by ω, is −n + (κB·(s − v·t) + τB·(h − v·n) − ω)·t. So
	//   s = (ω + κB·v·t + τB·v·n − (τA + τB)·h) / (κA + κB),
	// the slide's three coefficients. For two circles (no twist) the point stays on the centre
	// line, as it must, where the plain start v/(1 + μ) is exact only for translations; for a
	// corner on a face it follows the corner. Flat on flat (κA + κB near zero) the slide is
	// undetermined and none is recorded.
	// With rA = |∇ψA|, rB = rA/μ (∇ψA = −μ∇ψB at the root: one gradient's length is enough) and
	// the quadratic forms written out, (κA + κB)·rB = (tᵀHA t + μ·tᵀHB t)/μ = D/μ, and with
	// h = v·n/(1 + μ) the coefficients of ω, v·t and v·n are
	//   rA/D,  μ·tᵀHB t/D,  (μ²·tᵀHB n − tᵀHA n)/((1 + μ)·D),
	// over one division. The test on D is the flat-on-flat one: (κA + κB)·unit > 1e-6.
	const Vec2 t = Perp(n);
	const Vec2 ht = hessA * t, gt = hessB * t;
	const double ttA = Dot(ht, t), ttB = Dot(gt, t), tnA = Dot(ht, n), tnB = Dot(gt, n);
	const double den = ttA + mu * ttB, inv = 1.0 / ((1.0 + mu) * den);
	coefficients[0] = unit * gradA * (1.0 + mu) * inv;
	coefficients[1] = mu * ttB * (1.0 + mu) * inv;
	coefficients[2] = (mu * mu * tnB - tnA) * inv;
	return ttA >= 0.0 && ttB >= 0.0 && den * unit > 1e-6 * gradA &&
	       std::isfinite(coefficients[0] + coefficients[1] + coefficients[2]);
}

/// The slide of an answer (SlideCoefficients) from A's gauge gradient and both gauges' Hessians,
/// given in one frame whose length unit is `unit` world lengths and which `toWorld` turns to the
/// world; n is A's outward unit normal in that frame.
inline void ComputeSlide(Vec2 gradA, const Sym22& hessA, const Sym22& hessB, Vec2 n, double mu, double unit, Rot toWorld,
                         LevelSlide& out)
{
	out.valid = SlideCoefficients(hessA, hessB, n, mu, Length(gradA), unit, out.coefficients);
	out.normal = Rotate(toWorld, n);
}

/// Where a warm start puts the point at the new poses, in A's body frame: moved with B by the
/// weight 1/(1 + μ) where localPointB is known, and along the surfaces by the slide where
/// recorded. `size` is the pair's size (the slide's sanity bound).
inline Vec2 WarmStartPoint(const WarmStart& w, const Pose& pa, const Pose& pb, double size)
{
	const Vec2 x = w.localPoint;
	if (!w.hasPointB || !IsFinite(w.localPointB))
		return x;
	// Where the point went: between where it stayed with A and where it went with B. For two
	// circles, whose point divides the centre line in the ratio of the radii and whose
	// multiplier is rB/rA, the weight 1/(1 + μ) of B's is exact for translations.
	const Vec2 v = ToBody(pa, ToWorld(pb, w.localPointB)) - x;
	const double weight = 1.0 / (1.0 + w.multiplier);
	if (!w.hasSlide)
		return x + weight * v;
	// And along the surfaces by the slide (ComputeSlide). B's turn since is the angle from n to
	// B's copy of it turned with B. Where the predicted slide is large (over a tenth of the
	// size), the first-order model is no better a guess than the plain start.
	const Vec2 n(w.normalA[0], w.normalA[1]);
	const Vec2 nowB = InvRotate(pa.q, Rotate(pb.q, Vec2(w.normalB[0], w.normalB[1])));
	const Vec2 t = Perp(n);
	const double s = w.slide[0] * Cross(n, nowB) + w.slide[1] * Dot(v, t) + w.slide[2] * Dot(v, n);
	if (!(std::fabs(s) <= 0.1 * size))
		return x + weight * v;
	return x + s * t + (weight * Dot(v, n)) * n;
}

} // namespace b2a

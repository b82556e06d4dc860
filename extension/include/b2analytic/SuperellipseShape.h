// b2analytic: the superellipse family (superellipse, ellipse, circle).
#pragma once

#include "b2analytic/Shape.h"

namespace b2a
{

/// The constants of a superellipse's raw level f = |x/a|^n + |y/b|^m that every evaluation of f
/// and its derivatives needs, computed once per shape (a division costs as much as several
/// products). The contact solvers evaluate f inline from them (geometry/SuperellipseTerms.h).
struct SuperellipseTerms
{
	double n = 2.0, m = 2.0;         ///< the exponents
	int nInt = 2, mInt = 2;          ///< n and m as small integers (0 to 64), or -1
	double invA = 1.0, invB = 1.0;   ///< 1/a, 1/b
	double gradX = 2.0, gradY = 2.0; ///< n/a, m/b: ∂f/∂x = gradX·sgn(x)|x/a|^{n−1}
	double hessX = 2.0, hessY = 2.0; ///< n(n−1)/a², m(m−1)/b²: ∂²f/∂x² = hessX·|x/a|^{n−2}
};

/// Superellipse particle |x/a|^n + |y/b|^m ≤ 1 (paper eq. 2), with any real exponents n, m ≥ 1.
/// Its level function is f(x) = |x/a|^n + |y/b|^m, so the level-C set is the particle
/// "rescaled" to C (for n ≠ m the level sets are not similar copies: C is a measure, not a
/// linear scale). The normalised ζ-form of paper eq. 1, (|x/a|^{2ζ} + |y/b|^{2ζ})^{1/ζ}, is the
/// same particle with level f^{1/ζ}; make it with FromZeta.
///
/// Kind (BuiltinKinds): circle when n = m = 2 and a = b, ellipse when n = m = 2, superellipse for
/// other exponents n, m ≥ 2 on the raw level, smoothConvex for those in the ζ-form, convex for
/// exponents below 2.
/// Closed forms: radius (n = m), support (n = m, or Lagrange root for n ≠ m), area and second
/// moments (Beta/Gamma functions), bounding radius of ellipses and circles.
/// Smoothness: n, m ≥ 2 gives strictly convex, twice differentiable level sets (Newton
/// applies); 1 ≤ n < 2 is convex but has corners or infinite curvature on the axes.
/// At a point on an axis where an exponent is below 2, the infinite second derivative is
/// reported as 0 (the Hessian is not used for such shapes).
class SuperellipseShape final : public Shape, public LevelBounds
{
public:
	/// Superellipse |x/a|^n + |y/b|^m; throws InvalidParameter for a, b not finite and > 0, n, m
	/// not finite and ≥ 1, or a combination whose powers leave double precision's range (|1/a|^n
	/// under- or overflowing, a³b overflowing: a = 1e185 with n = 2, a = 1e30 with n = 12).
	SuperellipseShape(double a, double b, double n, double m);
	/// Normalised form (|x/a|^{2ζ} + |y/b|^{2ζ})^{1/ζ} of paper eq. 1, ζ ≥ 1/2.
	static std::shared_ptr<SuperellipseShape> FromZeta(double a, double b, double zeta);

	std::string Describe() const override;
	double Level(Vec2 x) const override;
	LevelDerivatives Derivatives(Vec2 x) const override;
	Vec2 Gradient(Vec2 x) const override;
	double RadiusAt(Vec2 u, double level) const override;
	Vec2 Support(Vec2 d) const override;
	/// Support with its Lagrange root (n ≠ m) cut after `lagrangeSteps` Newton steps, for a
	/// solver's start. Every point on the way has its normal along d; the steps start on the side
	/// of the bounding box (zero steps: the point there, one of |x/a|, |y/b| equal to 1) and
	/// descend onto the surface (three steps, half the exact root's six: the level within 2e-4 of
	/// 1). Closed forms (n = m) and axis directions are exact. Support(d) is SupportNear(d, 100):
	/// the steps stop once they reach rounding.
	Vec2 SupportNear(Vec2 d, int lagrangeSteps) const;
	/// For n = m the dual norm h = ‖(a·dx, b·dy)‖_q, q = n/(n − 1) (Hölder), without the point's
	/// divisions: two cube roots and two square roots at n = 4. Otherwise Support(d)·d.
	double SupportValue(Vec2 d) const override;
	/// From nested bodies, with e = (a·dx, b·dy): the axis points (±a, 0), (0, ±b) lie inside and
	/// the box |x| ≤ a, |y| ≤ b outside, so max(|ex|, |ey|) ≤ h ≤ |ex| + |ey|; the ellipse with the
	/// same axes (support |e|) lies inside when n, m ≥ 2 and outside when n, m ≤ 2. No powers.
	void SupportBounds(Vec2 d, double& lower, double& upper) const override;
	/// The half-widths are two support values along the world axes pulled back, the particle
	/// being symmetric about its centre.
	Box ComputeAABB(const Pose& pose) const override;
	/// The far crossing of the surface by the body line x + t·d: for an ellipse (n = m = 2) the
	/// larger root of a quadratic, for other exponents Newton on a convex function of t, from
	/// where it descends monotonically (false when the line misses or only grazes the particle).
	bool FarCrossing(Vec2 x, Vec2 d, double& t) const override;
	/// For exponents ≥ 2 on the raw level (the superellipse kind), Halley's steps on the level
	/// itself from the point near the surface (SmoothFarCrossingFrom: one division a step where
	/// FarCrossing's Newton on f^(1/p) takes a root and two); FarCrossing otherwise.
	bool FarCrossingNear(Vec2 x, Vec2 d, double& t) const override;
	/// LevelLowerBound and LevelSmoothOver of LevelBounds (the others claim nothing).
	const LevelBounds* Bounds() const override { return this; }
	/// Over the disc |x − c| ≤ ρ: |x| ≥ (|cx| − ρ)₊ and |y| ≥ (|cy| − ρ)₊, and the level grows
	/// with |x| and |y|. The grid method prunes with it where a superellipse meets a heart. (No
	/// upper bound: only the line search inside a non-convex particle would use one.)
	double LevelLowerBound(Vec2 centre, double radius) const override;
	/// An exponent that is not an even integer makes its term non-smooth on the axis where its
	/// coordinate vanishes (|x|^2.5 has no third derivative at x = 0); the ζ-form's power of
	/// the raw level is not smooth at the centre. Smooth over a disc clear of those.
	bool LevelSmoothOver(Vec2 centre, double radius) const override;
	/// For an ellipse, the quadratic of FarCrossing without real roots (its discriminant below
	/// rounding); for other exponents, a line that misses the bounding box |x| ≤ a, |y| ≤ b.
	bool LineMisses(Vec2 x, Vec2 d) const override;

	/// Semi-axis along body x.
	double A() const { return m_a; }
	/// Semi-axis along body y.
	double B() const { return m_b; }
	/// Exponent of |x/a|.
	double N() const { return m_n; }
	/// Exponent of |y/b|.
	double M() const { return m_m; }
	/// True for the normalised ζ-form (level = f^{1/ζ}).
	bool IsNormalised() const { return m_zeta > 0.0; }
	/// ζ of the normalised form (0 when not normalised).
	double Zeta() const { return m_zeta; }
	/// The constants of the raw level f (before the ζ transform), for inline evaluation.
	const SuperellipseTerms& Terms() const { return m_terms; }

	/// Closed-form area 4ab Γ(1+1/n)Γ(1+1/m)/Γ(1+1/n+1/m) and second moments.
	static MassProperties ClosedFormMass(double a, double b, double n, double m);

private:
	SuperellipseShape(double a, double b, double n, double m, double zeta);
	double LengthHint() const override { return m_a > m_b ? m_a : m_b; }

	double m_a, m_b, m_n, m_m;
	double m_zeta; // > 0 for the normalised form
	SuperellipseTerms m_terms;
};

/// Ellipse x²/a² + y²/b² ≤ 1 (a superellipse with n = m = 2).
std::shared_ptr<SuperellipseShape> MakeEllipse(double a, double b);
/// Circle of radius r (an ellipse with a = b = r).
std::shared_ptr<SuperellipseShape> MakeCircle(double r);
/// Superellipse |x/a|^n + |y/b|^m ≤ 1.
std::shared_ptr<SuperellipseShape> MakeSuperellipse(double a, double b, double n, double m);

} // namespace b2a

// b2analytic: the superellipsoid family (superellipsoid, ellipsoid, sphere).
#pragma once

#include "b2analytic/3d/Shape3.h"

namespace b2a
{

/// Superellipsoid particle |x/a|^n1 + |y/b|^n2 + |z/c|^n3 ≤ 1 in the paper's form (Li et al.
/// 2022, Figure 17), each exponent a real ≥ 1. Its level function is the left-hand side f, so
/// the level-C set is the particle rescaled to C (a similar copy only where the exponents are
/// equal).
///
/// Kinds: "sphere" (n1 = n2 = n3 = 2, a = b = c), "ellipsoid" (n1 = n2 = n3 = 2),
/// "superellipsoid" (every exponent ≥ 2, smooth), else "convex_superellipsoid" (convex, with
/// edges or infinite curvature: the grid method's). Closed forms: the level's derivatives (f is a sum of one-variable terms, its
/// Hessian diagonal in the body frame); the radius along a direction where the exponents are
/// equal (a Newton root otherwise); the support point (the dual norm where the exponents are
/// equal, a monotone one-dimensional root of its Lagrange condition otherwise); volume and
/// inertia from Dirichlet's integrals (Gamma functions); the bounding radius from the
/// conditions of its maximisation (exact for exponents ≥ 2; for an exponent below 2, the radius
/// of the same shape with that exponent raised to 2, which encloses it).
/// Smoothness: every exponent ≥ 2 gives strictly convex, twice differentiable level sets (Newton
/// applies); an exponent in [1, 2) is convex with edges or infinite curvature where its
/// coordinate vanishes, and the infinite second derivative there is reported as 0.
class SuperellipsoidShape final : public Shape3
{
public:
	/// Superellipsoid with semi-axes a, b, c and exponents n1, n2, n3; throws InvalidParameter
	/// naming the field and the value for a semi-axis not finite and > 0, an exponent not finite
	/// and ≥ 1, or a combination whose powers leave double precision's range.
	SuperellipsoidShape(double a, double b, double c, double n1, double n2, double n3);

	std::string Describe() const override;
	double Level(Vec3 x) const override;
	LevelDerivatives3 Derivatives(Vec3 x) const override;
	Vec3 Gradient(Vec3 x) const override;
	double RadiusAt(Vec3 u, double level) const override;
	Vec3 PointOnRay(Vec3 x, double level) const override;
	/// For an ellipsoid the larger root of a quadratic; otherwise Newton on the convex function
	/// g(t) = f(x + t·d)^{1/p} − 1 (p the smallest exponent) from the far side of the bounding
	/// sphere, from where it descends monotonically.
	bool FarCrossing(Vec3 x, Vec3 d, double& t) const override;
	Vec3 Support(Vec3 d) const override;
	/// For equal exponents n the dual norm ‖(a·dx, b·dy, c·dz)‖_q, q = n/(n − 1) (Hölder).
	double SupportValue(Vec3 d) const override;

	/// Semi-axis along body x.
	double A() const { return m_axis[0]; }
	/// Semi-axis along body y.
	double B() const { return m_axis[1]; }
	/// Semi-axis along body z.
	double C() const { return m_axis[2]; }
	/// Semi-axis i (0, 1, 2).
	double Axis(int i) const { return m_axis[i]; }
	/// Exponent i (0: of |x/a|, 1: of |y/b|, 2: of |z/c|).
	double Exponent(int i) const { return m_exponent[i]; }
	/// True when the three exponents are equal (closed-form radius and support).
	bool EqualExponents() const { return m_equal; }

	/// Volume 8abc·Γ(1+1/n1)Γ(1+1/n2)Γ(1+1/n3)/Γ(1+1/n1+1/n2+1/n3) and the second moments from
	/// Dirichlet's integral ∫ Π xᵢ^{kᵢ} over the first octant = Π [aᵢ^{kᵢ+1} Γ((kᵢ+1)/nᵢ)/nᵢ] /
	/// Γ(1 + Σ (kᵢ+1)/nᵢ).
	static MassProperties3 ClosedFormMass(double a, double b, double c, double n1, double n2, double n3);

private:
	SurfaceSamples3 BuildSamples(int count) const override;
	double Term(double x, int i) const; // |x/aᵢ|^nᵢ
	double FarthestDistance() const;

	double m_axis[3];
	double m_exponent[3];
	int m_integer[3];      // the exponents as small integers (0 to 64), or −1
	double m_inverse[3];   // 1/aᵢ
	double m_gradient[3];  // nᵢ/aᵢ
	double m_hessian[3];   // nᵢ(nᵢ − 1)/aᵢ²
	bool m_equal;
	int m_quadric;         // 2: sphere, 1: ellipsoid, 0: other exponents
};

/// Sphere of radius r.
std::shared_ptr<SuperellipsoidShape> MakeSphere(double r);
/// Ellipsoid x²/a² + y²/b² + z²/c² ≤ 1.
std::shared_ptr<SuperellipsoidShape> MakeEllipsoid(double a, double b, double c);
/// Superellipsoid |x/a|^n1 + |y/b|^n2 + |z/c|^n3 ≤ 1.
std::shared_ptr<SuperellipsoidShape> MakeSuperellipsoid(double a, double b, double c, double n1, double n2, double n3);

} // namespace b2a

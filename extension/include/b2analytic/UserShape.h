// b2analytic: particles of any shape given by a user's level function.
#pragma once

#include "b2analytic/Shape.h"

#include <functional>

namespace b2a
{

/// Description of a user shape by its implicit function G(x, L), as in paper eq. 20:
/// the particle rescaled to level L is { x : G(x, L) ≤ 0 }, and the particle itself is the one at
/// `level`. G must decrease (weakly) in L, and every level set must be star-shaped with respect
/// to the body origin (each ray from the origin leaves it once). Adding a shape this way needs no
/// change to the library; the contact solvers treat it like the built-in shapes.
struct UserShapeDef
{
	/// Name used in descriptions and error messages.
	std::string name = "user";
	/// G(x, L) (required).
	std::function<double(Vec2 x, double level)> function;
	/// The particle's own level L₀.
	double level = 1.0;
	/// Optional ∂G/∂x at (x, L); central differences of λ when empty, and near points where λ is
	/// a multiple root of L ↦ G(x, L) (there the implicit function theorem divides 0 by 0).
	std::function<Vec2(Vec2 x, double level)> gradient;
	/// Optional ∂²G/∂x² at (x, L); differences of the gradient when empty.
	std::function<Sym22(Vec2 x, double level)> hessian;
	/// Optional direct level function λ(x) (the L with G(x, L) = 0); a root solve when empty.
	std::function<double(Vec2 x)> levelOf;
	/// Declared: every level set is convex.
	bool convex = false;
	/// Declared: level sets are strictly convex and G is twice differentiable (Newton applies).
	bool smooth = false;
	/// q with λ^(1/q) convex and about quadratic (see Shape::LevelPower); 1 if λ itself is.
	double levelPower = 1.0;
	/// Typical size of the particle: brackets radial roots and sets finite-difference steps. The
	/// surface at `level` must lie within a factor 1e6 of it along the axes (InvalidParameter
	/// naming 'lengthScale' otherwise).
	double lengthScale = 1.0;
	/// Polar angles of corners of the surface, if any (sampling and quadrature split there).
	std::vector<double> cornerAngles;
	/// The registered 2D kind the shape belongs to (RegisterShapeKind), whose row and column of the
	/// dispatch table its pairs use: functions registered for it apply to the user shapes that
	/// name it and to no other. None (the default): the built-in kind of the declarations,
	/// smoothConvex, convex or nonConvex. The kind's solver class must not claim more than the
	/// declarations (InvalidParameter naming 'kind': a smoothConvex kind needs `smooth`).
	ShapeKind kind;
};

/// A shape from a UserShapeDef. The constructor checks that G is finite and negative at the
/// origin at the own level, that the surface is found along every sampled ray, and the scalar
/// fields; each failure throws InvalidParameter naming the field and the value.
class UserShape final : public Shape
{
public:
	/// Build and validate.
	explicit UserShape(UserShapeDef def);

	std::string Describe() const override;
	double Level(Vec2 x) const override;
	LevelDerivatives Derivatives(Vec2 x) const override;
	Vec2 Gradient(Vec2 x) const override;

	/// The definition the shape was made from.
	const UserShapeDef& Def() const { return m_def; }

private:
	double LengthHint() const override { return m_def.lengthScale; }
	// ∇λ by the implicit function theorem (user gradient) or central differences of λ.
	Vec2 LevelGradient(Vec2 x, double lambda) const;
	// The user derivatives and ∂G/∂L are trustworthy at (x, λ): fine and coarse differences of G
	// in L agree to the factor `agreement` (a simple root in L).
	bool ImplicitUsable(Vec2 x, double lambda, double agreement) const;
	UserShapeDef m_def;
};

/// Make a user shape.
std::shared_ptr<UserShape> MakeUserShape(UserShapeDef def);

} // namespace b2a

// b2analytic: a pair of posed shapes seen in a normalised frame (internal).
#pragma once

#include "b2analytic/Shape.h"
#include "numerics/Powers.h"

#include <cmath>

namespace b2a
{

/// Conditioned level ψ = (λ/λ₀)^(1/q), λ₀ the own surface level, and its derivatives with respect to normalised coordinates ξ.
struct GaugeValue
{
	double lambda = 0.0; ///< λ itself
	double psi = 0.0;    ///< ψ = λ^(1/q)
	Vec2 grad;           ///< ∇ξ ψ
	Sym22 hess;          ///< ∇²ξ ψ
	bool finite = true;  ///< every field is finite
};

/// A shape at a pose.
struct PosedShape
{
	const Shape* shape; ///< the shape
	Pose pose;          ///< its pose
	double unit;        ///< PairFrame::UnitOf the shape (1 / its own level), computed once
};

/// Centres closer than 1e-12 of the pair's mean bounding radius: no level point lies between
/// them, and the solvers that need one say so.
inline bool CentresCoincide(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb)
{
	const double tiny = 1e-12 * 0.5 * (a.BoundingRadius() + b.BoundingRadius());
	return !(LengthSquared(pb.p - pa.p) > tiny * tiny); // squared: no root on every contact
}

/// Two posed shapes in the frame X = origin + scale·ξ, with origin between the centres and scale
/// the mean bounding radius: the solvers see sizes of order one whatever the units (1e-3 to 1e3).
struct PairFrame
{
	PosedShape a, b; ///< the pair
	Vec2 origin;     ///< world point of ξ = 0
	double scale;    ///< world length of ξ = 1
	/// One power q for both shapes: ψA = ψB must mean λA = λB, so both levels go through the same
	/// monotone map λ ↦ λ^{1/q}. The smaller LevelPower keeps both ψ convex (λ^{1/q} stays convex
	/// for every q between 1 and a shape's own LevelPower).
	double power;
	double invPower; ///< 1 / power (the chain rule below needs it in every evaluation)

	/// Frame for a pair.
	PairFrame(const Shape& sa, const Pose& pa, const Shape& sb, const Pose& pb)
		: a{&sa, pa, UnitOf(sa)}, b{&sb, pb, UnitOf(sb)}, origin(0.5 * (pa.p + pb.p)),
		  scale(0.5 * (sa.BoundingRadius() + sb.BoundingRadius())),
		  power(sa.LevelPower() < sb.LevelPower() ? sa.LevelPower() : sb.LevelPower()), invPower(1.0 / power)
	{
	}
	/// World point of ξ.
	Vec2 World(Vec2 xi) const { return origin + scale * xi; }
	/// ξ of a world point.
	Vec2 Xi(Vec2 X) const { return (X - origin) / scale; }

	/// ψ and derivatives of one shape at ξ. By the chain rule, with x = Rᵀ(origin + s·ξ − c):
	/// ∇ξλ = s·R∇λ, ∇²ξλ = s²·R H Rᵀ; then ψ = λ^{1/q}: ∇ψ = ψ'∇λ, ∇²ψ = ψ'∇²λ + ψ''∇λ∇λᵀ with
	/// ψ' = ψ/(qλ), ψ'' = ψ'(1/q − 1)/λ.
	GaugeValue Eval(const PosedShape& ps, Vec2 xi, bool withHessian) const
	{
		const Vec2 x = ToBody(ps.pose, World(xi));
		GaugeValue g;
		const double q = power;
		const double k = ps.unit;
		if (withHessian)
		{
			const LevelDerivatives d = ps.shape->Derivatives(x);
			g.lambda = k * d.value;
			g.grad = (k * scale) * Rotate(ps.pose.q, d.gradient);
			g.hess = (k * scale * scale) * Rotate(ps.pose.q, d.hessian);
		}
		else
		{
			g.lambda = k * ps.shape->Level(x);
			g.grad = (k * scale) * Rotate(ps.pose.q, ps.shape->Gradient(x));
		}
		if (q == 1.0)
		{
			g.psi = g.lambda;
		}
		else if (g.lambda > 0.0)
		{
			g.psi = PsiOfPositive(g.lambda);
			const double invLambda = 1.0 / g.lambda;
			const double d1 = g.psi * invPower * invLambda;
			const double d2 = d1 * (invPower - 1.0) * invLambda;
			if (withHessian)
				g.hess = d1 * g.hess + d2 * Outer(g.grad);
			g.grad = d1 * g.grad;
		}
		else
		{
			// At the centre ψ = 0 and its gradient vanishes (degree > 1 at the origin).
			g.psi = 0.0;
			g.grad = Vec2();
			g.hess = Sym22{};
		}
		g.finite = std::isfinite(g.psi) && IsFinite(g.grad) && std::isfinite(g.hess.xx) && std::isfinite(g.hess.xy) &&
		           std::isfinite(g.hess.yy);
		return g;
	}
	/// ψ of one shape at ξ, without derivatives.
	double Psi(const PosedShape& ps, Vec2 xi) const
	{
		const double lambda = ps.unit * ps.shape->Level(ToBody(ps.pose, World(xi)));
		const double q = power;
		if (q == 1.0) return lambda;
		return lambda > 0.0 ? PsiOfPositive(lambda) : 0.0;
	}
	/// λ^{1/q} for λ > 0 (square roots for the commonest powers q = 2, 4, 8).
	double PsiOfPositive(double lambda) const { return RootOf(lambda, power); }
	/// The level unit of a shape: 1 / its own surface level when that is positive, else 1. Levels
	/// are measured in these units, so that "touching" is "common level ≤ 1" for every pair; the
	/// superellipse family is unchanged.
	static double UnitOf(const Shape& s)
	{
		const double own = s.SurfaceLevel();
		return own > 0.0 ? 1.0 / own : 1.0;
	}
	/// ψ of a (normalised) level value.
	double PsiOfLevel(double level) const
	{
		const double q = power;
		if (q == 1.0) return level;
		return level > 0.0 ? PsiOfPositive(level) : 0.0;
	}
};

} // namespace b2a

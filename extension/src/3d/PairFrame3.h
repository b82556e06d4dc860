// b2analytic: a pair of posed 3D shapes seen in a normalised frame (internal).
#pragma once

#include "b2analytic/3d/Shape3.h"
#include "numerics/Powers.h"

#include <cmath>

namespace b2a
{

/// Conditioned level ψ = (λ/λ₀)^(1/q) and its derivatives with respect to normalised coordinates
/// ξ (PairFrame's GaugeValue in 3D).
struct GaugeValue3
{
	double lambda = 0.0; ///< λ/λ₀
	double psi = 0.0;    ///< ψ
	Vec3 grad;           ///< ∇ξ ψ
	Sym33 hess;          ///< ∇²ξ ψ
	bool finite = true;  ///< every field is finite
};

/// A 3D shape at a pose, with its rotation matrix.
struct PosedShape3
{
	const Shape3* shape; ///< the shape
	Pose3 pose;          ///< its pose
	Mat33 R;             ///< the pose's rotation (body → world)
	double unit;         ///< 1 / the shape's own level

	/// Body point of a world point.
	Vec3 Body(Vec3 X) const { return MulT(R, X - pose.p); }
};

/// Centres closer than 1e-12 of the pair's mean bounding radius: no level point lies between them.
inline bool CentresCoincide(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb)
{
	const double tiny = 1e-12 * 0.5 * (a.BoundingRadius() + b.BoundingRadius());
	return !(LengthSquared(pb.p - pa.p) > tiny * tiny);
}

/// Two posed shapes in the frame X = origin + scale·ξ, origin between the centres and scale the
/// mean bounding radius (the 2D PairFrame's rules): the solvers see sizes of order one whatever
/// the units. One power q for both shapes (the smaller LevelPower) keeps both ψ convex and makes
/// ψA = ψB mean λA = λB.
struct PairFrame3
{
	PosedShape3 a, b; ///< the pair
	Vec3 origin;      ///< world point of ξ = 0
	double scale;     ///< world length of ξ = 1
	double power;     ///< q
	double invPower;  ///< 1/q

	/// Frame for a pair.
	PairFrame3(const Shape3& sa, const Pose3& pa, const Shape3& sb, const Pose3& pb)
		: a{&sa, pa, ToMatrix(pa.q), 1.0 / sa.SurfaceLevel()}, b{&sb, pb, ToMatrix(pb.q), 1.0 / sb.SurfaceLevel()},
		  origin(0.5 * (pa.p + pb.p)), scale(0.5 * (sa.BoundingRadius() + sb.BoundingRadius())),
		  power(sa.LevelPower() < sb.LevelPower() ? sa.LevelPower() : sb.LevelPower()), invPower(1.0 / power)
	{
	}
	/// World point of ξ.
	Vec3 World(Vec3 xi) const { return origin + scale * xi; }
	/// ξ of a world point.
	Vec3 Xi(Vec3 X) const { return (X - origin) / scale; }

	/// ψ and its derivatives at ξ. With x = Rᵀ(origin + s·ξ − c): ∇ξλ = s·R∇λ, ∇²ξλ = s²·R H Rᵀ;
	/// then ψ = λ^{1/q}: ∇ψ = ψ'∇λ, ∇²ψ = ψ'∇²λ + ψ''∇λ∇λᵀ with ψ' = ψ/(qλ), ψ'' = ψ'(1/q − 1)/λ.
	GaugeValue3 Eval(const PosedShape3& ps, Vec3 xi, bool withHessian) const
	{
		const Vec3 x = ps.Body(World(xi));
		GaugeValue3 g;
		const double k = ps.unit;
		if (withHessian)
		{
			const LevelDerivatives3 d = ps.shape->Derivatives(x);
			g.lambda = k * d.value;
			g.grad = (k * scale) * (ps.R * d.gradient);
			g.hess = (k * scale * scale) * Rotate(ps.R, d.hessian);
		}
		else
		{
			g.lambda = k * ps.shape->Level(x);
			g.grad = (k * scale) * (ps.R * ps.shape->Gradient(x));
		}
		if (power == 1.0)
			g.psi = g.lambda;
		else if (g.lambda > 0.0)
		{
			g.psi = RootOf(g.lambda, power);
			const double invLambda = 1.0 / g.lambda;
			const double d1 = g.psi * invPower * invLambda;
			const double d2 = d1 * (invPower - 1.0) * invLambda;
			if (withHessian)
				g.hess = d1 * g.hess + d2 * Outer(g.grad);
			g.grad = d1 * g.grad;
		}
		else
		{
			g.psi = 0.0;
			g.grad = Vec3();
			g.hess = Sym33{};
		}
		g.finite = std::isfinite(g.psi) && IsFinite(g.grad) &&
		           std::isfinite(g.hess.xx + g.hess.xy + g.hess.xz + g.hess.yy + g.hess.yz + g.hess.zz);
		return g;
	}
	/// ψ at ξ, without derivatives.
	double Psi(const PosedShape3& ps, Vec3 xi) const
	{
		const double lambda = ps.unit * ps.shape->Level(ps.Body(World(xi)));
		if (power == 1.0)
			return lambda;
		return lambda > 0.0 ? RootOf(lambda, power) : 0.0;
	}
	/// ψ of a level value (in own-level units).
	double PsiOfLevel(double level) const
	{
		if (power == 1.0)
			return level;
		return level > 0.0 ? RootOf(level, power) : 0.0;
	}
};

} // namespace b2a

// b2analytic: user shapes from an implicit function G(x, L).
#include "b2analytic/UserShape.h"

#include "numerics/RootFinding.h"

#include <cmath>
#include <limits>

namespace b2a
{

namespace
{
std::string Who(const UserShapeDef& def)
{
	return "user shape '" + def.name + "'";
}

// The kind the definition names, or the built-in one its declarations say. (Checked here, before
// the base class's check, so that the message names the shape.)
ShapeKind KindOf(const UserShapeDef& def)
{
	if (def.kind.Valid())
	{
		if (KindDimension(def.kind) != 2)
			throw InvalidParameter(Who(def), "kind", "must be a registered kind of dimension 2 (id)", def.kind.Id());
		const SolverClass solverClass = KindSolverClass(def.kind);
		if ((solverClass == SolverClass::smoothConvex && !def.smooth) ||
		    (solverClass == SolverClass::convex && !(def.convex || def.smooth)))
			throw InvalidParameter(Who(def) + ": field 'kind' (\"" + KindName(def.kind) + "\", solver class " +
			                           SolverClassName(solverClass) + ") needs the shape declared " +
			                           (solverClass == SolverClass::convex ? "'convex'" : "'smooth'"),
			                       "kind");
		return def.kind;
	}
	if (def.smooth)
		return BuiltinKinds::smoothConvex;
	return def.convex ? BuiltinKinds::convex : BuiltinKinds::nonConvex;
}
} // namespace

UserShape::UserShape(UserShapeDef def)
	: Shape(KindOf(def), def.level, def.convex || def.smooth, def.smooth, def.levelPower), m_def(std::move(def))
{
	const std::string who = Who(m_def);
	if (!m_def.function)
		throw InvalidParameter(who + ": field 'function' is empty (a callable G(x, level) is required)", "function");
	if (!std::isfinite(m_def.level))
		throw InvalidParameter(who, "level", "must be finite", m_def.level);
	if (!std::isfinite(m_def.lengthScale) || !(m_def.lengthScale > 0.0))
		throw InvalidParameter(who, "lengthScale", "must be finite and > 0", m_def.lengthScale);
	if (!std::isfinite(m_def.levelPower) || !(m_def.levelPower >= 1.0))
		throw InvalidParameter(who, "levelPower", "must be finite and >= 1", m_def.levelPower);
	for (double c : m_def.cornerAngles)
		if (!std::isfinite(c))
			throw InvalidParameter(who, "cornerAngles", "must be finite", c);
	const double g0 = m_def.function(Vec2(), m_def.level);
	if (!std::isfinite(g0))
		throw InvalidParameter(who, "function", "must be finite at the centre (0, 0) at the own level", g0);
	if (!(g0 < 0.0))
		throw InvalidParameter(who, "function", "must be negative at the centre (0, 0) at the own level (the centre is inside)", g0);
	if (m_def.levelOf)
	{
		const double l0 = m_def.levelOf(Vec2());
		if (!std::isfinite(l0) || !(l0 < m_def.level))
			throw InvalidParameter(who, "levelOf", "must be finite and below 'level' at the centre", l0);
	}
	for (double c : m_def.cornerAngles)
		AddCorner(c);
	// The solvers' steps and tolerances, and the radial searches that build the samples and
	// the mass, scale with lengthScale. A surface far from it (the fuzzer's own level 8e-308
	// put the surface 1e-78 from the centre with lengthScale 0.05) cannot be resolved: the
	// radii came out 1e31 too large, and building the shape took 40 s of level searches. So
	// the surface along the axes must lie within a factor 1e6 of lengthScale.
	for (const Vec2 u : {Vec2(1.0, 0.0), Vec2(0.0, 1.0), Vec2(-1.0, 0.0), Vec2(0.0, -1.0)})
	{
		const double r = RadiusAt(u, m_def.level);
		// (No surface on the ray at all, an unbounded particle, is the function's fault: Finalize
		// says so.)
		if (std::isfinite(r) && !(r >= 1e-6 * m_def.lengthScale && r <= 1e6 * m_def.lengthScale))
			throw InvalidParameter(who, "lengthScale",
			                       "must be within a factor 1e6 of the particle's size (the radial search along (" +
			                           FormatNumber(u.x) + ", " + FormatNumber(u.y) + ") put the surface at the level " +
			                           FormatNumber(m_def.level) + " " + FormatNumber(r) + " from the centre)",
			                       m_def.lengthScale);
	}
	Finalize(-1.0, nullptr);
}

std::string UserShape::Describe() const
{
	return Who(m_def);
}

double UserShape::Level(Vec2 x) const
{
	if (m_def.levelOf)
		return m_def.levelOf(x);
	// Root of L ↦ G(x, L), decreasing in L: bracket by doubling steps away from the own level.
	auto g = [&](double L) { return m_def.function(x, L); };
	const double L0 = m_def.level;
	const double g0 = g(L0);
	if (g0 == 0.0)
		return L0;
	if (std::isnan(g0))
		return std::numeric_limits<double>::quiet_NaN();
	const double dir = g0 > 0.0 ? 1.0 : -1.0; // outside: the level must grow
	// The step grows by a factor that squares each time (2, 4, 16, 256, ... up to 1e8), so a
	// level 1e300 away is bracketed in about 45 evaluations, not a thousand doublings (found by
	// the solver fuzzer: a grid contact with B held at level 1e300 took a minute); the root
	// search then narrows the wide bracket on a logarithmic scale.
	double step = std::max(std::fabs(L0), 1.0) * 0.25, factor = 2.0;
	double a = L0, ga = g0, b = L0, gb = g0;
	for (int i = 0; i < 1100; ++i)
	{
		b = L0 + dir * step;
		gb = g(b);
		if (std::isnan(gb))
			return std::numeric_limits<double>::quiet_NaN();
		if ((gb > 0.0) != (g0 > 0.0) || gb == 0.0)
			break;
		a = b;
		ga = gb;
		step *= factor;
		factor = std::min(factor * factor, 1e8);
		if (!std::isfinite(step))
			return dir * std::numeric_limits<double>::infinity();
	}
	if ((gb > 0.0) == (g0 > 0.0) && gb != 0.0)
		return dir * std::numeric_limits<double>::infinity();
	return FindRootScaleFree(g, a, b, ga, gb, 300).x;
}

bool UserShape::ImplicitUsable(Vec2 x, double lambda, double agreement) const
{
	// The implicit formulas divide by ∂G/∂L. Where λ is a multiple root of L ↦ G(x, L) (the heart
	// written as G has a triple root on its axes) ∂G/∂L vanishes with ∂G/∂x and the quotient is
	// noise, and near one (G far from linear in L over a small step) it loses digits. Detect both
	// by comparing ∂G/∂L at a fine step with a coarse one: at a well-separated simple root they
	// agree; near a multiple root the fine one is smaller.
	if (!m_def.gradient)
		return false;
	const double scale = std::max(std::fabs(lambda), 1.0);
	const double h = 1e-6 * scale, H = 1e-2 * scale;
	const double fine = (m_def.function(x, lambda + h) - m_def.function(x, lambda - h)) / (2.0 * h);
	const double coarse = (m_def.function(x, lambda + H) - m_def.function(x, lambda - H)) / (2.0 * H);
	return std::isfinite(fine) && fine != 0.0 && std::fabs(fine) >= agreement * std::fabs(coarse);
}

Vec2 UserShape::LevelGradient(Vec2 x, double lambda) const
{
	if (ImplicitUsable(x, lambda, 0.5))
	{
		// G(x, λ(x)) = 0  ⇒  ∇λ = −∂G/∂x / ∂G/∂L.
		const double h = 1e-6 * std::max(std::fabs(lambda), 1.0);
		const double GL = (m_def.function(x, lambda + h) - m_def.function(x, lambda - h)) / (2.0 * h);
		return -1.0 / GL * m_def.gradient(x, lambda);
	}
	const double h = 1e-6 * m_def.lengthScale;
	return Vec2((Level(Vec2(x.x + h, x.y)) - Level(Vec2(x.x - h, x.y))) / (2.0 * h),
	            (Level(Vec2(x.x, x.y + h)) - Level(Vec2(x.x, x.y - h))) / (2.0 * h));
}

Vec2 UserShape::Gradient(Vec2 x) const
{
	return LevelGradient(x, Level(x));
}

LevelDerivatives UserShape::Derivatives(Vec2 x) const
{
	LevelDerivatives d;
	d.value = Level(x);
	d.gradient = LevelGradient(x, d.value);
	if (m_def.hessian && ImplicitUsable(x, d.value, 0.5))
	{
		// Differentiate G(x, λ(x)) = 0 twice:
		//   ∇²λ = −(G_xx + G_xL ∇λᵀ + ∇λ G_xLᵀ + G_LL ∇λ∇λᵀ) / G_L.
		const double L = d.value;
		const double h = 1e-4 * std::max(std::fabs(L), 1.0);
		const double Gp = m_def.function(x, L + h), Gm = m_def.function(x, L - h), G0 = m_def.function(x, L);
		const double GL = (Gp - Gm) / (2.0 * h);
		const double GLL = (Gp - 2.0 * G0 + Gm) / (h * h);
		const Vec2 GxL = (m_def.gradient(x, L + h) - m_def.gradient(x, L - h)) / (2.0 * h);
		const Sym22 sum = m_def.hessian(x, L) + 2.0 * OuterSym(GxL, d.gradient) + GLL * Outer(d.gradient);
		d.hessian = (-1.0 / GL) * sum;
		return d;
	}
	// Central differences of the gradient, symmetrised.
	const double h = 1e-4 * m_def.lengthScale;
	const Vec2 gxp = Gradient(Vec2(x.x + h, x.y)), gxm = Gradient(Vec2(x.x - h, x.y));
	const Vec2 gyp = Gradient(Vec2(x.x, x.y + h)), gym = Gradient(Vec2(x.x, x.y - h));
	d.hessian.xx = (gxp.x - gxm.x) / (2.0 * h);
	d.hessian.yy = (gyp.y - gym.y) / (2.0 * h);
	d.hessian.xy = 0.5 * ((gxp.y - gxm.y) + (gyp.x - gym.x)) / (2.0 * h);
	return d;
}

std::shared_ptr<UserShape> MakeUserShape(UserShapeDef def)
{
	return std::make_shared<UserShape>(std::move(def));
}

} // namespace b2a

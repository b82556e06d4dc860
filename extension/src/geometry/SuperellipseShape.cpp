// b2analytic: superellipse family with closed forms.
#include "b2analytic/SuperellipseShape.h"

#include "geometry/SuperellipseTerms.h"
#include "numerics/Powers.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

namespace
{
// The kind: circle and ellipse for n = m = 2 (the ζ-form with ζ = 1 has the same level f^1);
// superellipse for the other smooth exponents on the raw level f, whose pair solver evaluates f
// inline; the ζ-form's level f^{1/ζ} is the generic smooth convex kind's; exponents below 2 give
// corners or infinite curvature on the axes.
ShapeKind KindOf(double a, double b, double n, double m, double zeta)
{
	if (n == 2.0 && m == 2.0)
		return a == b ? BuiltinKinds::circle : BuiltinKinds::ellipse;
	if (!(n >= 2.0 && m >= 2.0))
		return BuiltinKinds::convex;
	return zeta > 0.0 ? BuiltinKinds::smoothConvex : BuiltinKinds::superellipse;
}

int SmallInteger(double e)
{
	return (e == std::floor(e) && e >= 0.0 && e <= 64.0) ? int(e) : -1;
}

void RequirePositive(const char* what, const char* field, double v)
{
	if (!std::isfinite(v) || !(v > 0.0))
		throw InvalidParameter(what, field, "must be finite and > 0", v);
}

void RequireExponent(const char* what, const char* field, double v, double lowest)
{
	if (!std::isfinite(v) || !(v >= lowest))
		throw InvalidParameter(what, field, "must be finite and >= " + FormatNumber(lowest), v);
}

void RequireRepresentable(const char* what, const SuperellipseShape& s)
{
	// Lengths and exponents whose powers leave double precision's range have no usable surface:
	// |1/a|^n underflows to 0 for a = 1e185, n = 2, and the radius along x comes out infinite;
	// it overflows for a = 1e-30, n = 100, and the radius is 0; |cos 45°|^n underflows for n in the
	// thousands. Found by the fuzzers: such shapes were accepted and a solver threw later. Each
	// axis end must come back as the semi-axis, and the scaled diagonal as a point on the surface.
	auto near = [](double value, double expected) { return std::fabs(value - expected) <= 1e-9 * expected; };
	if (!near(s.RadiusAt(Vec2(1.0, 0.0), 1.0), s.A()))
		throw InvalidParameter(what, "a", "must keep |x/a|^n within double precision's range (n = " + FormatNumber(s.N()) + ")", s.A());
	if (!near(s.RadiusAt(Vec2(0.0, 1.0), 1.0), s.B()))
		throw InvalidParameter(what, "b", "must keep |y/b|^m within double precision's range (m = " + FormatNumber(s.M()) + ")", s.B());
	// Between the axes: the diagonal of the box and 14 directions more. A surface point must lie
	// in the box |x| ≤ a, |y| ≤ b at level 1. (Found by b2a_fuzz_contact_tool: a = 1, b = 8,
	// n = 7.8e51, m = 6 passed at the diagonal, where |x/a|^n underflowed harmlessly, but at
	// other angles |u_x/a|^n of the unit direction underflowed where t^n·|u_x/a|^n is the surface:
	// its points lay far outside the box, and sampling it took a minute.)
	for (int k = 1; k < 16; ++k)
	{
		const double t = k * kPi / 32.0;
		const Vec2 u = Normalize(Vec2(s.A() * std::cos(t), s.B() * std::sin(t)));
		const double r = s.RadiusAt(u, 1.0);
		const Vec2 p = r * u;
		const double slack = 1.0 + 1e-9;
		if (!(r > 0.0) || !std::isfinite(r) || !(std::fabs(p.x) <= slack * s.A()) || !(std::fabs(p.y) <= slack * s.B()) ||
		    !near(s.Level(p), 1.0))
		{
			const bool nLarger = s.N() >= s.M();
			throw InvalidParameter(what, nLarger ? "n" : "m",
			                       "must keep |x/a|^n + |y/b|^m within double precision's range between the axes", nLarger ? s.N() : s.M());
		}
	}
}
// The largest distance from the centre to the surface, on the exact parametrisation
// x = a·cos(t)^{2/n}, y = b·sin(t)^{2/m} of the first quadrant (the particle is symmetric about
// both axes): the best of 65 parameters from axis to axis, then Brent between its neighbours.
// What Finalize would otherwise find from the surface samples, without building them: a
// superellipse's fixture needs only its proxy's seven.
double FarthestSurfaceDistance(double a, double b, double n, double m)
{
	auto distance = [&](double t) {
		const double x = a * std::pow(std::fabs(std::cos(t)), 2.0 / n), y = b * std::pow(std::fabs(std::sin(t)), 2.0 / m);
		return std::hypot(x, y);
	};
	const int steps = 64;
	const double h = 0.5 * kPi / steps;
	int best = 0;
	double bestValue = a; // t = 0
	for (int k = 1; k <= steps; ++k)
	{
		const double v = k == steps ? b : distance(k * h);
		if (v > bestValue)
		{
			bestValue = v;
			best = k;
		}
	}
	const ScalarResult r = MinimizeBrent([&](double t) { return -distance(t); }, std::max(0, best - 1) * h,
	                                     std::min(steps, best + 1) * h, 1e-15, 1e-15, 200);
	return std::max(bestValue, -r.fx);
}
} // namespace

SuperellipseShape::SuperellipseShape(double a, double b, double n, double m) : SuperellipseShape(a, b, n, m, 0.0) {}

SuperellipseShape::SuperellipseShape(double a, double b, double n, double m, double zeta)
	: Shape(KindOf(a, b, n, m, zeta), 1.0, true, n >= 2.0 && m >= 2.0,
	        // λ^(1/q) with q = min(n, m)/2 is ‖(|x/a|^{n/q}, |y/b|^{m/q})‖_q squared-like: convex
	        // (a q-norm of convex non-negative terms) and of degree about 2. The ζ-form is already.
	        zeta > 0.0 ? 1.0 : std::max(1.0, 0.5 * std::min(n, m))),
	  m_a(a), m_b(b), m_n(n), m_m(m), m_zeta(zeta),
	  m_terms{n, m, SmallInteger(n), SmallInteger(m), 1.0 / a, 1.0 / b, n / a, m / b, n * (n - 1.0) / (a * a), m * (m - 1.0) / (b * b)}
{
	// Validation happens before Finalize touches any geometry.
	const char* what = "superellipse";
	RequirePositive(what, "a", a);
	RequirePositive(what, "b", b);
	RequireExponent(what, "n", n, 1.0);
	RequireExponent(what, "m", m, 1.0);
	SetDerivativesCheap(); // (the terms' powers serve the level and its derivatives alike)
	SetSupportBoundsCheap(); // (nested bodies, no powers)

	// An exponent of 1 puts a corner where its term vanishes: |x/a| at x = 0 (polar ±π/2),
	// |y/b| at y = 0 (polar 0 and π, reported as −π).
	if (n == 1.0)
	{
		AddCorner(0.5 * kPi);
		AddCorner(-0.5 * kPi);
	}
	if (m == 1.0)
	{
		AddCorner(0.0);
		AddCorner(-kPi);
	}
	RequireRepresentable(what, *this);
	const MassProperties mass = ClosedFormMass(a, b, n, m);
	if (!std::isfinite(mass.area) || !(mass.area > 0.0) || !std::isfinite(mass.polarMoment))
		throw InvalidParameter(what, a >= b ? "a" : "b", "must keep the area and second moments (a³b, ab³) within double precision's range",
		                       a >= b ? a : b);
	// For n, m ≤ 2 the level set lies inside the ellipse's: the farthest points are the axes' ends.
	const double radius = n <= 2.0 && m <= 2.0 ? std::max(a, b) : FarthestSurfaceDistance(a, b, n, m);
	Finalize(radius, &mass);
}

std::shared_ptr<SuperellipseShape> SuperellipseShape::FromZeta(double a, double b, double zeta)
{
	if (!std::isfinite(zeta) || !(zeta >= 0.5))
		throw InvalidParameter("superellipse", "zeta", "must be finite and >= 0.5", zeta);
	return std::shared_ptr<SuperellipseShape>(new SuperellipseShape(a, b, 2.0 * zeta, 2.0 * zeta, zeta));
}

std::string SuperellipseShape::Describe() const
{
	if (Kind() == BuiltinKinds::circle)
		return "circle(r=" + FormatNumber(m_a) + ")";
	if (Kind() == BuiltinKinds::ellipse)
		return "ellipse(a=" + FormatNumber(m_a) + ", b=" + FormatNumber(m_b) + ")";
	if (IsNormalised())
		return "superellipse(a=" + FormatNumber(m_a) + ", b=" + FormatNumber(m_b) + ", zeta=" + FormatNumber(m_zeta) + ")";
	return "superellipse(a=" + FormatNumber(m_a) + ", b=" + FormatNumber(m_b) + ", n=" + FormatNumber(m_n) + ", m=" +
	       FormatNumber(m_m) + ")";
}

double SuperellipseShape::Level(Vec2 x) const
{
	const double f = PowAbs(x.x * m_terms.invA, m_n, m_terms.nInt) + PowAbs(x.y * m_terms.invB, m_m, m_terms.mInt);
	return m_zeta > 0.0 ? std::pow(f, 1.0 / m_zeta) : f;
}

LevelDerivatives SuperellipseShape::Derivatives(Vec2 x) const
{
	LevelDerivatives d = RawSuperellipseDerivatives(m_terms, x);
	if (m_zeta > 0.0 && m_zeta != 1.0)
	{
		// λ = f^{1/ζ}: ∇λ = (1/ζ) f^{1/ζ−1} ∇f,
		// ∇²λ = (1/ζ) f^{1/ζ−1} ∇²f + (1/ζ)(1/ζ−1) f^{1/ζ−2} ∇f ∇fᵀ.
		const double f = d.value;
		if (f <= 0.0)
			return LevelDerivatives{}; // origin: λ, ∇λ vanish; the degree-0 Hessian has no limit
		const double p = 1.0 / m_zeta;
		const double g1 = p * std::pow(f, p - 1.0);
		const double g2 = p * (p - 1.0) * std::pow(f, p - 2.0);
		d.hessian = g1 * d.hessian + g2 * Outer(d.gradient);
		d.gradient = g1 * d.gradient;
		d.value = std::pow(f, p);
	}
	return d;
}

Vec2 SuperellipseShape::Gradient(Vec2 x) const
{
	return Derivatives(x).gradient;
}

double SuperellipseShape::RadiusAt(Vec2 u, double level) const
{
	const double F = m_zeta > 0.0 ? std::pow(std::max(level, 0.0), m_zeta) : level;
	if (!(F > 0.0))
		return 0.0;
	// f(t·u) = t^n·A + t^m·B.
	const double A = PowAbs(u.x / m_a, m_n, m_terms.nInt);
	const double B = PowAbs(u.y / m_b, m_m, m_terms.mInt);
	if (m_n == m_m)
		return RootOf(F / (A + B), m_n);
	if (A == 0.0)
		return std::pow(F / B, 1.0 / m_m);
	if (B == 0.0)
		return std::pow(F / A, 1.0 / m_n);
	// h(s) = A e^{ns} + B e^{ms} − F is convex and increasing in s = log t. Start where one term
	// alone reaches F (h ≥ 0 there): Newton then descends monotonically onto the root.
	double s = std::min(std::log(F / A) / m_n, std::log(F / B) / m_m);
	for (int it = 0; it < 100; ++it)
	{
		const double tn = A * std::exp(m_n * s), tm = B * std::exp(m_m * s);
		const double h = tn + tm - F;
		const double dh = m_n * tn + m_m * tm;
		const double step = h / dh;
		s -= step;
		if (!(std::fabs(step) > 1e-16 * std::max(1.0, std::fabs(s))))
			break;
	}
	return std::exp(s);
}

bool SuperellipseShape::FarCrossing(Vec2 x, Vec2 d, double& t) const
{
	if (m_n != 2.0 || m_m != 2.0)
		return SuperellipseFarCrossing(m_terms, x, d, t);
	// (X + t·D)² + (Y + t·E)² = 1 with X = x/a, D = dx/a, Y = y/b, E = dy/b (the own level is 1
	// in both forms: f^(1/ζ) = 1 where f = 1): A t² + 2 B t + C = 0, A = D² + E², B = X D + Y E,
	// C = X² + Y² − 1; the far crossing is its larger root.
	const double X = x.x * m_terms.invA, Y = x.y * m_terms.invB, D = d.x * m_terms.invA, E = d.y * m_terms.invB;
	return QuadraticFarRoot(D * D + E * E, X * D + Y * E, (X * X + Y * Y) - 1.0, t) == LineQuadratic::crosses;
}

bool SuperellipseShape::FarCrossingNear(Vec2 x, Vec2 d, double& t) const
{
	if (Kind() != BuiltinKinds::superellipse)
		return FarCrossing(x, d, t);
	return SmoothFarCrossingFrom(m_terms, x, d, std::min(m_a, m_b), t);
}

bool SuperellipseShape::LevelSmoothOver(Vec2 centre, double radius) const
{
	auto even = [](int k) { return k >= 2 && k % 2 == 0; };
	return (even(m_terms.nInt) || std::fabs(centre.x) >= radius) && (even(m_terms.mInt) || std::fabs(centre.y) >= radius) &&
	       (m_zeta <= 0.0 || Length(centre) >= radius);
}

double SuperellipseShape::LevelLowerBound(Vec2 centre, double radius) const
{
	// The level at the disc's point nearest the axes in each coordinate: f = |x/a|^n + |y/b|^m
	// is increasing in |x| and in |y| (and λ = f^{1/ζ} in f). A NaN centre gives NaN, which the
	// grid's comparisons treat as no pruning.
	const Vec2 near(std::max(std::fabs(centre.x) - radius, 0.0), std::max(std::fabs(centre.y) - radius, 0.0));
	return Level(near);
}

bool SuperellipseShape::LineMisses(Vec2 x, Vec2 d) const
{
	const double X = x.x * m_terms.invA, Y = x.y * m_terms.invB, D = d.x * m_terms.invA, E = d.y * m_terms.invB;
	if (!std::isfinite(X + Y + D + E))
		return false;
	if (m_n == 2.0 && m_m == 2.0)
	{
		// FarCrossing's quadratic without a real root, clear of rounding.
		double t = 0.0;
		return QuadraticFarRoot(D * D + E * E, X * D + Y * E, (X * X + Y * Y) - 1.0, t) == LineQuadratic::misses;
	}
	// Other exponents: the particle lies in its box |X|, |Y| ≤ 1 (|X|^n ≤ 1 on it), so a line
	// missing the box misses the particle. The line is in the slab |X + tD| ≤ 1 for t between
	// (±1 − X)/D, and likewise for Y; the box is missed where the two intervals do not meet,
	// by more than 1e-12 of the slab (a line along an edge grazes).
	double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
	auto slab = [&](double p, double v) {
		if (v == 0.0)
			return std::fabs(p) <= 1.0 + 1e-12;
		const double t1 = (-1.0 - p) / v, t2 = (1.0 - p) / v, margin = 1e-12 / std::fabs(v);
		lo = std::max(lo, std::min(t1, t2) - margin);
		hi = std::min(hi, std::max(t1, t2) + margin);
		return true;
	};
	if (!slab(X, D) || !slab(Y, E))
		return true;
	return lo > hi;
}

Box SuperellipseShape::ComputeAABB(const Pose& pose) const
{
	// The particle is symmetric about its centre, h(−d) = h(d): the box is centred on the pose,
	// and its half-widths are the support values along the world axes pulled back, (c, −s) and
	// (s, c).
	const double c = pose.q.c, s = pose.q.s;
	const Vec2 half(SupportValue(Vec2(c, -s)), SupportValue(Vec2(s, c)));
	Box b;
	b.lower = pose.p - half;
	b.upper = pose.p + half;
	return b;
}

double SuperellipseShape::SupportValue(Vec2 d) const
{
	// h(d) = max X·e over the unit p-ball in scaled coordinates, e = (a·dx, b·dy): the dual norm
	// ‖e‖_q, 1/p + 1/q = 1. Components far from 1 go through Support, which normalises against
	// overflow and underflow (e^{4/3} of 1e-250 is below the double range).
	const double ex = std::fabs(m_a * d.x), ey = std::fabs(m_b * d.y);
	const double emax = std::max(ex, ey);
	if (m_n != m_m || !(emax >= 1e-100 && emax <= 1e100) || !(std::min(ex, ey) >= 1e-100 || std::min(ex, ey) == 0.0))
		return Dot(Support(d), d);
	if (m_n == 2.0)
		return std::sqrt(ex * ex + ey * ey);
	if (m_n == 1.0)
		return emax;
	if (m_n == 4.0)
	{
		// q = 4/3: t = ex^{4/3} + ey^{4/3}, h = t^{3/4} = √t·⁴√t.
		double cx, cy;
		CubeRoots(ex, ey, cx, cy);
		const double t = ex * cx + ey * cy;
		const double r = std::sqrt(t);
		return r * std::sqrt(r);
	}
	// Divided by the larger component, so that no power overflows (q grows without bound as n
	// approaches 1).
	const double q = m_n / (m_n - 1.0);
	return emax * std::pow(std::pow(ex / emax, q) + std::pow(ey / emax, q), 1.0 / q);
}

Vec2 SuperellipseShape::Support(Vec2 d) const { return SupportNear(d, 100); }

Vec2 SuperellipseShape::SupportNear(Vec2 d, int lagrangeSteps) const
{
	// In scaled coordinates X = x/a, Y = y/b the support of the unit p-ball along e = (a·dx, b·dy).
	Vec2 e(m_a * d.x, m_b * d.y);
	const double emax = std::max(std::fabs(e.x), std::fabs(e.y));
	if (!(emax > 0.0) || !std::isfinite(emax))
		return Vec2(m_a, 0.0);
	e = e / emax; // degree-0 homogeneous: normalise against overflow
	if (m_n == m_m)
	{
		const double p = m_n;
		if (p == 1.0)
			return std::fabs(e.x) >= std::fabs(e.y) ? Vec2(m_a * SignOf(e.x), 0.0) : Vec2(0.0, m_b * SignOf(e.y));
		// Hölder: X_i = sgn(e_i)|e_i|^{q−1} / ‖e‖_q^{q−1}, q = p/(p−1).
		if (p == 2.0)
		{
			// q = 2: the unit ellipse's support is e/|e| (no pow; ellipses are the commonest).
			const double norm = std::sqrt(e.x * e.x + e.y * e.y);
			return Vec2(m_a * e.x / norm, m_b * e.y / norm);
		}
		if (p == 4.0)
		{
			// q = 4/3: |e_i|^{1/3} by CubeRoot, and ‖e‖_q^{1/3} = (Σ|e_i|^{4/3})^{1/4} by two roots.
			double px, py;
			CubeRoots(std::fabs(e.x), std::fabs(e.y), px, py);
			const double norm = std::sqrt(std::sqrt(px * std::fabs(e.x) + py * std::fabs(e.y)));
			return Vec2(m_a * SignOf(e.x) * px / norm, m_b * SignOf(e.y) * py / norm);
		}
		// e is divided by its larger component, so that component's power is exactly 1 (no pow),
		// and ‖e‖_q^{q−1} = (Σ|e_i|^q)^{1/p} is a root RootOf takes by square roots for p = 8:
		// one pow, not three.
		const double q = p / (p - 1.0);
		const double ax = std::fabs(e.x), ay = std::fabs(e.y);
		const double px = ax == 1.0 ? 1.0 : std::pow(ax, q - 1.0), py = ay == 1.0 ? 1.0 : std::pow(ay, q - 1.0);
		const double norm = RootOf(px * ax + py * ay, p);
		return Vec2(m_a * SignOf(e.x) * px / norm, m_b * SignOf(e.y) * py / norm);
	}
	if (m_n == 1.0 || m_m == 1.0)
		return Shape::Support(d);
	if (e.x == 0.0)
		return Vec2(0.0, m_b * SignOf(e.y));
	if (e.y == 0.0)
		return Vec2(m_a * SignOf(e.x), 0.0);
	// Lagrange: |e_x| = κ n |X|^{n−1}, |e_y| = κ m |Y|^{m−1}, |X|^n + |Y|^m = 1. With s = log κ,
	// g(s) = exp(αx (cx − s)) + exp(αy (cy − s)) − 1, α = n/(n−1), c = log(|e|/n): convex and
	// decreasing, so Newton from the left (g ≥ 0) is monotone. Start at s = max(cx, cy): one term
	// is 1 there, so g ≥ 0, and neither term can overflow (from min(cx, cy) the other term is
	// exp(α·|cx − cy|), infinite for exponents near 1 or directions near an axis).
	const double ax = m_n / (m_n - 1.0), ay = m_m / (m_m - 1.0);
	const double cx = std::log(std::fabs(e.x) / m_n), cy = std::log(std::fabs(e.y) / m_m);
	// Stop at a step of 4e-16 |s|, two units in the last place: a bound of 1e-16, below s's own
	// resolution, let 7 % of directions (n = 4, m = 8) bounce between neighbouring doubles until
	// the cap, 100 steps of two exponentials where 6 suffice.
	double s = std::max(cx, cy);
	for (int it = 0; it < lagrangeSteps; ++it)
	{
		const double tx = std::exp(ax * (cx - s)), ty = std::exp(ay * (cy - s));
		const double g = tx + ty - 1.0;
		const double dg = -ax * tx - ay * ty;
		const double step = g / dg;
		s -= step;
		if (!(std::fabs(step) > 4e-16 * std::max(1.0, std::fabs(s))))
			break;
	}
	const double X = std::exp((cx - s) / (m_n - 1.0));
	const double Y = std::exp((cy - s) / (m_m - 1.0));
	return Vec2(m_a * SignOf(e.x) * X, m_b * SignOf(e.y) * Y);
}

void SuperellipseShape::SupportBounds(Vec2 d, double& lower, double& upper) const
{
	const double ex = std::fabs(m_a * d.x), ey = std::fabs(m_b * d.y);
	const double ellipse = std::sqrt(ex * ex + ey * ey);
	lower = std::max(ex, ey);
	upper = ex + ey;
	if (m_n >= 2.0 && m_m >= 2.0)
		lower = ellipse;
	if (m_n <= 2.0 && m_m <= 2.0)
		upper = ellipse;
	// Rounding margins: the tests using the bounds must never be decided by rounding (at n = m = 2
	// both are the ellipse's; near n = 1 or n = ∞ a bound meets h along the diagonals or axes).
	lower *= 1.0 - 1e-12;
	upper *= 1.0 + 1e-12;
	if (!std::isfinite(upper) || !std::isfinite(lower))
	{
		// Overflowing components: the exact value (Support normalises against overflow).
		lower = upper = SupportValue(d);
	}
}

MassProperties SuperellipseShape::ClosedFormMass(double a, double b, double n, double m)
{
	// Dirichlet: ∫∫_{u,v≥0, uⁿ+vᵐ≤1} u^{p−1} v^{q−1} = Γ(p/n)Γ(q/m) / (n m Γ(1 + p/n + q/m)).
	auto dirichlet = [&](double p, double q) {
		return std::exp(std::lgamma(p / n) + std::lgamma(q / m) - std::lgamma(1.0 + p / n + q / m)) / (n * m);
	};
	MassProperties mp;
	mp.area = 4.0 * a * b * dirichlet(1.0, 1.0);
	mp.Iyy = 4.0 * a * a * a * b * dirichlet(3.0, 1.0); // ∫x² dA
	mp.Ixx = 4.0 * a * b * b * b * dirichlet(1.0, 3.0); // ∫y² dA
	mp.Ixy = 0.0;
	mp.polarMoment = mp.Ixx + mp.Iyy;
	return mp;
}

std::shared_ptr<SuperellipseShape> MakeEllipse(double a, double b)
{
	return std::make_shared<SuperellipseShape>(a, b, 2.0, 2.0);
}

std::shared_ptr<SuperellipseShape> MakeCircle(double r)
{
	if (!std::isfinite(r) || !(r > 0.0))
		throw InvalidParameter("circle", "r", "must be finite and > 0", r);
	return std::make_shared<SuperellipseShape>(r, r, 2.0, 2.0);
}

std::shared_ptr<SuperellipseShape> MakeSuperellipse(double a, double b, double n, double m)
{
	return std::make_shared<SuperellipseShape>(a, b, n, m);
}

} // namespace b2a

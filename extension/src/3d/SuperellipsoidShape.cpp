// b2analytic: the superellipsoid family with closed forms.
#include "b2analytic/3d/SuperellipsoidShape.h"
#include "b2analytic/3d/ShapeKind3.h"

#include "3d/SurfaceGrid.h"
#include "geometry/SuperellipseTerms.h" // PowAbs, SignOf
#include "numerics/Powers.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace b2a
{

namespace
{
int SmallInteger(double e) { return (e == std::floor(e) && e >= 0.0 && e <= 64.0) ? int(e) : -1; }

ShapeKind KindOf(double a, double b, double c, double n1, double n2, double n3)
{
	if (n1 == 2.0 && n2 == 2.0 && n3 == 2.0)
		return (a == b && b == c) ? BuiltinKinds3::sphere : BuiltinKinds3::ellipsoid;
	return (n1 >= 2.0 && n2 >= 2.0 && n3 >= 2.0) ? BuiltinKinds3::superellipsoid : BuiltinKinds3::convexSuperellipsoid;
}

void RequirePositive(const char* what, const char* field, double v)
{
	if (!std::isfinite(v) || !(v > 0.0))
		throw InvalidParameter(what, field, "must be finite and > 0", v);
}

void RequireExponent(const char* what, const char* field, double v)
{
	if (!std::isfinite(v) || !(v >= 1.0))
		throw InvalidParameter(what, field, "must be finite and >= 1", v);
}

// The root s of Σᵢ exp(kᵢ(cᵢ − s)) = 1 over the "smooth" coordinates, with "linear" coordinates
// (threshold cᵢ) taking what is left where the root lies below their largest threshold: the
// water-filling form of the Lagrange conditions of the support point and of the farthest
// surface point. Writes each coordinate's share (they sum to 1) and returns s.
// The sum is convex and decreasing in s and equals at least 1 at s₀ = max cᵢ (its largest term
// is 1 there), so Newton from s₀ increases monotonically onto the root.
enum class Fill : int { absent, smooth, linear };
double WaterFill(const double c[3], const double k[3], const Fill kind[3], double share[3])
{
	double s = -std::numeric_limits<double>::infinity(), linearTop = s;
	int linearIndex = -1;
	bool anySmooth = false;
	for (int i = 0; i < 3; ++i)
	{
		share[i] = 0.0;
		if (kind[i] == Fill::smooth)
		{
			anySmooth = true;
			s = std::max(s, c[i]);
		}
		else if (kind[i] == Fill::linear && c[i] > linearTop)
		{
			linearTop = c[i];
			linearIndex = i;
		}
	}
	auto terms = [&](double at, double out[3]) {
		double sum = 0.0, slope = 0.0;
		for (int i = 0; i < 3; ++i)
		{
			out[i] = kind[i] == Fill::smooth ? std::exp(k[i] * (c[i] - at)) : 0.0;
			sum += out[i];
			slope -= k[i] * out[i];
		}
		return std::make_pair(sum - 1.0, slope);
	};
	if (anySmooth)
	{
		for (int it = 0; it < 100; ++it)
		{
			double t[3];
			const auto [phi, slope] = terms(s, t);
			if (!(phi > 0.0) || !(slope < 0.0))
				break;
			const double step = -phi / slope;
			s += step;
			if (step <= 4e-16 * std::max(1.0, std::fabs(s)))
				break;
		}
	}
	if (linearIndex >= 0 && !(s >= linearTop))
		s = linearTop;
	double t[3];
	terms(s, t);
	double used = 0.0;
	for (int i = 0; i < 3; ++i)
		if (kind[i] == Fill::smooth)
		{
			share[i] = std::min(t[i], 1.0);
			used += share[i];
		}
	if (linearIndex >= 0)
		share[linearIndex] = std::max(0.0, 1.0 - used);
	return s;
}

double LogGammaRatio(const double k[3], const double n[3], const double a[3])
{
	// log of Π [aᵢ^{kᵢ+1} Γ((kᵢ+1)/nᵢ)/nᵢ] / Γ(1 + Σ (kᵢ+1)/nᵢ)
	double sum = 0.0, total = 1.0;
	for (int i = 0; i < 3; ++i)
	{
		const double e = (k[i] + 1.0) / n[i];
		sum += (k[i] + 1.0) * std::log(a[i]) + std::lgamma(e) - std::log(n[i]);
		total += e;
	}
	return sum - std::lgamma(total);
}
} // namespace

SuperellipsoidShape::SuperellipsoidShape(double a, double b, double c, double n1, double n2, double n3)
	: Shape3(KindOf(a, b, c, n1, n2, n3), 1.0, true, n1 >= 2.0 && n2 >= 2.0 && n3 >= 2.0,
	         // λ^(1/q) with q = min(nᵢ)/2 is a q-norm of convex terms, squared-like: convex and of
	         // degree about 2 (as the superellipse's).
	         std::max(1.0, 0.5 * std::min({n1, n2, n3}))),
	  m_axis{a, b, c}, m_exponent{n1, n2, n3}, m_integer{SmallInteger(n1), SmallInteger(n2), SmallInteger(n3)},
	  m_inverse{1.0 / a, 1.0 / b, 1.0 / c}, m_gradient{n1 / a, n2 / b, n3 / c},
	  m_hessian{n1 * (n1 - 1.0) / (a * a), n2 * (n2 - 1.0) / (b * b), n3 * (n3 - 1.0) / (c * c)},
	  m_equal(n1 == n2 && n2 == n3), m_quadric(0)
{
	const char* what = "superellipsoid";
	RequirePositive(what, "a", a);
	RequirePositive(what, "b", b);
	RequirePositive(what, "c", c);
	RequireExponent(what, "n1", n1);
	RequireExponent(what, "n2", n2);
	RequireExponent(what, "n3", n3);
	if (n1 == 2.0 && n2 == 2.0 && n3 == 2.0)
		m_quadric = (a == b && b == c) ? 2 : 1;
	// Lengths and exponents whose powers leave double precision's range have no usable surface
	// (|1/a|^n underflowing or overflowing): each axis end must come back as the semi-axis, and
	// points between the axes must lie on the surface inside the box |xᵢ| ≤ aᵢ.
	static const char* const axisField[3] = {"a", "b", "c"};
	static const char* const exponentField[3] = {"n1", "n2", "n3"};
	auto near = [](double value, double expected) { return std::fabs(value - expected) <= 1e-9 * expected; };
	for (int i = 0; i < 3; ++i)
	{
		Vec3 u;
		u[i] = 1.0;
		if (!near(RadiusAt(u, 1.0), m_axis[i]))
			throw InvalidParameter(what, axisField[i],
			                       "must keep |x/a|^n within double precision's range (exponent " + FormatNumber(m_exponent[i]) + ")",
			                       m_axis[i]);
	}
	for (int k = 0; k < 27; ++k)
	{
		const double t = (1 + k % 3) * kPi / 8.0, p = (k / 3 - 4) * kPi / 10.0;
		const Vec3 u = Normalize(Vec3(a * std::cos(p) * std::cos(t), b * std::cos(p) * std::sin(t), c * std::sin(p)));
		const double r = RadiusAt(u, 1.0);
		const Vec3 x = r * u;
		bool inBox = true;
		for (int i = 0; i < 3; ++i)
			inBox = inBox && std::fabs(x[i]) <= (1.0 + 1e-9) * m_axis[i];
		if (!(r > 0.0) || !std::isfinite(r) || !inBox || !near(Level(x), 1.0))
		{
			const int i = int(std::max_element(m_exponent, m_exponent + 3) - m_exponent);
			throw InvalidParameter(what, exponentField[i],
			                       "must keep |x/a|^n1 + |y/b|^n2 + |z/c|^n3 within double precision's range between the axes",
			                       m_exponent[i]);
		}
	}
	const MassProperties3 mass = ClosedFormMass(a, b, c, n1, n2, n3);
	if (!std::isfinite(mass.volume) || !(mass.volume > 0.0) || !std::isfinite(mass.inertia.xx + mass.inertia.yy + mass.inertia.zz))
		throw InvalidParameter(what, "a", "must keep the volume and inertia within double precision's range", a);
	Finalize(FarthestDistance(), mass);
}

std::string SuperellipsoidShape::Describe() const
{
	const double a = m_axis[0], b = m_axis[1], c = m_axis[2];
	if (m_quadric == 2)
		return "sphere(r=" + FormatNumber(a) + ")";
	if (m_quadric == 1)
		return "ellipsoid(a=" + FormatNumber(a) + ", b=" + FormatNumber(b) + ", c=" + FormatNumber(c) + ")";
	return "superellipsoid(a=" + FormatNumber(a) + ", b=" + FormatNumber(b) + ", c=" + FormatNumber(c) +
	       ", n1=" + FormatNumber(m_exponent[0]) + ", n2=" + FormatNumber(m_exponent[1]) + ", n3=" + FormatNumber(m_exponent[2]) + ")";
}

double SuperellipsoidShape::Term(double x, int i) const { return PowAbs(x * m_inverse[i], m_exponent[i], m_integer[i]); }

double SuperellipsoidShape::Level(Vec3 x) const
{
	if (m_quadric)
	{
		const double X = x.x * m_inverse[0], Y = x.y * m_inverse[1], Z = x.z * m_inverse[2];
		return X * X + Y * Y + Z * Z;
	}
	return Term(x.x, 0) + Term(x.y, 1) + Term(x.z, 2);
}

LevelDerivatives3 SuperellipsoidShape::Derivatives(Vec3 x) const
{
	// f = Σ |Xᵢ|^nᵢ with Xᵢ = xᵢ/aᵢ: ∂f/∂xᵢ = (nᵢ/aᵢ) sgn(Xᵢ)|Xᵢ|^{nᵢ−1},
	// ∂²f/∂xᵢ² = nᵢ(nᵢ−1)/aᵢ² |Xᵢ|^{nᵢ−2}, and no mixed terms.
	LevelDerivatives3 d;
	double hess[3];
	for (int i = 0; i < 3; ++i)
	{
		const double n = m_exponent[i];
		const int k = m_integer[i];
		const double X = x[i] * m_inverse[i], ax = std::fabs(X);
		const double p2 = (n < 2.0 && ax == 0.0) ? 0.0 : PowAbs(ax, n - 2.0, k >= 2 ? k - 2 : -1);
		const double p1 = n >= 2.0 ? p2 * ax : PowAbs(ax, n - 1.0, k >= 1 ? k - 1 : -1);
		d.value += p1 * ax;
		d.gradient[i] = m_gradient[i] * (n >= 2.0 ? std::copysign(p1, X) : SignOf(X) * p1);
		hess[i] = m_hessian[i] * p2;
	}
	d.hessian.xx = hess[0];
	d.hessian.yy = hess[1];
	d.hessian.zz = hess[2];
	return d;
}

Vec3 SuperellipsoidShape::Gradient(Vec3 x) const
{
	Vec3 g;
	for (int i = 0; i < 3; ++i)
	{
		const double n = m_exponent[i];
		const int k = m_integer[i];
		const double X = x[i] * m_inverse[i];
		g[i] = m_gradient[i] * SignOf(X) * PowAbs(X, n - 1.0, k >= 1 ? k - 1 : -1);
	}
	return g;
}

namespace
{
// The scale t > 0 with Σ sᵢ t^{nᵢ} = L (sᵢ ≥ 0, not all 0): in ρ = log t the left side's log,
// log Σ exp(log sᵢ + nᵢρ), is convex and increasing, and every term alone is at most L at the
// root, so ρ ≤ min over i of (log L − log sᵢ)/nᵢ; Newton from that bound descends monotonically.
double RayScale(const double s[3], const double n[3], double level)
{
	const double logL = std::log(level);
	double rho = std::numeric_limits<double>::infinity();
	double logS[3];
	for (int i = 0; i < 3; ++i)
	{
		logS[i] = s[i] > 0.0 ? std::log(s[i]) : -std::numeric_limits<double>::infinity();
		if (s[i] > 0.0)
			rho = std::min(rho, (logL - logS[i]) / n[i]);
	}
	if (!std::isfinite(rho))
		return std::numeric_limits<double>::infinity();
	for (int it = 0; it < 100; ++it)
	{
		// Terms relative to the largest, so that the sum neither overflows nor underflows.
		double e[3], top = -std::numeric_limits<double>::infinity();
		for (int i = 0; i < 3; ++i)
		{
			e[i] = logS[i] + n[i] * rho;
			top = std::max(top, e[i]);
		}
		double sum = 0.0, weighted = 0.0;
		for (int i = 0; i < 3; ++i)
		{
			const double w = std::exp(e[i] - top);
			sum += w;
			weighted += n[i] * w;
		}
		const double g = top + std::log(sum) - logL;
		const double step = g / (weighted / sum);
		if (!(step > 0.0))
			break;
		rho -= step;
		if (step <= 4e-16 * std::max(1.0, std::fabs(rho)))
			break;
	}
	return std::exp(rho);
}
} // namespace

double SuperellipsoidShape::RadiusAt(Vec3 u, double level) const
{
	if (m_equal)
	{
		const double sum = m_quadric ? Level(u) : Term(u.x, 0) + Term(u.y, 1) + Term(u.z, 2);
		return RootOf(level / sum, m_exponent[0]);
	}
	const double s[3] = {Term(u.x, 0), Term(u.y, 1), Term(u.z, 2)};
	return RayScale(s, m_exponent, level);
}

Vec3 SuperellipsoidShape::PointOnRay(Vec3 x, double level) const
{
	const double s[3] = {Term(x.x, 0), Term(x.y, 1), Term(x.z, 2)};
	if (m_equal)
		return RootOf(level / (s[0] + s[1] + s[2]), m_exponent[0]) * x;
	return RayScale(s, m_exponent, level) * x;
}

bool SuperellipsoidShape::FarCrossing(Vec3 x, Vec3 d, double& t) const
{
	if (m_quadric)
	{
		// |X + tD|² = 1 in scaled coordinates X = x/a, D = d/a.
		const Vec3 X(x.x * m_inverse[0], x.y * m_inverse[1], x.z * m_inverse[2]);
		const Vec3 D(d.x * m_inverse[0], d.y * m_inverse[1], d.z * m_inverse[2]);
		return QuadraticFarRoot(LengthSquared(D), Dot(X, D), LengthSquared(X) - 1.0, t) == LineQuadratic::crosses;
	}
	// g(t) = f^{1/p} − 1 with p = min nᵢ is a p-norm of the convex terms |Xᵢ + tDᵢ|^{nᵢ/p}: convex.
	// From a t₀ where g rises, Newton lands beyond the largest root (from g < 0 the tangent, below
	// the convex g, crosses zero past it) and then descends onto it monotonically. t₀ = 0 where g
	// rises there (the contact's points lie close to the surface along its normal: two or three
	// steps), else beyond the bounding sphere. A slope that stops being positive means the line
	// misses.
	const double p = std::min({m_exponent[0], m_exponent[1], m_exponent[2]});
	const double dl = Length(d);
	if (!(dl > 0.0) || !IsFinite(x) || !IsFinite(d))
		return false;
	const double reach = (BoundingRadius() + Length(x)) / dl;
	const double tol = 1e-15 * reach;
	auto evaluate = [&](double s, double& g, double& slope) {
		const LevelDerivatives3 dv = Derivatives(x + s * d);
		if (!(dv.value > 0.0))
			return false;
		const double root = RootOf(dv.value, p);
		g = root - 1.0;
		slope = root / (p * dv.value) * Dot(dv.gradient, d);
		return std::isfinite(g) && std::isfinite(slope);
	};
	double s = 0.0, g = 0.0, slope = 0.0;
	if (!evaluate(s, g, slope) || !(slope > 0.0))
	{
		s = reach * (1.0 + 1e-6);
		if (!evaluate(s, g, slope))
			return false;
	}
	for (int it = 0; it < 100; ++it)
	{
		if (!(slope > 0.0))
			return false;
		const double step = g / slope;
		s -= step;
		if (it > 0 && step < -tol)
			return false; // after the first step the iterates descend: not convex here, or grazing
		if (std::fabs(step) <= tol || std::fabs(g) <= 4e-16)
		{
			t = s;
			return true;
		}
		if (!evaluate(s, g, slope))
			return false;
	}
	return false;
}

Vec3 SuperellipsoidShape::Support(Vec3 d) const
{
	const Vec3 e(m_axis[0] * d.x, m_axis[1] * d.y, m_axis[2] * d.z); // the problem in scaled coordinates
	const double top = MaxAbs(e);
	if (!(top > 0.0) || !std::isfinite(top))
		return {};
	const Vec3 u = e / top; // h is homogeneous in d
	Vec3 y;                 // the support point in scaled coordinates, Σ|yᵢ|^nᵢ = 1
	if (m_quadric)
		y = u / Length(u);
	else if (m_equal && m_exponent[0] > 1.0)
	{
		// Hölder: yᵢ = sgn(uᵢ) (|uᵢ|/‖u‖_q)^{q−1}, q = n/(n − 1).
		const double n = m_exponent[0], q = n / (n - 1.0);
		double sum = 0.0;
		for (int i = 0; i < 3; ++i)
			sum += std::pow(std::fabs(u[i]), q);
		const double norm = std::pow(sum, 1.0 / q);
		for (int i = 0; i < 3; ++i)
			y[i] = SignOf(u[i]) * std::pow(std::fabs(u[i]) / norm, q - 1.0);
	}
	else
	{
		// Lagrange: |uᵢ| = μ nᵢ |yᵢ|^{nᵢ−1}, so |yᵢ|^{nᵢ} = exp(kᵢ(cᵢ − log μ)) with kᵢ = nᵢ/(nᵢ − 1),
		// cᵢ = log(|uᵢ|/nᵢ), and the shares sum to 1; an exponent of 1 takes |yᵢ| linearly where
		// μ = |uᵢ| (WaterFill).
		double c[3], k[3], share[3];
		Fill kind[3];
		for (int i = 0; i < 3; ++i)
		{
			const double n = m_exponent[i];
			kind[i] = u[i] == 0.0 ? Fill::absent : (n > 1.0 ? Fill::smooth : Fill::linear);
			c[i] = n > 1.0 ? std::log(std::fabs(u[i]) / n) : std::log(std::fabs(u[i]));
			k[i] = n > 1.0 ? n / (n - 1.0) : 1.0;
		}
		WaterFill(c, k, kind, share);
		for (int i = 0; i < 3; ++i)
			y[i] = SignOf(u[i]) * (kind[i] == Fill::smooth ? std::pow(share[i], 1.0 / m_exponent[i]) : share[i]);
	}
	return {m_axis[0] * y.x, m_axis[1] * y.y, m_axis[2] * y.z};
}

double SuperellipsoidShape::SupportValue(Vec3 d) const
{
	const Vec3 e(m_axis[0] * d.x, m_axis[1] * d.y, m_axis[2] * d.z);
	if (m_quadric)
		return Length(e);
	if (m_equal)
	{
		const double top = MaxAbs(e);
		if (!(top > 0.0) || !std::isfinite(top))
			return 0.0;
		if (m_exponent[0] == 1.0)
			return top;
		const double q = m_exponent[0] / (m_exponent[0] - 1.0);
		double sum = 0.0;
		for (int i = 0; i < 3; ++i)
			sum += std::pow(std::fabs(e[i]) / top, q);
		return top * std::pow(sum, 1.0 / q);
	}
	return Dot(Support(d), d);
}

double SuperellipsoidShape::FarthestDistance() const
{
	// max |x|² over the surface: with sᵢ = |xᵢ/aᵢ|^{nᵢ} on the simplex Σ sᵢ = 1, |x|² = Σ aᵢ² sᵢ^{pᵢ},
	// pᵢ = 2/nᵢ. For nᵢ ≥ 2 every term is concave, so the maximum is the unique point of the
	// Lagrange conditions aᵢ² pᵢ sᵢ^{pᵢ−1} = μ: sᵢ = exp(kᵢ(cᵢ − log μ)), kᵢ = 1/(1 − pᵢ),
	// cᵢ = log(aᵢ² pᵢ), with nᵢ = 2 (pᵢ = 1) taking its share linearly at μ = aᵢ² (WaterFill).
	// An exponent below 2 is raised to 2: that shape contains this one, so its radius encloses it.
	double c[3], k[3], share[3], p[3];
	Fill kind[3];
	for (int i = 0; i < 3; ++i)
	{
		const double n = std::max(2.0, m_exponent[i]);
		p[i] = 2.0 / n;
		const double a2 = m_axis[i] * m_axis[i];
		kind[i] = n > 2.0 ? Fill::smooth : Fill::linear;
		c[i] = n > 2.0 ? std::log(a2 * p[i]) : std::log(a2);
		k[i] = n > 2.0 ? 1.0 / (1.0 - p[i]) : 1.0;
	}
	WaterFill(c, k, kind, share);
	double r2 = 0.0;
	for (int i = 0; i < 3; ++i)
		r2 += m_axis[i] * m_axis[i] * (p[i] == 1.0 ? share[i] : std::pow(share[i], p[i]));
	// The enclosing radius must not fall short by the roots' rounding.
	return std::sqrt(r2) * (1.0 + 4.0 * std::numeric_limits<double>::epsilon());
}

MassProperties3 SuperellipsoidShape::ClosedFormMass(double a, double b, double c, double n1, double n2, double n3)
{
	const double axis[3] = {a, b, c}, n[3] = {n1, n2, n3};
	auto octant = [&](double kx, double ky, double kz) {
		const double k[3] = {kx, ky, kz};
		return 8.0 * std::exp(LogGammaRatio(k, n, axis));
	};
	MassProperties3 m;
	m.volume = octant(0, 0, 0);
	const double xx = octant(2, 0, 0), yy = octant(0, 2, 0), zz = octant(0, 0, 2);
	m.secondMoment.xx = xx;
	m.secondMoment.yy = yy;
	m.secondMoment.zz = zz;
	m.inertia.xx = yy + zz;
	m.inertia.yy = xx + zz;
	m.inertia.zz = xx + yy;
	return m;
}

SurfaceSamples3 SuperellipsoidShape::BuildSamples(int count) const
{
	// The grid's direction (a·cos η cos ω, b·cos η sin ω, c·sin η) is the ellipsoid's own
	// parametrisation, taken to the surface along its ray; at the poles exactly (0, 0, ±c).
	const double a = m_axis[0], b = m_axis[1], c = m_axis[2];
	return BuildLatitudeLongitudeSamples(
		[&](double eta, double omega) {
			if (std::fabs(eta) >= 0.5 * kPi)
				return Vec3(0.0, 0.0, eta > 0.0 ? c : -c);
			const double ce = std::cos(eta);
			return PointOnRay(Vec3(a * ce * std::cos(omega), b * ce * std::sin(omega), c * std::sin(eta)), 1.0);
		},
		count);
}

std::shared_ptr<SuperellipsoidShape> MakeSphere(double r)
{
	if (!std::isfinite(r) || !(r > 0.0))
		throw InvalidParameter("sphere", "r", "must be finite and > 0", r);
	return std::make_shared<SuperellipsoidShape>(r, r, r, 2.0, 2.0, 2.0);
}

std::shared_ptr<SuperellipsoidShape> MakeEllipsoid(double a, double b, double c)
{
	return std::make_shared<SuperellipsoidShape>(a, b, c, 2.0, 2.0, 2.0);
}

std::shared_ptr<SuperellipsoidShape> MakeSuperellipsoid(double a, double b, double c, double n1, double n2, double n3)
{
	return std::make_shared<SuperellipsoidShape>(a, b, c, n1, n2, n3);
}

} // namespace b2a

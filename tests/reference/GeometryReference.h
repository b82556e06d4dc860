// b2analytic reference library: independent geometry references, for the geometry tests.
// Nothing here calls into the library except Shape::SurfacePoint / Level where a test says so;
// the formulas (long double level functions, polygon moments, golden-section refinement, user
// shape definitions) are written from scratch so that they can disagree with the library.
#pragma once

#include "ReferenceRandom.h"
#include "b2analytic/b2analytic.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace b2a::test
{

// ---------------------------------------------------------------------------------------------
// Level functions recomputed in long double (independent of the library's double code paths).

/// The smallest and largest of level(x) over 40 rings of 120 points covering the disc
/// |x − centre| ≤ radius, and at its centre: the reference of the level bounds' tests.
template <class Level>
void DiscLevelRange(Level&& level, Vec2 centre, double radius, double& lowest, double& highest)
{
	lowest = highest = level(centre);
	for (int ring = 1; ring <= 40; ++ring)
		for (int k = 0; k < 120; ++k)
		{
			const double t = 2.0 * kPi * k / 120.0;
			const double v = level(centre + (radius * ring / 40.0) * Vec2(std::cos(t), std::sin(t)));
			lowest = std::min(lowest, v);
			highest = std::max(highest, v);
		}
}

/// The smallest of level(x) over an 81 × 81 lattice covering the box, its edges included: the
/// reference of the box bounds' tests.
template <class Level>
double BoxLevelLowest(Level&& level, const OrientedBox& box)
{
	const Vec2 across(-box.axis.y, box.axis.x);
	double lowest = std::numeric_limits<double>::infinity();
	for (int i = 0; i <= 80; ++i)
		for (int j = 0; j <= 80; ++j)
		{
			const double s = box.halfLength * (i / 40.0 - 1.0), r = box.halfWidth * (j / 40.0 - 1.0);
			lowest = std::min(lowest, double(level(box.centre + s * box.axis + r * across)));
		}
	return lowest;
}

/// |x/a|^n + |y/b|^m, or its ζ-form (|x/a|^{2ζ} + |y/b|^{2ζ})^{1/ζ} when zeta > 0.
inline long double SuperellipseLevelRef(Vec2 p, double a, double b, double n, double m, double zeta = 0.0)
{
	const long double f = std::pow(std::fabs((long double)p.x / a), (long double)n) +
	                      std::pow(std::fabs((long double)p.y / b), (long double)m);
	return zeta > 0.0 ? std::pow(f, 1.0L / zeta) : f;
}

/// Level of the heart, α(x) = x² + y² − cbrt(x² y³) (docs/method.md, "Shape functions and levels"), in long double.
inline long double HeartLevelRef(Vec2 p)
{
	const long double x = p.x, y = p.y;
	return x * x + y * y - std::cbrt(x * x * y * y * y);
}

/// Paper eq. 20 written as an implicit function: (x² + y² − L)³ − x² y³.
inline double HeartG(Vec2 p, double L)
{
	const double w = p.x * p.x + p.y * p.y - L;
	return w * w * w - p.x * p.x * p.y * p.y * p.y;
}

// ---------------------------------------------------------------------------------------------
// User shapes used as test subjects.

/// The heart as a user shape G(x, L) = (x² + y² − L)³ − x² y³ with its analytic gradient and
/// Hessian (no levelOf: the library finds the level by a root solve).
inline UserShapeDef UserHeartDef(double alpha)
{
	UserShapeDef def;
	def.name = "heart";
	def.level = alpha;
	def.function = HeartG;
	def.gradient = [](Vec2 p, double L) {
		const double w = p.x * p.x + p.y * p.y - L;
		return Vec2(6.0 * p.x * w * w - 2.0 * p.x * p.y * p.y * p.y, 6.0 * p.y * w * w - 3.0 * p.x * p.x * p.y * p.y);
	};
	def.hessian = [](Vec2 p, double L) {
		const double x = p.x, y = p.y, w = x * x + y * y - L;
		Sym22 h;
		h.xx = 6.0 * w * w + 24.0 * x * x * w - 2.0 * y * y * y;
		h.xy = 24.0 * x * y * w - 6.0 * x * y * y;
		h.yy = 6.0 * w * w + 24.0 * y * y * w - 6.0 * x * x * y;
		return h;
	};
	def.lengthScale = 1.5 * std::sqrt(alpha);
	def.cornerAngles = {0.5 * kPi, -0.5 * kPi};
	return def;
}

/// The ellipse x²/a² + y²/b² ≤ L as a user shape with no derivatives and no levelOf.
inline UserShapeDef UserEllipseDef(double a, double b)
{
	UserShapeDef def;
	def.name = "ellipse";
	def.function = [a, b](Vec2 p, double L) { return p.x * p.x / (a * a) + p.y * p.y / (b * b) - L; };
	def.convex = true;
	def.lengthScale = std::max(a, b);
	return def;
}

/// An ellipse with semi-axes a, b, rotated by phi and centred at c (the body origin must lie
/// inside it): G(x, L) = q(x) − L with q the ellipse's quadratic form about c. Its centroid is c
/// and its second moments about c are those of a rotated ellipse: a closed-form reference for a
/// shape whose centroid and product moment Ixy are not zero.
inline UserShapeDef OffsetEllipseDef(double a, double b, double phi, Vec2 c, bool giveLevelOf)
{
	auto q = [a, b, phi, c](Vec2 p) {
		const Vec2 d = InvRotate(Rot(phi), p - c);
		return d.x * d.x / (a * a) + d.y * d.y / (b * b);
	};
	UserShapeDef def;
	def.name = "offset ellipse";
	def.function = [q](Vec2 p, double L) { return q(p) - L; };
	if (giveLevelOf)
		def.levelOf = q;
	def.convex = true;
	def.lengthScale = std::max(a, b);
	return def;
}

// ---------------------------------------------------------------------------------------------
// Polygon moments (Green's theorem on the polygon through the given vertices, counter-clockwise).

struct PolygonMoments
{
	double area = 0.0;
	Vec2 centroid;
	double Ixx = 0.0; ///< ∫(y − cy)² dA
	double Iyy = 0.0; ///< ∫(x − cx)² dA
	double Ixy = 0.0; ///< ∫(x − cx)(y − cy) dA
};

/// Area, centroid and central second moments of a simple polygon (shoelace-type formulas,
/// accumulated in long double).
inline PolygonMoments PolygonMass(const std::vector<Vec2>& v)
{
	long double A2 = 0, Sx = 0, Sy = 0, Sxx = 0, Syy = 0, Sxy = 0;
	const size_t n = v.size();
	for (size_t i = 0; i < n; ++i)
	{
		const long double x0 = v[i].x, y0 = v[i].y, x1 = v[(i + 1) % n].x, y1 = v[(i + 1) % n].y;
		const long double c = x0 * y1 - x1 * y0;
		A2 += c;
		Sx += (x0 + x1) * c;
		Sy += (y0 + y1) * c;
		Sxx += (x0 * x0 + x0 * x1 + x1 * x1) * c;
		Syy += (y0 * y0 + y0 * y1 + y1 * y1) * c;
		Sxy += (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * c;
	}
	const long double A = A2 / 2, cx = Sx / (6 * A), cy = Sy / (6 * A);
	PolygonMoments pm;
	pm.area = double(A);
	pm.centroid = Vec2(double(cx), double(cy));
	pm.Iyy = double(Sxx / 12 - A * cx * cx);
	pm.Ixx = double(Syy / 12 - A * cy * cy);
	pm.Ixy = double(Sxy / 24 - A * cx * cy);
	return pm;
}

/// n surface points at uniformly spaced polar angles −π + 2πk/n (n divisible by 4 puts vertices
/// exactly on the axes, where the heart's cusps and the superellipses' axis points are).
inline std::vector<Vec2> SurfacePolygon(const Shape& s, int n)
{
	std::vector<Vec2> v(n);
	for (int k = 0; k < n; ++k)
		v[k] = s.SurfacePoint(-kPi + 2.0 * kPi * k / n);
	return v;
}

// ---------------------------------------------------------------------------------------------
// Brute-force extremes over the surface: a dense polygon, then golden-section refinement.

/// Largest value of g(θ) found by golden-section search on [lo, hi] (assumed unimodal there).
inline double GoldenMax(const std::function<double(double)>& g, double lo, double hi)
{
	const double r = 0.6180339887498949;
	double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
	double g1 = g(x1), g2 = g(x2), best = std::max(g1, g2);
	for (int it = 0; it < 120 && hi - lo > 1e-17; ++it)
	{
		if (g1 < g2) { lo = x1; x1 = x2; g1 = g2; x2 = lo + r * (hi - lo); g2 = g(x2); best = std::max(best, g2); }
		else { hi = x2; x2 = x1; g2 = g1; x1 = hi - r * (hi - lo); g1 = g(x1); best = std::max(best, g1); }
	}
	return best;
}

/// A dense surface sampling that can be maximised over repeatedly.
struct DenseSurface
{
	const Shape* shape = nullptr;
	std::vector<double> theta;
	std::vector<Vec2> point;

	DenseSurface(const Shape& s, int n) : shape(&s), theta(n), point(n)
	{
		for (int k = 0; k < n; ++k)
		{
			theta[k] = -kPi + 2.0 * kPi * (k + 0.5) / n; // off the axes: corners are found by refinement
			point[k] = s.SurfacePoint(theta[k]);
		}
	}

	/// Max of g over the dense points (polygonMax), and the refined max over the true surface:
	/// golden section between the neighbours of the best dense point.
	double Max(const std::function<double(Vec2)>& g, double* polygonMax = nullptr) const
	{
		const int n = int(point.size());
		int best = 0;
		for (int k = 1; k < n; ++k)
			if (g(point[k]) > g(point[best])) best = k;
		const double pmax = g(point[best]);
		if (polygonMax) *polygonMax = pmax;
		const double step = 2.0 * kPi / n;
		const double refined = GoldenMax([&](double t) { return g(shape->SurfacePoint(t)); }, theta[best] - step, theta[best] + step);
		return std::max(pmax, refined);
	}
};

// ---------------------------------------------------------------------------------------------
// A catalogue covering every shape kind, each with an independent long-double level function.

struct ShapeCase
{
	std::string name;
	ShapePtr shape;
	/// Independent level function (long double, written in the tests).
	std::function<long double(Vec2)> levelRef;
	/// Largest exponent of the level function in r (sets finite-difference steps: λ ~ r^p).
	double power = 2.0;
	/// The level function has no bounded third derivative near the axis x = 0 (resp. y = 0):
	/// finite differences lose their accuracy near it (and below exponent 2 it is not even
	/// twice differentiable), so random derivative checks keep away from it; the conventions on
	/// the axes are tested separately.
	bool avoidX0 = false;
	bool avoidY0 = false;
	/// A range of levels at which the level sets are well-conditioned (see LevelSetTests).
	double levelLo = 1e-3, levelHi = 1e3;
	/// The library's own derivatives are finite differences (user shapes): looser tolerances.
	bool numericDerivatives = false;
	/// The level is a difference of larger terms (the heart: r² − cbrt(x²y³)) and can cancel to
	/// near 0 off the surface: compare level values relative to r², the size of the terms.
	bool levelCancels = false;
};

inline ShapeCase SuperellipseCase(const std::string& name, double a, double b, double n, double m)
{
	ShapeCase c;
	c.name = name;
	c.shape = MakeSuperellipse(a, b, n, m);
	c.levelRef = [=](Vec2 p) { return SuperellipseLevelRef(p, a, b, n, m); };
	c.power = std::max(n, m);
	// |t|^e has a bounded third derivative near t = 0 only for e = 2 or e ≥ 3.
	c.avoidX0 = n < 3.0 && n != 2.0;
	c.avoidY0 = m < 3.0 && m != 2.0;
	return c;
}

inline ShapeCase ZetaCase(const std::string& name, double a, double b, double zeta)
{
	ShapeCase c;
	c.name = name;
	c.shape = SuperellipseShape::FromZeta(a, b, zeta);
	c.levelRef = [=](Vec2 p) { return SuperellipseLevelRef(p, a, b, 2 * zeta, 2 * zeta, zeta); };
	c.power = 2.0;
	c.avoidX0 = c.avoidY0 = 2.0 * zeta < 3.0 && zeta != 1.0;
	return c;
}

inline ShapeCase HeartCase(const std::string& name, double alpha)
{
	ShapeCase c;
	c.name = name;
	c.shape = MakeHeart(alpha);
	c.levelRef = HeartLevelRef;
	c.avoidX0 = true;
	c.levelCancels = true;
	// At small levels the heart's level r² − cbrt(x²y³) is a difference of terms much larger
	// than the level itself near the lobes: its rounding error grows like 1/L (measured 2e-14
	// at L = 1e-3, 2e-13 at L = 1e-4), so 1e-12 relative holds from L = 1e-3 on.
	c.levelLo = 1e-3;
	c.levelHi = 1e3;
	return c;
}

/// Every shape kind the library offers, with parameters chosen to exercise each code path
/// (integer fast paths, non-integer exponents, n ≠ m, exponents below 2, the ζ-form, the heart,
/// user shapes with and without derivatives).
inline std::vector<ShapeCase> MakeAllShapeKinds()
{
	std::vector<ShapeCase> all;
	{
		ShapeCase c;
		c.name = "circle r=1.7";
		c.shape = MakeCircle(1.7);
		c.levelRef = [](Vec2 p) { return SuperellipseLevelRef(p, 1.7, 1.7, 2, 2); };
		all.push_back(c);
	}
	{
		ShapeCase c;
		c.name = "ellipse a=3 b=0.8";
		c.shape = MakeEllipse(3.0, 0.8);
		c.levelRef = [](Vec2 p) { return SuperellipseLevelRef(p, 3.0, 0.8, 2, 2); };
		all.push_back(c);
	}
	{
		ShapeCase c;
		c.name = "ellipse 1000:1 a=0.1 b=100";
		c.shape = MakeEllipse(0.1, 100.0);
		c.levelRef = [](Vec2 p) { return SuperellipseLevelRef(p, 0.1, 100.0, 2, 2); };
		all.push_back(c);
	}
	all.push_back(SuperellipseCase("superellipse n=m=4", 2.0, 1.0, 4.0, 4.0));
	all.push_back(SuperellipseCase("superellipse n=3 m=5", 1.5, 2.5, 3.0, 5.0));
	all.push_back(SuperellipseCase("superellipse n=2.5 m=3.7", 1.2, 0.7, 2.5, 3.7));
	all.push_back(SuperellipseCase("superellipse n=7.3 m=2", 0.9, 1.6, 7.3, 2.0));
	all.push_back(SuperellipseCase("superellipse n=m=1.5", 1.0, 2.0, 1.5, 1.5));
	all.push_back(SuperellipseCase("superellipse n=1 m=3", 1.3, 0.6, 1.0, 3.0));
	all.push_back(SuperellipseCase("superellipse n=m=60", 1.0, 0.5, 60.0, 60.0));
	all.push_back(ZetaCase("zeta form zeta=1.5", 2.0, 1.0, 1.5));
	all.push_back(ZetaCase("zeta form zeta=0.8", 1.0, 3.0, 0.8));
	all.push_back(HeartCase("heart alpha=1", 1.0));
	all.push_back(HeartCase("heart alpha=2.5", 2.5));
	{
		ShapeCase c = HeartCase("user heart alpha=1.3 (analytic G derivatives)", 1.3);
		c.shape = MakeUserShape(UserHeartDef(1.3));
		// ∂G/∂L = −3 cbrt(x²y³)² vanishes on y = 0 too: the implicit-function derivatives
		// degrade there (see UserShapeTests), so this sweep keeps away from both axes.
		c.avoidY0 = true;
		c.numericDerivatives = true;
		all.push_back(c);
	}
	{
		ShapeCase c;
		c.name = "user ellipse a=2 b=1.2 (no derivatives)";
		c.shape = MakeUserShape(UserEllipseDef(2.0, 1.2));
		c.levelRef = [](Vec2 p) { return SuperellipseLevelRef(p, 2.0, 1.2, 2, 2); };
		c.numericDerivatives = true;
		all.push_back(c);
	}
	return all;
}

/// The catalogue, built once and shared by all tests (shapes are immutable).
inline const std::vector<ShapeCase>& AllShapeKinds()
{
	static const std::vector<ShapeCase> cases = MakeAllShapeKinds();
	return cases;
}

/// The catalogue entry with this name.
inline const ShapeCase& FindShapeCase(const std::string& name)
{
	for (const ShapeCase& c : AllShapeKinds())
		if (c.name == name) return c;
	throw std::logic_error("no shape case named " + name);
}

/// A random body point for derivative checks: polar angle uniform (rejected within ~6° of an
/// axis to avoid), radius between 0.3 and 2 times the surface radius in that direction.
inline Vec2 RandomPointNearSurface(Random& rng, const ShapeCase& c)
{
	for (;;)
	{
		const double t = rng.Angle();
		const Vec2 u(std::cos(t), std::sin(t));
		if ((c.avoidX0 && std::fabs(u.x) < 0.1) || (c.avoidY0 && std::fabs(u.y) < 0.1))
			continue;
		return rng.Uniform(0.3, 2.0) * c.shape->RadiusAt(u, c.shape->SurfaceLevel()) * u;
	}
}

} // namespace b2a::test

// Mass(): area, centroid and central second moments against closed forms and fine polygons.
#include <doctest/doctest.h>

#include "GeometryReference.h"
#include "TestSupport.h"

#include <array>
#include <cmath>
#include <utility>

using namespace b2a;
using namespace b2a::test;

namespace
{
void CheckMass(const MassProperties& mp, double area, Vec2 centroid, double Ixx, double Iyy, double Ixy, double tol)
{
	const double size = std::sqrt(area);
	CHECK(RelativeError(mp.area, area) < tol);
	CHECK(Distance(mp.centroid, centroid) <= tol * size);
	CHECK(RelativeError(mp.Ixx, Ixx) < tol);
	CHECK(RelativeError(mp.Iyy, Iyy) < tol);
	CHECK(std::fabs(mp.Ixy - Ixy) <= tol * (Ixx + Iyy));
	CHECK(RelativeError(mp.polarMoment, Ixx + Iyy) < tol);
	// The definition: polarMoment = ∫|x − c|² = Ixx + Iyy, whatever the values.
	CHECK(RelativeError(mp.polarMoment, mp.Ixx + mp.Iyy) < 1e-15);
}
} // namespace

TEST_CASE("mass: circle and ellipses match the closed forms")
{
	// Circle: πr², ∫y² = ∫x² = πr⁴/4. Ellipse: πab, Ixx = ∫y² = πab³/4, Iyy = ∫x² = πa³b/4.
	const double r = 1.7;
	CheckMass(MakeCircle(r)->Mass(), kPi * r * r, {}, kPi * std::pow(r, 4) / 4, kPi * std::pow(r, 4) / 4, 0.0, 1e-14);
	for (const auto& ab : {std::pair{3.0, 0.8}, std::pair{0.1, 100.0}, std::pair{100.0, 0.1}})
	{
		const double a = ab.first, b = ab.second;
		CAPTURE(a);
		CAPTURE(b);
		CheckMass(MakeEllipse(a, b)->Mass(), kPi * a * b, {}, kPi * a * b * b * b / 4, kPi * a * a * a * b / 4, 0.0, 1e-14);
		// The ζ = 1 normalised form is the same ellipse.
		CheckMass(SuperellipseShape::FromZeta(a, b, 1.0)->Mass(), kPi * a * b, {}, kPi * a * b * b * b / 4,
		          kPi * a * a * a * b / 4, 0.0, 1e-14);
	}
	// n = m = 1 is the rhombus with diagonals 2a, 2b: area 2ab, ∫x² = a³b/3, ∫y² = ab³/3.
	const double a = 2.0, b = 0.5;
	CheckMass(MakeSuperellipse(a, b, 1.0, 1.0)->Mass(), 2 * a * b, {}, a * b * b * b / 3, a * a * a * b / 3, 0.0, 1e-14);
}

TEST_CASE("mass: superellipses with growing n = m tend to the 2a x 2b rectangle")
{
	// Rectangle: area 4ab, ∫y² = 4ab³/3, ∫x² = 4a³b/3. For n = m the closed form's ratio to it is
	// Γ(1+1/n)²/Γ(1+2/n) (area) and Γ(1+1/n)Γ(1+3/n)/Γ(1+4/n) (moments). With
	// ln Γ(1+ε) = −γε + ζ(2)ε²/2 − ζ(3)ε³/3 + …, ε = 1/n, the deficits are (π²/6)ε² − 2ζ(3)ε³ + …
	// and (π²/2)ε² − 12ζ(3)ε³ + …: at n = 60 the leading term is 4.6e-4 (area) and 1.4e-3
	// (moments), and the cubic term lowers them by 2.4% and 4.9%. So the deficits lie in
	// [0.9, 1] × the leading term, and halve twice (ratio 4 × (1 − O(ε))) from n = 60 to 120.
	const double a = 1.5, b = 0.4;
	auto deficits = [&](double n) {
		const MassProperties mp = MakeSuperellipse(a, b, n, n)->Mass();
		return std::array<double, 3>{1 - mp.area / (4 * a * b), 1 - mp.Ixx / (4 * a * b * b * b / 3),
		                             1 - mp.Iyy / (4 * a * a * a * b / 3)};
	};
	const auto d60 = deficits(60.0), d120 = deficits(120.0);
	const double pi2 = kPi * kPi;
	const double lead[3] = {pi2 / 6 / 3600, pi2 / 2 / 3600, pi2 / 2 / 3600};
	for (int k = 0; k < 3; ++k)
	{
		CAPTURE(k);
		CHECK(d60[k] <= lead[k]);
		CHECK(d60[k] >= 0.9 * lead[k]);
	}
	CHECK(d60[0] < 1e-3);
	CHECK(d60[1] < 2e-3);
	for (int k = 0; k < 3; ++k)
	{
		CHECK(d120[k] > 0.0); // inscribed in the rectangle
		CHECK(d60[k] / d120[k] > 3.8);
		CHECK(d60[k] / d120[k] < 4.0);
	}
	// The closed form at n = 60 itself is confirmed by a fine polygon in the next test.
}

namespace
{
// Polygon references. The polygon through N surface points at equally spaced angles has
// moments with an error expansion c₂h² + c₄h⁴ + … (h = 2π/N) when the surface is smooth between
// vertices, so (i) N = 20000 is within ~(2π/N)² × (a shape factor of a few) ≈ 5e-7, and (ii) the
// Richardson combination (4 P(2N) − P(N))/3 of N = 10000 and 20000 removes the h² term.
// Where the curvature is infinite (exponents in (1, 2) on an axis, the heart's cusps) the
// expansion has fractional powers and Richardson leaves a larger residual: `richardsonTol`.
void CheckAgainstPolygon(const Shape& s, double richardsonTol)
{
	CAPTURE(s.Describe());
	const MassProperties& mp = s.Mass();
	const PolygonMoments p1 = PolygonMass(SurfacePolygon(s, 10000));
	const PolygonMoments p2 = PolygonMass(SurfacePolygon(s, 20000));
	const double size = std::sqrt(mp.area), J = mp.polarMoment;
	// (i) the fine polygon alone.
	CHECK(RelativeError(mp.area, p2.area) < 5e-7);
	CHECK(Distance(mp.centroid, p2.centroid) < 5e-7 * size);
	CHECK(RelativeError(mp.Ixx, p2.Ixx) < 5e-7);
	CHECK(RelativeError(mp.Iyy, p2.Iyy) < 5e-7);
	CHECK(std::fabs(mp.Ixy - p2.Ixy) < 5e-7 * J);
	// (ii) Richardson extrapolation.
	auto R = [](double x1, double x2) { return (4 * x2 - x1) / 3; };
	CHECK(RelativeError(mp.area, R(p1.area, p2.area)) < richardsonTol);
	CHECK(std::fabs(mp.centroid.x - R(p1.centroid.x, p2.centroid.x)) < richardsonTol * size);
	CHECK(std::fabs(mp.centroid.y - R(p1.centroid.y, p2.centroid.y)) < richardsonTol * size);
	CHECK(RelativeError(mp.Ixx, R(p1.Ixx, p2.Ixx)) < richardsonTol);
	CHECK(RelativeError(mp.Iyy, R(p1.Iyy, p2.Iyy)) < richardsonTol);
	CHECK(std::fabs(mp.Ixy - R(p1.Ixy, p2.Ixy)) < richardsonTol * J);
	CHECK(RelativeError(mp.polarMoment, mp.Ixx + mp.Iyy) < 1e-15);
}
} // namespace

TEST_CASE("mass: closed forms for n != m and non-integer exponents agree with a fine polygon")
{
	// Smooth between the polygon's vertices: Richardson residuals measured at 1e-14 to 1e-12.
	CheckAgainstPolygon(*MakeSuperellipse(1.5, 2.5, 3.0, 5.0), 1e-11);
	CheckAgainstPolygon(*MakeSuperellipse(1.2, 0.7, 2.5, 3.7), 1e-11);
	CheckAgainstPolygon(*MakeSuperellipse(0.9, 1.6, 7.3, 2.0), 1e-11);
	CheckAgainstPolygon(*MakeSuperellipse(1.3, 0.6, 1.0, 3.0), 1e-11); // the corners are vertices
	CheckAgainstPolygon(*MakeSuperellipse(1.0, 0.5, 60.0, 60.0), 1e-11);
	// Infinite curvature on the axes (exponent 1.5, 1.6): residuals measured at ~7e-10.
	CheckAgainstPolygon(*MakeSuperellipse(1.0, 2.0, 1.5, 1.5), 5e-9);
	CheckAgainstPolygon(*SuperellipseShape::FromZeta(1.0, 3.0, 0.8), 5e-9);
}

TEST_CASE("mass: heart (numerical quadrature) agrees with a fine polygon")
{
	// Cusps: the centroid and Ixx converge like h^{5/3}; Richardson residual measured ~7e-8.
	CheckAgainstPolygon(*MakeHeart(1.0), 5e-7);
	CheckAgainstPolygon(*MakeHeart(2.5), 5e-7);
	CheckAgainstPolygon(*MakeUserShape(UserHeartDef(1.3)), 5e-7);
}

TEST_CASE("mass: off-centre rotated user ellipse has the centroid and product moment of the closed form")
{
	// Ellipse a = 2, b = 0.7 rotated by φ = 0.6 about c = (0.5, −0.3): centroid c, area πab,
	// central moments (πab/4) R diag(a², b²) Rᵀ, i.e. Iyy = ∫(x−cx)² = (πab/4)(a²cos²φ + b²sin²φ),
	// Ixx = (πab/4)(a²sin²φ + b²cos²φ), Ixy = (πab/4)(a² − b²) cosφ sinφ.
	const double a = 2.0, b = 0.7, phi = 0.6;
	const Vec2 c(0.5, -0.3);
	const double k = kPi * a * b / 4, cs = std::cos(phi), sn = std::sin(phi);
	const double Iyy = k * (a * a * cs * cs + b * b * sn * sn), Ixx = k * (a * a * sn * sn + b * b * cs * cs);
	const double Ixy = k * (a * a - b * b) * cs * sn;
	// With levelOf (fast) and with the root solve on G: quadrature to 1e-14 relative.
	CheckMass(MakeUserShape(OffsetEllipseDef(a, b, phi, c, true))->Mass(), kPi * a * b, c, Ixx, Iyy, Ixy, 1e-13);
	const auto slow = MakeUserShape(OffsetEllipseDef(a, b, phi, c, false));
	CheckMass(slow->Mass(), kPi * a * b, c, Ixx, Iyy, Ixy, 1e-13);
	CheckAgainstPolygon(*slow, 1e-11);
}

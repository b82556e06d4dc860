// Gradients and Hessians of every shape kind against central finite differences at random points.
#include <doctest/doctest.h>

#include "GeometryReference.h"

#include <algorithm>
#include <cmath>

using namespace b2a;
using namespace b2a::test;

namespace
{

double MaxAbs(Sym22 h) { return std::max({std::fabs(h.xx), std::fabs(h.xy), std::fabs(h.yy)}); }

// Step-size reasoning. Near a point at distance r from the origin the level behaves like r^p, so
// its k-th derivative is about p^k λ / r^k. The central difference (f(x+h) − f(x−h))/2h has
//   truncation ≈ (h²/6) |f'''| ≈ (h p / r)² / 6 · |f'|   and   rounding ≈ ε |f| / h ≈ ε r / (h p) · |f'|.
// With h = 1e-5 r / p both are below about 2e-11 |f'|. Points closer than ~6° to an axis where the
// level has no bounded third derivative are not drawn (see RandomPointNearSurface), and the step
// never exceeds 1e-5 of the distance to such an axis.
double StepFor(const ShapeCase& c, Vec2 x, double relative)
{
	double scale = Length(x);
	if (c.avoidX0) scale = std::min(scale, std::fabs(x.x));
	if (c.avoidY0) scale = std::min(scale, std::fabs(x.y));
	return relative * scale / std::max(1.0, c.power);
}

void CheckDerivativesAgainstFiniteDifferences(const ShapeCase& c, std::uint64_t seed)
{
	CAPTURE(c.name);
	const Shape& s = *c.shape;
	Random rng(seed);
	// Gradient: 1e-8 relative leaves a margin of ~100 over the error budget above (also for user
	// shapes, whose Level is a root solve good to ~4ε and whose gradient uses the implicit
	// function theorem or differences with step 1e-6 · lengthScale).
	const double gradTol = 1e-8;
	// Hessian: differences of the library's gradient. For analytic shapes step 1e-5 r/p as above
	// and 1e-8 relative (observed worst case 6e-10, for n = 60). For user shapes the library's
	// gradient itself carries ~1e-10 relative rounding noise (it is a difference quotient), which
	// a 1e-5 step would amplify to 1e-5; step 1e-3 r/p keeps noise and truncation near 1e-7, and
	// the library's Hessian there is a difference quotient too (≈1e-6): tolerance 1e-5.
	const double hessStep = c.numericDerivatives ? 1e-3 : 1e-5;
	const double hessTol = c.numericDerivatives ? 1e-5 : 1e-8;
	for (int i = 0; i < 250; ++i)
	{
		const Vec2 x = RandomPointNearSurface(rng, c);
		CAPTURE(i);
		CAPTURE(x.x);
		CAPTURE(x.y);
		const LevelDerivatives d = s.Derivatives(x);
		const double r = Length(x);

		// Level value: the library against the independent long-double formula.
		const double ref = double(c.levelRef(x));
		const double levelScale = c.levelCancels ? r * r : std::fabs(ref);
		CHECK(std::fabs(d.value - ref) <= 1e-13 * levelScale);
		CHECK(std::fabs(d.value - s.Level(x)) <= 1e-13 * levelScale);
		const Vec2 g2 = s.Gradient(x);
		CHECK(Length(g2 - d.gradient) <= 1e-14 * Length(d.gradient));

		// Gradient by central differences of Level.
		const double h = StepFor(c, x, 1e-5);
		const Vec2 gfd((s.Level(x + Vec2(h, 0)) - s.Level(x - Vec2(h, 0))) / (2 * h),
		               (s.Level(x + Vec2(0, h)) - s.Level(x - Vec2(0, h))) / (2 * h));
		const double gScale = Length(d.gradient) + levelScale / r;
		CHECK(Length(gfd - d.gradient) <= gradTol * gScale);

		// Hessian by central differences of the gradient (itself checked just above).
		const double k = StepFor(c, x, hessStep);
		const Vec2 gxp = s.Gradient(x + Vec2(k, 0)), gxm = s.Gradient(x - Vec2(k, 0));
		const Vec2 gyp = s.Gradient(x + Vec2(0, k)), gym = s.Gradient(x - Vec2(0, k));
		const double hxx = (gxp.x - gxm.x) / (2 * k), hyy = (gyp.y - gym.y) / (2 * k);
		const double hxy = (gxp.y - gxm.y) / (2 * k), hyx = (gyp.x - gym.x) / (2 * k);
		const double hScale = MaxAbs(d.hessian) + Length(d.gradient) / r + levelScale / (r * r);
		CHECK(std::fabs(hxx - d.hessian.xx) <= hessTol * hScale);
		CHECK(std::fabs(hyy - d.hessian.yy) <= hessTol * hScale);
		CHECK(std::fabs(hxy - d.hessian.xy) <= hessTol * hScale);
		CHECK(std::fabs(hyx - d.hessian.xy) <= hessTol * hScale);
	}
}

} // namespace

TEST_CASE("derivatives: circle and ellipses match finite differences")
{
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("circle r=1.7"), 101);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("ellipse a=3 b=0.8"), 102);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("ellipse 1000:1 a=0.1 b=100"), 103);
}

TEST_CASE("derivatives: superellipses with integer exponents match finite differences")
{
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("superellipse n=m=4"), 111);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("superellipse n=3 m=5"), 112);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("superellipse n=m=60"), 113);
}

TEST_CASE("derivatives: superellipses with non-integer and low exponents match finite differences")
{
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("superellipse n=2.5 m=3.7"), 121);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("superellipse n=7.3 m=2"), 122);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("superellipse n=m=1.5"), 123);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("superellipse n=1 m=3"), 124);
}

TEST_CASE("derivatives: normalised zeta-form superellipses match finite differences")
{
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("zeta form zeta=1.5"), 131);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("zeta form zeta=0.8"), 132);
}

TEST_CASE("derivatives: heart matches finite differences off its axis of symmetry")
{
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("heart alpha=1"), 141);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("heart alpha=2.5"), 142);
}

TEST_CASE("derivatives: user shapes match finite differences")
{
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("user heart alpha=1.3 (analytic G derivatives)"), 151);
	CheckDerivativesAgainstFiniteDifferences(FindShapeCase("user ellipse a=2 b=1.2 (no derivatives)"), 152);
}

// SuperellipseShape: families, closed-form radii, the ζ-form, axis conventions, support points.
#include <doctest/doctest.h>

#include "GeometryReference.h"
#include "TestSupport.h"

#include <algorithm>
#include <cmath>
#include <string>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("superellipse: kind, flags and description follow the parameters")
{
	const auto circle = MakeCircle(2.0);
	CHECK(circle->Kind() == BuiltinKinds::circle);
	CHECK(circle->Describe() == "circle(r=2)");
	CHECK(std::string(KindName(circle->Kind())) == "circle");

	const auto ellipse = MakeEllipse(3.0, 0.5);
	CHECK(ellipse->Kind() == BuiltinKinds::ellipse);
	CHECK(ellipse->Describe() == "ellipse(a=3, b=0.5)");
	CHECK(ellipse->IsConvex());
	CHECK(ellipse->IsSmoothConvex());
	CHECK(ellipse->LevelPower() == 1.0);
	CHECK(ellipse->SurfaceLevel() == 1.0);

	// n = m = 2 with a = b is a circle whichever factory made it.
	CHECK(MakeSuperellipse(1.5, 1.5, 2.0, 2.0)->Kind() == BuiltinKinds::circle);
	CHECK(SuperellipseShape::FromZeta(1.5, 1.5, 1.0)->Kind() == BuiltinKinds::circle);
	CHECK(SuperellipseShape::FromZeta(1.5, 0.5, 1.0)->Kind() == BuiltinKinds::ellipse);

	const auto smooth = MakeSuperellipse(1.0, 2.0, 4.0, 6.0);
	CHECK(smooth->Kind() == BuiltinKinds::superellipse);
	CHECK(smooth->Describe() == "superellipse(a=1, b=2, n=4, m=6)");
	CHECK(smooth->IsConvex());
	CHECK(smooth->IsSmoothConvex());
	CHECK(smooth->DerivativesCheap());
	CHECK(ellipse->DerivativesCheap());
	CHECK(SuperellipseShape::FromZeta(2.0, 1.0, 1.5)->DerivativesCheap());
	CHECK(smooth->LevelPower() == 2.0); // min(n, m) / 2
	CHECK(smooth->N() == 4.0);
	CHECK(smooth->M() == 6.0);
	CHECK(!smooth->IsNormalised());

	// Exponents below 2: convex but with infinite curvature on an axis (Newton does not apply).
	const auto rough = MakeSuperellipse(1.0, 2.0, 1.5, 3.0);
	CHECK(rough->IsConvex());
	CHECK(!rough->IsSmoothConvex());
	CHECK(rough->LevelPower() == 1.0);

	const auto zeta = SuperellipseShape::FromZeta(2.0, 1.0, 1.5);
	CHECK(zeta->IsNormalised());
	CHECK(zeta->Zeta() == 1.5);
	CHECK(zeta->N() == 3.0);
	CHECK(zeta->M() == 3.0);
	CHECK(zeta->LevelPower() == 1.0);
	CHECK(zeta->Describe() == "superellipse(a=2, b=1, zeta=1.5)");
}

TEST_CASE("superellipse: the level power q makes Level^(1/q) convex")
{
	// LevelPower() promises that λ^(1/q) is convex. Check midpoint convexity on random pairs:
	// g((x+y)/2) ≤ (g(x) + g(y))/2, up to rounding (1e-13 of the larger side).
	const std::shared_ptr<const Shape> shapes[] = {MakeSuperellipse(1.0, 2.0, 4.0, 6.0), MakeSuperellipse(1.5, 0.7, 3.0, 5.0),
	                                               MakeSuperellipse(1.2, 0.7, 2.5, 3.7), MakeSuperellipse(1.0, 1.0, 60.0, 60.0),
	                                               SuperellipseShape::FromZeta(2.0, 1.0, 2.5)};
	for (const auto& s : shapes)
	{
		CAPTURE(s->Describe());
		const double q = s->LevelPower();
		Random rng(21);
		for (int i = 0; i < 2000; ++i)
		{
			const Vec2 x(rng.Uniform(-2, 2), rng.Uniform(-2, 2)), y(rng.Uniform(-2, 2), rng.Uniform(-2, 2));
			const double gm = std::pow(s->Level(0.5 * (x + y)), 1.0 / q);
			const double avg = 0.5 * (std::pow(s->Level(x), 1.0 / q) + std::pow(s->Level(y), 1.0 / q));
			CHECK(gm <= avg * (1.0 + 1e-13));
		}
	}
	// And the q promised is not just any q: for n = m = 60, λ itself (q = 1) is far from
	// quadratic, while λ^(1/30) is homogeneous of degree 2: λ^(1/q)(t x) = t² λ^(1/q)(x).
	const auto s60 = MakeSuperellipse(1.0, 1.0, 60.0, 60.0);
	CHECK(s60->LevelPower() == 30.0);
	const Vec2 x(0.3, -0.7);
	CHECK(RelativeError(std::pow(s60->Level(2.0 * x), 1.0 / 30.0), 4.0 * std::pow(s60->Level(x), 1.0 / 30.0)) < 1e-13);
}

TEST_CASE("superellipse: RadiusAt matches the polar closed forms")
{
	Random rng(31);
	// Ellipse: r(θ, L) = √L · ab / √(b² cos²θ + a² sin²θ); circle: r √L.
	const double a = 3.0, b = 0.8;
	const auto ellipse = MakeEllipse(a, b);
	const auto circle = MakeCircle(1.7);
	const auto needle = MakeEllipse(0.1, 100.0);
	for (int i = 0; i < 300; ++i)
	{
		const double t = rng.Angle(), L = rng.LogUniform(1e-4, 1e4);
		const Vec2 u(std::cos(t), std::sin(t));
		CHECK(RelativeError(ellipse->RadiusAt(u, L), std::sqrt(L) * a * b / std::hypot(b * u.x, a * u.y)) < 1e-14);
		CHECK(RelativeError(needle->RadiusAt(u, L), std::sqrt(L) * 0.1 * 100.0 / std::hypot(100.0 * u.x, 0.1 * u.y)) < 1e-14);
		CHECK(RelativeError(circle->RadiusAt(u, L), 1.7 * std::sqrt(L)) < 1e-14);
	}
	// n = m: r(θ, L) = L^{1/n} (|cos θ / a|^n + |sin θ / b|^n)^{−1/n} (long double), so
	// r(L) = r(1) L^{1/n}.
	for (double n : {1.0, 1.5, 2.0, 3.3, 4.0, 60.0})
	{
		CAPTURE(n);
		const auto s = MakeSuperellipse(1.3, 0.6, n, n);
		for (int i = 0; i < 100; ++i)
		{
			const double t = rng.Angle(), L = rng.LogUniform(1e-3, 1e3);
			const Vec2 u(std::cos(t), std::sin(t));
			const long double r1 = std::pow(std::pow(std::fabs(u.x / 1.3L), (long double)n) + std::pow(std::fabs(u.y / 0.6L), (long double)n), -1.0L / n);
			CHECK(RelativeError(s->RadiusAt(u, 1.0), double(r1)) < 1e-14);
			CHECK(RelativeError(s->RadiusAt(u, L), double(r1 * std::pow((long double)L, 1.0L / n))) < 1e-14);
		}
	}
	// ζ-form: level f^{1/ζ} means r(L) = r_f(L^ζ) = r(1) √L for every ζ (n = 2ζ).
	for (double zeta : {0.5, 0.8, 1.0, 2.5})
	{
		CAPTURE(zeta);
		const auto s = SuperellipseShape::FromZeta(2.0, 0.7, zeta);
		for (int i = 0; i < 100; ++i)
		{
			const Vec2 u = Rotate(Rot(rng.Angle()), Vec2(1, 0));
			const double L = rng.LogUniform(1e-3, 1e3);
			CHECK(RelativeError(s->RadiusAt(u, L), s->RadiusAt(u, 1.0) * std::sqrt(L)) < 1e-14);
		}
	}
	// n ≠ m along the axes: a L^{1/n} and b L^{1/m}.
	const auto s = MakeSuperellipse(1.5, 2.5, 3.0, 5.0);
	for (double L : {1e-3, 0.2, 1.0, 7.0, 1e3})
	{
		CHECK(RelativeError(s->RadiusAt(Vec2(1, 0), L), 1.5 * std::cbrt(L)) < 1e-14);
		CHECK(RelativeError(s->RadiusAt(Vec2(-1, 0), L), 1.5 * std::cbrt(L)) < 1e-14);
		CHECK(RelativeError(s->RadiusAt(Vec2(0, 1), L), 2.5 * std::pow(L, 0.2)) < 1e-14);
		CHECK(RelativeError(s->RadiusAt(Vec2(0, -1), L), 2.5 * std::pow(L, 0.2)) < 1e-14);
	}
}

TEST_CASE("superellipse: the zeta form is the same particle with level f^(1/zeta)")
{
	Random rng(41);
	for (double zeta : {0.5, 0.8, 1.5, 3.0})
	{
		CAPTURE(zeta);
		const auto z = SuperellipseShape::FromZeta(2.0, 0.7, zeta);
		const auto f = MakeSuperellipse(2.0, 0.7, 2 * zeta, 2 * zeta);
		for (int i = 0; i < 100; ++i)
		{
			const Vec2 x(rng.Uniform(-4, 4), rng.Uniform(-2, 2));
			CHECK(RelativeError(z->Level(x), std::pow(f->Level(x), 1.0 / zeta)) < 1e-14);
			const double t = rng.Angle();
			CHECK(Distance(z->SurfacePoint(t), f->SurfacePoint(t)) <= 1e-15 * 2.0);
		}
		CHECK(RelativeError(z->Mass().area, f->Mass().area) < 1e-15);
		CHECK(RelativeError(z->Mass().polarMoment, f->Mass().polarMoment) < 1e-15);
		CHECK(RelativeError(z->BoundingRadius(), f->BoundingRadius()) < 1e-14);
		const Vec2 d(0.3, -0.8);
		CHECK(Distance(z->Support(d), f->Support(d)) <= 1e-14);
	}
}

TEST_CASE("superellipse: derivatives on the axes follow the documented convention")
{
	// Exponent 1.5 on x: |x|^1.5 is differentiable with derivative 0 at x = 0, but its second
	// derivative is infinite there; the documentation says it is reported as 0.
	const auto s = MakeSuperellipse(1.0, 2.0, 1.5, 3.0);
	for (double y : {-1.5, -0.4, 0.3, 1.9})
	{
		const LevelDerivatives d = s->Derivatives(Vec2(0.0, y));
		const double Y = y / 2.0;
		CHECK(d.value == doctest::Approx(std::fabs(Y * Y * Y)).epsilon(1e-15));
		CHECK(d.gradient.x == 0.0);
		CHECK(d.gradient.y == doctest::Approx(3.0 / 2.0 * Y * std::fabs(Y)).epsilon(1e-15));
		CHECK(d.hessian.xx == 0.0);
		CHECK(d.hessian.xy == 0.0);
		CHECK(d.hessian.yy == doctest::Approx(6.0 / 4.0 * std::fabs(Y)).epsilon(1e-15));
		// Next to the axis the true second derivative is large and finite (0.75 |x|^{-1/2}),
		// so the convention is a choice, not a limit.
		CHECK(s->Derivatives(Vec2(1e-10, y)).hessian.xx == doctest::Approx(0.75e5).epsilon(1e-12));
	}
	// Exponent 1 (a corner): the gradient on the axis is finite and a subgradient, the Hessian 0.
	const auto diamond = MakeSuperellipse(1.3, 0.6, 1.0, 3.0);
	const LevelDerivatives d1 = diamond->Derivatives(Vec2(0.0, 0.4));
	CHECK(std::isfinite(d1.gradient.x));
	CHECK(std::fabs(d1.gradient.x) <= 1.0 / 1.3);
	CHECK(d1.hessian.xx == 0.0);
	// Exponents ≥ 2 are twice differentiable on the axes and report the true values.
	const auto e = MakeSuperellipse(2.0, 1.0, 2.0, 2.5);
	const LevelDerivatives d2 = e->Derivatives(Vec2(0.7, 0.0));
	CHECK(d2.hessian.xx == doctest::Approx(2.0 / 4.0).epsilon(1e-15));
	CHECK(d2.hessian.yy == 0.0); // 2.5·1.5 |Y|^{0.5} → 0
	CHECK(d2.gradient.y == 0.0);
	// The origin of a ζ-form is finite (the level is 0 there).
	const LevelDerivatives d0 = SuperellipseShape::FromZeta(1.0, 2.0, 0.8)->Derivatives(Vec2(0.0, 0.0));
	CHECK(d0.value == 0.0);
	CHECK(IsFinite(d0.gradient));
	CHECK(std::isfinite(d0.hessian.xx));
	// The ζ-form on an axis with 2ζ < 2: finite, with the same convention.
	const LevelDerivatives dz = SuperellipseShape::FromZeta(1.0, 2.0, 0.8)->Derivatives(Vec2(0.0, 1.0));
	CHECK(dz.gradient.x == 0.0);
	CHECK(dz.hessian.xx == 0.0);
	CHECK(std::isfinite(dz.hessian.yy));
}

TEST_CASE("superellipse: closed-form support points lie on the surface with the normal along d")
{
	// n = m uses Hölder's closed form, n ≠ m a Lagrange root: both should be exact to rounding,
	// so the point is on the level-1 set to 1e-13 and the outward normal ∇λ is parallel to d
	// to 1e-12 (sin of the angle between them). (n = 4, m = 8: the root's Newton steps stop two
	// units in the last place from it; stopping at half a unit let them bounce to their cap.)
	const std::shared_ptr<const Shape> shapes[] = {MakeCircle(1.7), MakeEllipse(3.0, 0.8), MakeEllipse(0.1, 100.0),
	                                               MakeSuperellipse(2.0, 1.0, 4.0, 4.0), MakeSuperellipse(1.5, 2.5, 3.0, 5.0),
	                                               MakeSuperellipse(1.2, 0.7, 2.5, 3.7), MakeSuperellipse(0.9, 1.6, 7.3, 2.0),
	                                               MakeSuperellipse(1.0, 2.0, 1.5, 1.5), MakeSuperellipse(1.0, 0.5, 60.0, 60.0),
	                                               MakeSuperellipse(1.0, 0.6, 4.0, 8.0), SuperellipseShape::FromZeta(2.0, 1.0, 1.5)};
	Random rng(51);
	for (const auto& s : shapes)
	{
		CAPTURE(s->Describe());
		for (int i = 0; i < 200; ++i)
		{
			const Vec2 d = rng.LogUniform(1e-3, 1e3) * Rotate(Rot(rng.Angle()), Vec2(1, 0));
			const Vec2 p = s->Support(d);
			CAPTURE(d.x);
			CAPTURE(d.y);
			CHECK(RelativeError(s->Level(p), 1.0) < 1e-13);
			const Vec2 nrm = Normalize(s->Gradient(p));
			CHECK(std::fabs(Cross(nrm, Normalize(d))) < 1e-12);
			CHECK(Dot(nrm, d) > 0.0);
		}
		// Along the axes the support point is the axis end (a, 0), (0, b), ...
		const auto* se = dynamic_cast<const SuperellipseShape*>(s.get());
		REQUIRE(se != nullptr);
		CHECK(Distance(s->Support(Vec2(2, 0)), Vec2(se->A(), 0)) <= 1e-15 * se->A());
		CHECK(Distance(s->Support(Vec2(-2, 0)), Vec2(-se->A(), 0)) <= 1e-15 * se->A());
		CHECK(Distance(s->Support(Vec2(0, 3)), Vec2(0, se->B())) <= 1e-15 * se->B());
		CHECK(Distance(s->Support(Vec2(0, -3)), Vec2(0, -se->B())) <= 1e-15 * se->B());
	}
	// n = m = 1 (a rhombus): the support point is a vertex.
	const auto rhombus = MakeSuperellipse(2.0, 1.0, 1.0, 1.0);
	CHECK(Distance(rhombus->Support(Vec2(1.0, 0.3)), Vec2(2.0, 0.0)) == 0.0);
	CHECK(Distance(rhombus->Support(Vec2(0.3, -1.0)), Vec2(0.0, -1.0)) == 0.0);
	CHECK(Distance(rhombus->Support(Vec2(-1.0, 2.1)), Vec2(0.0, 1.0)) == 0.0); // b·2.1 > a·1
}

TEST_CASE("superellipse: SupportNear is Support for n = m, for n ≠ m on the box side without steps and near Support after three")
{
	// The Lagrange condition's Newton steps start on the bounding box's side (zero steps: the
	// point there with its normal along d); three leave the level within 2e-4 of 1 (measured
	// 1.6e-4 to 1.8e-4 over 1e5 directions for exponents 2.5 to 20); with the default cap the
	// point is Support's, bit for bit, and n = m is closed-form either way.
	const std::shared_ptr<SuperellipseShape> mixed[] = {std::make_shared<SuperellipseShape>(1.0, 0.6, 4.0, 8.0),
	                                                    std::make_shared<SuperellipseShape>(2.0, 0.5, 3.0, 20.0),
	                                                    std::make_shared<SuperellipseShape>(0.7, 1.3, 2.5, 3.7)};
	const auto square = std::make_shared<SuperellipseShape>(1.0, 0.6, 4.0, 4.0);
	Random rng(52);
	double worst = 0.0, worstAngle = 0.0;
	for (int i = 0; i < 600; ++i)
	{
		const Vec2 d = rng.LogUniform(1e-3, 1e3) * Rotate(Rot(rng.Angle()), Vec2(1, 0));
		const SuperellipseShape& s = *mixed[size_t(i % 3)];
		const Vec2 near = s.SupportNear(d, 3);
		worst = std::max(worst, std::fabs(s.Level(near) - 1.0));
		worstAngle = std::max(worstAngle, std::fabs(Cross(Normalize(s.Gradient(near)), Normalize(d))));
		// No step: on the bounding box's side, outside the particle, the normal along d.
		const Vec2 side = s.SupportNear(d, 0);
		CHECK(std::max(std::fabs(side.x) / s.A(), std::fabs(side.y) / s.B()) == doctest::Approx(1.0).epsilon(1e-15));
		CHECK(s.Level(side) >= 1.0);
		worstAngle = std::max(worstAngle, std::fabs(Cross(Normalize(s.Gradient(side)), Normalize(d))));
		CHECK(s.SupportNear(d, 100).x == s.Support(d).x);
		CHECK(s.SupportNear(d, 100).y == s.Support(d).y);
		CHECK(square->SupportNear(d, 1).x == square->Support(d).x);
	}
	CAPTURE(worst);
	CAPTURE(worstAngle);
	CHECK(worst <= 2e-4);
	CHECK(worst >= 1e-6); // not the exact point: the test would not see a cap that was ignored
	CHECK(worstAngle <= 1e-12); // the normal is exact along the Lagrange path
}

TEST_CASE("superellipse: support bounds enclose the support value found by golden-section search on the surface")
{
	// Reference h(d) = max over the surface of x·d, on the exact parametrisation
	// x = a·sgn(cos s)|cos s|^(2/n), y = b·sgn(sin s)|sin s|^(2/m): the best of 4096 samples, then
	// golden-section search between its neighbours. It never exceeds the true h.
	struct Case { double a, b, n, m; };
	const Case cases[] = {{2.0, 0.7, 2.0, 2.0}, {1.0, 1.0, 2.0, 2.0}, {2.0, 1.0, 4.0, 4.0}, {0.6, 1.9, 8.0, 8.0},
	                      {1.5, 2.5, 3.0, 5.0}, {1.2, 0.7, 2.5, 3.7}, {1.0, 0.5, 60.0, 60.0}, {1.0, 2.0, 1.5, 1.5},
	                      {2.0, 1.0, 1.0, 1.0}, {0.9, 1.6, 7.3, 1.5}, {1.0, 3.0, 1.2, 1.9}};
	Random rng(88);
	for (const Case& c : cases)
	{
		const auto s = MakeSuperellipse(c.a, c.b, c.n, c.m);
		CAPTURE(s->Describe());
		auto point = [&](double t) {
			const double ct = std::cos(t), st = std::sin(t);
			return Vec2(c.a * std::copysign(std::pow(std::fabs(ct), 2.0 / c.n), ct),
			            c.b * std::copysign(std::pow(std::fabs(st), 2.0 / c.m), st));
		};
		for (int i = 0; i < 100; ++i)
		{
			const Vec2 d = rng.LogUniform(1e-2, 1e2) * Rotate(Rot(rng.Angle()), Vec2(1, 0));
			CAPTURE(d.x);
			CAPTURE(d.y);
			const int samples = 4096;
			int best = 0;
			for (int k = 1; k < samples; ++k)
				if (Dot(point(2.0 * kPi * k / samples), d) > Dot(point(2.0 * kPi * best / samples), d))
					best = k;
			const double h = GoldenMax([&](double t) { return Dot(point(t), d); }, 2.0 * kPi * (best - 1) / samples,
			                           2.0 * kPi * (best + 1) / samples);
			// The support value itself (closed form for n = m, else from the support point).
			CHECK(s->SupportValue(d) == doctest::Approx(h).epsilon(1e-12));
			double lower = 0.0, upper = 0.0;
			s->SupportBounds(d, lower, upper);
			CHECK(lower <= h);
			CHECK(h <= upper);
			CHECK(lower > 0.0);
			// The bounds' bodies: with e = (a dx, b dy), never looser than the axis points and the box.
			const double ex = std::fabs(c.a * d.x), ey = std::fabs(c.b * d.y);
			CHECK(lower >= (1.0 - 2e-12) * std::max(ex, ey));
			CHECK(upper <= (1.0 + 2e-12) * (ex + ey));
			// Ellipses: both bounds are the exact support value |e|; a blocky n = m = 4 keeps the
			// inner ellipse within 2^(1/4) of h (its worst direction is the diagonal).
			if (c.n == 2.0 && c.m == 2.0)
				CHECK(upper - lower <= 3e-12 * h);
			if (c.n == 4.0 && c.m == 4.0)
				CHECK(lower >= h / std::pow(2.0, 0.25) * (1.0 - 1e-9));
		}
	}
}

TEST_CASE("superellipse: the support value is homogeneous of degree 1 from 1e-250 to 1e250")
{
	// h(λd) = λ·h(d): directions whose components' powers would leave the double range (e^{4/3}
	// of 1e-250, e^q for the large q of n near 1) still give the scaled value, finite and exact.
	const double exponents[] = {1.0, 1.05, 1.5, 2.0, 4.0, 8.0, 60.0};
	Random rng(91);
	for (double n : exponents)
	{
		const auto s = MakeSuperellipse(1.7, 0.6, n, n);
		CAPTURE(s->Describe());
		for (int i = 0; i < 50; ++i)
		{
			const Vec2 d = Rotate(Rot(rng.Angle()), Vec2(1, 0));
			const double h = s->SupportValue(d);
			CHECK(h == doctest::Approx(Dot(s->Support(d), d)).epsilon(1e-13));
			for (double scale : {1e-250, 1e-120, 1e120, 1e250})
			{
				CAPTURE(scale);
				const double hs = s->SupportValue(scale * d);
				REQUIRE(std::isfinite(hs));
				CHECK(hs / scale == doctest::Approx(h).epsilon(1e-13));
			}
			// One component zero: the value is the other one's extent.
			CHECK(s->SupportValue(Vec2(d.x, 0.0)) == doctest::Approx(1.7 * std::fabs(d.x)).epsilon(1e-15));
		}
	}
}

TEST_CASE("superellipse: an exponent of 1 makes corners on the axes, reported by CornerAngles")
{
	// |x/a| + |y/b|^m has a tangent discontinuity where x = 0, i.e. at polar angles ±π/2, and
	// |y/b| one at 0 and π (reported as −π: CornerAngles are in [−π, π)). Shape::CornerAngles
	// promises the polar angles "where the surface has corners" (sampling splits there and puts a
	// sample on each corner). Exponents above 1 have no corners (the tangent is continuous).
	auto hasCorner = [](const Shape& s, double theta) {
		for (double c : s.CornerAngles())
			if (std::fabs(std::remainder(c - theta, 2.0 * kPi)) < 1e-15) return true;
		return false;
	};
	const auto xCorner = MakeSuperellipse(1.3, 0.6, 1.0, 3.0);
	CHECK(xCorner->CornerAngles().size() == 2);
	CHECK(hasCorner(*xCorner, 0.5 * kPi));
	CHECK(hasCorner(*xCorner, -0.5 * kPi));
	const auto rhombus = MakeSuperellipse(2.0, 1.0, 1.0, 1.0);
	CHECK(rhombus->CornerAngles().size() == 4);
	for (double t : {-kPi, -0.5 * kPi, 0.0, 0.5 * kPi})
	{
		CAPTURE(t);
		CHECK(hasCorner(*rhombus, t));
		// ... and so the rhombus's vertices are among its surface samples.
		const auto smp = rhombus->Samples(8);
		const Vec2 vertex = rhombus->SurfacePoint(t);
		double nearest = 1e300;
		for (const Vec2& p : smp->point) nearest = std::min(nearest, Distance(p, vertex));
		CHECK(nearest < 1e-12);
	}
	CHECK(MakeSuperellipse(1.3, 0.6, 1.5, 3.0)->CornerAngles().empty());
	CHECK(MakeEllipse(1.3, 0.6)->CornerAngles().empty());
}

namespace
{
// FarCrossing's t against the reference: the larger root of level(x + t·d) = 1, bisected in long
// double between `inside` (level below 1 there) and `beyond` (above). It must match to 1e-13 of
// the size, and its point must lie on the surface.
template <class Level>
void CheckFarCrossing(const SuperellipseShape& s, Level&& level, Vec2 x, Vec2 d, double t, long double inside,
                      long double beyond)
{
	for (int k = 0; k < 300; ++k)
	{
		const long double mid = 0.5L * (inside + beyond);
		(level(x.x + mid * d.x, x.y + mid * d.y) < 1.0L ? inside : beyond) = mid;
	}
	const double size = std::max(s.A(), s.B());
	CHECK(std::fabs(double(inside - t)) * Length(d) <= 1e-13 * size);
	CHECK(RelativeError(s.Level(x + t * d), 1.0) < 1e-12);
}
} // namespace

TEST_CASE("superellipse: the ellipse's far crossing of a line is the larger root, against long double bisection; LineMisses is exact")
{
	// Reference: the line's crossings of λ = 1 found by bisection of λ(x + t·d) − 1 in long
	// double between the line's point nearest the centre (inside when the line hits) and far
	// beyond; the closed form must give the far one to 1e-13 of the size, and its point must lie
	// on the surface. Lines from inside, outside, tangent-near and missing are all drawn.
	const std::shared_ptr<const Shape> ellipses[] = {MakeCircle(1.7), MakeEllipse(3.0, 0.8), MakeEllipse(0.1, 100.0),
	                                                 SuperellipseShape::FromZeta(2.0, 1.0, 1.0)};
	Random rng(77);
	for (const auto& s : ellipses)
	{
		CAPTURE(s->Describe());
		const auto* se = dynamic_cast<const SuperellipseShape*>(s.get());
		REQUIRE(se != nullptr);
		const long double a = se->A(), b = se->B();
		auto level = [&](long double x, long double y) { return (x / a) * (x / a) + (y / b) * (y / b); };
		int hits = 0, misses = 0;
		for (int i = 0; i < 400; ++i)
		{
			const Vec2 x = rng.Uniform(0.0, 2.0) * Vec2(se->A() * std::cos(rng.Angle()), se->B() * std::sin(rng.Angle()));
			const Vec2 d = rng.LogUniform(1e-2, 1e2) * Rotate(Rot(rng.Angle()), Vec2(1, 0));
			CAPTURE(x.x);
			CAPTURE(x.y);
			CAPTURE(d.x);
			CAPTURE(d.y);
			// The line's point nearest the centre in the scaled frame: the quadratic's vertex.
			const long double D = d.x / a, E = d.y / b, X = x.x / a, Y = x.y / b;
			const long double tv = -(X * D + Y * E) / (D * D + E * E);
			const long double lowest = level(x.x + tv * d.x, x.y + tv * d.y);
			const bool meets = lowest < 1.0L;
			double t = 0.0;
			const bool found = s->FarCrossing(x, d, t);
			// LineMisses: exactly the misses, but for lines grazing the surface to 1e-9.
			if (std::fabs(lowest - 1.0L) > 1e-9L)
				CHECK(s->LineMisses(x, d) == !meets);
			if (!meets)
			{
				++misses;
				CHECK_FALSE(found);
				continue;
			}
			++hits;
			REQUIRE(found);
			const long double reach = 4.0L * std::max(a, b) / std::sqrt((long double)(d.x * d.x + d.y * d.y));
			CheckFarCrossing(*se, level, x, d, t, tv, tv + reach + 1.0L);
		}
		CHECK(hits > 100);
		CHECK(misses > 10);
	}
	// A heart has none: the contact code searches instead.
	double t = 0.0;
	CHECK_FALSE(MakeHeart(1.0)->FarCrossing(Vec2(0.1, 0.0), Vec2(1.0, 0.0), t));
	CHECK_FALSE(MakeHeart(1.0)->LineMisses(Vec2(0.0, 5.0), Vec2(1.0, 0.0))); // nor a miss test
}

TEST_CASE("superellipse: the far crossing of other exponents (Newton) against long double bisection; LineMisses is the box test")
{
	// Reference as for the ellipse: bisection of f(x + t·d) − 1 in long double, f = |x/a|^n +
	// |y/b|^m, between the line's lowest-level point (found by golden sections of the convex f)
	// and far beyond. Newton must give the far crossing to 1e-13 of the size with its point on
	// the surface, and report a missing line as such. Lines come from inside, outside and the
	// contact code's typical case: from a point near the surface along its normal.
	const std::shared_ptr<const Shape> shapes[] = {MakeSuperellipse(1.0, 0.6, 4.0, 4.0), MakeSuperellipse(2.0, 0.5, 8.0, 8.0),
	                                               MakeSuperellipse(1.0, 0.7, 2.5, 3.7), MakeSuperellipse(0.8, 1.0, 12.0, 12.0),
	                                               MakeSuperellipse(1.0, 0.5, 4.0, 8.0), MakeSuperellipse(1.0, 0.5, 1.5, 3.0),
	                                               SuperellipseShape::FromZeta(1.0, 0.5, 2.0)};
	Random rng(78);
	for (const auto& s : shapes)
	{
		CAPTURE(s->Describe());
		const auto* se = dynamic_cast<const SuperellipseShape*>(s.get());
		REQUIRE(se != nullptr);
		const long double a = se->A(), b = se->B(), n = se->N(), m = se->M();
		auto level = [&](long double x, long double y) { return std::pow(std::fabs(x / a), n) + std::pow(std::fabs(y / b), m); };
		int hits = 0, misses = 0, normals = 0, boxMisses = 0;
		for (int i = 0; i < 600; ++i)
		{
			Vec2 x, d;
			if (i % 3 == 0)
			{
				// Near the surface along the outward normal, as ContactFromLevel asks.
				const Vec2 q = s->SurfacePoint(rng.Angle());
				d = Normalize(s->Gradient(q));
				x = q + rng.Uniform(-0.05, 0.05) * std::max(se->A(), se->B()) * d;
				++normals;
			}
			else
			{
				x = rng.Uniform(0.0, 2.0) * Vec2(se->A() * std::cos(rng.Angle()), se->B() * std::sin(rng.Angle()));
				d = rng.LogUniform(1e-2, 1e2) * Rotate(Rot(rng.Angle()), Vec2(1, 0));
			}
			CAPTURE(x.x);
			CAPTURE(x.y);
			CAPTURE(d.x);
			CAPTURE(d.y);
			const long double reach = 4.0L * std::max(a, b) / std::sqrt((long double)(d.x * d.x + d.y * d.y));
			auto along = [&](long double t) { return level(x.x + t * d.x, x.y + t * d.y); };
			long double lo = -reach - 1.0L, hi = reach + 1.0L;
			for (int k = 0; k < 300; ++k)
			{
				const long double m1 = lo + (hi - lo) * 0.381966L, m2 = hi - (hi - lo) * 0.381966L;
				(along(m1) < along(m2) ? hi : lo) = (along(m1) < along(m2) ? m2 : m1);
			}
			const long double tv = 0.5L * (lo + hi);
			const long double lowest = along(tv);
			double t = 0.0;
			const bool found = s->FarCrossing(x, d, t);
			// LineMisses claims a miss where the line misses the box |x| ≤ a, |y| ≤ b, which holds
			// the particle: the lowest of max(|x/a|, |y/b|) along the line (convex, by golden
			// sections in long double) above 1; lines grazing the box to 1e-9 may go either way.
			auto boxLevel = [&](long double t) { return std::max(std::fabs((x.x + t * d.x) / a), std::fabs((x.y + t * d.y) / b)); };
			long double blo = -reach - 1.0L, bhi = reach + 1.0L;
			for (int k = 0; k < 300; ++k)
			{
				const long double m1 = blo + (bhi - blo) * 0.381966L, m2 = bhi - (bhi - blo) * 0.381966L;
				(boxLevel(m1) < boxLevel(m2) ? bhi : blo) = (boxLevel(m1) < boxLevel(m2) ? m2 : m1);
			}
			const long double boxLowest = boxLevel(0.5L * (blo + bhi));
			const bool claimsMiss = s->LineMisses(x, d);
			if (std::fabs(boxLowest - 1.0L) > 1e-9L)
				CHECK(claimsMiss == (boxLowest > 1.0L));
			if (claimsMiss)
			{
				++boxMisses;
				CHECK(lowest > 1.0L); // never a line that meets the particle
			}
			if (lowest > 1.0L + 1e-9L)
			{
				++misses;
				CHECK_FALSE(found);
				continue;
			}
			if (lowest > 1.0L - 1e-9L)
				continue; // grazing to rounding: either answer is right
			++hits;
			REQUIRE(found);
			CheckFarCrossing(*se, level, x, d, t, tv, tv + reach + 1.0L);
		}
		CHECK(hits > 200);
		CHECK(misses > 10);
		CHECK(boxMisses > 10);
		CHECK(normals == 200);
	}
}

TEST_CASE("superellipse: LevelLowerBound is below the level over the disc, tightly for small discs")
{
	// Reference: the smallest level over 40 rings of 120 points covering the disc and its centre,
	// in long double from the closed form |x/a|^n + |y/b|^m (or its 1/ζ power). The bound takes
	// the disc's nearest coordinates, so it is exact for a disc of radius 0 and loses about
	// |∇λ|·ρ otherwise. A shape without bounds (a user shape) keeps the defaults, ∓∞: the grid
	// method then evaluates every sample.
	const std::shared_ptr<const SuperellipseShape> shapes[] = {MakeEllipse(1.0, 0.4), MakeSuperellipse(1.0, 0.6, 4.0, 4.0),
	                                                           MakeSuperellipse(0.8, 1.5, 2.5, 3.7), MakeSuperellipse(1.0, 0.7, 1.0, 1.5),
	                                                           SuperellipseShape::FromZeta(1.0, 0.5, 2.0)};
	Random rng(79);
	for (const auto& s : shapes)
	{
		CAPTURE(s->Describe());
		auto level = [&](Vec2 x) { return double(SuperellipseLevelRef(x, s->A(), s->B(), s->N(), s->M(), s->Zeta())); };
		const double R = s->BoundingRadius();
		for (int i = 0; i < 200; ++i)
		{
			const Vec2 c(rng.Uniform(-2.0 * R, 2.0 * R), rng.Uniform(-2.0 * R, 2.0 * R));
			const double r = rng.LogUniform(1e-4 * R, R);
			double lowest, highest;
			DiscLevelRange(level, c, r, lowest, highest);
			const double lower = s->LevelLowerBound(c, r);
			CAPTURE(c.x);
			CAPTURE(c.y);
			CAPTURE(r);
			CHECK(lower <= lowest * (1.0 + 1e-12));
			if (r < 1e-3 * R)
			{
				// Small discs: within ~|∇λ|·2ρ of the truth (the rings resolve ρ/40).
				const double slope = Length(s->Gradient(c)) + 1.0;
				CHECK(lowest - lower <= 4.0 * slope * r);
			}
		}
		const Vec2 c(0.3 * s->A(), -0.2 * s->B());
		CHECK(RelativeError(s->LevelLowerBound(c, 0.0), level(c)) < 1e-14);
	}
	// A user shape has no bounds (LevelBounds' −∞ and +∞ throughout): none to give.
	CHECK(MakeUserShape(UserHeartDef(1.0))->Bounds() == nullptr);
	CHECK(MakeSuperellipse(1.0, 0.5, 4.0, 4.0)->Bounds()->LevelUpperBound(Vec2(0.5, 0.5), 0.1) == std::numeric_limits<double>::infinity());
}

TEST_CASE("superellipse: LevelSmoothOver excludes the axes where an exponent is not an even integer, and the zeta form's centre")
{
	// The level's terms |x/a|^n and |y/b|^m are polynomials for even integer exponents and have
	// no third derivative where their coordinate vanishes otherwise; the ζ-form's f^{1/ζ} has
	// none at f = 0, the centre. The grid refinement's early stop relies on this answer.
	const auto even = MakeSuperellipse(2.0, 1.0, 4.0, 2.0);
	CHECK(even->LevelSmoothOver(Vec2(0.0, 0.0), 0.5));
	CHECK(even->LevelSmoothOver(Vec2(1.0, 0.01), 0.1));
	const auto mixed = MakeSuperellipse(2.0, 1.0, 2.5, 4.0); // |x|^2.5: not at x = 0
	CHECK_FALSE(mixed->LevelSmoothOver(Vec2(0.05, 0.9), 0.1));
	CHECK(mixed->LevelSmoothOver(Vec2(0.15, 0.9), 0.1));
	CHECK(mixed->LevelSmoothOver(Vec2(1.5, 0.0), 0.1)); // (y's exponent is even)
	const auto odd = MakeSuperellipse(1.0, 1.0, 3.0, 3.0); // |x|³: no third derivative at 0
	CHECK_FALSE(odd->LevelSmoothOver(Vec2(1.0, 0.05), 0.1));
	CHECK(odd->LevelSmoothOver(Vec2(0.7, 0.7), 0.1));
	const auto zeta = SuperellipseShape::FromZeta(1.0, 1.0, 1.0); // (x² + y²): f^{1/ζ} = f
	CHECK_FALSE(zeta->LevelSmoothOver(Vec2(0.05, 0.0), 0.1));
	CHECK(zeta->LevelSmoothOver(Vec2(1.0, 0.0), 0.1));
}

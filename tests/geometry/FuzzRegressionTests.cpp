// Inputs the fuzzers (tests/fuzz) found to break the geometry, checked against independent
// references. The crashing fuzzer inputs are kept in tests/fuzz/corpus/solvers/.
//
// Reference for superellipse supports: the boundary |x/a|^n + |y/b|^m = 1 parametrised by
// x = a·sgn(cos t)|cos t|^{2/n}, y = b·sgn(sin t)|sin t|^{2/m} (then |x/a|^n + |y/b|^m =
// cos²t + sin²t), maximised densely in t and refined by golden section in long double. User
// shapes: the closed-form area and radius of the ellipse they describe.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "GeometryReference.h"
#include "TestSupport.h"

#include <cmath>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
// max over the boundary of d·x, and the boundary point, by the parametrisation above.
long double SupportValueRef(double a, double b, double n, double m, Vec2 d)
{
	auto value = [&](long double t) {
		const long double c = std::cos(t), s = std::sin(t);
		const long double x = a * std::copysign(std::pow(std::fabs(c), 2.0L / n), c);
		const long double y = b * std::copysign(std::pow(std::fabs(s), 2.0L / m), s);
		return d.x * x + d.y * y;
	};
	const int count = 4096;
	const long double pi = 3.141592653589793238462643383279502884L;
	int best = 0;
	long double bestValue = value(-pi);
	for (int k = 1; k < count; ++k)
	{
		const long double v = value(-pi + 2.0L * pi * k / count);
		if (v > bestValue) { bestValue = v; best = k; }
	}
	// Golden section between the neighbours of the best sample.
	long double lo = -pi + 2.0L * pi * (best - 1) / count, hi = -pi + 2.0L * pi * (best + 1) / count;
	const long double r = 0.6180339887498948482L;
	for (int it = 0; it < 200 && hi - lo > 1e-19L; ++it)
	{
		const long double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
		if (value(x1) < value(x2)) lo = x1; else hi = x2;
	}
	return std::max(bestValue, value(0.5L * (lo + hi)));
}
} // namespace

TEST_CASE("fuzz regression: superellipse support with unequal exponents near 1 is finite along and near the axes")
{
	// Found by b2a_fuzz_solvers: superellipse(a=1.82056420302608, b=1.0000457129891656,
	// n=1.02568093385214, m=1.0446478980697338) had Support((cos π/2, sin π/2)) = (NaN, NaN):
	// the Lagrange iteration started where one of its exponentials, exp(n/(n−1)·|Δ|), overflows.
	// Its AABB, polygon contacts and time-of-impact bounds were NaN with it.
	struct Case { double a, b, n, m; };
	const std::vector<Case> cases = {
		{1.82056420302608, 1.0000457129891656, 1.02568093385214, 1.0446478980697338},
		{1.0, 1.0, 1.001, 1.021}, // NaN for 30% of all directions before the fix
		{0.5, 2.0, 1.01, 3.0},
		{2.0, 0.5, 6.0, 1.05},
	};
	for (const Case& c : cases)
	{
		CAPTURE(c.a);
		CAPTURE(c.b);
		CAPTURE(c.n);
		CAPTURE(c.m);
		const auto s = MakeSuperellipse(c.a, c.b, c.n, c.m);
		std::vector<double> angles = {0.5 * kPi, kPi, 1.5 * kPi, 0.0, 1e-12, 0.5 * kPi - 1e-9, 0.5 * kPi + 1e-5};
		for (int k = 0; k < 12; ++k)
			angles.push_back(0.1 + 2.0 * kPi * k / 12);
		for (double t : angles)
		{
			CAPTURE(t);
			const Vec2 d(std::cos(t), std::sin(t));
			const Vec2 p = s->Support(d);
			REQUIRE(IsFinite(p));
			CHECK(RelativeError(s->Level(p), 1.0) < 1e-9);
			const double ref = double(SupportValueRef(c.a, c.b, c.n, c.m, d));
			CHECK(std::fabs(Dot(p, d) - ref) <= 1e-12 * std::max(c.a, c.b));
		}
		// The AABB that Box2D's broad phase gets is finite and holds the shape's axis ends, which
		// turned by 45° span √2·max(a, b) along x.
		const Box box = s->ComputeAABB(Pose(Vec2(3.0, -1.0), 0.25 * kPi));
		CHECK(IsFinite(box.lower));
		CHECK(IsFinite(box.upper));
		CHECK(box.upper.x - box.lower.x >= std::sqrt(2.0) * std::max(c.a, c.b) * (1.0 - 1e-12));
	}
}

TEST_CASE("fuzz regression: a superellipse whose powers leave double range is refused when it is made, naming the field")
{
	// Found by b2a_fuzz_solvers: ellipse(a=1.8697385171969869e+185, b=0.17782567794691206) was
	// accepted, but |1/a|² underflows to 0, so its radius along x was infinite and the first
	// contact threw InvalidParameter from inside the solver ("no finite surface point ... field
	// 'function'"). A superellipse of size 1e-30 with n = 100 had bounding radius 0.
	auto field = [](double a, double b, double n, double m) -> std::string {
		try
		{
			MakeSuperellipse(a, b, n, m);
		}
		catch (const InvalidParameter& e)
		{
			CHECK(std::string(e.what()).find("double precision's range") != std::string::npos);
			return e.Field();
		}
		return "";
	};
	CHECK(field(1.8697385171969869e+185, 0.17782567794691206, 2.0, 2.0) == "a");
	CHECK(field(0.5, 1e-200, 2.0, 2.0) == "b");
	CHECK(field(1e-30, 1e-30, 100.0, 100.0) == "a");
	CHECK(field(1e30, 2.0, 12.0, 12.0) == "a");
	CHECK(field(1.0, 1.0, 1e4, 1e4) == "n");      // |cos 45°|^n underflows between the axes
	// Found by b2a_fuzz_contact_tool: the diagonal's point was right (the box's corner), but at
	// other angles the lost |x/a|^n term put the surface outside the box; a grid solve against
	// it sampled for a minute.
	CHECK(field(1.0, 8.0, 7.777777777777778e51, 6.0) == "n");
	CHECK(field(8.0, 1.0, 6.0, 7.777777777777778e51) == "m");
	CHECK(field(1e120, 1e120, 1.0, 1.0) == "a");  // the second moment a³b overflows
	CHECK_THROWS_AS(MakeEllipse(1.7976931348623157e308, 0.05), InvalidParameter);

	// What is representable is still accepted, with its closed-form area π·a·b.
	for (double size : {1e-50, 1e-3, 1e3, 1e50})
	{
		CAPTURE(size);
		const auto e = MakeEllipse(size, 2.0 * size);
		CHECK(e->Mass().area == doctest::Approx(kPi * 2.0 * size * size).epsilon(1e-14));
		CHECK(e->BoundingRadius() == doctest::Approx(2.0 * size).epsilon(1e-15));
	}
	// Exponent 8 keeps sizes up to about 1e38 (size⁸ within range).
	for (double size : {1e-30, 1e-3, 1e3, 1e30})
	{
		CAPTURE(size);
		const auto s = MakeSuperellipse(size, size, 6.0, 8.0);
		CHECK(std::isfinite(s->BoundingRadius()));
		CHECK(s->BoundingRadius() > size);
	}
	CHECK(MakeSuperellipse(1.0, 1.0, 1000.0, 1000.0)->Mass().area == doctest::Approx(4.0).epsilon(1e-2));
}

TEST_CASE("fuzz regression: a user shape's corner angle far outside -pi to pi is wrapped at once, not in steps of 2 pi")
{
	// Found by b2a_fuzz_solvers (a hang): a corner angle of 1e300 is finite, so UserShape took
	// it, and the sampling wrapped it into [−π, π) by subtracting 2π until it got there, which
	// never changes 1e300. Any finite angle now works, and means the same as its wrapped value.
	for (double corner : {1e300, -1e300, 1e17, 100.0, -7.0})
	{
		CAPTURE(corner);
		UserShapeDef def = UserEllipseDef(2.0, 1.0);
		def.cornerAngles = {corner};
		const auto s = MakeUserShape(def);
		CHECK(s->Mass().area == doctest::Approx(2.0 * kPi).epsilon(1e-9));
		CHECK(s->BoundingRadius() == doctest::Approx(2.0).epsilon(1e-9));
		const auto samples = s->Samples();
		CHECK(samples->angle.front() >= -kPi);
		CHECK(samples->angle.back() < kPi);
	}
}

TEST_CASE("fuzz regression: a user shape whose surface lies far from its lengthScale is refused at once, naming lengthScale")
{
	// Found by the world fuzzer: a bare user star (G = (r / (s·R(θ)))⁴ − L, no level function)
	// with the own level L₀ = 8.2e-308, so its surface lies about 1e-78 from the centre while
	// lengthScale says 0.05. Every level was a 300-step root search down to 1e-308 and the
	// radial searches, scaled by lengthScale, could not resolve the surface (radii 1e31 too
	// large): building it took 397 million calls of G, 40 s. It is now refused by name after a
	// few radial searches. The surface must lie within a factor 1e6 of lengthScale.
	long calls = 0;
	auto star = [&calls](double level, double lengthScale) {
		UserShapeDef def;
		def.name = "star";
		def.function = [&calls](Vec2 x, double L) {
			++calls;
			const double R = 0.10573833471337006 * (1.0 + 0.0082536049439230954 * std::cos(std::atan2(x.y, x.x) - kPi));
			return std::pow(Length(x) / R, 4.0) - L;
		};
		def.convex = true;
		def.levelPower = 2.0;
		def.level = level;
		def.lengthScale = lengthScale;
		return MakeUserShape(def);
	};
	std::string message, field;
	try
	{
		star(8.2049599694237439e-308, 0.050922648391717042);
	}
	catch (const InvalidParameter& e)
	{
		message = e.what();
		field = e.Field();
	}
	CAPTURE(message);
	CHECK(field == "lengthScale");
	CHECK(message.find("user shape 'star'") != std::string::npos);
	CHECK(calls < 20000);
	// Too large a lengthScale for an ordinary level is refused the same way; a fitting one
	// builds the particle, whose bounding radius at L = 1 is the largest R(θ), s·(1 + e) at θ = π.
	CHECK_THROWS_AS(star(1.0, 1e6), InvalidParameter);
	const ShapePtr fine = star(1.0, 0.1);
	CHECK(fine->BoundingRadius() == doctest::Approx(0.10573833471337006 * (1.0 + 0.0082536049439230954)).epsilon(1e-9));
}

TEST_CASE("fuzz regression: levels and radii of a bare user shape far above or below its own level take tens of calls, not thousands")
{
	// Found by the solver fuzzer: the grid method with B held at a level 1e300 times its own,
	// B a bare user disc (G = |x|/s − L, level by a root search in L). Its radial searches
	// doubled their way out to 1e300 and each level inside them doubled its bracket as far, a
	// thousand steps each: a minute for one call. Brackets now grow by squaring factors and the
	// roots are narrowed on a logarithmic scale. Reference: the closed form λ = |x|/s.
	long calls = 0;
	const double s = 0.55447708743484103;
	UserShapeDef def;
	def.name = "bare disc";
	def.function = [&calls, s](Vec2 x, double L) {
		++calls;
		return Length(x) / s - L;
	};
	def.convex = true;
	def.level = 0.2;
	def.lengthScale = 5.9226790622878562;
	const ShapePtr disc = MakeUserShape(def);
	for (const double r : {1e250, 1e30, 3.0, 1e-30, 1e-280})
	{
		CAPTURE(r);
		calls = 0;
		const double level = disc->Level(Vec2(0.6 * r, -0.8 * r));
		CHECK(level == doctest::Approx(r / s).epsilon(1e-12));
		CHECK(calls < 200);
	}
	for (const double level : {1e200, 1e-200})
	{
		CAPTURE(level);
		calls = 0;
		const double radius = disc->RadiusAt(Vec2(0.6, 0.8), level);
		CHECK(radius == doctest::Approx(level * s).epsilon(1e-10));
		CHECK(calls < 20000);
	}
}

// The superellipse's inline terms (geometry/SuperellipseTerms.h): IntegerSuperellipseDerivatives
// and SmoothSuperellipseDerivatives against RawSuperellipseDerivatives and against the closed
// forms in long double, and SmoothFarCrossing (the Halley steps of the raw-level finish) against
// long-double bisection along the line, for integer and real exponents, and SmoothFarCrossingFrom
// (the manifold's face-point crossing) against SuperellipseFarCrossing and the same reference.
#include <doctest/doctest.h>

#include "TestSupport.h"
#include "b2analytic/SuperellipseShape.h"
#include "geometry/SuperellipseTerms.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
// The crossing tests' shapes: integer exponents, equal and unequal, and real ones (one std::pow
// per axis and step), one of them in (2, 3), where g''' is unbounded at an axis; plus the test's
// own shape of axes a, b and exponents n, m.
std::vector<std::shared_ptr<SuperellipseShape>> CrossingShapes(double a, double b, double n, double m)
{
	return {std::make_shared<SuperellipseShape>(1.0, 0.6, 4.0, 4.0), std::make_shared<SuperellipseShape>(a, b, n, m),
	        std::make_shared<SuperellipseShape>(2.0, 0.5, 8.0, 8.0), std::make_shared<SuperellipseShape>(1.0, 0.5, 4.0, 8.0),
	        std::make_shared<SuperellipseShape>(0.8, 1.0, 12.0, 12.0), std::make_shared<SuperellipseShape>(1.0, 0.7, 3.0, 5.0),
	        std::make_shared<SuperellipseShape>(1.0, 0.6, 2.5, 2.5), std::make_shared<SuperellipseShape>(1.2, 0.5, 3.7, 3.7),
	        std::make_shared<SuperellipseShape>(0.9, 0.6, 5.3, 2.8), std::make_shared<SuperellipseShape>(1.0, 1.0, 2.2, 4.6)};
}

// The far crossing of f = 1 by the line x + u·d in long double: the lowest point of the convex f
// along the line (golden sections over ±4 sizes), then bisection of f − 1 towards 4 sizes beyond.
// Requires the lowest point inside (f < 1).
long double ReferenceFarCrossing(const SuperellipseShape& s, Vec2 x, Vec2 d)
{
	const long double a = s.A(), b = s.B(), n = s.N(), m = s.M(), size = std::max(s.A(), s.B());
	auto along = [&](long double u) {
		return std::pow(std::fabs((x.x + u * d.x) / a), n) + std::pow(std::fabs((x.y + u * d.y) / b), m);
	};
	long double lo = -4.0L * size, hi = 4.0L * size;
	for (int k = 0; k < 300; ++k)
	{
		const long double m1 = lo + (hi - lo) * 0.381966L, m2 = hi - (hi - lo) * 0.381966L;
		(along(m1) < along(m2) ? hi : lo) = (along(m1) < along(m2) ? m2 : m1);
	}
	long double inside = 0.5L * (lo + hi), beyond = 4.0L * size;
	REQUIRE(along(inside) < 1.0L);
	for (int k = 0; k < 300; ++k)
	{
		const long double mid = 0.5L * (inside + beyond);
		(along(mid) < 1.0L ? inside : beyond) = mid;
	}
	return inside;
}
// Every value of `fast` equal to RawSuperellipseDerivatives' at the same point, bit for bit.
void CheckSameAsRaw(const AxisDerivatives& fast, const LevelDerivatives& raw)
{
	CHECK(fast.f == raw.value);
	CHECK(fast.gx == raw.gradient.x);
	CHECK(fast.gy == raw.gradient.y);
	CHECK(fast.hx == raw.hessian.xx);
	CHECK(fast.hy == raw.hessian.yy);
}
} // namespace

TEST_CASE("superellipse terms: IntegerSuperellipseDerivatives is RawSuperellipseDerivatives, bit for bit, for integer exponents")
{
	// The same operations in the same order: every value equal, at random points of both signs,
	// on the axes (where |X|^{n−2} is 0 or, for n = 2, 1) and far out.
	Random rng(5);
	int compared = 0;
	for (int n : {2, 3, 4, 5, 6, 7, 8, 10, 12, 20})
		for (int m : {2, 4, 7, 8})
		{
			const SuperellipseShape s(rng.LogUniform(0.1, 10.0), rng.LogUniform(0.1, 10.0), n, m);
			const SuperellipseTerms& t = s.Terms();
			REQUIRE(IntegerExponents(t));
			for (int k = 0; k < 200; ++k)
			{
				Vec2 x(rng.Uniform(-2.0, 2.0) * s.A(), rng.Uniform(-2.0, 2.0) * s.B());
				if (k % 10 == 0) x.x = 0.0;
				if (k % 10 == 1) x.y = 0.0;
				if (k % 10 == 2) x = -x;
				const LevelDerivatives raw = RawSuperellipseDerivatives(t, x);
				CheckSameAsRaw(IntegerSuperellipseDerivatives(t, x.x, x.y), raw);
				++compared;
			}
		}
	CHECK(compared == 8000);
	// Real exponents and exponents below 2 are not integer terms.
	CHECK_FALSE(IntegerExponents(SuperellipseShape(1.0, 1.0, 2.5, 4.0).Terms()));
	CHECK_FALSE(IntegerExponents(SuperellipseShape(1.0, 1.0, 4.0, 1.0).Terms()));
}

TEST_CASE("superellipse terms: IntegerSuperellipseDerivativesEqual is RawSuperellipseDerivatives, bit for bit, for n = m")
{
	// Both axes in the lanes of SSE2 registers (PowAbsPair): each lane's operations are the
	// scalar code's, so every value is equal, for every exponent PowAbs multiplies out (2 to 10)
	// and those it loops for (12, 20, 33), on the axes, of both signs and far out; NaN stays NaN.
	Random rng(6);
	int compared = 0;
	for (int n : {2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 20, 33})
	{
		const SuperellipseShape s(rng.LogUniform(0.1, 10.0), rng.LogUniform(0.1, 10.0), n, n);
		const SuperellipseTerms& t = s.Terms();
		REQUIRE(t.nInt == t.mInt);
		for (int k = 0; k < 400; ++k)
		{
			Vec2 x(rng.Uniform(-2.0, 2.0) * s.A(), rng.Uniform(-2.0, 2.0) * s.B());
			if (k % 10 == 0) x.x = 0.0;
			if (k % 10 == 1) x.y = -0.0;
			if (k % 10 == 2) x = -x;
			if (k % 10 == 3) x = 1e3 * x;
			const LevelDerivatives raw = RawSuperellipseDerivatives(t, x);
			CAPTURE(n);
			CAPTURE(x.x);
			CAPTURE(x.y);
			CheckSameAsRaw(IntegerSuperellipseDerivativesEqual(t, x.x, x.y), raw);
			++compared;
		}
	}
	CHECK(compared == 4800);
	const AxisDerivatives nan = IntegerSuperellipseDerivativesEqual(SuperellipseShape(1.0, 0.5, 4.0, 4.0).Terms(), std::nan(""), 0.2);
	CHECK(std::isnan(nan.f));
	CHECK(std::isnan(nan.gx));
}

TEST_CASE("superellipse terms: SmoothSuperellipseDerivatives is RawSuperellipseDerivatives for exponents >= 2, and the closed forms")
{
	// For every exponent ≥ 2, integer or real, the same values as RawSuperellipseDerivatives, bit
	// for bit (one power |X|^{n−2} per axis, the rest by products, as it does), and so
	// IntegerSuperellipseDerivatives' for integer exponents. Against the closed forms in long
	// double (powl of each term on its own: f = |X|^n + |Y|^m, ∂f/∂x = (n/a) sgn(X)|X|^{n−1},
	// ∂²f/∂x² = n(n−1)/a² |X|^{n−2}): relative to each quantity's own scale to 1e-14 (measured:
	// 2.3e-15; std::pow is within an ulp, and the products add a few roundings).
	Random rng(17);
	int compared = 0;
	double worst = 0.0;
	for (double n : {2.0, 2.1, 2.5, 2.999, 3.0, 3.7, 4.0, 5.3, 7.25, 12.0})
		for (double m : {2.0, 2.37, 4.0, 5.49})
		{
			const SuperellipseShape s(rng.LogUniform(0.1, 10.0), rng.LogUniform(0.1, 10.0), n, m);
			const SuperellipseTerms& t = s.Terms();
			REQUIRE(SmoothExponents(t));
			const long double a = s.A(), b = s.B(), N = n, M = m;
			for (int k = 0; k < 200; ++k)
			{
				Vec2 x(rng.Uniform(-2.0, 2.0) * s.A(), rng.Uniform(-2.0, 2.0) * s.B());
				if (k % 10 == 0) x.x = 0.0;
				if (k % 10 == 1) x.y = 0.0;
				if (k % 10 == 2) x = -x;
				if (k % 10 == 3) x = 1e-3 * x; // near the centre, where |X|^{n−2} is small
				const LevelDerivatives raw = RawSuperellipseDerivatives(t, x);
				const AxisDerivatives smooth = SmoothSuperellipseDerivatives(t, x.x, x.y);
				CHECK(smooth.f == raw.value);
				CHECK(smooth.gx == raw.gradient.x);
				CHECK(smooth.gy == raw.gradient.y);
				CHECK(smooth.hx == raw.hessian.xx);
				CHECK(smooth.hy == raw.hessian.yy);
				if (IntegerExponents(t))
				{
					const AxisDerivatives integer = IntegerSuperellipseDerivatives(t, x.x, x.y);
					CHECK(smooth.f == integer.f);
					CHECK(smooth.gx == integer.gx);
					CHECK(smooth.hy == integer.hy);
				}
				const long double X = std::fabs(x.x / a), Y = std::fabs(x.y / b);
				const long double fx = std::pow(X, N), fy = std::pow(Y, M);
				const long double gx = N / a * std::pow(X, N - 1.0L) * (x.x < 0.0 ? -1.0L : 1.0L);
				const long double gy = M / b * std::pow(Y, M - 1.0L) * (x.y < 0.0 ? -1.0L : 1.0L);
				const long double hx = N * (N - 1.0L) / (a * a) * std::pow(X, N - 2.0L);
				const long double hy = M * (M - 1.0L) / (b * b) * std::pow(Y, M - 2.0L);
				auto relative = [](double got, long double want, long double scale) {
					return scale > 0.0L ? double(std::fabs(got - want) / scale) : double(std::fabs(got));
				};
				worst = std::max({worst, relative(smooth.f, fx + fy, fx + fy),
				                  relative(smooth.gx, gx, std::fabs(gx) + std::fabs(gy)),
				                  relative(smooth.gy, gy, std::fabs(gx) + std::fabs(gy)), relative(smooth.hx, hx, std::fabs(hx)),
				                  relative(smooth.hy, hy, std::fabs(hy))});
				++compared;
			}
		}
	CAPTURE(worst);
	CHECK(compared == 8000);
	CHECK(worst <= 1e-14);
	// Exponents below 2 are not smooth terms.
	CHECK(SmoothExponents(SuperellipseShape(1.0, 1.0, 2.5, 4.0).Terms()));
	CHECK_FALSE(SmoothExponents(SuperellipseShape(1.0, 1.0, 4.0, 1.5).Terms()));
	CHECK_FALSE(SmoothExponents(SuperellipseShape(1.0, 1.0, 1.9, 4.0).Terms()));
}

TEST_CASE("superellipse terms: SmoothFarCrossing's Halley steps land on the far crossing, against long-double bisection")
{
	// The finish's case: a point near both surfaces (the common-level point, within a quarter of
	// the size of the surface) and the line along the surface's normal there, with {f, f', f''}
	// at the point given, as the level solve ends with them. Reference: bisection of
	// f(x + t·d) − 1 in long double between the point of the line where f is lowest (inside) and
	// far beyond. Every crossing it reports must be right to 1e-13 of the size; it may decline
	// (false) only where the caller's search then decides, and does so rarely.
	const std::vector<std::shared_ptr<SuperellipseShape>> shapes = CrossingShapes(1.3, 0.4, 2.0, 2.0);
	Random rng(91);
	int found = 0, declined = 0;
	double worst = 0.0;
	for (const auto& s : shapes)
	{
		CAPTURE(s->Describe());
		const SuperellipseTerms& terms = s->Terms();
		const double size = std::max(s->A(), s->B()), unit = std::min(s->A(), s->B());
		for (int i = 0; i < 300; ++i)
		{
			// A surface point, its normal (sometimes tilted, as the pair's mean normal may be), and
			// the point moved along it by up to a quarter of the size either way.
			const Vec2 q = s->SurfacePoint(rng.Angle());
			const Vec2 d = Rotate(Rot(rng.Uniform(-0.2, 0.2)), Normalize(s->Gradient(q)));
			const Vec2 x = q + rng.Uniform(-0.25, 0.25) * unit * d;
			const LevelDerivatives at = RawSuperellipseDerivatives(terms, x);
			const double known[3] = {at.value, Dot(at.gradient, d), d.x * d.x * at.hessian.xx + d.y * d.y * at.hessian.yy};
			if (!(known[1] > 0.0))
				continue;
			double t = 0.0;
			if (!SmoothFarCrossing(terms, x, d, known, unit, t))
			{
				++declined;
				continue;
			}
			++found;
			worst = std::max(worst, double(std::fabs(ReferenceFarCrossing(*s, x, d) - t)) / size);
		}
	}
	CAPTURE(worst);
	CAPTURE(declined);
	CHECK(worst <= 1e-13);
	CHECK(found >= 2800); // measured: all 3000, to 8.9e-16 of the size
	CHECK(declined <= found / 100);
}

TEST_CASE("superellipse terms: SmoothFarCrossingFrom agrees with SuperellipseFarCrossing and long-double bisection")
{
	// The manifold's case (LowestAlong): a face point near the surface, within a tenth of the
	// size either way, and a line through it tilted by up to 0.6 rad from the surface's normal
	// (a face normal of the other particle), sometimes entering the particle sideways. Both the
	// Halley crossing from one evaluation and the Newton one on f^(1/p) it replaced must answer
	// alike: found or not for the same lines, and where found within 1e-14 of the size of each
	// other and of the long-double reference.
	const std::vector<std::shared_ptr<SuperellipseShape>> shapes = CrossingShapes(0.01, 0.01, 4.0, 4.0);
	Random rng(44);
	int found = 0, both = 0;
	double worstOld = 0.0, worstReference = 0.0;
	for (const auto& s : shapes)
	{
		CAPTURE(s->Describe());
		const SuperellipseTerms& terms = s->Terms();
		const double size = std::max(s->A(), s->B()), unit = std::min(s->A(), s->B());
		for (int i = 0; i < 1000; ++i)
		{
			const Vec2 q = s->SurfacePoint(rng.Angle());
			const Vec2 d = Rotate(Rot(rng.Uniform(-0.6, 0.6)), Normalize(s->Gradient(q)));
			const Vec2 x = q + rng.Uniform(-0.1, 0.1) * size * d;
			double tNew = 0.0, tOld = 0.0;
			const bool gotNew = SmoothFarCrossingFrom(terms, x, d, unit, tNew);
			const bool gotOld = SuperellipseFarCrossing(terms, x, d, tOld);
			CHECK(gotNew == gotOld);
			// The shape's FarCrossingNear, which the manifold calls, is this crossing for its kind.
			double tShape = 0.0;
			CHECK(s->FarCrossingNear(x, d, tShape) == gotNew);
			CHECK((!gotNew || tShape == tNew));
			if (!gotNew)
				continue;
			++found;
			if (gotOld)
			{
				++both;
				worstOld = std::max(worstOld, std::fabs(tNew - tOld) / size);
			}
			worstReference = std::max(worstReference, double(std::fabs(ReferenceFarCrossing(*s, x, d) - tNew)) / size);
		}
	}
	CAPTURE(worstOld);
	CAPTURE(worstReference);
	CAPTURE(found);
	CHECK(found >= 9900);
	CHECK(both == found);
	CHECK(worstOld <= 1e-14);
	CHECK(worstReference <= 1e-14); // measured: 1.1e-15 of the size, all 10,000 found
	// Where the Halley steps decline, SuperellipseFarCrossing decides: a line passing above the
	// particle misses it; one moving inwards from outside (f' < 0) has its far crossing at x = −1.
	const SuperellipseShape s(1.0, 0.6, 4.0, 4.0);
	double t = 0.0;
	CHECK_FALSE(SmoothFarCrossingFrom(s.Terms(), Vec2(0.2, 0.9), Vec2(1.0, 0.0), 0.6, t));
	REQUIRE(SmoothFarCrossingFrom(s.Terms(), Vec2(1.5, 0.0), Vec2(-1.0, 0.0), 0.6, t));
	CHECK(std::fabs(t - 2.5) <= 1e-15);
	// Superellipses of other kinds (an ellipse, an exponent below 2, the ζ-form) answer
	// FarCrossingNear with their FarCrossing, bit for bit.
	for (const auto& other : {MakeEllipse(1.0, 0.6), MakeSuperellipse(1.0, 0.6, 1.5, 4.0), SuperellipseShape::FromZeta(1.0, 0.6, 2.0)})
	{
		CAPTURE(other->Describe());
		CHECK(other->Kind() != BuiltinKinds::superellipse);
		double near = 0.0, far = 0.0;
		REQUIRE(other->FarCrossingNear(Vec2(0.9, 0.1), Vec2(0.6, 0.8), near));
		REQUIRE(other->FarCrossing(Vec2(0.9, 0.1), Vec2(0.6, 0.8), far));
		CHECK(near == far);
	}
}

TEST_CASE("superellipse terms: SmoothFarCrossing declines a line that misses the particle or runs inwards")
{
	const SuperellipseShape s(1.0, 0.6, 4.0, 4.0);
	const SuperellipseTerms& terms = s.Terms();
	auto known = [&](Vec2 x, Vec2 d, double out[3]) {
		const LevelDerivatives at = RawSuperellipseDerivatives(terms, x);
		out[0] = at.value;
		out[1] = Dot(at.gradient, d);
		out[2] = d.x * d.x * at.hessian.xx + d.y * d.y * at.hessian.yy;
	};
	double k[3], t = 0.0;
	// Passing above the particle (y = 0.9 > b), along x: f' > 0 on the right, yet no crossing.
	known(Vec2(0.2, 0.9), Vec2(1.0, 0.0), k);
	CHECK_FALSE(SmoothFarCrossing(terms, Vec2(0.2, 0.9), Vec2(1.0, 0.0), k, 0.6, t));
	// Moving inwards from outside (f' < 0): the far crossing lies behind, the caller's search's job.
	known(Vec2(1.5, 0.0), Vec2(-1.0, 0.0), k);
	CHECK_FALSE(SmoothFarCrossing(terms, Vec2(1.5, 0.0), Vec2(-1.0, 0.0), k, 0.6, t));
	// For contrast, outwards from there: the crossing at x = 1, behind the point.
	known(Vec2(1.5, 0.0), Vec2(1.0, 0.0), k);
	REQUIRE(SmoothFarCrossing(terms, Vec2(1.5, 0.0), Vec2(1.0, 0.0), k, 0.6, t));
	CHECK(std::fabs(t + 0.5) <= 1e-15);
}

TEST_CASE("superellipse terms: SmoothFarCrossings, interleaved, answers as the two crossings run alone, bit for bit")
{
	// The finish runs A's and B's crossings a step at a time in one loop; each must take the same
	// steps as alone: the same verdict and the same t to the bit, also where one ends (found or
	// declined) steps before the other.
	const SuperellipseShape sa(1.0, 0.6, 4.0, 4.0), sb(0.8, 0.5, 4.0, 8.0);
	Random rng(17);
	int compared = 0, unequalSteps = 0, declined = 0;
	for (int i = 0; i < 2000; ++i)
	{
		auto line = [&](const SuperellipseShape& s, Vec2& x, Vec2& d, double known[3]) {
			const Vec2 q = s.SurfacePoint(rng.Angle());
			d = Rotate(Rot(rng.Uniform(-0.6, 0.6)), Normalize(s.Gradient(q)));
			if (i % 7 == 3)
				d = -d; // running inwards: declined
			x = q + rng.Uniform(-0.3, 0.3) * std::min(s.A(), s.B()) * d;
			const LevelDerivatives at = RawSuperellipseDerivatives(s.Terms(), x);
			known[0] = at.value;
			known[1] = Dot(at.gradient, d);
			known[2] = d.x * d.x * at.hessian.xx + d.y * d.y * at.hessian.yy;
		};
		Vec2 xa, da, xb, db;
		double ka[3], kb[3];
		line(sa, xa, da, ka);
		line(sb, xb, db, kb);
		const double ua = std::min(sa.A(), sa.B()), ub = std::min(sb.A(), sb.B());
		double ta = 0.0, tb = 0.0;
		const bool alone[2] = {SmoothFarCrossing(sa.Terms(), xa, da, ka, ua, ta), SmoothFarCrossing(sb.Terms(), xb, db, kb, ub, tb)};
		SmoothCrossing ca(sa.Terms(), xa, da, ka, ua), cb(sb.Terms(), xb, db, kb, ub);
		int stepsA = 0, stepsB = 0;
		{
			SmoothCrossing a = ca, b = cb;
			while (a.state == SmoothCrossing::State::running && stepsA < 8)
				a.Step(), ++stepsA;
			while (b.state == SmoothCrossing::State::running && stepsB < 8)
				b.Step(), ++stepsB;
		}
		unequalSteps += stepsA != stepsB;
		SmoothFarCrossings(ca, cb);
		CHECK((ca.state == SmoothCrossing::State::found) == alone[0]);
		CHECK((cb.state == SmoothCrossing::State::found) == alone[1]);
		CHECK(ca.state != SmoothCrossing::State::running);
		CHECK(cb.state != SmoothCrossing::State::running);
		if (alone[0])
			CHECK(ca.t == ta);
		if (alone[1])
			CHECK(cb.t == tb);
		declined += !alone[0] + !alone[1];
		++compared;
	}
	CHECK(compared == 2000);
	CAPTURE(unequalSteps);
	CAPTURE(declined);
	CHECK(unequalSteps >= 100); // the interleaving's uneven case is exercised
	CHECK(declined >= 400);     // and so is a declined crossing beside a found one
}

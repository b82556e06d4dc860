// RootOf, CubeRoot, CubeRootWithInverse, RoughCubeRootWithInverse and RootGuess (numerics/Powers.h) against long-double references.
#include <doctest/doctest.h>

#include "TestSupport.h"
#include "numerics/Powers.h"

#include <cmath>
#include <limits>

using namespace b2a;
using namespace b2a::test;

namespace
{
// |got − want| in units of want's ulp (long double want, rounded to double's spacing there).
double Ulps(double got, long double want)
{
	const double w = double(want);
	const double ulp = std::nextafter(std::fabs(w), std::numeric_limits<double>::infinity()) - std::fabs(w);
	return double(std::fabs((long double)got - want) / ulp);
}
} // namespace

TEST_CASE("powers: CubeRoot is within 0.51 ulp of the exact cube root from 1e-290 to 1e290, both signs")
{
	// (glibc's std::cbrt, which CubeRoot hands the rest of the range to, is up to 3.2 ulp off.)
	Random rng(5);
	double worst = 0.0;
	for (int k = 0; k < 200000; ++k)
	{
		const double x = (k % 2 ? -1.0 : 1.0) * std::exp(rng.Uniform(-667.0, 667.0));
		const double got = CubeRoot(x);
		worst = std::max(worst, Ulps(got, cbrtl((long double)x)));
		REQUIRE(std::signbit(got) == std::signbit(x));
	}
	// Exact cubes.
	for (double r : {1.0, 2.0, 3.0, 10.0, 0.5, 1e-90, 7e90})
		worst = std::max(worst, Ulps(CubeRoot(r * r * r), cbrtl((long double)(r * r * r))));
	CAPTURE(worst);
	CHECK(worst <= 0.51); // all but the last rounding exact to about 1e-18
}

TEST_CASE("powers: CubeRootWithInverse gives CubeRoot and the inverse cube root within 2 ulp, over the whole range")
{
	Random rng(13);
	double worst = 0.0;
	auto check = [&](double x) {
		double inverse = 0.0;
		const double root = CubeRootWithInverse(x, inverse);
		CAPTURE(x);
		REQUIRE(root == CubeRoot(x));
		worst = std::max(worst, Ulps(inverse, 1.0L / cbrtl((long double)x)));
	};
	for (int k = 0; k < 200000; ++k)
		check(std::exp(rng.Uniform(-667.0, 667.0)));
	// Every cell's ends (the widest |d|) for the three residues of the exponent, and exact cubes.
	for (int e : {-3, -2, -1, 0, 1, 2})
		for (int i = 0; i < kCubeRootCells; ++i)
		{
			check(std::ldexp(1.0 + double(i) / kCubeRootCells, e));
			check(std::nextafter(std::ldexp(1.0 + double(i + 1) / kCubeRootCells, e), 0.0));
		}
	for (double r : {1.0, 2.0, 3.0, 10.0, 0.5, 1e-90, 7e90})
		check(r * r * r);
	CAPTURE(worst);
	CHECK(worst <= 2.0); // (1/c³ rounded in the table, c²·(1/c³), and the series' sum: 1.63 measured)
	CHECK(worst >= 0.5); // (not correctly rounded)
	// Outside the table's range: 1/CubeRoot; zero's inverse is infinite.
	for (double x : {1e-300, 1e300, std::numeric_limits<double>::max()})
	{
		double inverse = 0.0;
		CHECK(CubeRootWithInverse(x, inverse) == CubeRoot(x));
		CHECK(inverse == 1.0 / CubeRoot(x));
	}
	double inverse = 0.0;
	CHECK(CubeRootWithInverse(0.0, inverse) == 0.0);
	CHECK(inverse == std::numeric_limits<double>::infinity());
}

TEST_CASE("powers: RoughCubeRootWithInverse is within 2e-8 of the cube root and its inverse, over CubeRoot's main range")
{
	Random rng(14);
	double worstRoot = 0.0, worstInverse = 0.0;
	auto check = [&](double x) {
		double inverse = 0.0;
		const double root = RoughCubeRootWithInverse(x, inverse);
		const long double want = cbrtl((long double)x);
		worstRoot = std::max(worstRoot, double(std::fabs((long double)root / want - 1.0L)));
		worstInverse = std::max(worstInverse, double(std::fabs((long double)inverse * want - 1.0L)));
	};
	for (int k = 0; k < 200000; ++k)
		check(std::exp(rng.Uniform(-667.0, 667.0)));
	for (int e : {-3, -2, -1, 0, 1, 2}) // every cell's ends: the widest |d|
		for (int i = 0; i < kCubeRootCells; ++i)
		{
			check(std::ldexp(1.0 + double(i) / kCubeRootCells, e));
			check(std::nextafter(std::ldexp(1.0 + double(i + 1) / kCubeRootCells, e), 0.0));
		}
	CAPTURE(worstRoot);
	CAPTURE(worstInverse);
	CHECK(worstRoot <= 2e-8);    // (measured: 3.7e-9)
	CHECK(worstInverse <= 2e-8); // (measured: 1.03e-8)
	CHECK(worstInverse >= 1e-9); // (two terms of the series: a bound's accuracy, not a root's)
}

TEST_CASE("powers: RootGuess is within 6.2 % of the k-th root for 0 < x <= 1, and exact where it must be")
{
	// The bound is the bit pattern's reading of log2 (within 0.086) on the way in and out: a
	// factor 2^0.086 = 1.0615. Measured: 6.15 % worst over these draws (k = 9 and 16).
	Random rng(11);
	double worst = 0.0;
	for (int k = 3; k <= 16; ++k)
		for (int i = 0; i < 20000; ++i)
		{
			const double x = std::exp(rng.Uniform(-690.0, 0.0));
			const double want = double(powl((long double)x, 1.0L / k));
			worst = std::max(worst, std::fabs(RootGuess(x, k) / want - 1.0));
		}
	CAPTURE(worst);
	CHECK(worst <= 0.062);
	CHECK(worst >= 0.05); // a guess, not a root: a refined version would belong elsewhere
	// Exact: the square root, 1 and 0; NaN for NaN and negative x (outside its domain).
	for (double x : {0.3, 1e-200, 0.99})
		CHECK(RootGuess(x, 2) == std::sqrt(x));
	for (int k = 2; k <= 16; ++k)
	{
		CHECK(RootGuess(1.0, k) == 1.0);
		CHECK(RootGuess(0.0, k) == 0.0);
		CHECK(std::isnan(RootGuess(std::nan(""), k)));
		CHECK(std::isnan(RootGuess(-0.5, k)));
	}
}

TEST_CASE("powers: CubeRoot's table holds cube roots of 17 bits whose cubes are exact, within 4e-3 of every mantissa of their cell")
{
	// What CubeRoot's error bound rests on: m − c³ exact and |d| = |m/c³ − 1| ≤ 4e-3, where the
	// series' first left-out term, 0.0191·d⁷, is below 3e-19.
	double widest = 0.0;
	for (int r = 0; r < 3; ++r)
		for (int i = 0; i < kCubeRootCells; ++i)
		{
			const CubeRootCell& cell = kCubeRootTable.cell[r * kCubeRootCells + i];
			CAPTURE(r);
			CAPTURE(i);
			REQUIRE(cell.c * 65536.0 == std::floor(cell.c * 65536.0)); // 17 significant bits (1 ≤ c < 2)
			REQUIRE((long double)(cell.c * cell.c * cell.c) == (long double)cell.c * cell.c * cell.c);
			REQUIRE(std::fabs((long double)cell.inv * cell.c * cell.c * cell.c - 1.0L) <= 1.2e-16L);
			const double lo = std::ldexp(1.0 + double(i) / kCubeRootCells, r), hi = std::ldexp(1.0 + double(i + 1) / kCubeRootCells, r);
			for (double m : {lo, hi})
				widest = std::max(widest, std::fabs(double((long double)m / ((long double)cell.c * cell.c * cell.c) - 1.0L)));
		}
	CAPTURE(widest);
	CHECK(widest <= 4e-3);
	CHECK(widest >= 3.5e-3); // (7 bits of cells: 1/256 of the mantissa either side, give or take c's rounding)
}

#if defined(B2A_SSE2_PAIRS)
TEST_CASE("powers: CubeRootPair is CubeRoot bit for bit in both lanes, at every table cell's ends and middle and at random")
{
	// Every residue of the exponent mod 3 (three exponents in a row), every cell of the mantissa
	// (its first and last double and its middle), lanes swapped, and random draws over the range.
	auto same = [](double x0, double x1) {
		double out[2];
		_mm_storeu_pd(out, CubeRootPair(_mm_set_pd(x1, x0)));
		CAPTURE(x0);
		CAPTURE(x1);
		REQUIRE(out[0] == CubeRoot(x0));
		REQUIRE(out[1] == CubeRoot(x1));
	};
	for (int e : {-900, -3, -2, -1, 0, 1, 2, 3, 900})
		for (int i = 0; i < kCubeRootCells; ++i)
		{
			const double first = std::ldexp(1.0 + double(i) / kCubeRootCells, e);
			const double last = std::nextafter(std::ldexp(1.0 + double(i + 1) / kCubeRootCells, e), 0.0);
			const double middle = std::ldexp(1.0 + (i + 0.5) / kCubeRootCells, e);
			same(first, last);
			same(middle, first);
		}
	Random rng(12);
	for (int k = 0; k < 100000; ++k)
		same(std::exp(rng.Uniform(-667.0, 667.0)), std::exp(rng.Uniform(-667.0, 667.0)));
}
#endif

TEST_CASE("powers: CubeRoots is CubeRoot bit for bit for both values, in the pair's range and outside it")
{
	// Both in CubeRoot's main range: CubeRootPair; either outside it (zero, tiny, huge,
	// infinite, NaN): CubeRoot each. The values are CubeRoot's either way.
	auto same = [](double x, double y) {
		double cx = -1.0, cy = -1.0;
		CubeRoots(x, y, cx, cy);
		CAPTURE(x);
		CAPTURE(y);
		const double rx = CubeRoot(x), ry = CubeRoot(y);
		CHECK((cx == rx || (std::isnan(cx) && std::isnan(rx))));
		CHECK((cy == ry || (std::isnan(cy) && std::isnan(ry))));
		CHECK(std::signbit(cx) == std::signbit(rx));
		CHECK(std::signbit(cy) == std::signbit(ry));
	};
	Random rng(13);
	for (int k = 0; k < 20000; ++k)
		same(std::exp(rng.Uniform(-667.0, 667.0)), std::exp(rng.Uniform(-667.0, 667.0)));
	const double special[] = {0.0, 1e-300, 1e-290, 1e290, 1e300, std::numeric_limits<double>::infinity(), std::nan(""), 0.7};
	for (double x : special)
		for (double y : special)
			same(x, y);
}

TEST_CASE("powers: CubeRoot keeps zero with its sign and hands the ends of the range, infinities and NaN to std::cbrt")
{
	CHECK(CubeRoot(0.0) == 0.0);
	CHECK(std::signbit(CubeRoot(-0.0)));
	const double sub = 1e-310;
	CHECK(CubeRoot(sub) == std::cbrt(sub));
	CHECK(CubeRoot(-sub) == std::cbrt(-sub));
	CHECK(CubeRoot(std::numeric_limits<double>::infinity()) == std::numeric_limits<double>::infinity());
	CHECK(CubeRoot(-std::numeric_limits<double>::infinity()) == -std::numeric_limits<double>::infinity());
	CHECK(std::isnan(CubeRoot(std::nan(""))));
	// The ends of double's range.
	for (double x : {std::numeric_limits<double>::max(), std::numeric_limits<double>::min(), 1e300, -1e-300})
		CHECK(CubeRoot(x) == std::cbrt(x));
}

TEST_CASE("powers: CubeRootBounds bracket the exact cube root within 2e-3, over the whole range")
{
	Random rng(7);
	double widest = 0.0;
	auto check = [&](double x) {
		double lower = 0.0, upper = 0.0;
		CubeRootBounds(x, lower, upper);
		const long double want = cbrtl((long double)x);
		CAPTURE(x);
		REQUIRE((long double)lower <= want);
		REQUIRE((long double)upper >= want);
		if (want > 0.0L)
			widest = std::max(widest, double(((long double)upper - (long double)lower) / want));
	};
	for (int k = 0; k < 200000; ++k)
		check(std::exp(rng.Uniform(-708.0, 709.0)));
	// Exact cubes, where a rounded step could land below the root, and the ends.
	for (double r : {1.0, 2.0, 3.0, 10.0, 0.5, 1e-90, 7e90})
		check(r * r * r);
	for (double x : {0.0, 1e-310, 1e-290, 1e290, 1e300, std::numeric_limits<double>::max(), std::numeric_limits<double>::min()})
		check(x);
	CAPTURE(widest);
	CHECK(widest <= 2.1e-3); // (the lower margin, 2e-3, and the step's own 1e-3 at most)
	CHECK(widest >= 1e-3);   // (one step, not two: the bounds are meant to be cheap)
}

TEST_CASE("powers: RootOf is t^(1/e) by square roots for e = 2, 4, 8 and by pow otherwise")
{
	// By square roots, each correctly rounded: within 2 ulp. By pow, 1/e is itself rounded, which
	// costs |ln t| times its relative error (up to ~700 · 1e-16 here).
	Random rng(6);
	double worstRoots = 0.0, worstPow = 0.0;
	for (int k = 0; k < 20000; ++k)
	{
		const double t = std::exp(rng.Uniform(-300.0, 300.0));
		for (double e : {2.0, 4.0, 8.0})
			worstRoots = std::max(worstRoots, Ulps(RootOf(t, e), powl((long double)t, 1.0L / (long double)e)));
		for (double e : {3.0, 2.5})
			worstPow = std::max(worstPow, Ulps(RootOf(t, e), powl((long double)t, 1.0L / (long double)e)));
	}
	CAPTURE(worstRoots);
	CAPTURE(worstPow);
	CHECK(worstRoots <= 2.0);
	CHECK(worstPow <= 200.0);
}

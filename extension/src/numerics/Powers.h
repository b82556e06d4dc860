// b2analytic: roots by square roots where the exponent allows (internal).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
// SSE2 is part of x86-64: paired evaluation there (CubeRootPair), the scalar loop elsewhere.
#if defined(__x86_64__) || defined(_M_X64)
#define B2A_SSE2_PAIRS 1
#include <emmintrin.h>
#endif

namespace b2a
{

/// t^(1/e) for t ≥ 0: square roots for e = 2, 4 and 8 (ellipses, the blocky superellipses of the
/// demos, and the gauges of n = 4, 8, 16), pow otherwise. Shapes and the pair frame's gauge share it.
inline double RootOf(double t, double e)
{
	if (e == 2.0)
		return std::sqrt(t);
	if (e == 4.0)
		return std::sqrt(std::sqrt(t));
	if (e == 8.0)
		return std::sqrt(std::sqrt(std::sqrt(t)));
	return std::pow(t, 1.0 / e);
}

/// A first guess of ∛x for x > 0 from the exponent bits: the bit pattern of x^{1/3} is about a
/// third of x's plus a constant, within 4 % (CubeRoot and CubeRootBounds refine it).
constexpr std::uint64_t kCubeRootGuessBias = 0x2a9f7893782da1ceULL; ///< CubeRootGuess's constant
/// The range of x where CubeRoot and CubeRootBounds iterate (and their SSE2 pairs apply).
constexpr double kCubeRootLowest = 1e-290, kCubeRootHighest = 1e290;
/// CubeRootBounds' margins on its iterate: upper = y·kCubeRootUpperMargin, lower = y·kCubeRootLowerMargin.
constexpr double kCubeRootUpperMargin = 1.0 + 1e-14, kCubeRootLowerMargin = 1.0 / (1.0 + 1e-5);
inline double CubeRootGuess(double x)
{
	std::uint64_t bits;
	std::memcpy(&bits, &x, sizeof bits);
	bits = bits / 3 + kCubeRootGuessBias;
	double y;
	std::memcpy(&y, &bits, sizeof y);
	return y;
}

/// The real cube root, within 2 ulp of std::cbrt and about 2.5 times faster (glibc's goes
/// through frexp and ldexp, and was 40 % of a heart–heart contact, whose level has |x|^{2/3}).
/// From CubeRootGuess (within 4 %), two Halley steps y ← y·(y³ + 2x)/(2y³ + x), each cubing the
/// relative error (4e-2 → 2e-5 → 3e-15), and a Newton step to rounding, written
/// y ← y + (x/y² − y)/3 (its correction loses less to rounding than (y³ − x)/(3y²)). Outside
/// 1e-290 to 1e290 (where y³ and 2y³ could leave the range), infinities and NaN go to
/// std::cbrt; zero is its own root (a heart's level at its centre and on its axis, asked for on
/// every heart contact, where std::cbrt cost as much as the rest of the level).
inline double CubeRoot(double x)
{
	const double ax = std::fabs(x);
	if (!(ax >= kCubeRootLowest && ax <= kCubeRootHighest))
		return x == 0.0 ? x : std::cbrt(x);
	double y = CubeRootGuess(ax);
	for (int k = 0; k < 2; ++k)
	{
		const double y3 = y * y * y;
		y *= (y3 + 2.0 * ax) / (2.0 * y3 + ax); // the ratio first: y·(y³ + 2x) would underflow for x ~ 1e-283
	}
	y += (ax / (y * y) - y) * (1.0 / 3.0);
	return std::copysign(y, x);
}

/// x^{1/k} for 0 ≤ x ≤ 1 and an integer k ≥ 2, within 6.2 %, with no pow, exp or log: for a
/// solver's start. A double's bit pattern read as an integer is 2^52·(log2 x + 1023) to within
/// 0.086·2^52 (the mantissa's fraction f standing for log2(1 + f)), so dividing its offset from
/// 1.0's pattern by k takes the k-th root of x to within a factor 2^±0.086 (the reading's error
/// on the way in, divided by k, and on the way out). k = 2 is the square root itself; x = 0
/// gives 0, and NaN or a negative x NaN.
inline double RootGuess(double x, int k)
{
	if (k == 2)
		return std::sqrt(x);
	if (!(x > 0.0))
		return x == 0.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
	constexpr std::int64_t one = 0x3ff0000000000000; // 1.0's bit pattern
	std::int64_t bits;
	std::memcpy(&bits, &x, sizeof bits);
	bits = (bits - one) / k + one;
	double y;
	std::memcpy(&y, &bits, sizeof y);
	return y;
}

#if defined(B2A_SSE2_PAIRS)
/// CubeRootGuess of both lanes (the integer division per lane in 64-bit registers: SSE2 has no
/// 64-bit multiply).
inline __m128d CubeRootGuessPair(__m128d x)
{
	const __m128i bits = _mm_castpd_si128(x);
	const std::uint64_t b0 = std::uint64_t(_mm_cvtsi128_si64(bits)) / 3 + kCubeRootGuessBias;
	const std::uint64_t b1 = std::uint64_t(_mm_cvtsi128_si64(_mm_unpackhi_epi64(bits, bits))) / 3 + kCubeRootGuessBias;
	return _mm_castsi128_pd(_mm_set_epi64x(static_cast<long long>(b1), static_cast<long long>(b0)));
}

/// CubeRoot of both lanes, each in CubeRoot's main range 1e-290 ≤ x ≤ 1e290 (the caller checks):
/// CubeRoot's operations in its order, lane by lane, so that each lane is CubeRoot's bit for bit.
inline __m128d CubeRootPair(__m128d ax)
{
	__m128d y = CubeRootGuessPair(ax);
	const __m128d two = _mm_set1_pd(2.0);
	for (int k = 0; k < 2; ++k)
	{
		const __m128d y3 = _mm_mul_pd(_mm_mul_pd(y, y), y);
		y = _mm_mul_pd(y, _mm_div_pd(_mm_add_pd(y3, _mm_mul_pd(two, ax)), _mm_add_pd(_mm_mul_pd(two, y3), ax)));
	}
	return _mm_add_pd(y, _mm_mul_pd(_mm_sub_pd(_mm_div_pd(ax, _mm_mul_pd(y, y)), y), _mm_set1_pd(1.0 / 3.0)));
}
#endif

/// Bounds lower ≤ ∛x ≤ upper for x ≥ 0, within 2e-5 of each other, at half CubeRoot's cost: for
/// the level bounds of the grid method, which need a side, not the last digit. From
/// CubeRootGuess (within 4 %), two Newton steps y ← (2y + x/y²)/3: each lands at or above the
/// root (the arithmetic mean of y, y and x/y² is at least their geometric mean, ∛x) and squares
/// the relative error (4e-2 → 1.6e-3 → 2.6e-6). The upper end takes a margin for the steps'
/// rounding, the lower one divides by 1 + 1e-5. x = 0 has the exact bounds 0 (a disc across the
/// heart's axis: a tenth of the grid's bounds); outside 1e-290 to 1e290 and for non-finite x
/// both come from std::cbrt with the margin.
inline void CubeRootBounds(double x, double& lower, double& upper)
{
	if (x == 0.0)
	{
		lower = upper = 0.0;
		return;
	}
	if (!(x >= kCubeRootLowest && x <= kCubeRootHighest))
	{
		const double r = std::cbrt(x);
		lower = r * (1.0 - 1e-15);
		upper = r * (1.0 + 1e-15);
		return;
	}
	double y = CubeRootGuess(x);
	y = (2.0 * y + x / (y * y)) * (1.0 / 3.0);
	y = (2.0 * y + x / (y * y)) * (1.0 / 3.0);
	upper = y * kCubeRootUpperMargin;
	lower = y * kCubeRootLowerMargin;
}

#if defined(B2A_SSE2_PAIRS)
/// CubeRootBounds' iterate y of both lanes, each in its main range 1e-290 ≤ x ≤ 1e290 (the
/// caller checks and applies kCubeRootUpperMargin and kCubeRootLowerMargin): its operations in its
/// order, lane by lane, so that each lane is CubeRootBounds' bit for bit.
inline __m128d CubeRootBoundsPair(__m128d x)
{
	__m128d y = CubeRootGuessPair(x);
	const __m128d two = _mm_set1_pd(2.0), third = _mm_set1_pd(1.0 / 3.0);
	y = _mm_mul_pd(_mm_add_pd(_mm_mul_pd(two, y), _mm_div_pd(x, _mm_mul_pd(y, y))), third);
	y = _mm_mul_pd(_mm_add_pd(_mm_mul_pd(two, y), _mm_div_pd(x, _mm_mul_pd(y, y))), third);
	return y;
}
#endif

} // namespace b2a

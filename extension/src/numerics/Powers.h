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
/// third of x's plus a constant, within 3.3 % (CubeRootBounds refines it).
constexpr std::uint64_t kCubeRootGuessBias = 0x2a9f7893782da1ceULL; ///< CubeRootGuess's constant
/// The range of x where CubeRoot takes its table and CubeRootBounds iterates (and their SSE2 pairs apply).
constexpr double kCubeRootLowest = 1e-290, kCubeRootHighest = 1e290;
/// CubeRootBounds' margins on its iterate: upper = y·kCubeRootUpperMargin, lower = y·kCubeRootLowerMargin.
constexpr double kCubeRootUpperMargin = 1.0 + 1e-14, kCubeRootLowerMargin = 1.0 / (1.0 + 2e-3);
inline double CubeRootGuess(double x)
{
	std::uint64_t bits;
	std::memcpy(&bits, &x, sizeof bits);
	bits = bits / 3 + kCubeRootGuessBias;
	double y;
	std::memcpy(&y, &bits, sizeof y);
	return y;
}

/// CubeRoot's table: for each residue r = 0, 1, 2 of the binary exponent mod 3 and each of the
/// kCubeRootCells cells of the mantissa m = 2^r·(1 + f) ∈ [1, 8) (the top kCubeRootCellBits bits
/// of the fraction f), c ≈ ∛(the cell's middle) with 17 significant bits, so that c³ (51 bits)
/// is exact in a double, and inv = 1/c³ rounded.
constexpr int kCubeRootCellBits = 7, kCubeRootCells = 1 << kCubeRootCellBits;
/// One cell of CubeRoot's table.
struct CubeRootCell
{
	double c;   ///< ∛ of the cell's middle to 17 bits
	double inv; ///< 1/c³, rounded
};
/// CubeRoot's table: cell r·kCubeRootCells + i for residue r and fraction cell i (6 KB).
struct CubeRootTable
{
	CubeRootCell cell[3 * kCubeRootCells]; ///< cell r·kCubeRootCells + i
};
/// Builds CubeRoot's table at compile time.
constexpr CubeRootTable MakeCubeRootTable()
{
	CubeRootTable t{};
	for (int r = 0; r < 3; ++r)
		for (int i = 0; i < kCubeRootCells; ++i)
		{
			const double m = double(1 << r) * (1.0 + (i + 0.5) / kCubeRootCells);
			// Newton on y³ = m: after the first step at or above the root (the mean of y, y and
			// m/y² is at least their geometric mean) and then falling onto it; 60 steps is plenty.
			double y = 1.5;
			for (int k = 0; k < 60; ++k)
				y = (2.0 * y + m / (y * y)) / 3.0;
			const double c = double(static_cast<long long>(y * 65536.0 + 0.5)) / 65536.0; // 1 ≤ c < 2: 17 bits
			t.cell[r * kCubeRootCells + i] = {c, 1.0 / (c * c * c)};
		}
	return t;
}
/// CubeRoot's table, built by the compiler.
inline constexpr CubeRootTable kCubeRootTable = MakeCubeRootTable();

/// |x| = 2^(3q + r)·m split for CubeRoot and its pairs: m ∈ [1, 8), 2^q and m's table cell.
struct CubeRootSplit
{
	double m;                 ///< 2^r·(1 + f), r the exponent's residue mod 3
	double scale;             ///< 2^q
	const CubeRootCell* cell; ///< m's cell: r and the top kCubeRootCellBits bits of f
};
/// The split of x from its bits, for x in CubeRoot's range (1e-290 to 1e290, positive).
inline CubeRootSplit SplitForCubeRoot(std::uint64_t bits)
{
	// Biased exponent e = E + 1023 ≥ 1; t = E + 2046 ≥ 0, so E = 3(t/3 − 682) + t mod 3.
	const unsigned t = unsigned(bits >> 52) + 1023u;
	const unsigned third = t / 3u, r = t - 3u * third;
	const std::uint64_t mantissa = (bits & 0x000fffffffffffffULL) | (std::uint64_t(1023u + r) << 52);
	const std::uint64_t scaleBits = std::uint64_t(third - 682u + 1023u) << 52; // 2^q, q = t/3 − 682
	CubeRootSplit split;
	std::memcpy(&split.m, &mantissa, sizeof split.m);
	std::memcpy(&split.scale, &scaleBits, sizeof split.scale);
	split.cell = &kCubeRootTable.cell[r * kCubeRootCells + unsigned((bits >> (52 - kCubeRootCellBits)) & (kCubeRootCells - 1))];
	return split;
}

/// The real cube root, within 0.51 ulp of the exact one (all but the last rounding is exact to
/// 1e-18; docs/benchmarks.md has the measured error), with no division: a table cell and a
/// polynomial.
/// |x| = 2^(3q + r)·m with m ∈ [1, 8) (m's exponent is r, the exponent's residue mod 3), so
/// ∛|x| = 2^q·∛m. The cell of m (r and the top 7 bits of the fraction) gives c ≈ ∛m with c³
/// exact, so d = m/c³ − 1 = (m − c³)·(1/c³) has an exact difference (Sterbenz: m and c³ are
/// within 1 % of each other) and one rounding of a product whose value is |d| ≤ 4e-3: an
/// error of 1e-18 in d. Then ∛m = c·(1 + d)^{1/3} with the binomial series
///   (1 + d)^{1/3} − 1 = d/3 − d²/9 + 5d³/81 − 10d⁴/243 + 22d⁵/729 − 154d⁶/6561 + …,
/// whose next term is below 3e-19 at |d| ≤ 4e-3, evaluated in pairs of terms (Estrin) for a
/// shorter dependency chain; c + c·δ rounds once at the end. (Halley's or Newton's steps from a
/// bit-pattern guess need a division each, all in one chain of latency.) glibc's std::cbrt
/// goes through frexp and ldexp, slow for a heart's level, which takes |x|^{2/3} at every
/// evaluation. Outside 1e-290 to 1e290, infinities and NaN go to std::cbrt; zero is its own
/// root (a heart's level at its centre and on its axis, asked for on every heart contact).
inline double CubeRoot(double x)
{
	const double ax = std::fabs(x);
	if (!(ax >= kCubeRootLowest && ax <= kCubeRootHighest))
		return x == 0.0 ? x : std::cbrt(x);
	std::uint64_t bits;
	std::memcpy(&bits, &ax, sizeof bits);
	const CubeRootSplit split = SplitForCubeRoot(bits);
	const double m = split.m, scale = split.scale, c = split.cell->c;
	const double d = (m - c * c * c) * split.cell->inv;
	const double d2 = d * d;
	const double low = d * (1.0 / 3.0) - d2 * (1.0 / 9.0);
	const double middle = (5.0 / 81.0) - d * (10.0 / 243.0);
	const double high = (22.0 / 729.0) - d * (154.0 / 6561.0);
	const double delta = low + (d2 * d) * (middle + d2 * high);
	return std::copysign((c + c * delta) * scale, x);
}

/// 2^{−q} for CubeRoot's split |x| = 2^{3q}·m, from the bits of its 2^q: the scale of x^{−1/3}.
inline double InverseCubeRootScale(const CubeRootSplit& split)
{
	std::uint64_t scaleBits;
	std::memcpy(&scaleBits, &split.scale, sizeof scaleBits);
	const std::uint64_t inverseBits = (std::uint64_t(2046) << 52) - scaleBits; // exponent −q
	double inverseScale;
	std::memcpy(&inverseScale, &inverseBits, sizeof inverseScale);
	return inverseScale;
}

/// CubeRoot(x) for x > 0, and with it x^{−1/3} within 2 ulp, with no division:
/// from the same cell, 1/∛m = (1/c)·(1 + d)^{−1/3}, where 1/c = c²·(1/c³) (c² exact, 1/c³ the
/// cell's) and
///   (1 + d)^{−1/3} − 1 = −d/3 + 2d²/9 − 14d³/81 + 35d⁴/243 − 91d⁵/729 + 728d⁶/6561 − …
/// (the next term below 2e-18 at |d| ≤ 4e-3), times 2^{−q} from the bits of 2^q. A heart's
/// derivatives divided by |x|^{1/3} and by |x|^{4/3}: two divisions in a chain after the root,
/// in the latency of every Newton step on its level. Outside CubeRoot's
/// main range, 1/CubeRoot(x) (infinite at 0).
inline double CubeRootWithInverse(double x, double& inverse)
{
	if (!(x >= kCubeRootLowest && x <= kCubeRootHighest))
	{
		const double root = CubeRoot(x);
		inverse = root == 0.0 ? std::numeric_limits<double>::infinity() : 1.0 / root;
		return root;
	}
	std::uint64_t bits;
	std::memcpy(&bits, &x, sizeof bits);
	const CubeRootSplit split = SplitForCubeRoot(bits);
	const double m = split.m, scale = split.scale, c = split.cell->c, inv = split.cell->inv;
	const double d = (m - c * c * c) * inv;
	const double d2 = d * d, d3 = d2 * d;
	const double low = d * (1.0 / 3.0) - d2 * (1.0 / 9.0);
	const double middle = (5.0 / 81.0) - d * (10.0 / 243.0);
	const double high = (22.0 / 729.0) - d * (154.0 / 6561.0);
	const double delta = low + d3 * (middle + d2 * high);
	const double inverseLow = d2 * (2.0 / 9.0) - d * (1.0 / 3.0);
	const double inverseMiddle = d * (35.0 / 243.0) - (14.0 / 81.0);
	const double inverseHigh = d * (728.0 / 6561.0) - (91.0 / 729.0);
	const double inverseDelta = inverseLow + d3 * (inverseMiddle + d2 * inverseHigh);
	const double reciprocal = (c * c) * inv; // 1/c
	inverse = (reciprocal + reciprocal * inverseDelta) * InverseCubeRootScale(split);
	return (c + c * delta) * scale;
}

/// x^{1/3}, and x^{−1/3} into `inverse`, each within 2e-8, for bounds: CubeRootWithInverse's
/// cell with two terms of each series,
///   (1 + d)^{1/3} = 1 + d/3 − d²/9 + 5d³/81 − …,  (1 + d)^{−1/3} = 1 − d/3 + 2d²/9 − 14d³/81 + …
/// (what is left out: 4e-9 and 1.1e-8 at |d| ≤ 4e-3). For x in CubeRoot's main range (1e-290 to
/// 1e290); the caller checks.
inline double RoughCubeRootWithInverse(double x, double& inverse)
{
	std::uint64_t bits;
	std::memcpy(&bits, &x, sizeof bits);
	const CubeRootSplit split = SplitForCubeRoot(bits);
	const double c = split.cell->c, inv = split.cell->inv;
	const double d = (split.m - c * c * c) * inv;
	const double reciprocal = (c * c) * inv; // 1/c
	inverse = (reciprocal - reciprocal * (d * ((1.0 / 3.0) - d * (2.0 / 9.0)))) * InverseCubeRootScale(split);
	return (c + c * (d * ((1.0 / 3.0) - d * (1.0 / 9.0)))) * split.scale;
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
/// CubeRoot's operations in its order, lane by lane, so that each lane is CubeRoot's bit for bit
/// (SplitForCubeRoot per lane, in 64-bit registers).
inline __m128d CubeRootPair(__m128d ax)
{
	const __m128i bits = _mm_castpd_si128(ax);
	const CubeRootSplit s0 = SplitForCubeRoot(std::uint64_t(_mm_cvtsi128_si64(bits)));
	const CubeRootSplit s1 = SplitForCubeRoot(std::uint64_t(_mm_cvtsi128_si64(_mm_unpackhi_epi64(bits, bits))));
	const __m128d m = _mm_set_pd(s1.m, s0.m), scale = _mm_set_pd(s1.scale, s0.scale);
	const __m128d c = _mm_set_pd(s1.cell->c, s0.cell->c), inv = _mm_set_pd(s1.cell->inv, s0.cell->inv);
	const __m128d d = _mm_mul_pd(_mm_sub_pd(m, _mm_mul_pd(_mm_mul_pd(c, c), c)), inv);
	const __m128d d2 = _mm_mul_pd(d, d);
	const __m128d low = _mm_sub_pd(_mm_mul_pd(d, _mm_set1_pd(1.0 / 3.0)), _mm_mul_pd(d2, _mm_set1_pd(1.0 / 9.0)));
	const __m128d middle = _mm_sub_pd(_mm_set1_pd(5.0 / 81.0), _mm_mul_pd(d, _mm_set1_pd(10.0 / 243.0)));
	const __m128d high = _mm_sub_pd(_mm_set1_pd(22.0 / 729.0), _mm_mul_pd(d, _mm_set1_pd(154.0 / 6561.0)));
	const __m128d delta = _mm_add_pd(low, _mm_mul_pd(_mm_mul_pd(d2, d), _mm_add_pd(middle, _mm_mul_pd(d2, high))));
	return _mm_mul_pd(_mm_add_pd(c, _mm_mul_pd(c, delta)), scale);
}
#endif

/// CubeRoot of two values x, y ≥ 0 into cx and cy, bit for bit: CubeRootPair where both lie in
/// its main range (one code path for both roots, half the instructions of two CubeRoots), else
/// CubeRoot each. A superellipse of n = 4 takes both components' roots for every support.
inline void CubeRoots(double x, double y, double& cx, double& cy)
{
#if defined(B2A_SSE2_PAIRS)
	if (x >= kCubeRootLowest && x <= kCubeRootHighest && y >= kCubeRootLowest && y <= kCubeRootHighest)
	{
		const __m128d c = CubeRootPair(_mm_set_pd(y, x));
		cx = _mm_cvtsd_f64(c);
		cy = _mm_cvtsd_f64(_mm_unpackhi_pd(c, c));
		return;
	}
#endif
	cx = CubeRoot(x);
	cy = CubeRoot(y);
}

/// Bounds lower ≤ ∛x ≤ upper for x ≥ 0, within 2e-3 of each other, cheaper than CubeRoot: for
/// the level bounds of the grid method, which need a side, not the last digit. From
/// CubeRootGuess (within 3.3 %), one Newton step y ← (2y + x/y²)/3: it lands at or above the
/// root (the arithmetic mean of y, y and x/y² is at least their geometric mean, ∛x) and squares
/// the relative error, to 1.0e-3 at most (over the mantissas, every exponent residue). The upper
/// end takes a margin for the step's rounding, the lower one divides by 1 + 2e-3. (A second step
/// would bring them within 2e-5 of each other, which the bounds' own slack, of the order of the
/// disc's radius, does not notice, for a division in the latency chain of every disc bound.)
/// x = 0 has the exact bounds 0 (a disc across the
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
	return y;
}
#endif

} // namespace b2a

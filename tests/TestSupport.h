// b2analytic tests: small helpers shared by the test folders.
#pragma once

#include "b2analytic/Math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

namespace b2a::test
{

/// Deterministic random numbers for tests (fixed seed per test case).
struct Random
{
	std::mt19937_64 engine;
	/// Seeded generator.
	explicit Random(std::uint64_t seed) : engine(seed) {}
	/// Uniform in [lo, hi).
	double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
	/// Log-uniform in [lo, hi).
	double LogUniform(double lo, double hi) { return std::exp(Uniform(std::log(lo), std::log(hi))); }
	/// Uniform angle in [-π, π).
	double Angle() { return Uniform(-kPi, kPi); }
};

/// |a − b| / max(|b|, floor).
inline double RelativeError(double a, double b, double floor = 1e-300)
{
	return std::fabs(a - b) / std::max(std::fabs(b), floor);
}

/// The pose at `position` turned by the rotation with exactly this cosine and sine: a pose
/// written out in hexadecimal doubles, as the benchmarks held it (Pose(p, angle) would take the
/// cosine and sine anew, to libm's rounding).
inline Pose PoseOf(Vec2 position, double c, double s)
{
	Rot q;
	q.c = c;
	q.s = s;
	return Pose(position, q);
}

} // namespace b2a::test

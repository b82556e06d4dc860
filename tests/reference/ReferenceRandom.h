// b2analytic reference library: the seeded random numbers its generators and catalogues draw from.
#pragma once

#include "b2analytic/Math.h"

#include <cmath>
#include <cstdint>
#include <random>

namespace b2a::test
{

/// Deterministic random numbers for tests, references and benchmarks (a fixed seed per use).
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

} // namespace b2a::test

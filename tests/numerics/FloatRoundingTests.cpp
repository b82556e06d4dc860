// NextFloatUp, NextFloatDown, FloatBelow and FloatAbove (numerics/FloatRounding.h) against
// std::nextafter, bit for bit.
#include <doctest/doctest.h>

#include "numerics/FloatRounding.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace b2a;

namespace
{
std::uint32_t Bits(float f)
{
	std::uint32_t b;
	std::memcpy(&b, &f, sizeof b);
	return b;
}

float FromBits(std::uint32_t b)
{
	float f;
	std::memcpy(&f, &b, sizeof f);
	return f;
}

// The same float, or both NaN (a NaN's payload is not compared).
bool Same(float got, float want) { return std::isnan(want) ? std::isnan(got) : Bits(got) == Bits(want); }
} // namespace

TEST_CASE("NextFloatUp and NextFloatDown are std::nextafter towards ±infinity, bit for bit")
{
	using L = std::numeric_limits<float>;
	std::vector<float> values = {0.0f, -0.0f, L::denorm_min(), -L::denorm_min(), L::min(), -L::min(), L::max(), -L::max(),
	                             L::infinity(), -L::infinity(), L::quiet_NaN(), 1.0f, -1.0f, 0.5f, -2.0f};
	// Each special value's neighbours, and a sweep over the whole bit space in steps of 65,537
	// (every exponent, both signs, subnormals and NaN patterns among them).
	const size_t special = values.size();
	for (size_t i = 0; i < special; ++i)
		for (float toward : {L::infinity(), -L::infinity()})
			values.push_back(std::nextafter(values[i], toward));
	for (std::uint64_t b = 0; b <= 0xffffffffull; b += 65537)
		values.push_back(FromBits(std::uint32_t(b)));
	int checked = 0;
	for (float f : values)
	{
		CAPTURE(f);
		CAPTURE(Bits(f));
		CHECK(Same(NextFloatUp(f), std::nextafter(f, L::infinity())));
		CHECK(Same(NextFloatDown(f), std::nextafter(f, -L::infinity())));
		++checked;
	}
	CHECK(checked > 65000);
	// The edges, spelled out.
	CHECK(NextFloatUp(L::max()) == L::infinity());
	CHECK(NextFloatDown(-L::max()) == -L::infinity());
	CHECK(Bits(NextFloatUp(-L::denorm_min())) == Bits(-0.0f));
	CHECK(NextFloatUp(0.0f) == L::denorm_min());
	CHECK(NextFloatDown(-0.0f) == -L::denorm_min());
}

TEST_CASE("FloatBelow and FloatAbove bracket the double they round")
{
	// A float box rounded outwards must contain the double box: below ≤ v ≤ above, and each one
	// float step from v's nearest float.
	std::mt19937_64 rng(7);
	std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
	std::uniform_int_distribution<int> exponent(-140, 120);
	for (int i = 0; i < 20000; ++i)
	{
		const double v = std::ldexp(mantissa(rng), exponent(rng));
		CAPTURE(v);
		const float below = FloatBelow(v), above = FloatAbove(v);
		CHECK(double(below) <= v);
		CHECK(double(above) >= v);
		CHECK(Bits(below) == Bits(std::nextafter(float(v), -std::numeric_limits<float>::infinity())));
		CHECK(Bits(above) == Bits(std::nextafter(float(v), std::numeric_limits<float>::infinity())));
	}
}

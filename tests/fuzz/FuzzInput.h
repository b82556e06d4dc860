// b2analytic fuzzing: the fuzzer's bytes as numbers and choices.
//
// The bytes are read front to back; past the end every read returns zero bytes, so every input
// decodes to something and short inputs mean "small, ordinary choices". Numbers are mostly drawn
// from an ordinary range, so that the fuzzer spends its time inside the solvers, and sometimes
// are an extreme (0, denormals, 1e±300, the largest double, infinities, NaN) or any 64 bits.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace b2a::fuzz
{

/// A reader of fuzzer bytes.
class FuzzInput
{
public:
	/// Read from data[0, size).
	FuzzInput(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

	/// The next byte (0 past the end).
	std::uint8_t Byte() { return m_pos < m_size ? m_data[m_pos++] : 0; }
	/// True when every byte has been read.
	bool Done() const { return m_pos >= m_size; }
	/// A choice in [lo, hi] (hi − lo < 256).
	int Int(int lo, int hi) { return lo + int(Byte() % unsigned(hi - lo + 1)); }
	/// A yes/no choice.
	bool Bool() { return (Byte() & 1) != 0; }
	/// A number in [lo, hi] with 16-bit resolution (always finite).
	double Uniform(double lo, double hi)
	{
		const unsigned u = unsigned(Byte()) << 8 | Byte();
		return lo + (hi - lo) * (u / 65535.0);
	}
	/// A positive number in [lo, hi], even in log scale (always finite).
	double LogUniform(double lo, double hi) { return std::exp(Uniform(std::log(lo), std::log(hi))); }

	/// Uniform(lo, hi) for a selector byte below 224, else an extreme value (1 in 8) or any
	/// 64 bits (1 in 32).
	double Number(double lo, double hi)
	{
		const std::uint8_t s = Byte();
		return s < kOrdinary ? Uniform(lo, hi) : Extreme(s);
	}
	/// LogUniform(lo, hi) for an ordinary selector byte, else as Number.
	double Positive(double lo, double hi)
	{
		const std::uint8_t s = Byte();
		return s < kOrdinary ? LogUniform(lo, hi) : Extreme(s);
	}
	/// True when some Number or Positive was not from its ordinary range, or MarkExtreme was called.
	bool AnyExtreme() const { return m_extreme; }
	/// Marks the input as beyond the ordinary for a choice that is not a number: a user shape
	/// declared convex that is not, whose contacts may fail (saying so) where ordinary ones may not.
	void MarkExtreme() { m_extreme = true; }

private:
	static constexpr std::uint8_t kOrdinary = 224;

	double Extreme(std::uint8_t s)
	{
		m_extreme = true;
		constexpr double inf = std::numeric_limits<double>::infinity();
		static constexpr double table[24] = {
			0.0, -0.0, 1.0, -1.0, 4.9406564584124654e-324, 2.2250738585072014e-308, 1e-300, -1e-300,
			1e-150, 1e-12, 1e-8, 1.0 + 2.220446049250313e-16, 1e8, 1e12, 1e150, -1e150,
			1e300, -1e300, 1.7976931348623157e308, -1.7976931348623157e308, inf, -inf, 0.0, 0.5};
		if (s < kOrdinary + 24)
		{
			const int k = s - kOrdinary;
			return k == 22 ? std::numeric_limits<double>::quiet_NaN() : table[k];
		}
		std::uint64_t bits = 0;
		for (int i = 0; i < 8; ++i)
			bits = bits << 8 | Byte();
		double v;
		std::memcpy(&v, &bits, sizeof v);
		return v;
	}

	const std::uint8_t* m_data;
	std::size_t m_size;
	std::size_t m_pos = 0;
	bool m_extreme = false;
};

} // namespace b2a::fuzz

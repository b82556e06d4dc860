// b2analytic: the float one step outwards from a double, for Box2D's float boxes (internal).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace b2a
{

/// The next float above f: std::nextafter(f, +∞) for every float, NaN and infinities included.
/// Inline on the bit pattern for finite non-zero f, where the four libm calls were about a third
/// of an n = 4 superellipse's proxy AABB and half of an ellipse's. For positive floats the
/// patterns increase with the value, for negative ones they decrease, so one step up is +1 on
/// the pattern of a positive float and −1 on a negative one (FLT_MAX + 1 is +∞'s pattern; the
/// smallest negative subnormal − 1 is −0, as nextafter gives).
inline float NextFloatUp(float f)
{
	if (!(f != 0.0f && std::fabs(f) <= std::numeric_limits<float>::max()))
		return std::nextafter(f, INFINITY); // zeros, infinities and NaN
	std::uint32_t bits;
	std::memcpy(&bits, &f, sizeof bits);
	bits = f > 0.0f ? bits + 1u : bits - 1u;
	std::memcpy(&f, &bits, sizeof bits);
	return f;
}

/// The next float below f: std::nextafter(f, −∞) for every float (NextFloatUp mirrored).
inline float NextFloatDown(float f) { return -NextFloatUp(-f); }

/// A float at or below v (one float below v rounded to nearest: never above v).
inline float FloatBelow(double v) { return NextFloatDown(float(v)); }

/// A float at or above v.
inline float FloatAbove(double v) { return NextFloatUp(float(v)); }

} // namespace b2a

// b2analytic: roots by square roots where the exponent allows (internal).
#pragma once

#include <cmath>

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

} // namespace b2a

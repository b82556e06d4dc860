// b2analytic: what the public solvers promise about their input and results (internal).
#pragma once

#include "b2analytic/ContactResult.h"

#include <cmath>
#include <limits>

namespace b2a
{

/// Position and rotation are finite: anything else has no contact to compute.
inline bool PoseFinite(const Pose& p)
{
	return IsFinite(p.p) && std::isfinite(p.q.c) && std::isfinite(p.q.s);
}

/// The failure for a pose that is not finite (a NaN position passed every "centres coincide"
/// test and came back as a converged overlap-axis contact full of NaN).
template <typename Result>
Result NonFinitePoseFailure()
{
	Result r;
	r.failure = "a pose is not finite (positions and angles must be finite numbers)";
	return r;
}

/// The failure that replaces a result with a field that is not finite: its own reason if it had
/// failed, else "not finite"; its method and iterations, and no other field.
template <typename Result>
Result NonFiniteFailure(const Result& r)
{
	Result f;
	f.method = r.method;
	f.iterations = r.iterations;
	f.failure = r.Ok() ? "the answer is not finite (lengths or distances beyond double precision's range)" : r.failure;
	return f;
}

/// A solved contact promises finite fields, a failed one no NaN (ContactResult.h). Finite input
/// can still overflow (circles 1e300 apart have the level (d / (rA + rB))² = inf): a result with
/// a field that is not finite becomes a failure (NonFiniteFailure). In place, so that a caller
/// that checks the named result it returns copies nothing: checked by value and returned, the
/// result would be copied once more on every contact (a function parameter is not returned in
/// place).
inline void CheckResult(ContactResult& c)
{
	const bool finite = std::isfinite(c.level) && IsFinite(c.point) && IsFinite(c.normal) && IsFinite(c.pointA) &&
	                    IsFinite(c.pointB) && std::isfinite(c.separation);
	if (!finite)
		c = NonFiniteFailure(c);
}

/// The same for a level solve.
inline void CheckResult(LevelResult& r)
{
	const bool finite = std::isfinite(r.level) && IsFinite(r.point) && IsFinite(r.normal) && std::isfinite(r.multiplier);
	if (!finite)
		r = NonFiniteFailure(r);
}

/// CheckResult of a result by value (where it is not returned from a named variable).
template <typename Result>
inline Result CheckedResult(Result r)
{
	CheckResult(r);
	return r;
}

/// The separation along the normal between the points, agreeing in sign with the level solve's
/// verdict `touching` (where rounding makes them disagree, |separation| is at rounding level).
inline void SetSeparation(ContactResult& c, bool touching)
{
	c.separation = Dot(c.pointB - c.pointA, c.normal);
	if (touching && c.separation > 0.0)
		c.separation = 0.0; // tangent to rounding
	else if (!touching && !(c.separation > 0.0))
		c.separation = std::numeric_limits<double>::denorm_min(); // apart by a rounding-level gap
	c.touching = touching;
}

} // namespace b2a

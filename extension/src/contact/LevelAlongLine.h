// b2analytic: where a shape's level along a line reaches a value, in a bracket (internal).
#pragma once

#include "b2analytic/Shape.h"
#include "numerics/RootFinding.h"

namespace b2a
{

/// The root s in [s0, s1] of λ(ToBody(pose, X + s·dir)) − level, given its values f0 and f1 at
/// the ends: Newton kept in the bracket where the shape's derivatives are cheap (2 or 3
/// evaluations for a heart where Brent's method takes 7 or 8; the same root to rounding),
/// Brent's method on the values otherwise (a user shape's derivatives may be differences of its
/// level). `iterations` of the result counts the shape's evaluations. `xtol`: an absolute
/// tolerance on s besides the relative one of rounding (FindRootNewtonSafe's and FindRootBrent's).
inline ScalarResult LevelRootAlongLine(const Shape& shape, const Pose& pose, Vec2 X, Vec2 dir, double level, double s0,
                                       double s1, double f0, double f1, double xtol = 0.0)
{
	if (!shape.DerivativesCheap())
	{
		auto f = [&](double s) { return shape.Level(ToBody(pose, X + s * dir)) - level; };
		return FindRootBrent(f, s0, s1, f0, f1, xtol, 200);
	}
	const Vec2 bodyDir = InvRotate(pose.q, dir);
	auto fdf = [&](double s, double& df) {
		const LevelDerivatives d = shape.Derivatives(ToBody(pose, X + s * dir));
		df = Dot(d.gradient, bodyDir);
		return d.value - level;
	};
	return FindRootNewtonSafe(fdf, s0, s1, f0, f1, xtol, 100);
}

} // namespace b2a

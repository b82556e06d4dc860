// b2analytic tests: helpers shared by the misuse, deep-overlap, tunnelling tests.
#pragma once

#include "SceneSupport.h"

#include <algorithm>
#include <cmath>

namespace b2a::test
{

/// Distance from a shape's origin to its surface along the world direction `u` for a shape
/// turned by `angle` (shapes are star-shaped about their origins): bisection on the level
/// function, independent of the contact solvers.
inline double Radial(const Shape& s, double angle, Vec2 u)
{
	const Vec2 d = InvRotate(Rot(angle), u);
	double inside = 0.0, outside = 1.01 * s.BoundingRadius();
	for (int k = 0; k < 60; ++k)
	{
		const double mid = 0.5 * (inside + outside);
		(s.Level(mid * d) <= s.SurfaceLevel() ? inside : outside) = mid;
	}
	return inside;
}

/// Radius of the largest disk about the shape's origin inside it (smallest radial distance
/// over 720 directions).
inline double InscribedRadius(const Shape& s)
{
	double r = 1e300;
	for (int i = 0; i < 720; ++i)
		r = std::min(r, Radial(s, 0.0, Vec2(std::cos(i * kPi / 360.0), std::sin(i * kPi / 360.0))));
	return r;
}

/// A body's pose as a b2a::Pose.
inline Pose PoseOf(const b2Body* b)
{
	return Pose(Vec2(b->GetPosition().x, b->GetPosition().y), double(b->GetAngle()));
}

/// True when a body's position, angle and velocities are all finite.
inline bool Finite(const b2Body* b)
{
	return std::isfinite(b->GetPosition().x) && std::isfinite(b->GetPosition().y) && std::isfinite(b->GetAngle()) &&
	       std::isfinite(b->GetLinearVelocity().x) && std::isfinite(b->GetLinearVelocity().y) && std::isfinite(b->GetAngularVelocity());
}

} // namespace b2a::test

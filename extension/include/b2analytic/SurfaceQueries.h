// b2analytic: queries against one posed shape: point test, line crossings, ray casts.
#pragma once

#include "b2analytic/Shape.h"

namespace b2a
{

/// True when the world point lies in the particle (level at or below the own level).
bool TestPoint(const Shape& shape, const Pose& pose, Vec2 point);

/// First s in [0, sMax] at which the line X + s·dir crosses the particle's own surface, leaving
/// the particle when X is inside it and entering it when X is outside; −1 when it does not.
/// Convex shapes: one bracketed root (after a Brent minimisation of the level along the line
/// when X is outside); other shapes: a march in steps finer than the surface samples, then a
/// bracketed root. Where the shape bounds its level (LevelUpperBound inside, LevelLowerBound
/// outside; the heart does), the march steps over stretches the bounds clear, and near the
/// shape's corners looks down to 1/64 of its step where they do not, so that it finds crossing
/// pairs that thin (a line clipping a heart's tip); without bounds a pair thinner than the step
/// can be missed. `dir` need not be unit (s is in units of |dir|).
double FirstSurfaceCrossing(const Shape& shape, const Pose& pose, Vec2 X, Vec2 dir, double sMax);

/// Result of a ray cast.
struct RayHit
{
	bool hit = false;   ///< the ray enters the particle within the fraction range
	double fraction = 0.0; ///< p1 + fraction·(p2 − p1) is the entry point
	Vec2 point;         ///< the entry point (world)
	Vec2 normal;        ///< the outward unit normal there (world)
};

/// Ray cast from p1 towards p2, up to maxFraction of the way, against the true shape. As in
/// Box2D, a ray starting inside the particle does not hit it.
RayHit RayCast(const Shape& shape, const Pose& pose, Vec2 p1, Vec2 p2, double maxFraction = 1.0);

/// World support point of a posed shape along the world direction d.
Vec2 WorldSupport(const Shape& shape, const Pose& pose, Vec2 d);

} // namespace b2a

// b2analytic: pieces the contact functions share (internal).
#pragma once

#include "b2analytic/Contact.h"

#include <cmath>
#include <vector>

namespace b2a
{

/// Coincident centres: no level point lies between them. The axis along which the overlap is
/// smallest (the separating-axis depth), refined from 64 directions.
ContactResult OverlapAxisContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb);

/// The failed contact of a failed level solve (its method, reason and iterations).
ContactResult FailedContact(const LevelResult& level);

/// What a contact takes over from its level solve unchanged, written into it.
inline void TakeOverLevel(ContactResult& c, const LevelResult& level)
{
	c.status = level.status;
	c.method = level.method;
	c.iterations = level.iterations;
	c.level = level.level;
	c.point = level.point;
}

/// The corner (index into CornerDirections and CornerPoints) whose ray the body point lies on,
/// within 1e-7 rad, or −1 (the heart's tip and notch, the vertices of exponent-1
/// superellipses): at a corner the gradient has no meaningful direction.
inline int CornerAt(const Shape& s, Vec2 x)
{
	// On the ray's side of the centre, |u × x| ≤ sin(1e-7)·|x| (NearCorner's test, without the
	// atan2).
	if (s.CornerAngles().empty() || !(LengthSquared(x) > 0.0))
		return -1;
	const double off = 1e-7 * Length(x); // sin(1e-7) = 1e-7 to 2e-22
	const std::vector<Vec2>& rays = s.CornerDirections();
	for (size_t i = 0; i < rays.size(); ++i)
		if (Dot(rays[i], x) > 0.0 && std::fabs(Cross(rays[i], x)) < off)
			return int(i);
	return -1;
}

/// A body point x of `from` in the body frame of `to`, with the offset of the centres and the
/// rotated point summed exactly (TwoSum, fma): only the result's own rounding is left.
Vec2 CompensatedBodyPoint(const Pose& from, Vec2 x, const Pose& to);

/// The point xt on a corner ray of t (t's body frame) in o's body frame, placed without the
/// centres' rounding (CompensatedBodyPoint): t's corner point where t is at its own surface
/// there, else the point on the ray where o's level is its own. Beside a needle the other
/// particle's normal at a corner turns by its curvature times that rounding.
Vec2 CornerInOther(const Shape& t, const Pose& pt, Vec2 xt, const Shape& o, const Pose& po);

/// ContactFromLevel, given A's body gradient at the level point where the caller has it
/// (`gradientA`, or null): the grid's contact needs it again for its one-side test.
ContactResult ContactFromLevelGiven(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const LevelResult& level,
                                    bool touching, bool pointOnB, const Vec2* gradientA);

/// The contact of the level chain `level` (a LevelFunction of the table, run as SolveCommonLevel
/// runs it: non-finite poses refused, the answer checked and recorded into `warm`), built by
/// ContactFromLevel; a failed solve's failure; coincident centres, which have no level point
/// between them, the axis of least overlap.
ContactResult ContactFromLevelChain(LevelFunction level, const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                    const SolverOptions& options, WarmStart* warm);

/// The level chains of the table (ContactTable.cpp), as LevelFunctions.
/// Newton from `warm` where valid, from the geometric start where that fails, and the min–max
/// solver where both fail (convergedAfterFallback).
LevelResult NewtonLevelChain(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                             const WarmStart* warm, LevelSlide* slide);
/// Two plain ellipses (or an ellipse and a circle) by Perram–Wertheim's one-dimensional form;
/// NewtonLevelChain where it fails.
LevelResult EllipseLevelChain(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                              const WarmStart* warm, LevelSlide* slide);

/// The fast paths of the table's chains. Each returns its contact, or, where it declines (the
/// chain then goes on), a default-made ContactResult: method none, which no answer has.
/// Two plain ellipses by the ellipse-pair solver with the points in closed form; declined where
/// the shapes are not plain ellipses, their centres coincide, or the solve fails or gives no
/// positive multiplier.
ContactResult EllipsePairContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, WarmStart* warm);
/// Two smooth superellipses on the raw level by the inline Newton and, for integer exponents,
/// the raw-level finish; declined where the shapes are not such superellipses, their centres
/// coincide, or the solve fails.
ContactResult SuperellipsePairContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                      const SolverOptions& options, WarmStart* warm);
/// Whether a fast path declined.
inline bool Declined(const ContactResult& c) { return c.method == SolveMethod::none; }

} // namespace b2a

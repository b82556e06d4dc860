// b2analytic: the first time two moving particles touch.
#pragma once

#include "b2analytic/Contact.h"

namespace b2a
{

/// A particle moving with constant linear and angular velocity about its body origin:
/// position p + v·t, angle θ + ω·t.
struct Motion
{
	Pose pose;                    ///< pose at t = 0
	Vec2 velocity;                ///< linear velocity of the body origin
	double angularVelocity = 0.0; ///< angular velocity, counter-clockwise positive

	/// Pose at time t.
	Pose At(double t) const { return Pose(pose.p + t * velocity, pose.q.Angle() + t * angularVelocity); }
};

/// Options of the time-of-impact search.
struct TimeOfImpactOptions
{
	double timeTolerance = 1e-13;  ///< bracket width at the end, relative to the end of the bracket (at most tMax)
	int maxIterations = 100000;    ///< cap on conservative-advancement steps
	SolverOptions solver;          ///< options of the contact solves
};

/// Result of a time-of-impact search.
struct TimeOfImpactResult
{
	SolveStatus status = SolveStatus::failed; ///< converged, or failed with a reason
	const char* failure = "";                 ///< reason when failed
	int iterations = 0;                       ///< conservative-advancement steps plus root-finding steps
	bool hit = false;                         ///< the particles touch within [0, tMax]
	double time = 0.0;                        ///< first touching time (tMax when they do not touch)
	ContactResult contact;                    ///< the contact at `time`

	/// True unless the search failed.
	bool Ok() const { return status != SolveStatus::failed; }
};

/// First time in [0, tMax] at which A and B touch. The centres move on straight lines, so the
/// search is confined to the interval in which the bounding circles overlap (none: no contact
/// is solved but the one reported at tMax). Within it, by conservative advancement: the distance
/// is bounded from below (by the gap of the supports along the current contact normal, which
/// bounds the distance of the convex hulls, by the bounding circles, and, for non-convex
/// shapes whose hulls overlap, by the distance of the sampled surfaces less their measured
/// deviation) and the approach speed from above (|vB − vA| + |ωA|·RA + |ωB|·RB), so each step
/// is safe. Close to contact the separation is bracketed in time and Brent's method finishes
/// the root to `timeTolerance` relative. Particles touching at t = 0 give time 0.
TimeOfImpactResult TimeOfImpact(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb, double tMax,
                                const TimeOfImpactOptions& options = {});

} // namespace b2a

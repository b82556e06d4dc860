// b2analytic: the first time two moving 3D particles touch.
#pragma once

#include "b2analytic/3d/Contact3.h"
#include "b2analytic/TimeOfImpact.h" // TimeOfImpactOptions

namespace b2a
{

/// A 3D particle moving with constant linear velocity and constant angular velocity about a
/// world axis through its centre: position p + v·t, orientation exp(t·[ω]×)·R₀.
struct Motion3
{
	Pose3 pose;           ///< pose at t = 0
	Vec3 velocity;        ///< linear velocity of the centre
	Vec3 angularVelocity; ///< angular velocity, a world-frame vector (radians per unit time)

	/// Pose at time t.
	Pose3 At(double t) const { return Pose3(pose.p + t * velocity, Normalize(RotationVector(t * angularVelocity) * pose.q)); }
};

/// Result of a 3D time-of-impact search (TimeOfImpactResult's fields).
struct TimeOfImpactResult3
{
	SolveStatus status = SolveStatus::failed; ///< converged, or failed with a reason
	const char* failure = "";                 ///< reason when failed
	int iterations = 0;                       ///< conservative-advancement steps plus root-finding steps
	bool hit = false;                         ///< the particles touch within [0, tMax]
	double time = 0.0;                        ///< first touching time (tMax when they do not touch)
	ContactResult3 contact;                   ///< the contact at `time`

	/// True unless the search failed.
	bool Ok() const { return status != SolveStatus::failed; }
};

/// First time in [0, tMax] at which A and B touch, exact (not stepped): as the 2D TimeOfImpact.
/// The search is confined to the interval in which the bounding spheres overlap; within it,
/// conservative advancement with a lower bound of the distance (the gap of the supports along
/// the current contact normal, and the bounding spheres) and an upper bound of the approach
/// speed (|vB − vA| + |ωA|·RA + |ωB|·RB), so no step passes the contact; close to contact the
/// separation is bracketed in time and Brent's method finishes the root to `timeTolerance`
/// relative. Particles touching at t = 0 give time 0.
TimeOfImpactResult3 TimeOfImpact(const Shape3& a, const Motion3& ma, const Shape3& b, const Motion3& mb, double tMax,
                                 const TimeOfImpactOptions& options = {});

} // namespace b2a

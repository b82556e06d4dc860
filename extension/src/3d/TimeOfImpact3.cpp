// b2analytic: time of impact of two 3D particles by conservative advancement and a bracketed root.
#include "b2analytic/3d/TimeOfImpact3.h"

#include "contact/FirstContactSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

namespace
{
// The times at which the bounding spheres overlap form one interval [t0, t1] (the centres move
// on straight lines): with u the unit relative velocity w/|w| and d = pB − pA, the distance along
// the path s = |w|·t is |d + s·u|² = (s + d·u)² + h², h = |d × u|, at most R for s within
// ±√(R² − h²) of −d·u. False when they never overlap.
bool SphereOverlapInterval(Vec3 d, Vec3 w, double R, double& t0, double& t1)
{
	const double dl = Length(d), wl = Length(w);
	if (!(wl > 0.0) || !std::isfinite(wl))
	{
		t0 = 0.0;
		t1 = std::numeric_limits<double>::infinity();
		return dl <= R;
	}
	const Vec3 u = w / wl;
	const double h = Length(Cross(d, u));
	if (!(h < R))
		return false;
	const double half = std::sqrt((R - h) * (R + h));
	const double s0 = -Dot(d, u) - half, s1 = -Dot(d, u) + half;
	t0 = std::max(0.0, s0 / wl);
	t1 = s1 / wl;
	return t1 >= 0.0;
}

} // namespace

TimeOfImpactResult3 TimeOfImpact(const Shape3& a, const Motion3& ma, const Shape3& b, const Motion3& mb, double tMax,
                                 const TimeOfImpactOptions& options)
{
	TimeOfImpactResult3 out;
	if (!std::isfinite(tMax) || !(tMax >= 0.0))
	{
		out.failure = "tMax must be finite and >= 0";
		return out;
	}
	if (!IsValidPose(ma.pose) || !IsValidPose(mb.pose) || !IsFinite(ma.velocity) || !IsFinite(mb.velocity) ||
	    !IsFinite(ma.angularVelocity) || !IsFinite(mb.angularVelocity))
	{
		out.failure = "motions must be finite, with unit quaternions";
		return out;
	}
	const double RA = a.BoundingRadius(), RB = b.BoundingRadius();
	const double size = 0.5 * (RA + RB);
	// No point of A moves faster than |vA| + |ωA|·RA, so the gap shrinks at most at this rate.
	const double rate = Length(mb.velocity - ma.velocity) + Length(ma.angularVelocity) * RA + Length(mb.angularVelocity) * RB;
	WarmStart3 warm; // the contacts along the way follow one another
	auto contactAt = [&](double t) {
		return ComputeContact(a, ma.At(t), b, mb.At(t), MethodChoice::automatic, options.solver, &warm);
	};
	auto lowerBound = [&](double t, const ContactResult3& c) {
		const Pose3 pa = ma.At(t), pb = mb.At(t);
		const Vec3 n = c.normal;
		const double gap = Dot(pb.p - pa.p, n) - a.SupportValue(InvRotate(pa.q, n)) - b.SupportValue(InvRotate(pb.q, -n));
		return std::max(Distance(pa.p, pb.p) - RA - RB, gap);
	};
	const double R = (RA + RB) * (1.0 + 1e-9);
	double t0 = 0.0, t1 = tMax;
	if (!SphereOverlapInterval(mb.pose.p - ma.pose.p, mb.velocity - ma.velocity, R, t0, t1) || t0 > tMax)
		return ReportNoContact(out, contactAt(tMax), tMax);
	const double tEnd = std::min(tMax, t1);

	return SearchFirstContact(out, contactAt, lowerBound, t0, tEnd, tMax, rate, size, options);
}

} // namespace b2a

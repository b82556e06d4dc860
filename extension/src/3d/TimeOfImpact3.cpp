// b2analytic: time of impact of two 3D particles by conservative advancement and a bracketed root.
#include "b2analytic/3d/TimeOfImpact3.h"

#include "numerics/RootFinding.h"

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

TimeOfImpactResult3& Finish(TimeOfImpactResult3& out, bool hit, double time, const ContactResult3& c)
{
	out.status = SolveStatus::converged;
	out.iterations = std::max(out.iterations, 1);
	out.hit = hit;
	out.time = time;
	out.contact = c;
	return out;
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
	const double switchGap = 1e-3 * size; // below this, look for a sign change to bracket
	const double touchGap = 1e-12 * size; // a lower bound this small is contact (grazing)
	WarmStart3 warm;                      // the contacts along the way follow one another
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
		return Finish(out, false, tMax, contactAt(tMax));
	const double tEnd = std::min(tMax, t1);

	double t = t0;
	ContactResult3 c = contactAt(t);
	for (int it = 0; it < options.maxIterations; ++it)
	{
		out.iterations = it + 1;
		if (!c.Ok())
		{
			out.failure = c.failure;
			return out;
		}
		if (c.touching)
			return Finish(out, true, t, c);
		const double lb = lowerBound(t, c);
		if (!(rate > 0.0))
			break; // nothing moves relative to the other
		if (lb <= touchGap)
			return Finish(out, true, t, c);
		if (lb <= switchGap)
		{
			// Close: the separation's rate of change from a difference, and where a sign change is
			// found ahead, Brent's method on the separation (a touching contact has separation ≤ 0).
			const double dt = std::max(c.separation / rate, 1e-9 * std::max(t, lb / rate));
			const double slope = (contactAt(std::min(tMax, t + dt)).separation - c.separation) / dt;
			if (slope < 0.0)
			{
				const double guess = t + c.separation / -slope;
				const double hi = std::min(tMax, t + 1.5 * (guess - t) + lb / rate);
				const ContactResult3 chi = contactAt(hi);
				if (chi.Ok() && chi.touching)
				{
					auto separation = [&](double s) { return contactAt(s).separation; };
					const double tol = options.timeTolerance * std::max(hi, 1e-300);
					const ScalarResult root = FindRootBrent(separation, t, hi, c.separation, chi.separation, tol, 200);
					out.iterations += root.iterations;
					// Report a touching contact: the bracket's end on the touching side.
					double tr = root.x;
					ContactResult3 cr = contactAt(tr);
					if (!cr.touching)
					{
						tr = std::min(hi, tr + tol);
						cr = contactAt(tr);
					}
					return Finish(out, true, tr, cr);
				}
			}
		}
		const double next = t + lb / rate;
		if (next > tEnd)
			break;
		t = next;
		c = contactAt(t);
	}
	if (out.iterations >= options.maxIterations)
	{
		out.failure = "conservative advancement reached its step cap";
		return out;
	}
	return Finish(out, false, tMax, contactAt(tMax));
}

} // namespace b2a

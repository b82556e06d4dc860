// b2analytic: time of impact by conservative advancement and a bracketed root.
#include "b2analytic/TimeOfImpact.h"
#include "b2analytic/SurfaceQueries.h"

#include "contact/FirstContactSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

namespace
{
// Distance between two closed polylines (segments do not cross: that case returns 0).
double PolylineDistance(const std::vector<Vec2>& p, const std::vector<Vec2>& q)
{
	double best = std::numeric_limits<double>::infinity();
	const int n = int(p.size()), m = int(q.size());
	for (int i = 0; i < n; ++i)
	{
		const Vec2 a0 = p[i], a1 = p[(i + 1) % n];
		for (int j = 0; j < m; ++j)
		{
			const Vec2 b0 = q[j], b1 = q[(j + 1) % m];
			// Proper crossing: opposite orientations on both segments.
			const double d1 = Cross(a1 - a0, b0 - a0), d2 = Cross(a1 - a0, b1 - a0);
			const double d3 = Cross(b1 - b0, a0 - b0), d4 = Cross(b1 - b0, a1 - b0);
			if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)))
				return 0.0;
			best = std::min({best, DistanceToSegment(a0, b0, b1), DistanceToSegment(a1, b0, b1), DistanceToSegment(b0, a0, a1),
			                 DistanceToSegment(b1, a0, a1)});
		}
	}
	return best;
}

std::vector<Vec2> WorldSamples(const Shape& s, const Pose& pose, int count)
{
	const auto samples = s.Samples(count);
	std::vector<Vec2> out;
	out.reserve(samples->point.size());
	for (Vec2 p : samples->point)
		out.push_back(ToWorld(pose, p));
	return out;
}

// The centres move on straight lines (Motion::At), so the times at which the bounding circles
// overlap form one interval [t0, t1]: with u = w/|w| the direction of the relative velocity
// w = vB − vA and d = pB − pA, the centre distance along the path s = |w|·t is
// |d + s·u|² = (s + d·u)² + h², h = |d × u|, which is ≤ R² for s within ±√(R² − h²) of −d·u.
// Outside that interval the particles cannot touch; false when they never overlap. The squares
// are never formed from d or w, so positions and speeds near the double range stay finite.
bool CircleOverlapInterval(Vec2 d, Vec2 w, double R, double& t0, double& t1)
{
	const double dl = std::hypot(d.x, d.y);
	const double wl = std::hypot(w.x, w.y);
	if (!(wl > 0.0) || !std::isfinite(wl))
	{
		t0 = 0.0;
		t1 = std::numeric_limits<double>::infinity();
		return dl <= R; // no relative motion of the centres (or speeds beyond range: no filter)
	}
	const Vec2 u = w / wl;
	const double h = std::fabs(Cross(d, u));
	if (!(h < R))
		return false;
	const double half = std::sqrt((R - h) * (R + h));
	const double s0 = -Dot(d, u) - half, s1 = -Dot(d, u) + half;
	t0 = std::max(0.0, s0 / wl);
	t1 = s1 / wl;
	return t1 >= 0.0;
}

} // namespace

TimeOfImpactResult TimeOfImpact(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb, double tMax,
                                const TimeOfImpactOptions& options)
{
	TimeOfImpactResult out;
	if (!std::isfinite(tMax) || !(tMax >= 0.0))
	{
		out.failure = "tMax must be finite and >= 0";
		return out;
	}
	if (!IsFinite(ma.pose.p) || !IsFinite(mb.pose.p) || !IsFinite(ma.velocity) || !IsFinite(mb.velocity) ||
	    !std::isfinite(ma.angularVelocity) || !std::isfinite(mb.angularVelocity))
	{
		out.failure = "motions must be finite";
		return out;
	}
	const double RA = a.BoundingRadius(), RB = b.BoundingRadius();
	const double size = 0.5 * (RA + RB);
	// No point of A moves faster than |vA| + |ωA|·RA relative to the world, so the distance
	// between the particles shrinks at most at this rate.
	const double rate = Length(mb.velocity - ma.velocity) + std::fabs(ma.angularVelocity) * RA + std::fabs(mb.angularVelocity) * RB;
	const bool convex = a.IsConvex() && b.IsConvex();
	const double switchGap = 1e-3 * size;  // below this, the polylines bound the distance too

	auto contactAt = [&](double t) { return ComputeContact(a, ma.At(t), b, mb.At(t), MethodChoice::automatic, options.solver); };
	auto lowerBound = [&](double t, const ContactResult& c) {
		const Pose pa = ma.At(t), pb = mb.At(t);
		double lb = Distance(pa.p, pb.p) - RA - RB;
		const Vec2 n = c.normal;
		lb = std::max(lb, Dot(WorldSupport(b, pb, -n), n) - Dot(WorldSupport(a, pa, n), n));
		if (!convex && lb <= switchGap)
		{
			const int count = options.solver.gridSamples;
			const double poly = PolylineDistance(WorldSamples(a, pa, count), WorldSamples(b, pb, count));
			lb = std::max(lb, poly - a.Samples(count)->maxDeviation - b.Samples(count)->maxDeviation);
		}
		return lb;
	};

	// Skip the times at which the bounding circles are apart (margin for the radii's rounding): no
	// contact is solved there, which matters when the particles race apart or pass far away.
	const double R = (RA + RB) * (1.0 + 1e-9);
	double t0 = 0.0, t1 = tMax;
	if (!CircleOverlapInterval(mb.pose.p - ma.pose.p, mb.velocity - ma.velocity, R, t0, t1) || t0 > tMax)
		return ReportNoContact(out, contactAt(tMax), tMax);
	const double tEnd = std::min(tMax, t1);

	return SearchFirstContact(out, contactAt, lowerBound, t0, tEnd, tMax, rate, size, options);
}

} // namespace b2a

// b2analytic: analytic shape against a convex polygon or segment, by the separating axis.
#include "b2analytic/PolygonContact.h"

#include "b2analytic/SurfaceQueries.h"
#include "contact/ResultChecks.h"
#include "numerics/RootFinding.h"

#include <cmath>
#include <limits>
#include <vector>

namespace b2a
{

ContactResult ComputePolygonContact(const Shape& a, const Pose& pa, const Vec2* vertices, int count, const Pose& pb,
                                    const Vec2* guessNormal)
{
	ContactResult c;
	c.method = SolveMethod::separatingAxis;
	if (count < 2 || vertices == nullptr)
	{
		c.failure = "a polygon needs at least two vertices";
		return c;
	}
	std::vector<Vec2> w(count);
	for (int j = 0; j < count; ++j)
		w[j] = ToWorld(pb, vertices[j]);
	int evaluations = 0;
	// Gap along n: B's lowest vertex along n minus A's highest point along n.
	auto gap = [&](Vec2 n) {
		++evaluations;
		double lowest = std::numeric_limits<double>::infinity();
		for (const Vec2& v : w)
			lowest = std::min(lowest, Dot(v, n));
		return lowest - Dot(WorldSupport(a, pa, n), n);
	};
	double bestAngle = 0.0, best = -std::numeric_limits<double>::infinity();
	auto consider = [&](Vec2 n) {
		if (!(LengthSquared(n) > 0.0) || !IsFinite(n))
			return;
		n = Normalize(n);
		const double g = gap(n);
		if (g > best)
		{
			best = g;
			bestAngle = std::atan2(n.y, n.x);
		}
	};
	// Face normals (pointing into B from A's side: minus the outward normal), both sides of a
	// segment, the directions to the vertices and to the centroid, a guess, and even directions.
	Vec2 centroid;
	for (int j = 0; j < count; ++j)
	{
		const Vec2 e = w[(j + 1) % count] - w[j];
		const Vec2 outward(e.y, -e.x);
		consider(-outward);
		if (count == 2)
			consider(outward);
		consider(w[j] - pa.p);
		centroid += w[j] / double(count);
	}
	consider(centroid - pa.p);
	if (guessNormal)
		consider(*guessNormal);
	for (int k = 0; k < 16; ++k)
		consider(Vec2(std::cos(kPi * k / 8.0), std::sin(kPi * k / 8.0)));
	// Refine: the gap is a continuous function of the angle with kinks at face normals.
	auto negGap = [&](double t) { return -gap(Vec2(std::cos(t), std::sin(t))); };
	const double span = kPi / 8.0;
	const ScalarResult m = MinimizeBrent(negGap, bestAngle - span, bestAngle + span, 1e-12, 1e-14, 200);
	if (-m.fx > best)
	{
		best = -m.fx;
		bestAngle = m.x;
	}
	if (!std::isfinite(best))
	{
		c.failure = "non-finite gap (check the polygon vertices and the pose)";
		return c;
	}
	c.status = SolveStatus::converged;
	c.iterations = evaluations;
	c.normal = Vec2(std::cos(bestAngle), std::sin(bestAngle));
	c.pointA = WorldSupport(a, pa, c.normal);
	c.separation = best;
	c.pointB = c.pointA + best * c.normal;
	c.point = 0.5 * (c.pointA + c.pointB);
	c.level = 0.0;
	c.touching = best <= 0.0;
	return CheckedResult(c);
}

} // namespace b2a

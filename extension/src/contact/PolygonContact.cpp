// b2analytic: analytic shape against a convex polygon or segment, by the separating axis.
#include "b2analytic/PolygonContact.h"

#include "b2analytic/SurfaceQueries.h"
#include "contact/ResultChecks.h"
#include "numerics/RootFinding.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
// The 16 directions kπ/8 that every wall contact tries, computed once and normalised as each
// candidate is (`consider`): the same values as computing them at each call, without 32 libm
// calls, a square root and two divisions each a contact (and the angle of the best direction is
// taken once, after the candidates, not at each improvement).
const std::array<Vec2, 16>& EvenDirections()
{
	static const std::array<Vec2, 16> directions = [] {
		std::array<Vec2, 16> d;
		for (int k = 0; k < 16; ++k)
			d[k] = Normalize(Vec2(std::cos(kPi * k / 8.0), std::sin(kPi * k / 8.0)));
		return d;
	}();
	return directions;
}
} // namespace

ContactResult SeparatingAxisContact(const Shape& a, const Pose& pa, const Vec2* vertices, int count, const Pose& pb,
                                    const Vec2* guessNormal)
{
	ContactResult c;
	c.method = SolveMethod::separatingAxis;
	if (count < 2 || vertices == nullptr)
	{
		c.failure = "a polygon needs at least two vertices";
		return c;
	}
	// World vertices: on the stack for Box2D's polygons (at most 8) and segments.
	Vec2 local[16];
	std::vector<Vec2> heap;
	Vec2* w = local;
	if (count > 16)
	{
		heap.resize(count);
		w = heap.data();
	}
	for (int j = 0; j < count; ++j)
		w[j] = ToWorld(pb, vertices[j]);
	int evaluations = 0;
	Vec2 support; // A's support point along the last n the gap was taken for
	// B's lowest vertex along n.
	auto lowestAlong = [&](Vec2 n) {
		double lowest = std::numeric_limits<double>::infinity();
		for (int j = 0; j < count; ++j)
			lowest = std::min(lowest, Dot(w[j], n));
		return lowest;
	};
	// Gap along n: B's lowest vertex along n minus A's highest point along n.
	auto gap = [&](Vec2 n) {
		++evaluations;
		const double lowest = lowestAlong(n);
		support = WorldSupport(a, pa, n);
		return lowest - Dot(support, n);
	};
	double best = -std::numeric_limits<double>::infinity();
	int bestFace = -1; // the face whose normal gave the best gap (-1: another direction)
	Vec2 bestNormal, bestSupport;
	// A shape whose SupportBounds are cheap (SupportBoundsCheap: a superellipse's closed form,
	// no roots of its exponent; a heart's surface sample farthest along the direction, no Newton
	// step) bounds its support value below first: a candidate whose gap, with that bound in place
	// of the support value, does not beat the best one found cannot win, and takes no support.
	// Only the face normals near the contact's do; the wrong side of a segment and most of the 16
	// even directions stop here (24 supports a wall contact took, 4 or 5 now). The skip is exact:
	// the computed gap, lowest − (support·n), exceeds lowest − p·n − h(Qᵀn) by the rounding of the
	// support point and the dot products alone, a few 1e-16 of |p·n| + R + |lowest|, and `margin`
	// is 1e-12 of that; so a skipped candidate's computed gap would not have passed g > best
	// either, and the result is the one without the skip, bit for bit.
	const bool cheapBounds = a.SupportBoundsCheap();
	const double radius = a.BoundingRadius();
	// `unit`: n is already a unit vector as Normalize leaves it (the even directions).
	auto consider = [&](Vec2 n, int face, bool unit) {
		if (!unit)
		{
			if (!(LengthSquared(n) > 0.0) || !IsFinite(n))
				return;
			n = Normalize(n);
		}
		if (cheapBounds && std::isfinite(best))
		{
			double lower = 0.0, upper = 0.0;
			a.SupportBounds(InvRotate(pa.q, n), lower, upper);
			const double lowest = lowestAlong(n), centre = Dot(pa.p, n);
			const double margin = 1e-12 * (std::fabs(centre) + radius + std::fabs(lowest));
			if (lowest - centre - lower + margin <= best)
				return;
		}
		const double g = gap(n);
		if (g > best)
		{
			best = g;
			bestFace = face;
			bestNormal = n;
			bestSupport = support;
		}
	};
	// Face normals (pointing into B from A's side: minus the outward normal), both sides of a
	// segment, the directions to the vertices and to the centroid, a guess, and even directions.
	// A segment's second edge is its first reversed (w0 − w1 = −(w1 − w0) exactly): its two normals
	// are the first edge's two, to the bit, and an equal gap never replaces the best (g > best),
	// so they are tried once.
	Vec2 centroid;
	for (int j = 0; j < count; ++j)
	{
		if (count > 2 || j == 0)
		{
			const Vec2 e = w[(j + 1) % count] - w[j];
			const Vec2 outward(e.y, -e.x);
			consider(-outward, j, false);
			if (count == 2)
				consider(outward, j, false);
		}
		consider(w[j] - pa.p, -1, false);
		centroid += w[j] / double(count);
	}
	consider(centroid - pa.p, -1, false);
	if (guessNormal)
		consider(*guessNormal, -1, false);
	for (const Vec2& n : EvenDirections())
		consider(n, -1, true);
	double bestAngle = std::atan2(bestNormal.y, bestNormal.x);
	// A face normal that is a local maximum needs no refinement: a particle resting on a wall.
	// With t = n' (the normal turned by +90°), the gap's one-sided derivatives there are
	// (v − s_A(n))·t, v the face end that is lowest along n turned slightly that way (the
	// support value h_A(n) has derivative s_A(n)·t when A is strictly convex). Both pointing
	// down, the kink is a local maximum, and the search below would only find it again.
	// The same holds for any shape whose support at n is one point (then h_A is differentiable
	// there, Danskin's theorem): a heart's hull has a flat only between its lobes, and its tip is
	// one point. Where A is not smooth and convex, the supports at n turned by ±1e-9 rad tell:
	// on a flat of the hull they jump to its two ends; elsewhere they lie within the curvature
	// radius times 2e-9 of each other.
	bool kinkMaximum = false;
	if (bestFace >= 0)
	{
		const Vec2 t(-bestNormal.y, bestNormal.x);
		const double s = Dot(bestSupport, t);
		const double t0 = Dot(w[bestFace], t), t1 = Dot(w[(bestFace + 1) % count], t);
		kinkMaximum = std::min(t0, t1) - s < 0.0 && std::max(t0, t1) - s > 0.0;
		if (kinkMaximum && !a.IsSmoothConvex())
		{
			const double turn = 1e-9;
			const Vec2 before = WorldSupport(a, pa, bestNormal - turn * t), after = WorldSupport(a, pa, bestNormal + turn * t);
			evaluations += 2;
			kinkMaximum = Length(after - before) <= 1e-6 * a.BoundingRadius();
		}
	}
	if (!kinkMaximum)
	{
		// Refine: the gap is a continuous function of the angle with kinks at face normals.
		auto negGap = [&](double t) { return -gap(Vec2(std::cos(t), std::sin(t))); };
		const double span = kPi / 8.0;
		const ScalarResult m = MinimizeBrent(negGap, bestAngle - span, bestAngle + span, 1e-12, 1e-14, 200);
		if (-m.fx > best)
		{
			best = -m.fx;
			bestAngle = m.x;
		}
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

// b2analytic: the contact built from a level solution, and the contact of coincident centres.
#include "contact/ContactParts.h"

#include "b2analytic/SurfaceQueries.h"

#include "contact/ResultChecks.h"
#include "contact/SurfaceCrossing.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
// The surface point of a shape on the ray from its centre towards X (always exists).
Vec2 RadialPoint(const Shape& shape, const Pose& pose, Vec2 X)
{
	const Vec2 x = ToBody(pose, X);
	const double theta = LengthSquared(x) > 0.0 ? std::atan2(x.y, x.x) : 0.0;
	return ToWorld(pose, shape.SurfacePoint(theta));
}
} // namespace

ContactResult OverlapAxisContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb)
{
	auto depth = [&](double t) {
		const Vec2 n(std::cos(t), std::sin(t));
		return Dot(WorldSupport(a, pa, n) - WorldSupport(b, pb, -n), n);
	};
	const int count = 64;
	const double step = 2.0 * kPi / count;
	double value[count];
	int lowest = 0;
	for (int k = 0; k < count; ++k)
	{
		value[k] = depth(step * k);
		if (value[k] < value[lowest]) lowest = k;
	}
	// The depth has a local minimum at each particle's narrow axes, sharp ones for blocky
	// superellipses, so the lowest sample can lie by the wrong one (a large square and a small
	// needle: the square's other axis, across the needle, is the least overlap). Refine the four
	// lowest local minima of the samples and keep the least depth.
	std::vector<int> minima;
	for (int k = 0; k < count; ++k)
		if (value[k] <= value[(k + count - 1) % count] && value[k] < value[(k + 1) % count])
			minima.push_back(k);
	if (minima.empty())
		minima.push_back(lowest); // constant depth (two circles)
	std::sort(minima.begin(), minima.end(), [&](int i, int j) { return value[i] < value[j]; });
	if (minima.size() > 4)
		minima.resize(4);
	double t = step * minima[0], bestDepth = value[minima[0]];
	for (int k : minima)
	{
		const ScalarResult m = MinimizeBrent(depth, step * (k - 1), step * (k + 1), 1e-12, 1e-14, 200);
		if (m.fx < bestDepth) { bestDepth = m.fx; t = m.x; }
	}
	ContactResult c;
	c.status = SolveStatus::converged;
	c.method = SolveMethod::overlapAxis;
	c.normal = Vec2(std::cos(t), std::sin(t));
	c.pointA = WorldSupport(a, pa, c.normal);
	c.pointB = WorldSupport(b, pb, -c.normal);
	c.point = 0.5 * (pa.p + pb.p);
	c.separation = Dot(c.pointB - c.pointA, c.normal);
	c.touching = c.separation <= 0.0;
	c.level = 0.0;
	return c;
}

ContactResult FailedContact(const LevelResult& level)
{
	ContactResult c;
	c.status = SolveStatus::failed;
	c.method = level.method;
	c.failure = level.failure;
	c.iterations = level.iterations;
	return c;
}

namespace
{
// True when the body point lies on one of the shape's corners.
bool AtCorner(const Shape& s, Vec2 x) { return CornerAt(s, x) >= 0; }

// A convex shape's extreme point along `dir` on the line X + t·dir (the largest root of
// g(t) = λ(X + t·dir) − own), by Newton from t = 0, where g(0) = g0. g is convex along the line
// (λ is convex for a convex shape of the superellipse family; user shapes declared convex are
// taken at their word, and the result is checked). Where g'(0) > 0, Newton converges to the
// largest root monotonically: every tangent lies below g, so from g(0) > 0 each iterate stays
// between the root and the previous one, and from g(0) < 0 the first iterate overshoots past
// the root, after which the same holds. A few iterations replace the ~40 level evaluations of a
// bracketing search; where the conditions fail (g'(0) ≤ 0, the line misses the shape, no
// convergence in 30 steps) it returns false and the bracketing search decides.
bool ConvexLineExtreme(const Shape& s, const Pose& ps, Vec2 X, Vec2 dir, double g0, double reach, double& t)
{
	const Vec2 localDir = InvRotate(ps.q, dir);
	const double own = s.SurfaceLevel();
	// Level and slope from one evaluation per iterate; stop where the step or the level is at
	// rounding (a level within 4 eps of the own level is on the surface to rounding).
	const double tol = 1e-15 * reach, levelTol = 4.0 * std::numeric_limits<double>::epsilon() * std::fabs(own);
	t = 0.0;
	LevelDerivatives d = s.Derivatives(ToBody(ps, X));
	double g = g0;
	for (int it = 0; it < 30; ++it)
	{
		const double slope = Dot(d.gradient, localDir);
		if (!(slope > 0.0) || !std::isfinite(g))
			return false;
		const double step = g / slope;
		const double next = t - step;
		if (!(std::fabs(next) <= reach))
			return false;
		// After the first step the iterates decrease monotonically onto the root: an increase
		// means g is not convex along the line here; let the bracketing search decide.
		if (it > 0 && step < -tol)
			return false;
		t = next;
		if (std::fabs(step) <= tol)
			return true;
		d = s.Derivatives(ToBody(ps, X + t * dir));
		g = d.value - own;
		if (std::fabs(g) <= levelTol)
			return true;
	}
	return false;
}

// The weight of a shape's normal in the contact's: the inverse of its level curve's curvature
// at x, |tᵀHt|/|∇λ| (t the unit tangent; the same for any monotone function of λ, so geometric).
// A point off the common-level point by δ along the surfaces (a level solve stops at its own
// tolerance, and rounds) turns each normal by its curvature times δ: beside a needle's tip that
// is 1e4 or more times the other particle's turn.
double NormalCurvature(const Shape& s, Vec2 x)
{
	const LevelDerivatives d = s.Derivatives(x);
	const double g = Length(d.gradient);
	const Vec2 t = Perp(d.gradient);
	return std::fabs(Dot(t, d.hessian * t)) / (g * g * g);
}

// A's outward unit normal na and B's nb, opposed: their mean where they agree to 1e-8 rad (its
// error then at most that), else their mean weighted by the inverse curvatures (NormalCurvature),
// whose error is at most twice the smaller curvature's turn: the mean of a needle's normal and a
// round particle's carried half the needle's error (up to 4e-4 rad). The weights assume a point
// near the solution (its error small against the curvatures' radii); where the normals are more
// than 4e-3 rad apart it is not (an unrefined grid's sample), and the plain mean is no worse a
// guess. Swapping A and B flips it exactly either way.
Vec2 OpposedNormal(const Shape& a, Vec2 xa, Vec2 na, const Shape& b, Vec2 xb, Vec2 nb)
{
	const Vec2 mean = na - nb;
	const double apart = LengthSquared(na + nb);
	if (apart <= 1e-16 || apart > 4e-3 * 4e-3)
		return Normalize(mean);
	const double ka = NormalCurvature(a, xa), kb = NormalCurvature(b, xb);
	const Vec2 weighted = kb * na - ka * nb;
	return std::isfinite(ka + kb) && LengthSquared(weighted) > 0.0 ? Normalize(weighted) : Normalize(mean);
}

} // namespace

// A body point x of `from` in the body frame of `to`, R_toᵀ((c_from − c_to) + R_from·x), with the
// sum carried exactly (TwoSum; the products' roundings by fma): what is left is the rounding of the
// result itself, not of the centres' coordinates and of R_from·x, which cancel where the point is
// far from `from`'s centre and near `to`'s (a heart's tip beside a needle 1e4 of its size away:
// 1e-16 of the heart's size is 1e-12 of the needle's, and turns its normal by 1e-6 rad).
Vec2 CompensatedBodyPoint(const Pose& from, Vec2 x, const Pose& to)
{
	auto sum = [](double a, double b, double& low) {
		const double s = a + b, bb = s - a;
		low += (a - (s - bb)) + (b - bb);
		return s;
	};
	auto product = [](double a, double b, double& low) {
		const double p = a * b;
		low += std::fma(a, b, -p);
		return p;
	};
	auto component = [&](double c0, double c1, double r0, double x0, double r1, double x1) {
		double low = 0.0;
		const double rotated = sum(product(r0, x0, low), product(r1, x1, low), low);
		const double offset = sum(c0, -c1, low);
		return sum(offset, rotated, low) + low;
	};
	const Vec2 w(component(from.p.x, to.p.x, from.q.c, x.x, -from.q.s, x.y),
	             component(from.p.y, to.p.y, from.q.s, x.x, from.q.c, x.y));
	return InvRotate(to.q, w);
}

// At a corner of one particle (T, the body point xt on its corner ray) and not of the other (O),
// the contact normal is O's at the corner, which turns with the corner's place across O's surface
// by O's curvature: beside a needle's end (curvature 1e8 of a heart's size) the centres' rounding
// alone turned it by 1e-6 rad. The corner's body point in O's frame, without that rounding
// (CompensatedBodyPoint), on the surface of whichever particle is at its own level there (the
// nearer one, relative to its own level; the other is the scaled one): T's own corner point, or
// the point on T's corner ray where O's level is its own, by Newton along the ray (from the given
// point, within rounding of it, so one step). Where neither is (a common level), the
// given point.
Vec2 CornerInOther(const Shape& t, const Pose& pt, Vec2 xt, const Shape& o, const Pose& po)
{
	const int k = CornerAt(t, xt);
	if (k < 0)
		return ToBody(po, ToWorld(pt, xt));
	const double ownT = t.SurfaceLevel(), ownO = o.SurfaceLevel();
	const double unitT = ownT != 0.0 ? std::fabs(ownT) : 1.0, unitO = ownO != 0.0 ? std::fabs(ownO) : 1.0;
	const Vec2 u = t.CornerDirections()[size_t(k)];
	double s = Dot(u, xt);
	Vec2 x = CompensatedBodyPoint(pt, s * u, po);
	// (T's level on its ray, where it is smooth: across the ray it grows like |x|^{2/3} at a
	// heart's tip, and the given point's rounding alone would move it by 1e-10 of itself.)
	const double gapT = std::fabs(t.Level(s * u) - ownT) / unitT, gapO = std::fabs(o.Level(x) - ownO) / unitO;
	if (gapT <= 1e-9 && gapT < gapO)
	{
		// T's corner point, its distance along the ray polished on T's own level (RadiusAt
		// stops a few roundings short).
		// (From within 1e-6 of the root Newton's next step is below 1e-12 of the last: one
		// step where the first is below 1e-8 of s, two at most.)
		s = Dot(u, t.CornerPoints()[size_t(k)]);
		for (int it = 0; it < 2; ++it)
		{
			const LevelDerivatives d = t.Derivatives(s * u);
			const double step = (d.value - ownT) / Dot(d.gradient, u);
			if (!std::isfinite(step) || !(std::fabs(step) <= 1e-6 * s))
				break;
			s -= step;
			if (std::fabs(step) <= 1e-8 * s)
				break;
		}
		return CompensatedBodyPoint(pt, s * u, po);
	}
	if (!(gapO <= 1e-6))
		return x;
	const Vec2 along = InvRotate(po.q, Rotate(pt.q, u)); // d/ds of the point s·u in O's frame
	for (int it = 0; it < 4; ++it)
	{
		const LevelDerivatives d = o.Derivatives(x);
		const double step = (d.value - ownO) / Dot(d.gradient, along);
		if (!std::isfinite(step) || !(std::fabs(step) <= 1e-6 * s))
			break;
		s -= step;
		x = CompensatedBodyPoint(pt, s * u, po);
		if (std::fabs(step) <= 1e-8 * s)
			break;
	}
	return x;
}

namespace
{
// The contact normal at X, from A to B: the mean of A's outward and B's inward unit normals,
// which agree at a tangency. A shape whose corner X is gives no normal; the other's is used.
// When the two normals point the same way, one particle's centre lies inside the other and X is
// B's surface point nearest A (pointOnB, the grid method): A leaves B fastest through that
// point, so the normal is B's inward one there.
// (`cornerA`, `cornerB`: whether X is a corner of A, of B; the caller has them.)
// `solved`: a converged Newton's normal (A's unit gradient where it solved the conditions). Where
// the two normals at X are more than 4e-3 rad apart it is the answer: a converged Newton's point
// has them opposed in the frame it solved in, and only the rounding of X to world coordinates
// parts them (needles crossing deep inside each other, the point within that rounding of a
// needle's tip, solved in the needle's own frame: SolveSuperellipsePairLevel).
Vec2 ContactNormal(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Vec2 X, bool pointOnB,
                   const Vec2* gradientA, bool cornerA, bool cornerB, const Vec2* solved)
{
	const Vec2 xa = ToBody(pa, X), xb = ToBody(pb, X);
	Vec2 na, nb;
	if (cornerA != cornerB)
	{
		// One corner: the other's normal at it, placed without the centres' rounding.
		if (cornerB)
			na = Normalize(Rotate(pa.q, a.Gradient(CornerInOther(b, pb, xb, a, pa))));
		else
			nb = Normalize(Rotate(pb.q, b.Gradient(CornerInOther(a, pa, xa, b, pb))));
	}
	else if (!cornerA)
	{
		na = Normalize(Rotate(pa.q, gradientA ? *gradientA : a.Gradient(xa)));
		nb = Normalize(Rotate(pb.q, b.Gradient(xb)));
	}
	const bool hasA = LengthSquared(na) > 0.0, hasB = LengthSquared(nb) > 0.0;
	Vec2 n;
	if (hasA && hasB && solved && LengthSquared(na + nb) > 4e-3 * 4e-3)
		n = *solved;
	else if (hasA && hasB)
		n = Dot(na, nb) < 0.0 ? OpposedNormal(a, xa, na, b, xb, nb) : (pointOnB ? -nb : na);
	else if (hasA)
		n = na;
	else if (hasB)
		n = -nb;
	if (!(LengthSquared(n) > 0.0))
		n = Normalize(pb.p - pa.p);
	if (!(LengthSquared(n) > 0.0))
		n = Vec2(1.0, 0.0);
	return n;
}
} // namespace

ContactResult ContactFromLevelGiven(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const LevelResult& level,
                                    bool touching, bool pointOnB, const Vec2* gradientA)
{
	ContactResult c;
	TakeOverLevel(c, level);
	const Vec2 X = level.point;
	// The ellipse-pair solver's normal is ∇λA or −∇λB at its point, whichever its rounding
	// disturbs less (at the root they are opposed: the point minimises (1 − s)λA + sλB), from
	// residuals computed in each body frame: re-deriving it from the double point's gradient
	// would lose up to 1e-7 rad on 1000:1 needles.
	// Whether X is a corner of either shape, found once each for the normal and for each point's
	// search.
	const bool cornerA = AtCorner(a, ToBody(pa, X)), cornerB = AtCorner(b, ToBody(pb, X));
	c.normal = level.method == SolveMethod::ellipsePair ? level.normal
	                                                    : ContactNormal(a, pa, b, pb, X, pointOnB, gradientA, cornerA, cornerB,
	                                                                    level.method == SolveMethod::newton ? &level.normal : nullptr);
	const Vec2 n = c.normal;

	// The points: for a convex shape, where the line through X along n leaves A last (A's
	// extreme along +n on it) and enters B first (B's extreme along −n): from X itself when the
	// shape contains X, else entering the line from beyond the shape. For a non-convex shape the
	// line may cross it more than once (a heart's lobes around a particle in its notch): there
	// the crossing nearest X counts, leaving the shape along the direction when X is inside it,
	// entering it behind X when X is outside.
	auto extreme = [&](const Shape& s, const Pose& ps, Vec2 dir, const Vec2* bodyGradient, const double* known,
	                   bool atCorner) -> Vec2 {
		// A point on the surface to 1e-10 of the level (the grid's points are) is its own
		// crossing; at a corner, where the level grows like |x|^{2/3} (a heart's tip), rounding
		// of the point's coordinates moves the level by up to 1e-6.
		const double own = s.SurfaceLevel();
		const Vec2 x = ToBody(ps, X);
		const double level = known ? *known : s.Level(x);
		const double onSurface = atCorner ? 1e-6 : 1e-10;
		if (std::fabs(level - own) <= onSurface * std::max(std::fabs(own), 1.0))
			return X;
		const bool inside = level <= own;
		double far = 0.0;
		const Vec2 bodyDir = InvRotate(ps.q, dir);
		if (s.IsConvex() && s.FarCrossing(x, bodyDir, far))
			return X + far * dir; // the common case: no search, no reach
		if (!inside && s.IsConvex() && s.LineMisses(x, bodyDir))
			return RadialPoint(s, ps, X); // what the searches below end with, without them
		const double reach = Distance(X, ps.p) + 1.01 * s.BoundingRadius();
		if (s.IsConvex() && ConvexLineExtreme(s, ps, X, dir, level - own, reach, far))
			return X + far * dir;
		if (inside || !s.IsConvex())
		{
			const Vec2 way = inside ? dir : -dir;
			// (The level at X is known, and with the gradient there (the caller's, where it has
			// it) a non-convex shape's march heads for the estimated crossing instead of doubling
			// its way there; a convex shape's crossing takes no slope.)
			double slope = std::numeric_limits<double>::quiet_NaN();
			if (!s.IsConvex())
				slope = Dot(bodyGradient ? *bodyGradient : s.Gradient(x), InvRotate(ps.q, way));
			const double t = FirstSurfaceCrossingFrom(s, ps, X, way, reach, level - own, slope);
			if (t >= 0.0)
				return X + t * way;
		}
		else
		{
			const double beyond = Dot(ps.p - X, dir) + 1.01 * s.BoundingRadius();
			const Vec2 start = X + std::max(beyond, 0.0) * dir;
			const double t = FirstSurfaceCrossing(s, ps, start, -dir, 2.02 * s.BoundingRadius() + Distance(start, ps.p));
			if (t >= 0.0)
				return start - t * dir;
		}
		return RadialPoint(s, ps, X); // the line misses a far-away particle
	};
	// (With the point on B's surface, the level solved for is A's own there: not evaluated again.)
	c.pointA = extreme(a, pa, n, gradientA, pointOnB ? &level.level : nullptr, cornerA);
	c.pointB = extreme(b, pb, -n, nullptr, nullptr, cornerB);
	SetSeparation(c, touching);
	return c;
}


ContactResult ContactFromLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const LevelResult& level,
                               bool touching, bool pointOnB)
{
	return ContactFromLevelGiven(a, pa, b, pb, level, touching, pointOnB, nullptr);
}

ContactResult FlipContact(const ContactResult& c)
{
	ContactResult f = c;
	f.normal = -c.normal;
	f.pointA = c.pointB;
	f.pointB = c.pointA;
	return f;
}

} // namespace b2a

// b2analytic: contact points, separation, and the shape-pair dispatch table.
#include "b2analytic/Contact.h"
#include "b2analytic/SuperellipseShape.h"
#include "b2analytic/SurfaceQueries.h"

#include "contact/GridScale.h"
#include "contact/PairFrame.h"
#include "contact/ResultChecks.h"
#include "contact/SolverCore.h"
#include "contact/SurfaceCrossing.h"
#include "contact/WarmSlide.h"
#include "geometry/SuperellipseTerms.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
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

// Coincident centres: no level point lies between them. Use the axis along which the overlap
// is smallest (the separating-axis depth), refined from 64 directions.
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

ContactResult Failed(const LevelResult& level)
{
	ContactResult c;
	c.status = SolveStatus::failed;
	c.method = level.method;
	c.failure = level.failure;
	c.iterations = level.iterations;
	return c;
}

// The corner (index into CornerDirections and CornerPoints) whose ray the body point lies on,
// within 1e-7 rad, or −1 (the heart's tip and notch, the vertices of exponent-1
// superellipses): at a corner the gradient has no meaningful direction.
int CornerAt(const Shape& s, Vec2 x)
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

// The contact normal at X, from A to B: the mean of A's outward and B's inward unit normals,
// which agree at a tangency. A shape whose corner X is gives no normal; the other's is used.
// When the two normals point the same way, one particle's centre lies inside the other and X is
// B's surface point nearest A (pointOnB, the grid method): A leaves B fastest through that
// point, so the normal is B's inward one there.
// (`cornerA`, `cornerB`: whether X is a corner of A, of B; the caller has them.)
Vec2 ContactNormal(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, Vec2 X, bool pointOnB,
                   const Vec2* gradientA, bool cornerA, bool cornerB)
{
	const Vec2 xa = ToBody(pa, X), xb = ToBody(pb, X);
	const Vec2 na = cornerA ? Vec2() : Normalize(Rotate(pa.q, gradientA ? *gradientA : a.Gradient(xa)));
	const Vec2 nb = cornerB ? Vec2() : Normalize(Rotate(pb.q, b.Gradient(xb)));
	const bool hasA = LengthSquared(na) > 0.0, hasB = LengthSquared(nb) > 0.0;
	Vec2 n;
	if (hasA && hasB)
		n = Dot(na, nb) < 0.0 ? Normalize(na - nb) : (pointOnB ? -nb : na);
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

// What a contact takes over from its level solve unchanged, written into it.
void TakeOverLevel(ContactResult& c, const LevelResult& level)
{
	c.status = level.status;
	c.method = level.method;
	c.iterations = level.iterations;
	c.level = level.level;
	c.point = level.point;
}

// ContactFromLevel, given A's body gradient at the level point where the caller has it
// (`gradientA`, or null): the grid's contact needs it again for its one-side test.
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
	// Whether X is a corner of either shape, for the normal and for each point's search (found
	// once each: four times, as it was, was 1 % of a heart contact's instructions).
	const bool cornerA = AtCorner(a, ToBody(pa, X)), cornerB = AtCorner(b, ToBody(pb, X));
	c.normal = level.method == SolveMethod::ellipsePair ? level.normal
	                                                    : ContactNormal(a, pa, b, pb, X, pointOnB, gradientA, cornerA, cornerB);
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

} // namespace

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

ContactResult CircleContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions&, WarmStart*)
{
	// Closed form: the level solution (the centre line, the point dividing it in the ratio of
	// the radii), the radii's ends as points, and the separation d − rA − rB.
	if (CentresCoincide(a, pa, b, pb))
		return OverlapAxisContact(a, pa, b, pb);
	const LevelResult level = CircleLevel(a, pa, b, pb);
	const double ra = a.BoundingRadius(), rb = b.BoundingRadius();
	ContactResult c;
	c.status = level.status;
	c.method = level.method;
	c.normal = level.normal;
	c.point = level.point;
	c.level = level.level;
	c.pointA = pa.p + ra * c.normal;
	c.pointB = pb.p - rb * c.normal;
	c.separation = Distance(pa.p, pb.p) - ra - rb;
	c.touching = c.separation <= 0.0;
	return c;
}

namespace
{
// A superellipse's point on the line through X along `dir` (ContactFromLevel's rule for convex
// shapes, with direct calls on the final class): X itself when it lies on the surface, else the
// far crossing, in closed form for an ellipse and by Newton otherwise, whose first step starts
// from `known` = {λ(X), ∇λ(X)·dir} where the caller has them. False where the line misses.
bool SuperellipseLinePoint(const SuperellipseShape& s, const Pose& p, Vec2 X, Vec2 dir, const double* known, Vec2& point)
{
	const Vec2 x = ToBody(p, X);
	if (std::fabs((known ? known[0] : s.Level(x)) - 1.0) <= 1e-10)
	{
		point = X;
		return true;
	}
	double t = 0.0;
	const Vec2 d = InvRotate(p.q, dir);
	const bool ellipse = s.N() == 2.0 && s.M() == 2.0;
	if (!(ellipse ? s.FarCrossing(x, d, t) : SuperellipseFarCrossing(s.Terms(), x, d, t, known)))
		return false;
	point = X + t * dir;
	return true;
}
} // namespace

ContactResult EllipseContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                             WarmStart* warm)
{
	// What SolveCommonLevel and ContactFromLevel do for two plain ellipses, without the choice of
	// solver, the virtual calls and the general line search: ~20 % of a warm ellipse contact.
	// Anything else (other shapes under these families, coincident centres, a failed solve,
	// a line missing a particle) takes the generic path, which decides as before.
	// Every path returns c, which is then built in the caller's result (the rare ones copy into
	// it): with other objects returned beside it, c was copied out on every contact.
	ContactResult c;
	const SuperellipseShape* ea = AsPlainEllipse(a);
	const SuperellipseShape* eb = ea ? AsPlainEllipse(b) : nullptr;
	// (A pose that is not finite fails CentresCoincide or the solve, and ConvexContact says so.)
	if (!eb || CentresCoincide(a, pa, b, pb))
	{
		c = ConvexContact(a, pa, b, pb, options, warm);
		return c;
	}
	EllipsePairPoints points;
	LevelResult level = SolveEllipsePairLevel(*ea, pa, *eb, pb, warm, &points);
	CheckResult(level);
	if (!level.Ok() || !(level.multiplier > 0.0))
	{
		c = ConvexContact(a, pa, b, pb, options, warm);
		return c;
	}
	RecordWarmStart(warm, pa, pb, level);
	TakeOverLevel(c, level);
	c.normal = level.normal;
	if (points.valid)
	{
		c.pointA = points.a;
		c.pointB = points.b;
	}
	else if (!EllipseLinePoint(*ea, pa, level.point, c.normal, c.pointA) ||
	         !EllipseLinePoint(*eb, pb, level.point, -c.normal, c.pointB))
	{
		c = ContactFromLevel(a, pa, b, pb, level, level.level <= 1.0);
		return c;
	}
	SetSeparation(c, level.level <= 1.0);
	return c;
}

ContactResult SuperellipseContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                                  WarmStart* warm)
{
	// What SolveCommonLevel and ContactFromLevel do for two smooth superellipses, with the levels
	// evaluated inline and the normal from the solve's last gradients; anything else, and what
	// the fast solve does not finish, takes the generic path (which decides as before).
	// (Every path returns c, as in EllipseContact.)
	ContactResult c;
	const SuperellipseShape* sa = AsSmoothSuperellipse(a);
	const SuperellipseShape* sb = sa ? AsSmoothSuperellipse(b) : nullptr;
	if (!sb || CentresCoincide(a, pa, b, pb))
	{
		c = ConvexContact(a, pa, b, pb, options, warm);
		return c;
	}
	// Integer exponents: the last Newton steps and the points on the raw levels
	// (FinishSuperellipseContact), from a warm start or from where the cold solve's steps are
	// small; where it declines, the full solve from the start.
	SuperellipseHandOver handOver;
	SuperellipseHandOver* hand = nullptr;
	if (FinishApplies(*sa, *sb))
	{
		if (warm && warm->valid && warm->hasPointB && warm->multiplier > 0.0)
		{
			const double size = 0.5 * (a.BoundingRadius() + b.BoundingRadius());
			if (FinishSuperellipseContact(*sa, pa, *sb, pb, options, WarmStartPoint(*warm, pa, pb, size), warm->multiplier, 0,
			                              warm, c))
				return c;
		}
		else
		{
			hand = &handOver;
			// For n = m on both shapes (each gauge a norm, f = ψ^n along a ray) the raw levels'
			// Newton takes over from gauge steps of 10 % of the size as surely as from 5 %, one
			// gauge evaluation earlier in a quarter of the pairs: cold n = 4 contacts 4 % cheaper,
			// n = 8 2 %. With n ≠ m it declines 6 % of them from 10 % (n = 4, m = 8: 2 % dearer).
			const SuperellipseTerms &ta = sa->Terms(), &tb = sb->Terms();
			if (ta.nInt == ta.mInt && tb.nInt == tb.mInt)
				handOver.below = 0.1;
		}
	}
	SuperellipsePairPoint at;
	LevelResult level = SolveSuperellipsePairLevel(*sa, pa, *sb, pb, options, warm, &at, hand);
	CheckResult(level);
	if (handOver.taken)
	{
		if (FinishSuperellipseContact(*sa, pa, *sb, pb, options, handOver.point, handOver.multiplier, handOver.iterations, warm, c))
			return c;
		level = SolveSuperellipsePairLevel(*sa, pa, *sb, pb, options, warm, &at);
		CheckResult(level);
	}
	if (!level.Ok() || !at.valid)
	{
		c = ConvexContact(a, pa, b, pb, options, warm);
		return c;
	}
	RecordWarmStart(warm, pa, pb, level, &at.slide);
	TakeOverLevel(c, level);
	// ContactNormal's mean of the unit normals (they are opposed: the solve checked).
	c.normal = Normalize(Normalize(at.gradA) - Normalize(at.gradB));
	// ContactFromLevel's points, the first step of each line crossing from the level and
	// gradient the solve ended with.
	const double knownA[2] = {at.levelA, Dot(at.gradA, c.normal)}, knownB[2] = {at.levelB, -Dot(at.gradB, c.normal)};
	if (!SuperellipseLinePoint(*sa, pa, level.point, c.normal, knownA, c.pointA) ||
	    !SuperellipseLinePoint(*sb, pb, level.point, -c.normal, knownB, c.pointB))
	{
		c = ContactFromLevel(a, pa, b, pb, level, level.level <= 1.0);
		return c;
	}
	SetSeparation(c, level.level <= 1.0);
	return c;
}

ContactResult ConvexContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                            WarmStart* warm)
{
	if (!a.IsSmoothConvex() || !b.IsSmoothConvex())
		return GridContact(a, pa, b, pb, options, warm);
	if (CentresCoincide(a, pa, b, pb))
		return OverlapAxisContact(a, pa, b, pb);
	const LevelResult level = SolveCommonLevel(a, pa, b, pb, MethodChoice::automatic, options, warm);
	if (!level.Ok())
	{
		// No level meets the solvers' standard (needles crossing deep inside each other, levels
		// of 1e-12 and below): where the particles overlap, the axis of least overlap still
		// separates them, as for coincident centres.
		const ContactResult axis = OverlapAxisContact(a, pa, b, pb);
		return axis.touching ? axis : Failed(level);
	}
	return ContactFromLevel(a, pa, b, pb, level, level.level <= 1.0);
}

namespace
{
// Whether one side's grid contact (P rescaled onto the other's surface at X) stands alone: P not
// deep in the other (its level at least a quarter of its own: deeper, P may cross a thin wall's
// mid-plane, and then its side of the wall is the wrong one), and the separation along the
// normal of the size of the gap from X to P's surface (where the line through X along the
// normal crosses P far from X, a non-convex P's other lobe, it is not, and the other side says
// better). Where it does not, both sides run, as for nested centres.
bool OneSideHolds(const Shape& p, const Pose& pp, const LevelResult& level, const ContactResult& c, Vec2 gradient)
{
	const double own = p.SurfaceLevel();
	if (!(level.level >= 0.25 * own))
		return false;
	// The gap from X to P's surface: first order along the gradient, and at a corner of P (a
	// heart's tip, where the level grows like |x|^{2/3} across the ray and the gradient says
	// nothing) along the corner's ray, |x| − |corner|.
	const Vec2 x = ToBody(pp, level.point);
	const int corner = CornerAt(p, x);
	const double gap = corner >= 0 ? Length(x) - Length(p.CornerPoints()[size_t(corner)])
	                               : (level.level - own) / Length(gradient);
	const double size = p.BoundingRadius();
	if (!std::isfinite(gap))
		return false;
	// A separation that ContactFromLevel set to agree with the verdict (0 or the least double)
	// was measured with the other sign: right only where the gap is at rounding level too.
	if (c.separation == 0.0 || c.separation == std::numeric_limits<double>::denorm_min())
		return std::fabs(gap) <= 1e-9 * size;
	// The level is not linear in the distance (a superellipse's |x|⁴ makes the gap along the
	// normal 1.4 to 2.4 times the first-order one at 2 % to 50 % of the size): a factor of four
	// either way; a line that crossed P far from X (a heart dropped into another's notch: 2000
	// times) is caught.
	const double ratio = c.separation / gap;
	return (ratio >= 0.25 && ratio <= 4.0) || std::fabs(c.separation - gap) <= 1e-9 * size;
}

// A fixed order of poses that does not depend on which particle is called A: the grid's ties.
std::tuple<double, double, double, double> PoseOrder(const Pose& p) { return std::make_tuple(p.p.x, p.p.y, p.q.c, p.q.s); }
} // namespace

GridSide ChooseGridSide(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb)
{
	// Levels in units of each shape's own (1 for the superellipse family); a centre whose level
	// is NaN (a broken shape function) makes neither side decisive, and both ways report it.
	const double unitA = a.SurfaceLevel() > 0.0 ? a.SurfaceLevel() : 1.0;
	const double unitB = b.SurfaceLevel() > 0.0 ? b.SurfaceLevel() : 1.0;
	const double centreAInB = b.Level(ToBody(pb, pa.p)) / unitB, centreBInA = a.Level(ToBody(pa, pb.p)) / unitA;
	const bool canA = centreAInB > 1.0 && a.CentreLevel() < a.SurfaceLevel();
	const bool canB = centreBInA > 1.0 && b.CentreLevel() < b.SurfaceLevel();
	// The side that samples the smaller particle, where one is more than twice the other: the
	// samples (256 of them) must be dense against the rescaled particle, or the refinement can
	// miss a dip in its level narrower than their spacing (a heart 1e-4 the size of the other,
	// rescaled onto it, was found 680 times too high and not touching).
	const double ra = a.BoundingRadius(), rb = b.BoundingRadius();
	bool preferA;
	if (ra > 2.0 * rb || rb > 2.0 * ra)
		preferA = ra > rb;
	else if (a.IsConvex() != b.IsConvex())
		preferA = a.IsConvex();
	else if (centreAInB != centreBInA)
		preferA = centreAInB < centreBInA;
	else
		preferA = PoseOrder(pa) <= PoseOrder(pb);
	if (preferA ? canA : canB)
		return preferA ? GridSide::aOntoB : GridSide::bOntoA;
	if (preferA ? canB : canA)
		return preferA ? GridSide::bOntoA : GridSide::aOntoB;
	return GridSide::bothWays;
}

ContactResult GridContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                          WarmStart*)
{
	if (CentresCoincide(a, pa, b, pb))
		return OverlapAxisContact(a, pa, b, pb);
	// The grid method is one-sided (A rescaled onto B's surface). Where the rescaled particle's
	// centre lies outside the other, one side decides (ChooseGridSide) at about half the cost of
	// both (0.56 for two hearts; 0.45 for a heart and a superellipse, the superellipse rescaled).
	// Each side's solve and contact (seen from A), made at most once.
	// (The rescaled particle's body gradient at its point is taken once, by the solve, for its
	// normal, the contact's and the one-side test: computing it twice more was 1.7 % of a heart
	// contact, and taking it again after the solve one more evaluation of its derivatives.)
	LevelResult ab, ba;
	ContactResult cab, cba;
	Vec2 gab, gba;
	auto solveAB = [&] {
		ab = SolveGridScale(a, pa, b, pb, options, std::numeric_limits<double>::quiet_NaN(), &gab);
		if (ab.Ok())
		{
			cab = ContactFromLevelGiven(a, pa, b, pb, ab, ab.level <= a.SurfaceLevel(), true, &gab);
		}
		return ab.Ok();
	};
	auto solveBA = [&] {
		ba = SolveGridScale(b, pb, a, pa, options, std::numeric_limits<double>::quiet_NaN(), &gba);
		if (ba.Ok())
		{
			cba = FlipContact(ContactFromLevelGiven(b, pb, a, pa, ba, ba.level <= b.SurfaceLevel(), true, &gba));
		}
		return ba.Ok();
	};
	const GridSide side = ChooseGridSide(a, pa, b, pb);
	if (side == GridSide::aOntoB)
	{
		if (!solveAB())
			return Failed(ab);
		if (OneSideHolds(a, pa, ab, cab, gab))
			return cab;
	}
	else if (side == GridSide::bOntoA)
	{
		if (!solveBA())
			return Failed(ba);
		if (OneSideHolds(b, pb, ba, cba, gba)) // (its separation is the same either way round)
			return cba;
	}
	// Each centre inside the other, or one side's answer not to be trusted alone: run it both
	// ways. The pair overlaps exactly when either way finds a level at or below the own level (a
	// particle inside the other shows up as the inner one's surface inside the outer one).
	// Choosing between the two answers by a rule symmetric in A and B makes swapping A and B
	// flip the normal and swap the points exactly.
	if (!ab.Ok() && !solveAB())
		return Failed(ab);
	if (!ba.Ok() && !solveBA())
		return Failed(ba);
	const bool touchAB = cab.touching, touchBA = cba.touching;
	const int iterations = ab.iterations + ba.iterations;
	cab.iterations = cba.iterations = iterations;
	if (touchAB != touchBA)
		return touchAB ? cab : cba;
	// The deeper (or nearer) of the two. Ties (two equal circles, say) go to the answer that
	// rescales the particle whose pose comes first in a fixed order, an order that does not
	// depend on which of the two is called A.
	// A separation that SetSeparation set to agree with the verdict was measured with the other
	// sign: that side's point and normal do not fit (a small heart beside a plank, rescaled onto
	// the plank's sparse samples, found the wrong lobe), and the other side's measurement decides.
	const bool clampedAB = cab.separation == std::numeric_limits<double>::denorm_min(),
	           clampedBA = cba.separation == std::numeric_limits<double>::denorm_min();
	if (clampedAB != clampedBA) return clampedAB ? cba : cab;
	const double tol = 1e-12 * 0.5 * (a.BoundingRadius() + b.BoundingRadius());
	if (cab.separation < cba.separation - tol) return cab;
	if (cba.separation < cab.separation - tol) return cba;
	return PoseOrder(pa) <= PoseOrder(pb) ? cab : cba;
}

namespace
{
// The shape-pair table: generic solvers over whole families first, specialisations after.
struct DispatchTable
{
	ContactFunction cell[int(ShapeFamily::count)][int(ShapeFamily::count)];
	bool flipped[int(ShapeFamily::count)][int(ShapeFamily::count)];

	DispatchTable()
	{
		const int n = int(ShapeFamily::count);
		// The generic solvers take their pair in either order.
		for (int i = 0; i < n; ++i)
			for (int j = 0; j < n; ++j)
				SetSymmetric(ShapeFamily(i), ShapeFamily(j), &ConvexContact); // Newton or grid by the shapes' flags
		for (int i = 0; i < n; ++i)
			SetSymmetric(ShapeFamily::heart, ShapeFamily(i), &GridContact);   // never convex
		SetSymmetric(ShapeFamily::superellipse, ShapeFamily::superellipse, &SuperellipseContact);
		SetSymmetric(ShapeFamily::superellipse, ShapeFamily::ellipse, &SuperellipseContact);
		SetSymmetric(ShapeFamily::superellipse, ShapeFamily::circle, &SuperellipseContact);
		SetSymmetric(ShapeFamily::ellipse, ShapeFamily::ellipse, &EllipseContact);
		SetSymmetric(ShapeFamily::ellipse, ShapeFamily::circle, &EllipseContact);
		SetSymmetric(ShapeFamily::circle, ShapeFamily::circle, &CircleContact);
	}
	void SetSymmetric(ShapeFamily a, ShapeFamily b, ContactFunction f)
	{
		cell[int(a)][int(b)] = cell[int(b)][int(a)] = f;
		flipped[int(a)][int(b)] = flipped[int(b)][int(a)] = false;
	}
	// A function written for (a, b) in that order; (b, a) calls it flipped.
	void Set(ShapeFamily a, ShapeFamily b, ContactFunction f)
	{
		cell[int(a)][int(b)] = f;
		flipped[int(a)][int(b)] = false;
		if (a != b)
		{
			cell[int(b)][int(a)] = f;
			flipped[int(b)][int(a)] = true;
		}
	}
};

DispatchTable& Table()
{
	static DispatchTable table;
	return table;
}
} // namespace

void RegisterContactFunction(ShapeFamily a, ShapeFamily b, ContactFunction function)
{
	if (int(a) < 0 || int(a) >= int(ShapeFamily::count) || int(b) < 0 || int(b) >= int(ShapeFamily::count))
		throw InvalidParameter("RegisterContactFunction", "family", "must name a shape family", double(int(a)));
	if (!function)
		throw InvalidParameter("RegisterContactFunction: field 'function' is null", "function");
	Table().Set(a, b, function);
}

ContactFunction GetContactFunction(ShapeFamily a, ShapeFamily b)
{
	return Table().cell[int(a)][int(b)];
}

namespace
{
ContactResult Dispatch(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                       const SolverOptions& options, WarmStart* warm)
{
	if (method == MethodChoice::grid)
		return GridContact(a, pa, b, pb, options, warm);
	if (method == MethodChoice::newton)
	{
		if (CentresCoincide(a, pa, b, pb))
			return OverlapAxisContact(a, pa, b, pb);
		const LevelResult level = SolveCommonLevel(a, pa, b, pb, MethodChoice::newton, options, warm);
		if (!level.Ok())
			return Failed(level);
		return ContactFromLevel(a, pa, b, pb, level, level.level <= 1.0);
	}
	const DispatchTable& table = Table();
	const int i = int(a.Family()), j = int(b.Family());
	if (table.flipped[i][j])
	{
		// The cell was registered for (B, A): solve that way round and flip. A warm start is
		// stored in the first shape's frame, so it is not shared across the flip.
		return FlipContact(table.cell[i][j](b, pb, a, pa, options, nullptr));
	}
	return table.cell[i][j](a, pa, b, pb, options, warm);
}

// Dispatch's answer checked where it lies, the caller's result (one named return).
ContactResult CheckedDispatch(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                              const SolverOptions& options, WarmStart* warm)
{
	ContactResult c = Dispatch(a, pa, b, pb, method, options, warm);
	CheckResult(c);
	return c;
}
} // namespace

ContactResult ComputeContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, MethodChoice method,
                             const SolverOptions& options, WarmStart* warm)
{
	if (!PoseFinite(pa) || !PoseFinite(pb))
		return NonFinitePoseFailure<ContactResult>();
	return CheckedDispatch(a, pa, b, pb, method, options, warm);
}

} // namespace b2a

// b2analytic: closed forms and fast paths for pairs of the superellipse family.
#include "contact/ContactParts.h"

#include "b2analytic/SuperellipseShape.h"

#include "contact/PairFrame.h"
#include "contact/ResultChecks.h"
#include "contact/SolverCore.h"
#include "contact/WarmSlide.h"
#include "geometry/SuperellipseTerms.h"
#include "numerics/CodeLayout.h"

#include <cmath>

namespace b2a
{

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

ContactResult EllipsePairContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, WarmStart* warm)
{
	// What SolveCommonLevel and ContactFromLevel do for two plain ellipses, without the choice of
	// solver, the virtual calls and the general line search. The rare cases it does not handle
	// (coincident centres, a failed solve, no positive multiplier) go on along the chain, and a
	// line missing a particle takes ContactFromLevel's search.
	// (Every path returns c, so that it is built in the caller's result: returning other
	// objects beside it would copy it out on every contact.)
	ContactResult c;
	const SuperellipseShape* ea = AsPlainEllipse(a);
	const SuperellipseShape* eb = ea ? AsPlainEllipse(b) : nullptr;
	if (!eb || CentresCoincide(a, pa, b, pb))
		return c;
	EllipsePairPoints points;
	LevelResult level = SolveEllipsePairLevel(*ea, pa, *eb, pb, warm, &points);
	CheckResult(level);
	if (!level.Ok() || !(level.multiplier > 0.0))
		return c;
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

namespace
{
// SuperellipsePairContact's full solve (a cold start handed over to the finish where it can be,
// or a warm finish that declined): out of line, so that the warm finish's path through
// SuperellipsePairContact, taken by most contacts at most steps, stays in a few instruction
// cache lines. The contact is built in c (the caller's result).
B2A_NOINLINE void SolvedSuperellipsePairContact(const SuperellipseShape& sa, const Pose& pa, const SuperellipseShape& sb,
                                                const Pose& pb, const SolverOptions& options, WarmStart* warm,
                                                SuperellipseHandOver* hand, ContactResult& c)
{
	const Shape &a = sa, &b = sb;
	SuperellipsePairPoint at;
	LevelResult level = SolveSuperellipsePairLevel(sa, pa, sb, pb, options, warm, &at, hand);
	CheckResult(level);
	if (hand && hand->taken)
	{
		if (FinishSuperellipseContact(sa, pa, sb, pb, options, hand->point, hand->multiplier, hand->iterations, warm, c))
			return;
		level = SolveSuperellipsePairLevel(sa, pa, sb, pb, options, warm, &at);
		CheckResult(level);
	}
	if (!level.Ok() || !at.valid)
		return;
	RecordWarmStart(warm, pa, pb, level, &at.slide);
	TakeOverLevel(c, level);
	// ContactNormal's mean of the unit normals (they are opposed: the solve checked).
	c.normal = Normalize(Normalize(at.gradA) - Normalize(at.gradB));
	// ContactFromLevel's points, the first step of each line crossing from the level and
	// gradient the solve ended with.
	const double knownA[2] = {at.levelA, Dot(at.gradA, c.normal)}, knownB[2] = {at.levelB, -Dot(at.gradB, c.normal)};
	if (!SuperellipseLinePoint(sa, pa, level.point, c.normal, knownA, c.pointA) ||
	    !SuperellipseLinePoint(sb, pb, level.point, -c.normal, knownB, c.pointB))
	{
		c = ContactFromLevel(a, pa, b, pb, level, level.level <= 1.0);
		return;
	}
	SetSeparation(c, level.level <= 1.0);
}
} // namespace

ContactResult SuperellipsePairContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb,
                                      const SolverOptions& options, WarmStart* warm)
{
	// What SolveCommonLevel and ContactFromLevel do for two smooth superellipses, with the levels
	// evaluated inline and the normal from the solve's last gradients. Other shapes, coincident
	// centres, and what the fast solve does not finish go on along the chain. (Every path
	// returns c, as in EllipsePairContact.)
	ContactResult c;
	const SuperellipseShape* sa = AsSmoothSuperellipse(a);
	const SuperellipseShape* sb = sa ? AsSmoothSuperellipse(b) : nullptr;
	if (!sb || CentresCoincide(a, pa, b, pb))
		return c;
	// Exponents ≥ 2: the last Newton steps and the points on the raw levels
	// (FinishSuperellipseContact), from a warm start, or for integer exponents also from where
	// the cold solve's steps are small; where it declines, the full solve from the start. (A
	// cold pair of real exponents keeps the full solve: handed over, its rare ill-conditioned
	// poses came out a little further from the reference, 4.38e-11 of the size against 4.32e-11
	// in b2a_bench_pairs, for a gain on contacts that are not the scenes' bulk.)
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
		else if (IntegerExponents(sa->Terms()) && IntegerExponents(sb->Terms()))
		{
			hand = &handOver;
			// For n = m on both shapes (each gauge a norm, f = ψ^n along a ray) the raw levels'
			// Newton takes over from gauge steps of a tenth of the size as surely as from a
			// twentieth, a gauge evaluation earlier; with n ≠ m it would decline more pairs from
			// a tenth, which then cost a full solve, so it keeps the twentieth.
			const SuperellipseTerms &ta = sa->Terms(), &tb = sb->Terms();
			if (ta.n == ta.m && tb.n == tb.m)
				handOver.below = 0.1;
		}
	}
	SolvedSuperellipsePairContact(*sa, pa, *sb, pb, options, warm, hand, c);
	return c;
}

} // namespace b2a

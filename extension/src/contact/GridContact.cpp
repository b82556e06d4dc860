// b2analytic: the grid method's contact: which side is rescaled, and when one side decides.
#include "contact/ContactParts.h"

#include "contact/GridScale.h"
#include "contact/PairFrame.h"
#include "numerics/CodeLayout.h"

#include <cmath>
#include <limits>
#include <tuple>

namespace b2a
{

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

// One side's grid solve (P rescaled onto Q's surface) and its contact, seen from P, flipped to be
// seen from Q where `flip`; false where the solve failed. (One out-of-line function for both
// sides: inlined at each call, the solve would be in GridContact's code twice, and the heart
// contact's code already exceeds the instruction cache.)
B2A_NOINLINE bool SolveSide(const Shape& p, const Pose& pp, const Shape& q, const Pose& pq, const SolverOptions& options,
                            bool flip, LevelResult& level, ContactResult& contact, Vec2& gradient)
{
	level = SolveGridScale(p, pp, q, pq, options, std::numeric_limits<double>::quiet_NaN(), &gradient);
	if (!level.Ok())
		return false;
	contact = ContactFromLevelGiven(p, pp, q, pq, level, level.level <= p.SurfaceLevel(), true, &gradient);
	if (flip)
		contact = FlipContact(contact);
	return true;
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
	// both. Each side's solve and contact (seen from A), made at most once.
	// (The rescaled particle's body gradient at its point is taken once, by the solve, for its
	// normal, the contact's and the one-side test.)
	LevelResult ab, ba;
	ContactResult cab, cba;
	Vec2 gab, gba;
	auto solveAB = [&] { return SolveSide(a, pa, b, pb, options, false, ab, cab, gab); };
	auto solveBA = [&] { return SolveSide(b, pb, a, pa, options, true, ba, cba, gba); };
	const GridSide side = ChooseGridSide(a, pa, b, pb);
	if (side == GridSide::aOntoB)
	{
		if (!solveAB())
			return FailedContact(ab);
		if (OneSideHolds(a, pa, ab, cab, gab))
			return cab;
	}
	else if (side == GridSide::bOntoA)
	{
		if (!solveBA())
			return FailedContact(ba);
		if (OneSideHolds(b, pb, ba, cba, gba)) // (its separation is the same either way round)
			return cba;
	}
	// Each centre inside the other, or one side's answer not to be trusted alone: run it both
	// ways. The pair overlaps exactly when either way finds a level at or below the own level (a
	// particle inside the other shows up as the inner one's surface inside the outer one).
	// Choosing between the two answers by a rule symmetric in A and B makes swapping A and B
	// flip the normal and swap the points exactly.
	if (!ab.Ok() && !solveAB())
		return FailedContact(ab);
	if (!ba.Ok() && !solveBA())
		return FailedContact(ba);
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

} // namespace b2a

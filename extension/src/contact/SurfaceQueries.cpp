// b2analytic: point tests, line crossings and ray casts against the true shape.
#include "b2analytic/SurfaceQueries.h"

#include "contact/LevelAlongLine.h"
#include "contact/SurfaceCrossing.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

bool TestPoint(const Shape& shape, const Pose& pose, Vec2 point)
{
	return shape.Level(ToBody(pose, point)) <= shape.SurfaceLevel();
}

Vec2 WorldSupport(const Shape& shape, const Pose& pose, Vec2 d)
{
	return ToWorld(pose, shape.Support(InvRotate(pose.q, d)));
}

namespace
{
// The first crossing of f(s) = λ(x + s·u) − own from f(0) = f0 with slope p = f'(0) heading
// for the surface (f0·p < 0), without a march, where the shape bounds its curvature over the
// stretch ahead and the level is convex there. Over a stretch [0, end] inside the disc that
// has it as a diameter, f'' lies in [lo, hi]·|u|², so f lies between the parabolas
// f0 + p s + (c/2) s², c = lo|u|² and hi|u|²:
// - from inside (f0 < 0 < p), f < 0 before the first root of hi's parabola, and f ≥ 0 at the
//   first root of lo's (which lies before the tangent's root −f0/p, for lo > 0: the stretch up
//   to the tangent's root is the one to bound);
// - from outside (p < 0 < f0), f > 0 before the first root of lo's parabola, and f ≤ 0 at the
//   first root of hi's (beyond the tangent's root: the stretch bounded is twice as long, and
//   where hi's root lies beyond it, or either parabola has none, this gives up).
// With lo > 0, f is convex, and convex f crosses zero once between a point where it has the
// starting side's sign and one where it has the other's: the first crossing lies between the
// two roots, alone, and any root found in that bracket is it. Halley's steps from the
// bracket's end where f ≥ 0 (beyond the crossing from inside, before it from outside) find
// it. Where any of this fails (no bounds, lo ≤ 0, f not monotone along the way at an iterate,
// an iterate leaving the bracket, no convergence in 30 steps) it returns false and the march
// decides. (The march evaluates disc bounds and levels before it has a bracket; this has one
// from the start, and decides most of the crossings a heart's grid contact asks for. Most of
// the others run near the heart's axis, where its level has its |x|^{2/3} kink and no
// curvature bound.)
bool CrossingByCurvature(const Shape& shape, Vec2 x, Vec2 u, double f0, double p, double sMax, double xtol, double& root)
{
	const double own = shape.SurfaceLevel();
	const bool inside = f0 < 0.0;
	const double tangent = -f0 / p;
	const double end = inside ? tangent : 2.0 * tangent;
	// (|u| of its own, not the caller's |dir|: a pose made from Box2D's float rotation turns
	// lengths by up to 1e-7, and the curvature bounds below hold to 1e-12.)
	const double len2 = LengthSquared(u), len = std::sqrt(len2);
	if (!(end > 0.0 && end <= sMax))
		return false;
	double lo, hi;
	const LevelBounds* bounds = shape.Bounds();
	if (!bounds || !bounds->CurvatureBounds(x + (0.5 * end) * u, 0.5 * end * len, lo, hi) || !(lo > 0.0))
		return false;
	// The root of f0 + p s + (c/2) s² nearest 0, in the form without cancellation; none (NaN)
	// where the discriminant is negative.
	auto first = [&](double c) {
		const double d = p * p - 2.0 * c * f0;
		return d >= 0.0 ? -2.0 * f0 / (p + std::copysign(std::sqrt(d), p)) : std::numeric_limits<double>::quiet_NaN();
	};
	const double early = first(inside ? hi * len2 : lo * len2), late = first(inside ? lo * len2 : hi * len2);
	if (!(early >= 0.0 && late >= early && late <= end))
		return false;
	// Halley's steps (the Hessian comes with the level's derivatives), from the bracket's end
	// where f ≥ 0, kept in the bracket, where the crossing is the only one; stopping where the
	// level is at rounding, or where the step is or the next one would be (below).
	const double levelTol = 4.0 * std::numeric_limits<double>::epsilon() * std::fabs(own);
	const double way = inside ? -1.0 : 1.0; // toward the crossing from the start
	const double curvature = hi * len2, width = (late - early) + 2.0 * xtol;
	double s = inside ? late : early;
	for (int it = 0; it < 30; ++it)
	{
		const LevelDerivatives d = shape.Derivatives(x + s * u);
		const double f = d.value - own, slope = Dot(d.gradient, u);
		if (std::fabs(f) <= levelTol)
		{
			root = s;
			return true;
		}
		if (!(slope * way < 0.0)) // (f increasing from inside, decreasing from outside)
			return false;
		// Newton's step δ = −f/f', and Halley's δ/(1 − x), x = f f''/(2f'²) (|x| ≤ 1/2).
		const double newton = -f / slope;
		const double bend = u.x * (d.hessian.xx * u.x + d.hessian.xy * u.y) + u.y * (d.hessian.xy * u.x + d.hessian.yy * u.y);
		const double x2 = f * bend / (2.0 * slope * slope);
		const double step = std::fabs(x2) <= 0.5 ? newton / (1.0 - x2) : newton;
		s += step;
		if (!(s >= early - xtol && s <= late + xtol))
			return false;
		// The next step would be below the tolerance: with a = hi|u|²/(2|f'(s)|) ≥ |f''|/(2|f'|)
		// on the bracket and W its width, Taylor about s puts Newton's iterate within a e² of
		// the crossing, e the error before, and e ≤ |δ| + aWe, so e ≤ 2|δ| for aW ≤ 1/2 and
		// Newton's error is at most 4aδ²; Halley's iterate lies |δ||x|/(1 − x) ≤ 2aδ² from
		// Newton's. So within 6aδ². (So the last, tiny step is never evaluated, as a stop on
		// the step's length alone would evaluate it.)
		const double a = curvature / (2.0 * std::fabs(slope));
		if (std::fabs(step) <= xtol || (a * width <= 0.5 && 6.0 * a * newton * newton <= xtol))
		{
			root = s;
			return true;
		}
	}
	return false;
}
} // namespace

double FirstSurfaceCrossing(const Shape& shape, const Pose& pose, Vec2 X, Vec2 dir, double sMax)
{
	const double f0 = shape.Level(ToBody(pose, X)) - shape.SurfaceLevel();
	return FirstSurfaceCrossingFrom(shape, pose, X, dir, sMax, f0, std::numeric_limits<double>::quiet_NaN());
}

namespace
{
// FirstSurfaceCrossingFrom for a convex shape (f0 finite and not 0, sMax positive and finite).
double ConvexCrossing(const Shape& shape, const Pose& pose, Vec2 X, Vec2 dir, double sMax, double f0)
{
	const double own = shape.SurfaceLevel();
	auto f = [&](double s) { return shape.Level(ToBody(pose, X + s * dir)) - own; };
	// The shape's own far crossing where it has one: leaving along dir from inside, or
	// entering from outside, which is the far crossing of the reversed line.
	const Vec2 xb = ToBody(pose, X), db = InvRotate(pose.q, dir);
	double t = 0.0;
	if (f0 < 0.0 ? shape.FarCrossing(xb, db, t) : shape.FarCrossing(xb, -db, t))
	{
		const double s = f0 < 0.0 ? t : -t;
		return s >= 0.0 && s <= sMax ? s : -1.0;
	}
	const double fmax = f(sMax);
	if (f0 < 0.0)
		return fmax > 0.0 ? FindRootBrent(f, 0.0, sMax, f0, fmax, 0.0, 200).x : -1.0;
	// Outside: the level is quasi-convex along the line, so its minimum tells whether the
	// line enters; the entry is then bracketed by 0 and that minimum.
	const ScalarResult m = MinimizeBrent(f, 0.0, sMax, 1e-12, 1e-15 * sMax, 200);
	if (!(m.fx <= 0.0))
		return -1.0;
	return FindRootBrent(f, 0.0, m.x, f0, m.fx, 0.0, 200).x;
}

// FirstSurfaceCrossingFrom for a non-convex shape (f0 finite and not 0, sMax positive and
// finite).
double NonConvexCrossing(const Shape& shape, const Pose& pose, Vec2 X, Vec2 dir, double sMax, double f0, double slope0)
{
	const double own = shape.SurfaceLevel();
	auto f = [&](double s) { return shape.Level(ToBody(pose, X + s * dir)) - own; };
	// Non-convex: march in steps finer than the surface samples, then bracket. Where the shape
	// bounds its level over a disc, a stretch of the line whose covering disc lies wholly on the
	// starting side (inside: the upper bound below the surface level; outside: the lower bound
	// above it) holds no crossing and is stepped over, in lengths doubled while the bound holds
	// and halved where it fails, down to the plain step, where the level is evaluated: the
	// march evaluates only near the surface. Near the shape's corners it looks down to 1/64 of
	// the step, and finds a crossing pair that thin (a line clipping a heart's tip) where the
	// plain step would step over it.
	// The crossing in a bracket the march found, to the rounding of the point it gives: X + s·dir
	// lies |x| from the shape's centre (x = X in the body frame), so a tolerance of a few
	// roundings of |x| on s·|dir| is all a double point holds. (Relative to s alone, a crossing
	// 1e-11 from X, where X is all but on the surface, would ask for 1e-27: the level's own
	// rounding keeps Newton from settling there, and the bracket is halved some 15 times.)
	const double len = Length(dir);
	const double xtol = 4.0 * std::numeric_limits<double>::epsilon() * Length(ToBody(pose, X)) / len;
	auto root = [&](double from, double to, double ffrom, double fto) {
		return LevelRootAlongLine(shape, pose, X, dir, own, from, to, ffrom, fto, xtol).x;
	};
	double byCurvature = 0.0;
	if (f0 * slope0 < 0.0 && shape.DerivativesCheap() &&
	    CrossingByCurvature(shape, ToBody(pose, X), InvRotate(pose.q, dir), f0, slope0, sMax, xtol, byCurvature))
		return byCurvature;
	const double h = std::min(sMax / 64.0, 0.5 * shape.SamplesRef().maxSpacing / std::max(len, 1e-300));
	const bool inside = f0 < 0.0;
	auto middle = [&](double from, double to) { return ToBody(pose, X + (0.5 * (from + to)) * dir); };
	const LevelBounds* const bounds = shape.Bounds();
	auto clear = [&](double from, double to) {
		const Vec2 c = middle(from, to);
		const double rho = 0.5 * (to - from) * len;
		return inside ? bounds->LevelUpperBound(c, rho) < own : bounds->LevelLowerBound(c, rho) > own;
	};
	const bool bounded =
		bounds && std::isfinite(inside ? bounds->LevelUpperBound(ToBody(pose, X), 0.0) : bounds->LevelLowerBound(ToBody(pose, X), 0.0));
	// A crossing pair thinner than the step forms only at a corner (a heart's tip: the
	// surface there is a cusp); elsewhere the step is fine enough, as for the plain march.
	const std::vector<Vec2>& corners = shape.CornerPoints();
	auto nearCorner = [&](double from, double to) {
		const Vec2 c = middle(from, to);
		const double reach = (0.5 * (to - from) + 2.0 * h) * len;
		for (const Vec2 p : corners)
			if (LengthSquared(p - c) <= reach * reach)
				return true;
		return false;
	};
	const double finest = bounded ? h / 64.0 : h;
	double s0 = 0.0, fa = f0, jumpStart = 0.0;
	double step = bounded ? 4.0 * h : h;
	bool stale = false; // fa is not yet the value at s0 (after a jump)
	// With the slope at X (given by the caller), the march heads for est, where the level,
	// taken as growing like the square of the distance from the centre (the heart's does
	// exactly, along rays), reaches the own level: each stretch cleared covers half the way
	// left to it, and within a plain step of it the plain step (twice the way left, at most h)
	// is taken without a bound, where the crossing is expected. The first bound that fails, or
	// a plain step that finds no crossing, ends the guidance. Doubling its way there instead,
	// the march spends most of its bounds on stretches that reach past the surface (and f0,
	// which the caller has, is not computed again).
	double est = std::numeric_limits<double>::quiet_NaN();
	const double level0 = f0 + own;
	if (bounded && f0 * slope0 < 0.0 && level0 > 0.0 && own > 0.0)
		est = -2.0 * level0 * (1.0 - std::sqrt(own / level0)) / slope0; // −g/g' of g = √λ − √own
	bool guided = std::isfinite(est) && est > 0.0;
	bool halved = false; // the last bound failed and the step was halved
	for (int k = 0; k < 400000 && s0 < sMax; ++k)
	{
		bool expect = false;
		if (guided)
		{
			const double left = est - s0;
			if (left > h)
				step = 0.5 * left;
			else
			{
				step = std::max(std::min(h, 2.0 * left), finest);
				expect = true;
				guided = false;
			}
		}
		const double s1 = std::min(s0 + step, sMax);
		if (bounded && !expect)
		{
			if (clear(s0, s1))
			{
				if (!stale)
					jumpStart = s0;
				s0 = s1;
				stale = true;
				// Doubled again right after a halving, the stretch mostly failed again (a line
				// running along the surface alternated failures and successes).
				if (!halved)
					step *= 2.0;
				halved = false;
				continue;
			}
			guided = false;
			if (step > h)
			{
				step *= 0.5; // look closer
				halved = true;
				continue;
			}
		}
		halved = false;
		if (stale)
		{
			fa = f(s0);
			stale = false;
			if ((fa <= 0.0) != inside) // the bound failed by rounding: the crossing is in the jump
			{
				const double fj = f(jumpStart);
				if ((fj <= 0.0) == inside)
					return root(jumpStart, s0, fj, fa);
			}
		}
		const double fb = f(s1);
		if ((fb <= 0.0) != (fa <= 0.0))
			return root(s0, s1, fa, fb);
		if (bounded && step > finest && nearCorner(s0, s1))
		{
			step *= 0.5; // no crossing at the ends, but near a corner the bound cannot rule out a pair
			continue;
		}
		s0 = s1;
		fa = fb;
		if (bounded)
			step = expect ? std::max(2.0 * step, 4.0 * h) : 2.0 * step; // (a wrong guess: start afresh)
	}
	return -1.0;
}
} // namespace

double FirstSurfaceCrossingFrom(const Shape& shape, const Pose& pose, Vec2 X, Vec2 dir, double sMax, double f0, double slope0)
{
	if (!IsFinite(dir))
		return -1.0; // (as when f0 was the level at X + 0·dir, NaN for such a dir)
	if (f0 == 0.0)
		return 0.0;
	if (!std::isfinite(f0) || !(sMax > 0.0) || !std::isfinite(sMax))
		return -1.0;
	if (shape.IsConvex())
		return ConvexCrossing(shape, pose, X, dir, sMax, f0);
	return NonConvexCrossing(shape, pose, X, dir, sMax, f0, slope0);
}

RayHit RayCast(const Shape& shape, const Pose& pose, Vec2 p1, Vec2 p2, double maxFraction)
{
	RayHit out;
	const Vec2 d = p2 - p1;
	if (!(maxFraction > 0.0) || !(LengthSquared(d) > 0.0) || !IsFinite(p1) || !IsFinite(p2))
		return out;
	if (TestPoint(shape, pose, p1))
		return out; // starts inside: no hit, as Box2D's own shapes answer
	// Only the part of the ray near the bounding circle can hit: skip to it. The circle is
	// widened by 1e-9 so that where it touches the surface (a circle's everywhere) the search
	// starts clear of it, outside by far more than rounding.
	const double R = shape.BoundingRadius();
	const double reach2 = R * R * (1.0 + 1e-9);
	const double len2 = LengthSquared(d);
	const double tc = Dot(pose.p - p1, d) / len2; // fraction of the point closest to the centre
	const double miss2 = LengthSquared(p1 + tc * d - pose.p);
	if (miss2 > reach2)
		return out;
	const double half = std::sqrt(std::max(0.0, reach2 - miss2) / len2);
	double t0 = std::max(0.0, tc - half);
	const double t1 = std::min(maxFraction, tc + half);
	if (!(t1 > t0))
		return out;
	// The search must start outside: from inside it looks for where the ray leaves, and would
	// answer the far side, or miss. The point on the widened circle is outside wherever the pose
	// is a rigid motion; where it is not (a rotation whose cosine and sine are off unit length,
	// as a float b2Rot's are by up to 1e-7), the particle reaches past its bounding circle, and
	// the search starts at p1, which is outside.
	if (t0 > 0.0 && TestPoint(shape, pose, p1 + t0 * d))
		t0 = 0.0;
	const Vec2 start = p1 + t0 * d;
	const double s = FirstSurfaceCrossing(shape, pose, start, d, t1 - t0);
	if (s < 0.0)
		return out;
	out.hit = true;
	out.fraction = t0 + s;
	out.point = p1 + out.fraction * d;
	out.normal = Normalize(Rotate(pose.q, shape.Gradient(ToBody(pose, out.point))));
	return out;
}

} // namespace b2a

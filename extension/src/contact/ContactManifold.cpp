// b2analytic: one- and two-point manifolds from a contact.
#include "b2analytic/ContactManifold.h"

#include "b2analytic/SurfaceQueries.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace b2a
{

namespace
{
struct Interval
{
	double lo = 0.0, hi = 0.0;
	bool valid = false;
};

// Tangent extent (coordinates along t from `origin`) of the arc of an analytic convex shape
// whose points lie within tol of its extreme along d. db is d in the body frame and q the
// support point along it (Face has them already). Each end is found in polar angle to within
// kEndTolerance, and cache / slopes keep each end and the slope of the excess there for the
// next step:
//  - from last step's end, secant steps (the first on last step's slope) converge on the new
//    end: in a settling packing ends move 1e-5 to 1e-3 rad per step, the first guess is off
//    by 1e-10 to 1e-6 and each step multiplies the error by about the one before. One point a
//    tolerance beyond the last proves the end: about five surface points, the end's included;
//  - else (the first step, or the proof failed) the end is bracketed by steps that double from
//    a small one, from last step's end or the support point, and Brent's method finishes:
//    about seven points, and one more for the slope.
Interval AnalyticFace(const Shape& shape, const Pose& pose, Vec2 db, Vec2 q, Vec2 origin, Vec2 t, double tol, double* cache,
                      double* slopes, bool& cached)
{
	constexpr double kEndTolerance = 1e-10; // rad: 1e-10 of the size, far below Box2D's float points
	Interval out;
	const double h = Dot(q, db);
	const double ts = std::atan2(q.y, q.x);
	// excess(θ) = (h − x(θ)·d) − tol: the depth below the extreme, less tol; ≤ 0 on the face.
	// Angles are measured from ts, unwrapped into (−π, π].
	auto excessAt = [&](Vec2 x) { return (h - Dot(x, db)) - tol; };
	auto excess = [&](double relativeAngle) { return excessAt(shape.SurfacePoint(ts + relativeAngle)); };
	auto relative = [&](double theta) { return std::remainder(theta - ts, 2.0 * kPi); };
	const double atSupport = excess(0.0); // the same for both ends
	if (!(atSupport <= 0.0))
		return out;
	double ends[2];
	for (int side = 0; side < 2; ++side)
	{
		const double dir = side == 0 ? -1.0 : 1.0;
		double start = 0.0;
		if (cached && dir * relative(cache[side]) > 0.0)
			start = relative(cache[side]);
		const double fs = start != 0.0 ? excess(start) : atSupport;
		// Secant steps from last step's end, the first on last step's slope (the excess rises
		// outwards: slope·dir > 0), at most five. Once the next step would move less than half
		// a tolerance, the end lies within a tolerance of the last point: outwards if that point
		// is on the face, else inwards. One point a tolerance that way proves it by its sign.
		if (start != 0.0 && slopes[side] * dir > 0.0)
		{
			auto inRange = [&](double x) { return dir * x > 0.0 && std::fabs(x) < kPi; };
			double xPrev = start, fPrev = fs, x = start - fs / slopes[side];
			bool found = false;
			for (int k = 0; k < 5 && inRange(x); ++k)
			{
				const Vec2 px = shape.SurfacePoint(ts + x);
				const double f = excessAt(px);
				const double next = x - f * (x - xPrev) / (f - fPrev);
				if (std::fabs(next - x) < 0.5 * kEndTolerance)
				{
					const double other = x + (f <= 0.0 ? dir : -dir) * kEndTolerance;
					if (!inRange(other))
						break;
					const Vec2 po = shape.SurfacePoint(ts + other);
					const double fo = excessAt(po);
					if ((f <= 0.0) == (fo <= 0.0))
						break;
					// The end lies between x and other; the one kept is on the face, as Brent's is.
					const bool xInside = f <= 0.0;
					cache[side] = ts + (xInside ? x : other);
					slopes[side] = (fo - f) / (other - x);
					ends[side] = Dot(ToWorld(pose, xInside ? px : po) - origin, t);
					found = true;
					break;
				}
				xPrev = x;
				fPrev = f;
				x = next;
			}
			if (found)
				continue;
		}
		double inner = 0.0, fin = atSupport, outer = 0.0, fout = 0.0;
		double step = cached ? 1e-3 : kPi / 64.0;
		if (fs <= 0.0)
		{
			inner = start;
			fin = fs;
			for (outer = start + dir * step, fout = excess(outer); fout <= 0.0; outer += dir * step, fout = excess(outer))
			{
				inner = outer;
				fin = fout;
				step *= 2.0;
				if (std::fabs(outer) > kPi)
					return out; // the whole half turns within tol: not a patch we can bound
			}
		}
		else
		{
			outer = start;
			fout = fs;
			for (inner = start - dir * step; dir * inner > 0.0; inner -= dir * step)
			{
				fin = excess(inner);
				if (fin <= 0.0)
					break;
				outer = inner;
				fout = fin;
				step *= 2.0;
			}
			if (dir * inner <= 0.0)
			{
				inner = 0.0;
				fin = atSupport;
			}
		}
		const ScalarResult root = FindRootBrent(excess, inner, outer, fin, fout, kEndTolerance, 100);
		// The slope for the next step's secant, over 1e-8 rad outwards: its rounding (1e-16 of
		// the excess's terms over 1e-8 of the slope) and its curvature error are both about 1e-8
		// of the slope, which moves the next guess by far less than the tolerance.
		constexpr double kSlopeStep = 1e-8;
		slopes[side] = (excess(root.x + dir * kSlopeStep) - root.fx) / (dir * kSlopeStep);
		cache[side] = ts + root.x;
		ends[side] = Dot(ToWorld(pose, shape.SurfacePoint(cache[side])) - origin, t);
	}
	cached = true;
	out.lo = std::min(ends[0], ends[1]);
	out.hi = std::max(ends[0], ends[1]);
	out.valid = true;
	return out;
}

// Tangent extent of the part of a polygon or segment within tol of its extreme along d.
Interval PolygonFace(const Vec2* w, int count, Vec2 d, Vec2 origin, Vec2 t, double tol)
{
	Interval out;
	double h = -std::numeric_limits<double>::infinity();
	for (int j = 0; j < count; ++j)
		h = std::max(h, Dot(w[j], d));
	out.lo = std::numeric_limits<double>::infinity();
	out.hi = -out.lo;
	auto add = [&](Vec2 p) {
		const double s = Dot(p - origin, t);
		out.lo = std::min(out.lo, s);
		out.hi = std::max(out.hi, s);
	};
	const int edges = count == 2 ? 1 : count;
	for (int j = 0; j < count; ++j)
		if (Dot(w[j], d) >= h - tol)
			add(w[j]);
	for (int j = 0; j < edges; ++j)
	{
		// Where an edge crosses the level h − tol, the patch ends.
		const Vec2 p = w[j], r = w[(j + 1) % count];
		const double fp = Dot(p, d) - (h - tol), fr = Dot(r, d) - (h - tol);
		if ((fp > 0.0) != (fr > 0.0))
			add(p + (fp / (fp - fr)) * (r - p));
	}
	out.valid = out.lo <= out.hi;
	return out;
}

// Whether the arc of an analytic shape around its support point q (body frame) may be a flat patch.
// Flat means nearly zero curvature where it touches: a blocky superellipse's side (its
// curvature vanishes on the axis), not an ellipse, which is curved everywhere (κ·R = b/a) and
// whose rocking must follow that curvature. So the curvature κ there must be below a tenth of
// the shape's bounding radius's inverse, and then the arc, which stays within tol over about
// 2·√(2·tol/κ), must be able to reach half of minWidth (a margin for arcs that are not parabolas)
// before the costly search for its ends runs.
bool MayBeFlat(const Shape& shape, Vec2 q, double tol, double minWidth)
{
	const LevelDerivatives ld = shape.Derivatives(q);
	const double g = Length(ld.gradient);
	if (!(g > 0.0) || !std::isfinite(g))
		return true;
	const Vec2 t = Perp(ld.gradient) / g;
	const double kappa = Dot(t, ld.hessian * t) / g;
	if (!(kappa > 0.0) || !std::isfinite(kappa))
		return true;
	if (kappa * shape.BoundingRadius() > 0.1)
		return false;
	return 2.0 * std::sqrt(2.0 * tol / kappa) >= 0.5 * minWidth;
}

Interval Face(const ManifoldSide& side, Vec2 d, Vec2 origin, Vec2 t, double tol, double minWidth, double* cache, double* slopes,
              bool& cached)
{
	if (side.point)
		return {};
	if (side.shape)
	{
		if (!side.shape->IsConvex())
			return {};
		// The support point along d, which both the flatness test and the face search start from.
		const Vec2 db = InvRotate(side.pose.q, d);
		const Vec2 q = side.shape->Support(db);
		if (side.shape->IsSmoothConvex() && !MayBeFlat(*side.shape, q, tol, minWidth))
			return {};
		return AnalyticFace(*side.shape, side.pose, db, q, origin, t, tol, cache, slopes, cached);
	}
	if (side.vertices && side.count >= 2)
		return PolygonFace(side.vertices, side.count, d, origin, t, tol);
	return {};
}

// B's surface point on the line through p along n that is lowest along n (B's near side).
bool LowestAlong(const ManifoldSide& b, Vec2 p, Vec2 n, Vec2& out)
{
	if (b.shape)
	{
		// B's near crossing of the line is its far crossing of the reversed line, where B has one.
		double t = 0.0;
		if (b.shape->IsConvex() && b.shape->FarCrossing(ToBody(b.pose, p), InvRotate(b.pose.q, -n), t))
		{
			out = p - t * n;
			return true;
		}
		if (b.shape->IsConvex() && b.shape->LineMisses(ToBody(b.pose, p), InvRotate(b.pose.q, n)))
			return false; // what the search below finds, in closed form
		// Else start beyond B's support plane along −n (outside B) and enter along +n.
		const double low = -Dot(WorldSupport(*b.shape, b.pose, -n), n);
		const double margin = 1e-3 * b.shape->BoundingRadius() + 1e-12;
		const Vec2 start = p + (low - margin - Dot(p, n)) * n;
		const double sMax = 2.0 * b.shape->BoundingRadius() + Distance(start, b.pose.p) + margin;
		const double s = FirstSurfaceCrossing(*b.shape, b.pose, start, n, sMax);
		if (s < 0.0)
			return false;
		out = start + s * n;
		return true;
	}
	// Polygon or segment: the smallest line parameter among the edge intersections.
	const Vec2 t = Perp(n);
	const double tp = Dot(p, t);
	double best = std::numeric_limits<double>::infinity();
	const int edges = b.count == 2 ? 1 : b.count;
	for (int j = 0; j < edges; ++j)
	{
		const Vec2 u = b.vertices[j], v = b.vertices[(j + 1) % b.count];
		const double fu = Dot(u, t) - tp, fv = Dot(v, t) - tp;
		if ((fu > 0.0) == (fv > 0.0) && fu != 0.0 && fv != 0.0)
			continue;
		const double denom = fu - fv;
		const Vec2 x = denom != 0.0 ? u + (fu / denom) * (v - u) : (Dot(u, n) < Dot(v, n) ? u : v);
		best = std::min(best, Dot(x - p, n));
	}
	if (!std::isfinite(best))
		return false;
	out = p + best * n;
	return true;
}
} // namespace

ContactManifold BuildContactManifold(const ContactResult& c, const ManifoldSide& a, const ManifoldSide& b, double tol,
                                     double minWidth, double radii, ManifoldCache* cache)
{
	ManifoldCache scratch;
	if (!cache)
		cache = &scratch;
	ContactManifold m;
	m.normal = c.normal;
	m.pointA = c.pointA;
	const double sep0 = Dot(c.pointB - c.pointA, c.normal) - radii;
	if (!c.Ok() || !(sep0 <= 0.0))
		return m;
	m.count = 1;
	m.points[0] = {c.pointB, sep0, 0};
	const Vec2 n = c.normal, t = Perp(n), origin = c.pointA;
	const Interval fa = Face(a, n, origin, t, tol, minWidth, cache->endsA, cache->slopesA, cache->validA);
	if (!fa.valid)
		return m;
	const Interval fb = Face(b, -n, origin, t, tol, minWidth, cache->endsB, cache->slopesB, cache->validB);
	if (!fb.valid)
		return m;
	const double lo = std::max(fa.lo, fb.lo), hi = std::min(fa.hi, fb.hi);
	if (!(hi - lo > std::max(tol, minWidth)))
		return m; // a curved contact: one point
	ManifoldPoint ends[2];
	int kept = 0;
	for (double s : {lo, hi})
	{
		Vec2 q;
		if (!LowestAlong(b, origin + s * t, n, q))
			continue;
		const double sep = Dot(q - c.pointA, n) - radii;
		if (sep <= 0.0)
		{
			ends[kept] = {q, sep, kept};
			++kept;
		}
	}
	if (kept == 2)
	{
		m.count = 2;
		m.points[0] = ends[0];
		m.points[1] = ends[1];
	}
	return m;
}

} // namespace b2a

// b2analytic reference library: long-double reference contacts of shape pairs, for the pair
// benchmark and the contact tests.
//
// The contact a method reports (ContactResult) is defined from a level point X: the normal is
// the mean of A's outward and B's inward unit normals at X, pointA is where the line through X
// along the normal leaves A (A's extreme along +n on it), pointB where it enters B, and the
// separation is (pointB − pointA)·n. Two level definitions exist:
//  - the common level (Newton, min–max, the automatic path for convex pairs): X from the
//    long-double references of the unit tests (Perram–Wertheim for ellipses, the fixed point of
//    the surface minimum for other superellipses, ContactReference.h);
//  - the one-sided level of the grid method, on each side: X is the point of B's surface where
//    A's level is smallest (and the same with A and B swapped), from a dense long-double
//    surface minimum; the grid contact is compared with the side it took (GridContact picks
//    one, or both and then the deeper or nearer).
// Here the contact is rebuilt from the reference X in long double, from the shapes' formulas
// (RefShape), with the line crossings found by bisection to long-double resolution. Nothing
// here calls the library's shapes or solvers.
#pragma once

#include "ContactReference.h"

#include <algorithm>
#include <cmath>


namespace b2a::bench
{

using test::ref::LD;
using test::ref::RefPose;
using test::ref::RefShape;
using test::ref::V;

/// A posed reference shape with its dense surface curve (for the one-sided minimum).
struct RefPosed
{
	RefShape shape;      ///< the formula
	RefPose pose;        ///< the placement
	LD reach = 1.0L;     ///< bounding radius (every surface point lies within it of the centre)
	const test::ref::Curve* curve = nullptr; ///< dense samples of the own surface (shared per shape)
};

/// A reference contact, in the convention of ContactResult.
struct RefContact
{
	V point;              ///< the level point
	LD level = 0.0L;      ///< its level
	V normal;             ///< unit normal from A to B
	V pointA, pointB;     ///< surface points
	LD separation = 0.0L; ///< (pointB − pointA)·normal
	bool touching = false; ///< the level at or below the own level
};

/// λ − own along the line X + t·dir.
inline LD LineLevel(const RefPosed& s, V X, V dir, LD t)
{
	return s.shape.Level(test::ref::ToBodyL(s.pose, X + t * dir)) - s.shape.Own();
}

/// Root of g on [lo, hi] where g(lo) and g(hi) differ in sign, to long-double resolution.
template <class G>
LD BisectL(G&& g, LD lo, LD hi)
{
	const LD glo = g(lo), ghi = g(hi);
	if (glo == 0.0L || ghi == 0.0L)
		return glo == 0.0L ? lo : hi; // a point exactly on the surface (the grid's level points)
	const bool lowNegative = glo < 0.0L;
	for (int i = 0; i < 200; ++i)
	{
		const LD mid = 0.5L * (lo + hi);
		if (mid == lo || mid == hi)
			break;
		((g(mid) < 0.0L) == lowNegative ? lo : hi) = mid;
	}
	return 0.5L * (lo + hi);
}

/// True where the body point lies on a corner of the shape: the heart's axis (its level grows
/// like |x|^{2/3} across it, so the gradient has no direction there).
inline bool RefAtCorner(const RefShape& s, V x)
{
	if (s.kind != RefShape::Kind::heart)
		return false;
	const LD r = test::ref::Len(x);
	return r > 0.0L && std::fabs(x.x) <= 1e-7L * r;
}

/// World unit normal of a shape at a world point, or (0, 0) at a corner.
inline V RefUnitNormal(const RefPosed& s, V X)
{
	const V x = test::ref::ToBodyL(s.pose, X);
	if (RefAtCorner(s.shape, x))
		return {};
	const V g = test::ref::RotateL(s.pose, s.shape.Gradient(x));
	const LD len = test::ref::Len(g);
	return len > 0.0L ? (1.0L / len) * g : V{};
}

/// The point of a shape's surface where the line X + t·dir (t ≥ 0) first crosses it, or where
/// the line "leaves" it: for a convex shape the level along a line is convex, so from inside the
/// crossing is unique (doubling then bisection); from outside the extreme crossing along +dir is
/// found beyond the line's minimum of the level (golden section). Non-convex shapes are scanned
/// finely from X. Returns false when the line misses the shape.
inline bool RefExtreme(const RefPosed& s, V X, V dir, bool convex, V& out)
{
	auto g = [&](LD t) { return LineLevel(s, X, dir, t); };
	const LD reach = test::ref::Len(X - s.pose.p) + 1.01L * s.reach;
	// A level point on the surface is its own crossing (the grid's points lie on B's surface),
	// whichever way the normal leaves it. At a corner (the heart's tip) the level grows like
	// |x|^{2/3} across the axis, so a point exact to 1e-19 is on the surface only to ~1e-13.
	const LD g0 = g(0.0L);
	const LD onSurface = RefAtCorner(s.shape, test::ref::ToBodyL(s.pose, X)) ? 1e-10L : 1e-15L;
	if (std::fabs(g0) <= onSurface * std::max(s.shape.Own(), 1.0L))
	{
		out = X;
		return true;
	}
	const bool inside = g0 <= 0.0L;
	if (inside || !convex)
	{
		// Non-convex and outside: the crossing nearest X behind it (entering the shape against
		// dir), as ContactFromLevel documents. Inside: the first crossing along dir.
		const V way = inside ? dir : -1.0L * dir;
		auto h = [&](LD t) { return LineLevel(s, X, way, t); };
		const int steps = 8192;
		LD prev = 0.0L, hprev = h(0.0L);
		for (int k = 1; k <= steps; ++k)
		{
			const LD t = reach * LD(k) / steps;
			const LD ht = h(t);
			if ((ht > 0.0L) != (hprev > 0.0L))
			{
				out = X + BisectL(h, prev, t) * way;
				return true;
			}
			prev = t;
			hprev = ht;
		}
		return false;
	}
	// Convex, X outside: minimise the level along the line over the shape's extent, then the
	// root on the far side of the minimum (A's extreme along dir).
	const LD centre = test::ref::Dot(s.pose.p - X, dir);
	LD lo = centre - 1.01L * s.reach, hi = centre + 1.01L * s.reach;
	const LD phi = 0.5L * (std::sqrt(5.0L) - 1.0L);
	LD x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo), f1 = g(x1), f2 = g(x2);
	for (int i = 0; i < 200 && hi - lo > 1e-19L * (1.0L + std::fabs(centre)); ++i)
	{
		if (f1 < f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - phi * (hi - lo); f1 = g(x1); }
		else { lo = x1; x1 = x2; f1 = f2; x2 = lo + phi * (hi - lo); f2 = g(x2); }
	}
	const LD tmin = 0.5L * (lo + hi);
	if (g(tmin) > 0.0L)
		return false;
	out = X + BisectL(g, tmin, centre + 1.01L * s.reach) * dir;
	return true;
}

/// The surface point on the ray from the centre towards X (the level grows along every ray of a
/// star-shaped shape, so bisection finds it).
inline V RefRadial(const RefPosed& s, V X)
{
	const V d = X - s.pose.p;
	const LD len = test::ref::Len(d);
	const V u = len > 0.0L ? (1.0L / len) * d : V{1.0L, 0.0L};
	auto g = [&](LD t) { return LineLevel(s, s.pose.p, u, t); };
	return s.pose.p + BisectL(g, 0.0L, 1.01L * s.reach) * u;
}

/// The contact built from a level point, as ContactFromLevel documents it.
inline RefContact RefContactFromPoint(const RefPosed& A, const RefPosed& B, V X, LD level, bool touching,
                                      bool pointOnB, bool convexA, bool convexB, const V* given = nullptr)
{
	RefContact c;
	c.point = X;
	c.level = level;
	c.touching = touching;
	const V na = RefUnitNormal(A, X), nb = RefUnitNormal(B, X);
	const bool hasA = test::ref::Len(na) > 0.0L, hasB = test::ref::Len(nb) > 0.0L;
	V n{};
	if (given)
		n = *given;
	else if (hasA && hasB)
		n = test::ref::Dot(na, nb) < 0.0L ? test::ref::Unit(na - nb) : (pointOnB ? -1.0L * nb : na);
	else if (hasA)
		n = na;
	else if (hasB)
		n = -1.0L * nb;
	else
		n = test::ref::Unit(B.pose.p - A.pose.p);
	c.normal = n;
	if (!RefExtreme(A, X, n, convexA, c.pointA))
		c.pointA = RefRadial(A, X);
	if (!RefExtreme(B, X, -1.0L * n, convexB, c.pointB))
		c.pointB = RefRadial(B, X);
	c.separation = test::ref::Dot(c.pointB - c.pointA, n);
	return c;
}

/// The common-level reference contact of two convex shapes of the superellipse family.
inline RefContact CommonContactRef(const RefPosed& A, const RefPosed& B)
{
	V X;
	LD C;
	const bool ellipses = A.shape.n == 2 && A.shape.m == 2 && B.shape.n == 2 && B.shape.m == 2;
	if (ellipses)
	{
		const auto pw = test::ref::PerramWertheim(test::ref::QuadOf(A.shape.a, A.shape.b, A.pose),
		                                          test::ref::QuadOf(B.shape.a, B.shape.b, B.pose));
		X = pw.point;
		C = pw.level;
		// The normal from the shapes' matrices (PwNormal): the gradients at X turn with X's
		// rounding by up to (a/b)² where the point sits near both centres of crossing needles.
		return RefContactFromPoint(A, B, X, C, C <= 1.0L, false, true, true, &pw.normal);
	}
	else
	{
		const auto r = test::ref::CommonLevelRef(A.shape, A.pose, B.shape, B.pose, 1024);
		X = r.point;
		C = r.level;
	}
	return RefContactFromPoint(A, B, X, C, C <= 1.0L, false, true, true);
}

/// The one-sided (grid-method) reference contacts, both seen from A: A rescaled onto B's
/// surface (`aOntoB`) and B onto A's (`bOntoA`, normal flipped and points swapped), each from
/// the dense surface minimum.
struct OneSidedRefs
{
	RefContact aOntoB, bOntoA;
	bool touching = false; ///< the pair overlaps: either side at or below its own level
};

inline OneSidedRefs OneSidedContactRefs(const RefPosed& A, const RefPosed& B, bool convexA, bool convexB)
{
	auto side = [&](const RefPosed& P, const RefPosed& Q, bool convexP, bool convexQ) {
		const auto m = test::ref::SurfaceMin(P.shape, P.pose, Q.shape, Q.pose, Q.shape.Own(), 0, 8, Q.curve);
		return RefContactFromPoint(P, Q, m.point, m.value, m.value <= P.shape.Own(), true, convexP, convexQ);
	};
	OneSidedRefs r;
	r.aOntoB = side(A, B, convexA, convexB);
	r.bOntoA = side(B, A, convexB, convexA);
	r.bOntoA.normal = -1.0L * r.bOntoA.normal;
	std::swap(r.bOntoA.pointA, r.bOntoA.pointB);
	r.touching = r.aOntoB.touching || r.bOntoA.touching;
	return r;
}

} // namespace b2a::bench

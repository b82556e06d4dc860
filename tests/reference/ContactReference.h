// b2analytic reference library: independent long-double contact references (tests and benchmarks).
//
// Nothing here calls a contact solver of the library, nor its shapes' level, radius or sample
// functions: every shape is described again from its formula (docs/method.md) and evaluated in
// long double (64-bit mantissa, eps ≈ 1.1e-19, about 1000 times finer than double), so the
// references are exact to far below the tolerances the tests assert on double-precision results.
// The only things taken from the library are the poses' stored cosine and sine (so that the
// reference describes exactly the geometry the solver was given) and the plain value types.
//
// What is here:
//  - RefShape: superellipse (ellipse, circle) and heart level functions, and a closed-curve
//    parametrisation of every level set (closed form for superellipses, a long-double bisection
//    of the radial equation for the heart).
//  - SurfaceMin: the smallest level of A over B's level-L surface by dense sampling, then
//    golden-section search and a bisection on the sign of a centred difference at each of the
//    lowest local minima (the grid method done independently, and much more finely).
//  - CommonLevelRef: the common level of two convex shapes as the fixed point G(C) = C of
//    G(L) = min of λA over B's solid level-L set (decreasing in L), by the Illinois method.
//  - Perram–Wertheim for ellipses: C = max over μ of min over X of the weighted sum of the two
//    quadratic forms, with X(μ) from a 2×2 solve; the maximiser is where F_A(X(μ)) = F_B(X(μ)),
//    a monotone function of log μ, found by bisection. Plus the one-sided ellipse scale and the
//    line–ellipse intersections (quadratic roots) that ComputeContact's points must match.
#pragma once

#include "b2analytic/b2analytic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace b2a::test::ref
{

using LD = long double;
static_assert(std::numeric_limits<LD>::digits >= 64,
              "the contact references need an extended long double (x87 80-bit or IEEE quad); with a 53-bit "
              "long double they are no more exact than the solvers they check");

/// A long-double 2D vector.
struct V
{
	LD x = 0.0L;
	LD y = 0.0L;
};
inline V operator+(V a, V b) { return {a.x + b.x, a.y + b.y}; }
inline V operator-(V a, V b) { return {a.x - b.x, a.y - b.y}; }
inline V operator*(LD s, V a) { return {s * a.x, s * a.y}; }
inline LD Dot(V a, V b) { return a.x * b.x + a.y * b.y; }
inline LD Cross(V a, V b) { return a.x * b.y - a.y * b.x; }
inline LD Len(V a) { return std::sqrt(a.x * a.x + a.y * a.y); }
inline V Unit(V a) { return (1.0L / Len(a)) * a; }
inline V FromVec(Vec2 a) { return {a.x, a.y}; }
inline Vec2 ToVec(V a) { return Vec2(double(a.x), double(a.y)); }
/// Distance between a double point and a long-double point, in long double.
inline LD Dist(Vec2 a, V b) { return Len(FromVec(a) - b); }

inline constexpr LD kPiL = 3.141592653589793238462643383279502884L;

/// x^e for x ≥ 0, e > 0: exact repeated multiplication for small integer e, else exp(e·log x)
/// (relative error ≤ |e log x|·eps ≈ 1e-17 here; glibc's powl is ~5× slower and the references
/// call this millions of times).
inline LD PowL(LD x, LD e)
{
	if (!(x > 0.0L))
		return 0.0L;
	if (e == std::floor(e) && e <= 64.0L)
	{
		LD r = 1.0L, t = x;
		for (int k = int(e); k > 0; k >>= 1)
		{
			if (k & 1) r *= t;
			t *= t;
		}
		return r;
	}
	return std::exp(e * std::log(x));
}

/// A rigid placement in long double.
struct RefPose
{
	V p;
	LD c = 1.0L, s = 0.0L;
};
/// The library pose's placement: its own cosine and sine (so both describe the same placement),
/// renormalised so that the rotation is exactly orthogonal in long double. (The double pair has
/// c² + s² = 1 ± 1e-16; left as is, body → world → body would rescale by that much, which a
/// multiplier μ ~ 500, as in the 1000:1 ellipses, turns into a 1e-14 error of a level.)
inline RefPose Of(const Pose& q)
{
	const LD c = q.q.c, s = q.q.s, r = std::sqrt(c * c + s * s);
	return {FromVec(q.p), c / r, s / r};
}
/// A pose built in long double from an angle (used where the test defines the motion itself).
inline RefPose PoseL(V p, LD angle) { return {p, std::cos(angle), std::sin(angle)}; }
inline V ToBodyL(const RefPose& t, V X)
{
	const V d = X - t.p;
	return {t.c * d.x + t.s * d.y, -t.s * d.x + t.c * d.y};
}
inline V ToWorldL(const RefPose& t, V x) { return {t.c * x.x - t.s * x.y + t.p.x, t.s * x.x + t.c * x.y + t.p.y}; }
inline V RotateL(const RefPose& t, V x) { return {t.c * x.x - t.s * x.y, t.s * x.x + t.c * x.y}; }

/// A shape described from its formula, independently of the library.
struct RefShape
{
	enum class Kind { superellipse, heart };
	Kind kind = Kind::superellipse;
	LD a = 1.0L, b = 1.0L, n = 2.0L, m = 2.0L; // |x/a|^n + |y/b|^m
	LD alpha = 1.0L;                            // heart size

	static RefShape Super(LD a, LD b, LD n, LD m)
	{
		RefShape s;
		s.a = a; s.b = b; s.n = n; s.m = m;
		return s;
	}
	static RefShape Ellipse(LD a, LD b) { return Super(a, b, 2.0L, 2.0L); }
	static RefShape Circle(LD r) { return Super(r, r, 2.0L, 2.0L); }
	static RefShape Heart(LD alpha)
	{
		RefShape s;
		s.kind = Kind::heart;
		s.alpha = alpha;
		return s;
	}

	/// The particle's own level (1 for superellipses, α for the heart).
	LD Own() const { return kind == Kind::heart ? alpha : 1.0L; }

	/// λ(x): |x/a|^n + |y/b|^m, or the heart's α(x) = x² + y² − cbrt(x² y³) (docs/method.md, "Shape functions and levels").
	LD Level(V x) const
	{
		if (kind == Kind::heart)
			return x.x * x.x + x.y * x.y - std::cbrt(x.x * x.x * x.y * x.y * x.y);
		return PowL(std::fabs(x.x / a), n) + PowL(std::fabs(x.y / b), m);
	}

	/// ∇λ(x) away from the axes' singular points (used only for Lagrange-condition checks).
	V Gradient(V x) const
	{
		if (kind == Kind::heart)
		{
			const LD ax = std::fabs(x.x), c = std::cbrt(ax);
			const LD sg = x.x > 0 ? 1.0L : (x.x < 0 ? -1.0L : 0.0L);
			return {ax > 0 ? 2.0L * x.x - (2.0L / 3.0L) * sg / c * x.y : 0.0L, 2.0L * x.y - c * c};
		}
		const LD X = x.x / a, Y = x.y / b;
		const LD sx = X > 0 ? 1.0L : (X < 0 ? -1.0L : 0.0L), sy = Y > 0 ? 1.0L : (Y < 0 ? -1.0L : 0.0L);
		return {n / a * sx * PowL(std::fabs(X), n - 1.0L), m / b * sy * PowL(std::fabs(Y), m - 1.0L)};
	}

	/// Body point of the level-L set at curve parameter s (period 4, counter-clockwise, s = 0 on
	/// the +x axis, s = 1, 2, 3 on the +y, −x, −y axes).
	///  - Superellipse: X = a L^{1/n} cos(τ)^{2/n}, Y = b L^{1/m} sin(τ)^{2/m} per quadrant, which
	///    satisfies |X/a|^n + |Y/b|^m = L exactly; τ = (π/2) w(σ) with the warp
	///    w = σ^{m/2} / (σ^{m/2} + (1−σ)^{n/2}) so that points do not bunch away from the axes.
	///  - Heart: polar angle θ = π(s/2 − 1), radius from a long-double bisection of the radial
	///    equation w⁶ − k w⁵ = L (w = r^{1/3}, k = cbrt(ux² uy³)), which has one positive root.
	V Surface(LD s, LD L) const
	{
		s = std::fmod(s, 4.0L);
		if (s < 0) s += 4.0L;
		if (kind == Kind::heart)
		{
			const LD theta = kPiL * (0.5L * s - 1.0L);
			const LD ux = std::cos(theta), uy = std::sin(theta);
			const LD k = std::cbrt(ux * ux * uy * uy * uy);
			auto h = [&](LD w) { const LD w5 = w * w * w * w * w; return w5 * (w - k) - L; };
			// h(hi) ≥ 0 at hi = |k| + L^{1/6} (then w⁵ ≥ L^{5/6} and w − k ≥ L^{1/6}); 66 halvings
			// take the bracket below long-double resolution.
			LD lo = 0.0L, hi = std::fabs(k) + std::pow(L, 1.0L / 6.0L);
			for (int i = 0; i < 66; ++i)
			{
				const LD mid = 0.5L * (lo + hi);
				if (h(mid) < 0) lo = mid; else hi = mid;
			}
			const LD w = 0.5L * (lo + hi), r = w * w * w;
			return {r * ux, r * uy};
		}
		int q = int(std::floor(s));
		if (q > 3) q = 3;
		LD sigma = s - q;
		if (q == 1 || q == 3) sigma = 1.0L - sigma;
		const LD p1 = PowL(sigma, 0.5L * m), p2 = PowL(1.0L - sigma, 0.5L * n);
		const LD tau = 0.5L * kPiL * (p1 / (p1 + p2));
		LD X = a * PowL(L, 1.0L / n) * PowL(std::fabs(std::cos(tau)), 2.0L / n);
		LD Y = b * PowL(L, 1.0L / m) * PowL(std::fabs(std::sin(tau)), 2.0L / m);
		if (q == 1 || q == 2) X = -X;
		if (q == 2 || q == 3) Y = -Y;
		return {X, Y};
	}
};

/// Closed-curve samples of B's level-L surface in B's body frame (they do not depend on the
/// pose, so time-stepping references compute them once).
struct Curve
{
	LD level = 1.0L;
	std::vector<LD> s;
	std::vector<V> point;
};
inline Curve SampleCurve(const RefShape& B, LD L, int count)
{
	Curve c;
	c.level = L;
	c.s.resize(count);
	c.point.resize(count);
	for (int k = 0; k < count; ++k)
	{
		c.s[k] = 4.0L * LD(k) / LD(count);
		c.point[k] = B.Surface(c.s[k], L);
	}
	return c;
}

/// Minimiser of f on [lo, hi] where f is unimodal. Two searches, the lower value wins:
///  - golden section down to long-double resolution of the argument: exact for kinks and cusps
///    (the heart's level has a |x|^{2/3} valley along its axis, where stopping at a bracket of
///    1e-7 would leave an error ~(1e-7)^{2/3}), and exact in the value for smooth minima, where
///    rounding stalls it at an argument error ~sqrt(eps) ≈ 3e-10;
///  - for smooth minima, a bisection on the sign of the centred difference f(s + h) − f(s − h),
///    h = 1e-7, which places the argument to ~h² + eps/h ≈ 1e-12.
template <class F>
std::pair<LD, LD> Minimise1D(F&& f, LD lo, LD hi)
{
	const LD g = 0.6180339887498948482045868343656381L;
	const LD lo0 = lo, hi0 = hi;
	LD x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
	LD f1 = f(x1), f2 = f(x2);
	for (int i = 0; i < 200 && hi - lo > 1e-18L * (1.0L + std::fabs(lo)); ++i)
	{
		if (f1 <= f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = f(x1); }
		else { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = f(x2); }
	}
	LD best = f1 <= f2 ? x1 : x2, fbest = std::min(f1, f2);
	const LD h = 1e-7L;
	auto D = [&](LD s) { return f(s + h) - f(s - h); };
	LD a = std::max(lo0, best - 1e-6L), b = std::min(hi0, best + 1e-6L);
	if (D(a) < 0 && D(b) > 0)
	{
		for (int i = 0; i < 60 && b - a > 1e-19L; ++i)
		{
			const LD mid = 0.5L * (a + b);
			if (D(mid) < 0) a = mid; else b = mid;
		}
		// Prefer this argument unless it is worse than golden's beyond rounding (at a kink it is:
		// the difference changes sign within ~h of it, which costs first order there).
		const LD s = 0.5L * (a + b), fs = f(s);
		if (fs <= fbest + 8.0L * std::numeric_limits<LD>::epsilon() * std::fabs(fbest)) { best = s; fbest = std::min(fs, fbest); }
	}
	return {best, fbest};
}

/// Value, gradient and Hessian of a level function (body or world frame).
struct Deriv
{
	LD value = 0.0L; ///< λ
	V grad;          ///< ∇λ
	LD hxx = 0.0L;   ///< ∂²λ/∂x²
	LD hxy = 0.0L;   ///< ∂²λ/∂x∂y
	LD hyy = 0.0L;   ///< ∂²λ/∂y²
};

/// x^e for x ≥ 0 with 0^0 = 1 (the Hessian of an n = 2 superellipse on its axis).
inline LD PowZ(LD x, LD e) { return e == 0.0L ? 1.0L : PowL(x, e); }

/// Sign of x as −1, 0 or 1.
inline LD Sign(LD x) { return x > 0.0L ? 1.0L : (x < 0.0L ? -1.0L : 0.0L); }

/// Body-frame derivatives from the formulas (docs/method.md, "Shape functions and levels"):
///  - superellipse λ = |x/a|^n + |y/b|^m: λ_x = (n/a) sgn(x) |x/a|^{n−1}, λ_xx = n(n−1)/a² |x/a|^{n−2},
///    λ_xy = 0 (likewise in y);
///  - heart λ = x² + y² − |x|^{2/3} y: λ_x = 2x − (2/3) sgn(x) |x|^{−1/3} y, λ_y = 2y − |x|^{2/3},
///    λ_xx = 2 + (2/9)|x|^{−4/3} y, λ_xy = −(2/3) sgn(x)|x|^{−1/3}, λ_yy = 2. On the axis x = 0 the
///    |x|-terms are singular; they are dropped there (PolishLagrange does not polish there).
inline Deriv BodyDeriv(const RefShape& s, V x)
{
	Deriv d;
	if (s.kind == RefShape::Kind::heart)
	{
		const LD c = std::cbrt(std::fabs(x.x)), sg = Sign(x.x); // c = |x|^{1/3}
		d.value = x.x * x.x + x.y * x.y - c * c * x.y;
		d.grad = {c > 0.0L ? 2.0L * x.x - (2.0L / 3.0L) * sg * x.y / c : 0.0L, 2.0L * x.y - c * c};
		d.hxx = c > 0.0L ? 2.0L + (2.0L / 9.0L) * x.y / (c * c * c * c) : 2.0L;
		d.hxy = c > 0.0L ? -(2.0L / 3.0L) * sg / c : 0.0L;
		d.hyy = 2.0L;
		return d;
	}
	const LD X = x.x / s.a, Y = x.y / s.b, u = std::fabs(X), v = std::fabs(Y);
	d.value = PowL(u, s.n) + PowL(v, s.m);
	d.grad = {s.n / s.a * Sign(X) * PowZ(u, s.n - 1.0L), s.m / s.b * Sign(Y) * PowZ(v, s.m - 1.0L)};
	d.hxx = s.n * (s.n - 1.0L) / (s.a * s.a) * PowZ(u, s.n - 2.0L);
	d.hyy = s.m * (s.m - 1.0L) / (s.b * s.b) * PowZ(v, s.m - 2.0L);
	return d;
}

/// World-frame derivatives at a world point: ∇ = R∇_body, H = R H_body Rᵀ.
inline Deriv WorldDeriv(const RefShape& shape, const RefPose& pose, V X)
{
	const Deriv b = BodyDeriv(shape, ToBodyL(pose, X));
	const LD c = pose.c, s = pose.s;
	Deriv w;
	w.value = b.value;
	w.grad = RotateL(pose, b.grad);
	w.hxx = c * c * b.hxx - 2.0L * c * s * b.hxy + s * s * b.hyy;
	w.hyy = s * s * b.hxx + 2.0L * c * s * b.hxy + c * c * b.hyy;
	w.hxy = c * s * (b.hxx - b.hyy) + (c * c - s * s) * b.hxy;
	return w;
}

/// A Lagrange point polished by Newton's method in long double: the common point, where
/// ∇λA + μ∇λB = 0 and λA = λB (`common`), or the smallest λA on B's level-L set, where
/// ∇λA + μ∇λB = 0 and λB = L. A minimum found by comparing values (CommonLevelRef's and
/// SurfaceMin's) fixes its point only to the square root of their rounding, ~3e-10 of the size:
/// at a 4,8 superellipse pose of b2a_bench_pairs that put the common reference's contact points
/// 1.1e-9 of the size off, where a 60-digit solution found the library's within 1e-15. Newton's
/// steps square that error away. Each is kept only while it lowers the residual, at most 8 are
/// taken, and X is returned unchanged where they would move it by more than 1e-6 of its distance
/// from B's centre (not the local root), or where a shape has no Hessian there (a superellipse
/// exponent below 2, the heart's axis, where BodyDeriv drops its infinite terms).
inline V PolishLagrange(const RefShape& A, const RefPose& pa, const RefShape& B, const RefPose& pb, V X, bool common, LD L = 1.0L)
{
	auto smooth = [](const RefShape& S) { return S.kind == RefShape::Kind::heart || (S.n >= 2.0L && S.m >= 2.0L); };
	if (!smooth(A) || !smooth(B))
		return X;
	// WorldDeriv, with the level from Level itself (SurfaceMin compares the values it gives) and
	// none on the heart's axis.
	struct Side
	{
		LD level;
		V grad;
		LD hxx, hxy, hyy;
		bool onAxis;
	};
	auto side = [](const RefShape& S, const RefPose& p, V at) {
		const Deriv d = WorldDeriv(S, p, at);
		const V x = ToBodyL(p, at);
		return Side{S.Level(x), d.grad, d.hxx, d.hxy, d.hyy, S.kind == RefShape::Kind::heart && x.x == 0.0L};
	};
	const V start = X;
	Side sa = side(A, pa, X), sb = side(B, pb, X);
	if (sa.onAxis || sb.onAxis)
		return X;
	const LD gb2 = Dot(sb.grad, sb.grad);
	if (!(gb2 > 0.0L))
		return X;
	LD mu = -Dot(sa.grad, sb.grad) / gb2;
	if (!(mu > 0.0L))
		return X;
	auto constraint = [&](const Side& p, const Side& q) { return common ? p.level - q.level : q.level - L; };
	auto residual = [&](const Side& p, const Side& q, LD m) {
		const LD r0 = p.grad.x + m * q.grad.x, r1 = p.grad.y + m * q.grad.y, r2 = constraint(p, q);
		return r0 * r0 + r1 * r1 + r2 * r2;
	};
	auto det3 = [](LD a, LD b, LD c, LD d, LD e, LD f, LD g, LD h, LD i) {
		return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
	};
	LD res = residual(sa, sb, mu);
	for (int it = 0; it < 8 && res > 0.0L; ++it)
	{
		// [[HA + μHB, ∇λB], [cᵀ, 0]]·(δx, δμ) = −(∇λA + μ∇λB, constraint), c its gradient, by
		// Cramer's rule.
		const LD h11 = sa.hxx + mu * sb.hxx, h12 = sa.hxy + mu * sb.hxy, h22 = sa.hyy + mu * sb.hyy;
		const LD g1 = sb.grad.x, g2 = sb.grad.y;
		const LD d1 = common ? sa.grad.x - sb.grad.x : sb.grad.x, d2 = common ? sa.grad.y - sb.grad.y : sb.grad.y;
		const LD r0 = -(sa.grad.x + mu * sb.grad.x), r1 = -(sa.grad.y + mu * sb.grad.y), r2 = -constraint(sa, sb);
		const LD det = det3(h11, h12, g1, h12, h22, g2, d1, d2, 0.0L);
		if (!(std::fabs(det) > 0.0L) || !std::isfinite(det))
			break;
		const LD dx = det3(r0, h12, g1, r1, h22, g2, r2, d2, 0.0L) / det;
		const LD dy = det3(h11, r0, g1, h12, r1, g2, d1, r2, 0.0L) / det;
		const LD dm = det3(h11, h12, r0, h12, h22, r1, d1, d2, r2) / det;
		const V next{X.x + dx, X.y + dy};
		const Side na = side(A, pa, next), nb = side(B, pb, next);
		const LD nres = residual(na, nb, mu + dm);
		if (na.onAxis || nb.onAxis || !(nres < res) || !(mu + dm > 0.0L))
			break;
		X = next;
		mu += dm;
		sa = na;
		sb = nb;
		res = nres;
	}
	return Len(X - start) <= 1e-6L * Len(start - pb.p) ? X : start;
}

/// Result of a surface minimum.
struct SurfaceMinResult
{
	LD value = 0.0L; ///< smallest level of A on B's level-L surface
	V point;         ///< its world point
	LD s = 0.0L;     ///< curve parameter on B
	LD secondValue = std::numeric_limits<LD>::infinity(); ///< the next-lowest distinct local minimum
};

/// The smallest level of A over B's level-L surface (world poses pa, pb): `count` samples
/// (or the precomputed `curve`), the lowest `candidates` local minima polished by Minimise1D,
/// and the corners s = 0, 1, 2, 3 (axis points, where superellipses with an exponent below 2
/// and the heart have kinks) as extra candidates; the point then by PolishLagrange unless
/// `polish` is false.
inline SurfaceMinResult SurfaceMin(const RefShape& A, const RefPose& pa, const RefShape& B, const RefPose& pb, LD L,
                                   int count = 4096, int candidates = 8, const Curve* curve = nullptr, bool polish = true)
{
	Curve local;
	// A superellipse's level-L set is its level-1 set stretched by (L^{1/n}, L^{1/m}) (exactly so
	// in the parametrisation of RefShape::Surface), so one precomputed curve serves every level.
	V stretch{1.0L, 1.0L};
	if (curve && curve->level != L)
	{
		if (B.kind != RefShape::Kind::superellipse)
			curve = nullptr;
		else
			stretch = {PowL(L / curve->level, 1.0L / B.n), PowL(L / curve->level, 1.0L / B.m)};
	}
	if (!curve)
	{
		local = SampleCurve(B, L, count);
		curve = &local;
	}
	const int N = int(curve->point.size());
	auto f = [&](LD s) { return A.Level(ToBodyL(pa, ToWorldL(pb, B.Surface(s, L)))); };
	std::vector<LD> value(N);
	for (int k = 0; k < N; ++k)
	{
		const V p{stretch.x * curve->point[k].x, stretch.y * curve->point[k].y};
		value[k] = A.Level(ToBodyL(pa, ToWorldL(pb, p)));
	}
	std::vector<int> minima;
	for (int k = 0; k < N; ++k)
		if (value[k] <= value[(k + N - 1) % N] && value[k] < value[(k + 1) % N])
			minima.push_back(k);
	std::sort(minima.begin(), minima.end(), [&](int i, int j) { return value[i] < value[j]; });
	if (int(minima.size()) > candidates)
		minima.resize(candidates);
	std::vector<std::pair<LD, LD>> polished; // (value, s)
	for (int k : minima)
	{
		const LD lo = curve->s[k] - 4.0L / N, hi = curve->s[k] + 4.0L / N;
		const auto r = Minimise1D(f, lo, hi);
		polished.push_back({r.second, r.first});
	}
	for (int c = 0; c < 4; ++c)
		polished.push_back({f(LD(c)), LD(c)});
	std::sort(polished.begin(), polished.end());
	SurfaceMinResult out;
	out.value = polished[0].first;
	out.s = polished[0].second;
	out.point = ToWorldL(pb, B.Surface(out.s, L));
	// Minimise1D fixes s to the square root of the values' rounding; the point is polished on
	// the Lagrange system (s, which only locates it on the curve, is left as found). Where the
	// minimum is a kink (the heart's |x|^{2/3} valley along its axis) there is no Lagrange point,
	// and Newton's steps end beside it on a higher value: the polish is kept only where the
	// value is as low, to the rounding of the values (1e-14 of it).
	const V exact = polish ? PolishLagrange(A, pa, B, pb, out.point, false, L) : out.point;
	const LD exactValue = A.Level(ToBodyL(pa, exact));
	if ((exact.x != out.point.x || exact.y != out.point.y) && exactValue <= out.value + 1e-14L * std::fabs(out.value))
	{
		out.point = exact;
		out.value = exactValue;
	}
	// The next local minimum that is a different place on the curve (not the same one found twice).
	for (size_t i = 1; i < polished.size(); ++i)
	{
		LD gap = std::fabs(polished[i].second - out.s);
		gap = std::min(gap, 4.0L - gap);
		if (gap > 16.0L / N)
		{
			out.secondValue = polished[i].first;
			break;
		}
	}
	return out;
}

/// Result of a common-level reference.
struct CommonLevelResult
{
	LD level = 0.0L; ///< C
	V point;         ///< the common point (on B's level-C surface)
};

/// Common level of two convex superellipse-family shapes: the root of h(L) = G(L) − L with
/// G(L) = min of λA over B's solid level-L set, i.e. 0 (λA at A's centre) when A's centre lies
/// in B_L, else the surface minimum. G decreases, so h has one root; the Illinois method on
/// log L keeps a bracket and converges superlinearly. For convex shapes (superellipses with
/// n, m ≥ 1); λA restricted to B's surface has one minimum near the answer, so three polished
/// candidates are plenty.
inline CommonLevelResult CommonLevelRef(const RefShape& A, const RefPose& pa, const RefShape& B, const RefPose& pb,
                                        int count = 2048)
{
	const LD centreA = B.Level(ToBodyL(pb, pa.p)); // B's level at A's centre
	const Curve unit = SampleCurve(B, 1.0L, count);
	auto h = [&](LD logL) {
		const LD L = std::exp(logL);
		if (centreA <= L) return -L;
		// (Unpolished: only the value counts here, which the polish moves by its rounding.)
		return SurfaceMin(A, pa, B, pb, L, count, 3, &unit, false).value - L;
	};
	// Bracket in log L by steps of 4: h > 0 at small L (A's level on a tiny B is large), h < 0
	// at large L (B's level set swallows A's centre).
	LD lo = 0.0L, hlo = h(lo), hi = lo, hhi = hlo;
	if (hlo > 0)
		while (hhi > 0) { lo = hi; hlo = hhi; hi += 4.0L; hhi = h(hi); }
	else
		while (hlo <= 0) { hi = lo; hhi = hlo; lo -= 4.0L; hlo = h(lo); }
	int side = 0;
	// A bracket of 1e-16 in log L is a relative 1e-16 in C, beyond what any test asks.
	for (int it = 0; it < 200 && hi - lo > 1e-16L; ++it)
	{
		LD x = (lo * hhi - hi * hlo) / (hhi - hlo);
		if (!(x > lo && x < hi)) x = 0.5L * (lo + hi);
		const LD hx = h(x);
		if (hx == 0) { lo = hi = x; break; }
		if (hx > 0)
		{
			lo = x; hlo = hx;
			if (side == 1) hhi *= 0.5L;
			side = 1;
		}
		else
		{
			hi = x; hhi = hx;
			if (side == -1) hlo *= 0.5L;
			side = -1;
		}
	}
	CommonLevelResult r;
	const LD logC = 0.5L * (lo + hi);
	r.level = std::exp(logC);
	r.point = SurfaceMin(A, pa, B, pb, r.level, count, 3, &unit).point;
	r.point = PolishLagrange(A, pa, B, pb, r.point, true);
	return r;
}

// ---------------------------------------------------------------------------------------------
// Ellipses: quadratic forms F(X) = (X − c)ᵀ M (X − c), M = R diag(1/a², 1/b²) Rᵀ.
// ---------------------------------------------------------------------------------------------

struct Quad
{
	LD a = 1.0L, b = 1.0L;             // semi-axes
	RefPose pose;                      // placement
	LD m11 = 1.0L, m12 = 0.0L, m22 = 1.0L; // world matrix M (used only for the 2×2 solve)
	V c;                               // centre
	// F and ∇F are evaluated through body coordinates, x = Rᵀ(X − c): in world coordinates the
	// quadratic form of a 1000:1 ellipse cancels terms ~1e5 times larger than its value.
	LD F(V X) const
	{
		const V x = ToBodyL(pose, X);
		return (x.x / a) * (x.x / a) + (x.y / b) * (x.y / b);
	}
	V Grad(V X) const
	{
		const V x = ToBodyL(pose, X);
		return RotateL(pose, V{2.0L * x.x / (a * a), 2.0L * x.y / (b * b)});
	}
};

inline Quad QuadOf(LD a, LD b, const RefPose& p)
{
	const LD ia = 1.0L / (a * a), ib = 1.0L / (b * b);
	Quad q;
	q.a = a;
	q.b = b;
	q.pose = p;
	q.m11 = p.c * p.c * ia + p.s * p.s * ib;
	q.m22 = p.s * p.s * ia + p.c * p.c * ib;
	q.m12 = p.c * p.s * (ia - ib);
	q.c = p.p;
	return q;
}

/// X(μ) = argmin F_A + μ F_B = c_A + (M_A + μ M_B)^{-1} μ M_B (c_B − c_A).
inline V PwPoint(const Quad& A, const Quad& B, LD mu)
{
	const LD s11 = A.m11 + mu * B.m11, s12 = A.m12 + mu * B.m12, s22 = A.m22 + mu * B.m22;
	const V d = B.c - A.c;
	const V r{mu * (B.m11 * d.x + B.m12 * d.y), mu * (B.m12 * d.x + B.m22 * d.y)};
	const LD det = s11 * s22 - s12 * s12;
	return A.c + V{(s22 * r.x - s12 * r.y) / det, (s11 * r.y - s12 * r.x) / det};
}

/// The unit normal of the Perram–Wertheim contact at multiplier μ, from the shapes' matrices
/// alone: H·x = μ·M_B·d (x the point's offset from A's centre, d = c_B − c_A, H = M_A + μM_B)
/// gives ∇F_A = 2M_A·x = 2μ·M_A·H⁻¹·M_B·d = 2μ·(Σ_B + μΣ_A)⁻¹·d, with Σ = M⁻¹ = R·diag(a², b²)·Rᵀ
/// (M_A·H⁻¹·M_B = (M_B⁻¹·H·M_A⁻¹)⁻¹). A gradient evaluated at the point instead turns with the
/// point's rounding by up to (a/b)² where the point lies near both centres of crossing needles:
/// at such a 1000:1 pose (common level 5.5e-12) ∇F_B there was 1.1e-10 off in long double, and
/// the mean of the two unit normals, which b2a_bench_pairs' reference took, 5.5e-11 (the
/// library's double answer: 5e-17, by a 60-digit check), while Σ_B + μΣ_A is well-conditioned.
inline V PwNormal(const Quad& A, const Quad& B, LD mu)
{
	auto sigma = [](const Quad& q, LD& s11, LD& s12, LD& s22) {
		const LD a2 = q.a * q.a, b2 = q.b * q.b, c = q.pose.c, s = q.pose.s;
		s11 = c * c * a2 + s * s * b2;
		s22 = s * s * a2 + c * c * b2;
		s12 = c * s * (a2 - b2);
	};
	LD a11, a12, a22, b11, b12, b22;
	sigma(A, a11, a12, a22);
	sigma(B, b11, b12, b22);
	const LD k11 = b11 + mu * a11, k12 = b12 + mu * a12, k22 = b22 + mu * a22;
	const V d = B.c - A.c;
	return Unit(V{k22 * d.x - k12 * d.y, k11 * d.y - k12 * d.x}); // adj(K)·d: det K > 0 drops out
}

struct PwResult
{
	LD level = 0.0L; ///< common level C (F_A = F_B = C at the point)
	V point;         ///< the common point
	LD mu = 0.0L;    ///< multiplier (∇F_A + μ∇F_B = 0)
	V normal;        ///< the unit normal, ∇F_A's direction at the exact point (PwNormal)
};

/// Perram–Wertheim common level of two ellipses: S(μ) = min_X (F_A + μF_B)/(1 + μ) is concave
/// in λ = μ/(1+μ) and its maximum is where F_A(X(μ)) = F_B(X(μ)); that difference increases
/// with ν = log μ, so a bisection in ν (to long-double resolution) finds it.
inline PwResult PerramWertheim(const Quad& A, const Quad& B)
{
	auto g = [&](LD nu) { const V X = PwPoint(A, B, std::exp(nu)); return A.F(X) - B.F(X); };
	LD lo = -1.0L, hi = 1.0L;
	while (g(lo) > 0) lo *= 2.0L;
	while (g(hi) < 0) hi *= 2.0L;
	for (int i = 0; i < 200; ++i)
	{
		const LD mid = 0.5L * (lo + hi);
		if (mid == lo || mid == hi) break;
		if (g(mid) < 0) lo = mid; else hi = mid;
	}
	PwResult r;
	const LD nu = 0.5L * (lo + hi);
	r.mu = std::exp(nu);
	r.point = PwPoint(A, B, r.mu);
	// S = (F_A + μF_B)/(1 + μ) at X(μ) is stationary in X (X minimises F_A + μF_B) and in μ
	// (the maximum over μ), so rounding in X and μ enters C only at second order.
	r.level = (A.F(r.point) + r.mu * B.F(r.point)) / (1.0L + r.mu);
	r.normal = PwNormal(A, B, r.mu);
	return r;
}

/// The smallest F_A over B's own surface F_B = 1 when A's centre is outside B: the Lagrange
/// point X(μ) with μ > 0 and F_B(X(μ)) = 1 (F_B(X(μ)) decreases from F_B(c_A) > 1 to 0).
inline PwResult EllipseScaleRef(const Quad& A, const Quad& B)
{
	auto g = [&](LD nu) { return B.F(PwPoint(A, B, std::exp(nu))) - 1.0L; };
	LD lo = -1.0L, hi = 1.0L;
	while (g(lo) < 0) lo *= 2.0L;
	while (g(hi) > 0) hi *= 2.0L;
	for (int i = 0; i < 200; ++i)
	{
		const LD mid = 0.5L * (lo + hi);
		if (mid == lo || mid == hi) break;
		if (g(mid) > 0) lo = mid; else hi = mid;
	}
	PwResult r;
	r.mu = std::exp(0.5L * (lo + hi));
	r.point = PwPoint(A, B, r.mu);
	// The 2×2 solve of a thin pair is ill-conditioned (~1e6), so X(μ) misses B's surface by
	// rounding noise that μ·(F_B − 1) turns into a first-order error of F_A. Project X back onto
	// F_B = 1 along ∇F_B (two Newton steps); the remaining tangential error is second order in F_A.
	for (int k = 0; k < 2; ++k)
	{
		const V gb = B.Grad(r.point);
		r.point = r.point - ((B.F(r.point) - 1.0L) / Dot(gb, gb)) * gb;
	}
	r.level = A.F(r.point);
	r.normal = Unit(A.Grad(r.point));
	return r;
}

/// Roots s1 ≤ s2 of F(X + s·n) = 1 (the line meets the ellipse); false when it misses.
inline bool LineEllipse(const Quad& q, V X, V n, LD& s1, LD& s2)
{
	// In body coordinates (no cancellation): F(x + s·u) = A s² + 2B s + F(x).
	const V d = ToBodyL(q.pose, X);
	const V u = ToBodyL(RefPose{V{}, q.pose.c, q.pose.s}, n);
	const LD A = (u.x / q.a) * (u.x / q.a) + (u.y / q.b) * (u.y / q.b);
	const LD B = d.x * u.x / (q.a * q.a) + d.y * u.y / (q.b * q.b); // half the linear term
	const LD C = q.F(X) - 1.0L;
	const LD disc = B * B - A * C;
	if (disc < 0) return false;
	const LD sq = std::sqrt(disc);
	// Stable form: q = −(B + sgn(B)·sq); roots q/A and C/q.
	const LD qq = -(B + (B >= 0 ? sq : -sq));
	LD r1 = qq / A, r2 = qq != 0 ? C / qq : -r1;
	if (r1 > r2) std::swap(r1, r2);
	s1 = r1;
	s2 = r2;
	return true;
}

/// Contact of two ellipses built from the reference common point and normal exactly as
/// ContactResult documents it: pointA where the line X + s·n meets A's surface on the side it
/// leaves (X inside A) or first enters (X outside), which is the larger root for A; pointB the
/// smaller root for B; where the line misses a particle on that side, the documented fallback:
/// the surface point on the ray from its centre towards X, c + (X − c)/√F(X). The separation is
/// (pointB − pointA)·n.
struct EllipseContactRef
{
	PwResult level;
	V pointA, pointB;
	LD separation = 0.0L;
	bool fallbackA = false, fallbackB = false;
	bool lineHitsBoth = false;
};
inline EllipseContactRef EllipseContact(const Quad& A, const Quad& B)
{
	EllipseContactRef r;
	r.level = PerramWertheim(A, B);
	const V X = r.level.point, n = r.level.normal;
	LD a1 = 0, a2 = 0, b1 = 0, b2 = 0;
	const bool ha = LineEllipse(A, X, n, a1, a2);
	const bool hb = LineEllipse(B, X, n, b1, b2);
	const bool inA = A.F(X) <= 1.0L, inB = B.F(X) <= 1.0L;
	r.fallbackA = !(ha && (inA ? a2 >= 0 : a2 <= 0));
	r.fallbackB = !(hb && (inB ? b1 <= 0 : b1 >= 0));
	r.lineHitsBoth = !r.fallbackA && !r.fallbackB;
	r.pointA = r.fallbackA ? A.c + (1.0L / std::sqrt(A.F(X))) * (X - A.c) : X + a2 * n;
	r.pointB = r.fallbackB ? B.c + (1.0L / std::sqrt(B.F(X))) * (X - B.c) : X + b1 * n;
	r.separation = Dot(r.pointB - r.pointA, n);
	return r;
}

} // namespace b2a::test::ref

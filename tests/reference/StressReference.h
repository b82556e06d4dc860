// b2analytic reference library: long-double checks of contact answers from the shapes' formulas,
// for the stress benchmark.
//
// Nothing here calls the library's level, gradient, radius, support or solver functions: the
// shapes are ref::RefShape (ContactReference.h), evaluated in long double, and only
// the poses' stored cosine and sine are taken from the library (ref::Of). What is here:
//  - WorldDeriv: value, gradient and Hessian of a level function from its formula (the
//    reference's BodyDeriv and WorldDeriv, ContactReference.h, at a Posed);
//  - Support: the point of a level set with a given outward normal (closed form for
//    superellipses, a scan and a golden search over the polar angle for the heart's hull);
//  - Polish: Newton on the optimality conditions of a level problem, in long double;
//  - ResidualStep: one such Newton step from a solver's answer (the cheap independent check);
//  - LineExtreme, OverlapDepth: the contact points on the normal line and the coincident-centre
//    overlap depth, as ContactResult documents them.
#pragma once

#include "ContactReference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace b2a::stress
{

namespace ref = test::ref;
using ref::LD;
using ref::RefPose;
using ref::RefShape;
using ref::V;
using ref::Deriv;
using ref::BodyDeriv;
using ref::PowZ;
using ref::Sign;

/// A shape at a placement, both in long double.
struct Posed
{
	RefShape shape; ///< the shape's formula
	RefPose pose;   ///< its placement
};

/// World-frame derivatives at a world point (ref::WorldDeriv).
inline Deriv WorldDeriv(const Posed& p, V X) { return ref::WorldDeriv(p.shape, p.pose, X); }

/// Hessian times a vector.
inline V HessTimes(const Deriv& d, V v) { return {d.hxx * v.x + d.hxy * v.y, d.hxy * v.x + d.hyy * v.y}; }

/// Counter-clockwise perpendicular.
inline V PerpL(V v) { return {-v.y, v.x}; }

/// A world point from its body point (V) under a pose.
inline V World(const Posed& p, V x) { return ref::ToWorldL(p.pose, x); }

/// The level at which a world point lies.
inline LD LevelAt(const Posed& p, V X) { return p.shape.Level(ref::ToBodyL(p.pose, X)); }

/// The body direction of a world direction.
inline V BodyDir(const RefPose& p, V d) { return {p.c * d.x + p.s * d.y, -p.s * d.x + p.c * d.y}; }

// ---------------------------------------------------------------------------------------------
// Support points
// ---------------------------------------------------------------------------------------------

/// A point of a level set with a given outward normal (its support point in that direction).
struct SupportPoint
{
	V x;                 ///< body point
	bool corner = false; ///< the heart's tip (no gradient there; the normal is any of a cone)
	LD margin = 0.0L;    ///< heart: how much farther along d the point is than any other local maximum
};

/// Superellipse support at level L in the unit body direction d. Lagrange: d ∝ ∇λ gives
/// |x/a| = u = (|d_x| a / (t n))^{1/(n−1)}, |y/b| = v = (|d_y| b / (t m))^{1/(m−1)}; with
/// σ = −log t, u^n + v^m = exp(n(α_x + σ)/(n−1)) + exp(m(α_y + σ)/(m−1)), α = log(|d_x| a / n),
/// increases and is convex in σ, so Newton from the right of the root (σ where the larger term
/// alone equals L) converges monotonically.
inline SupportPoint SuperSupport(const RefShape& s, LD L, V d)
{
	const bool hx = d.x != 0.0L, hy = d.y != 0.0L;
	const LD ax = hx ? std::log(std::fabs(d.x) * s.a / s.n) : 0.0L;
	const LD ay = hy ? std::log(std::fabs(d.y) * s.b / s.m) : 0.0L;
	const LD kx = s.n / (s.n - 1.0L), ky = s.m / (s.m - 1.0L);
	const LD logL = std::log(L);
	LD sigma = std::numeric_limits<LD>::infinity();
	if (hx) sigma = std::min(sigma, logL / kx - ax);
	if (hy) sigma = std::min(sigma, logL / ky - ay);
	auto terms = [&](LD sg, LD& tx, LD& ty) {
		tx = hx ? std::exp(kx * (ax + sg)) : 0.0L;
		ty = hy ? std::exp(ky * (ay + sg)) : 0.0L;
	};
	for (int it = 0; it < 200; ++it)
	{
		LD tx, ty;
		terms(sigma, tx, ty);
		const LD step = (tx + ty - L) / (kx * tx + ky * ty);
		sigma -= step;
		// Quadratic convergence: after a step of 1e-17 the error is far below rounding (which
		// would keep a tighter test stepping back and forth for ever).
		if (!(std::fabs(step) > 1e-17L * (1.0L + std::fabs(sigma))))
			break;
	}
	LD tx, ty;
	terms(sigma, tx, ty);
	// u = tx^{1/n}, v = ty^{1/m}.
	SupportPoint p;
	p.x = {hx ? Sign(d.x) * s.a * std::exp(std::log(tx) / s.n) : 0.0L, hy ? Sign(d.y) * s.b * std::exp(std::log(ty) / s.m) : 0.0L};
	p.margin = std::numeric_limits<LD>::infinity();
	return p;
}

/// The heart's level-L radius along the unit body direction (ux, uy): w = r^{1/3} solves
/// w⁶ − k w⁵ = L with k = cbrt(ux² uy³) (one positive root, docs/method.md, "Shape functions and levels"). From w₀ = |k| + L^{1/6}
/// (`root6` = L^{1/6}), where the left side is ≥ L, Newton decreases monotonically: the function
/// is convex for w > 2k/3, and the root exceeds k.
inline LD HeartRadius(LD ux, LD uy, LD L, LD root6)
{
	const LD k = std::cbrt(ux * ux * uy * uy * uy);
	LD w = std::fabs(k) + root6;
	for (int it = 0; it < 200; ++it)
	{
		const LD w4 = w * w * w * w;
		const LD step = (w4 * w * (w - k) - L) / (w4 * (6.0L * w - 5.0L * k));
		w -= step;
		if (!(step > 1e-17L * w))
			break;
	}
	return w * w * w;
}

/// Heart body point at polar angle θ on the level-L set.
inline V HeartPoint(LD theta, LD L, LD root6)
{
	const LD ux = std::cos(theta), uy = std::sin(theta);
	const LD r = HeartRadius(ux, uy, L, root6);
	return {r * ux, r * uy};
}

/// Maximiser of f on [lo, hi] (unimodal there) by golden section to 1e-13 in the argument: a
/// start for the long-double Newton of Polish, which needs no more.
template <class F>
LD GoldenMax(F&& f, LD lo, LD hi)
{
	const LD g = 0.6180339887498948482045868343656381L;
	LD x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
	for (int i = 0; i < 100 && hi - lo > 1e-13L; ++i)
	{
		if (f1 >= f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = f(x1); }
		else { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = f(x2); }
	}
	return f1 >= f2 ? x1 : x2;
}

/// Heart support at level L in the unit body direction d (the support of its convex hull):
/// 128 polar angles, the three highest local maxima of d·X(θ) polished by golden section, and
/// the tip (0, −√L) as an exact candidate. `margin` is the lead of the best over the second-best
/// distinct local maximum, relative to √L: where it is tiny the support jumps between two places
/// (across the notch, or between the tip and a lobe) and a pair built there has two near-equal
/// contacts.
inline SupportPoint HeartSupport(LD L, V d)
{
	constexpr int N = 128;
	struct Table
	{
		LD c[N], s[N];
		Table()
		{
			for (int k = 0; k < N; ++k)
			{
				c[k] = std::cos(-ref::kPiL + 2.0L * ref::kPiL * k / N);
				s[k] = std::sin(-ref::kPiL + 2.0L * ref::kPiL * k / N);
			}
		}
	};
	static const Table table;
	const LD step = 2.0L * ref::kPiL / N, root6 = std::pow(L, 1.0L / 6.0L);
	LD value[N];
	for (int k = 0; k < N; ++k)
		value[k] = HeartRadius(table.c[k], table.s[k], L, root6) * (d.x * table.c[k] + d.y * table.s[k]);
	std::vector<int> peaks;
	for (int k = 0; k < N; ++k)
		if (value[k] >= value[(k + N - 1) % N] && value[k] > value[(k + 1) % N])
			peaks.push_back(k);
	std::sort(peaks.begin(), peaks.end(), [&](int i, int j) { return value[i] > value[j]; });
	if (peaks.size() > 3)
		peaks.resize(3);
	auto f = [&](LD t) { const V x = HeartPoint(t, L, root6); return d.x * x.x + d.y * x.y; };
	std::vector<std::pair<LD, V>> maxima; // (d·x, x)
	for (int k : peaks)
	{
		const LD t = GoldenMax(f, -ref::kPiL + step * (k - 1), -ref::kPiL + step * (k + 1));
		maxima.push_back({f(t), HeartPoint(t, L, root6)});
	}
	const V tip{0.0L, -std::sqrt(L)};
	maxima.push_back({d.y * tip.y, tip});
	std::sort(maxima.begin(), maxima.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
	SupportPoint p;
	p.x = maxima[0].second;
	// The golden search reaches the tip only to its argument resolution; a candidate that close
	// to it is the tip.
	const LD scale = std::sqrt(L);
	p.corner = ref::Len(p.x - tip) < 1e-9L * scale;
	if (p.corner)
		p.x = tip;
	p.margin = std::numeric_limits<LD>::infinity();
	for (size_t i = 1; i < maxima.size(); ++i)
		if (ref::Len(maxima[i].second - p.x) > 1e-6L * scale)
		{
			p.margin = (maxima[0].first - maxima[i].first) / scale;
			break;
		}
	return p;
}

/// Support point of either kind.
inline SupportPoint Support(const RefShape& s, LD L, V d)
{
	return s.kind == RefShape::Kind::heart ? HeartSupport(L, d) : SuperSupport(s, L, d);
}

// ---------------------------------------------------------------------------------------------
// The optimality conditions of the level problems
// ---------------------------------------------------------------------------------------------

/// Which level problem: the common level (λA = λB = C) or A's one-sided scale onto B's own
/// surface (λA = L, λB = B's own level).
enum class Problem { common, scaleA };

/// A solution (X, L) of a level problem with its normal, and how it was reached.
struct LevelSolution
{
	V point;              ///< X (world)
	LD level = 0.0L;      ///< C, or A's level L
	V normal;             ///< unit ∇λA at X (from A to B)
	LD lastStep = 0.0L;   ///< size of the last Newton correction of X (its uncertainty), world units
	LD curvature = 0.0L;  ///< κA + κB at X: the point along the tangent is determined to ~eps/(κA + κB)
	bool ok = false;      ///< Newton converged with opposed gradients
};

/// The residual of the conditions at (X, L) and the Newton correction (ΔX, ΔL) that zeroes it to
/// first order:
///   F₁ = λA(X) − L,  F₂ = λB(X) − (C or B's own level),  F₃ = (∇λA × ∇λB)/(|∇λA||∇λB|),
/// with the Jacobian rows (∇λA, −1), (∇λB, −1 or 0) and
///   ∇F₃ = [HA (∇λB)⊥' − HB (∇λA)⊥'] / (|∇λA||∇λB|),  v⊥' = (v_y, −v_x),
/// (the derivative of the normalisation multiplies F₃ and vanishes at a solution). Solved with
/// the columns scaled to the pair's size and to L, rows by their magnitudes, partial pivoting.
struct NewtonStep
{
	V dX;                  ///< correction of the point
	LD dL = 0.0L;          ///< correction of the level
	bool opposed = false;  ///< ∇λA · ∇λB < 0 at X
	bool finite = false;   ///< the step is finite (the Jacobian was not singular)
	LD curvature = 0.0L;   ///< κA + κB at X
};

inline NewtonStep LevelNewtonStep(const Posed& A, const Posed& B, Problem problem, V X, LD L, LD size)
{
	const Deriv a = WorldDeriv(A, X), b = WorldDeriv(B, X);
	const LD ga = ref::Len(a.grad), gb = ref::Len(b.grad);
	NewtonStep s;
	s.opposed = ref::Dot(a.grad, b.grad) < 0.0L;
	if (!(ga > 0.0L) || !(gb > 0.0L))
		return s;
	const V t = PerpL((1.0L / ga) * a.grad);
	s.curvature = std::fabs(ref::Dot(t, HessTimes(a, t))) / ga + std::fabs(ref::Dot(t, HessTimes(b, t))) / gb;
	const LD target = problem == Problem::common ? L : B.shape.Own();
	const V r3 = (1.0L / (ga * gb)) * (HessTimes(a, V{b.grad.y, -b.grad.x}) - HessTimes(b, V{a.grad.y, -a.grad.x}));
	// Unknowns scaled: ΔX = size·p, ΔL = L·q.
	LD M[3][4] = {
		{a.grad.x * size, a.grad.y * size, -L, -(a.value - L)},
		{b.grad.x * size, b.grad.y * size, problem == Problem::common ? -L : 0.0L, -(b.value - target)},
		{r3.x * size, r3.y * size, 0.0L, -ref::Cross(a.grad, b.grad) / (ga * gb)},
	};
	for (int i = 0; i < 3; ++i)
	{
		const LD norm = std::max({std::fabs(M[i][0]), std::fabs(M[i][1]), std::fabs(M[i][2])});
		if (norm > 0.0L)
			for (int j = 0; j < 4; ++j) M[i][j] /= norm;
	}
	for (int c = 0; c < 3; ++c)
	{
		int piv = c;
		for (int i = c + 1; i < 3; ++i)
			if (std::fabs(M[i][c]) > std::fabs(M[piv][c])) piv = i;
		if (!(std::fabs(M[piv][c]) > std::numeric_limits<LD>::min()))
			return s;
		for (int j = 0; j < 4; ++j) std::swap(M[c][j], M[piv][j]);
		for (int i = c + 1; i < 3; ++i)
		{
			const LD f = M[i][c] / M[c][c];
			for (int j = c; j < 4; ++j) M[i][j] -= f * M[c][j];
		}
	}
	LD z[3];
	for (int i = 2; i >= 0; --i)
	{
		LD acc = M[i][3];
		for (int j = i + 1; j < 3; ++j) acc -= M[i][j] * z[j];
		z[i] = acc / M[i][i];
	}
	s.dX = {size * z[0], size * z[1]};
	s.dL = L * z[2];
	s.finite = std::isfinite(z[0]) && std::isfinite(z[1]) && std::isfinite(z[2]);
	return s;
}

/// Newton on the conditions from (X, L) (a constructed solution of nearly the same pair): at
/// most 8 steps, stopping when the correction of X is below 1e-18 of the size. Converged when a
/// further step would move X by less than 1e-15 of the size (plus 1e-16/(κA + κB), the long-double
/// noise along a flat contact, still far below double's 2e-16/(κA + κB)) and L by less than 1e-15
/// of itself, with opposed gradients. (The residual is no test: at a sharp tip, κ·size ~ 1e6, the
/// normals' angle changes by 1e6 times any rounding of X.)
inline LevelSolution Polish(const Posed& A, const Posed& B, Problem problem, V X, LD L, LD size)
{
	LevelSolution sol;
	sol.point = X;
	sol.level = L;
	for (int it = 0; it < 8; ++it)
	{
		const NewtonStep s = LevelNewtonStep(A, B, problem, sol.point, sol.level, size);
		if (!s.finite)
			return sol;
		sol.point = sol.point + s.dX;
		sol.level += s.dL;
		sol.lastStep = ref::Len(s.dX);
		sol.curvature = s.curvature;
		if (sol.lastStep <= 1e-18L * size && std::fabs(s.dL) <= 1e-18L * sol.level)
			break;
	}
	const NewtonStep check = LevelNewtonStep(A, B, problem, sol.point, sol.level, size);
	sol.ok = check.finite && check.opposed && ref::Len(check.dX) <= 1e-15L * size + 1e-16L / check.curvature &&
	         std::fabs(check.dL) <= 1e-15L * sol.level;
	sol.normal = ref::Unit(WorldDeriv(A, sol.point).grad);
	return sol;
}

/// Polish of the common level in one particle's body frame (`inB`: B's, else A's), from X with
/// that particle's coordinate across its thinner level set (the axis of smaller extent at the
/// other's level C there, a·C^{1/n} or b·C^{1/m}) set so that its level is C too, on the side
/// where the other's level falls; the answer in world terms. Needles crossing deep inside each
/// other (levels 1e-30 to 1e-9) have level sets 1e-15 of their size thick, which long-double
/// world coordinates of 1e3 sizes hold to a tenth, and a particle's own frame exactly.
inline LevelSolution PolishInFrame(const Posed& A, const Posed& B, V X, LD L, LD size, bool inB)
{
	const RefPose f = (inB ? B : A).pose;
	auto in = [&](const RefPose& q) { return RefPose{ref::ToBodyL(f, q.p), f.c * q.c + f.s * q.s, f.c * q.s - f.s * q.c}; };
	const Posed A1{A.shape, in(A.pose)}, B1{B.shape, in(B.pose)};
	const RefShape& s = (inB ? B : A).shape;
	const Posed& other = inB ? A1 : B1;
	V x = ref::ToBodyL(f, X);
	const LD C = LevelAt(other, x);
	const V g = WorldDeriv(other, x).grad;
	if (s.kind == RefShape::Kind::superellipse && C > 0.0L && std::isfinite(C))
	{
		if (s.a * std::pow(C, 1.0L / s.n) <= s.b * std::pow(C, 1.0L / s.m))
		{
			const LD rest = C - std::pow(std::fabs(x.y) / s.b, s.m);
			if (rest > 0.0L)
				x.x = -std::copysign(s.a * std::pow(rest, 1.0L / s.n), g.x);
		}
		else
		{
			const LD rest = C - std::pow(std::fabs(x.x) / s.a, s.n);
			if (rest > 0.0L)
				x.y = -std::copysign(s.b * std::pow(rest, 1.0L / s.m), g.y);
		}
	}
	// Polish's own test does not see a needle's tip, whose normal turns over 1e-24 of the size:
	// solved here means the normals opposed to 1e-12 rad in the frame.
	auto opposed = [&](V at) {
		const V na = ref::Unit(WorldDeriv(A1, at).grad), nb = ref::Unit(WorldDeriv(B1, at).grad);
		return std::atan2(std::fabs(ref::Cross(na, nb)), -ref::Dot(na, nb)) <= 1e-12L;
	};
	LevelSolution sol = Polish(A1, B1, Problem::common, x, L, size);
	for (int k = 0; k < 30 && !(sol.ok && opposed(sol.point)) && std::isfinite(sol.level); ++k)
		sol = Polish(A1, B1, Problem::common, sol.point, sol.level, size);
	sol.ok = sol.ok && opposed(sol.point);
	sol.point = ref::ToWorldL(f, sol.point);
	sol.normal = ref::RotateL(f, sol.normal);
	return sol;
}

/// PolishInFrame in the frame of the superellipse whose level set at L is the thinner (the
/// smaller of a·L^{1/n}, b·L^{1/m}).
inline LevelSolution PolishInThinFrame(const Posed& A, const Posed& B, V X, LD L, LD size)
{
	auto thin = [&](const RefShape& s) { return std::min(s.a * std::pow(L, 1.0L / s.n), s.b * std::pow(L, 1.0L / s.m)); };
	return PolishInFrame(A, B, X, L, size, thin(B.shape) < thin(A.shape));
}

/// The solution of a one-sided scale (problem scaleA) at one heart's tip, A's or B's (not both),
/// for the placements as given: a pair is built around a tip in long double and its centres are
/// then rounded to double, which moves the tip by ~1e-16 of the centres' coordinates, and beside
/// a needle (curvature 1e8 to 1e9 of its size) that turns the contact normal by ~1e-6 rad.
/// At B's tip T (fixed, B at its own level): L = λA(T), the normal A's gradient there. At A's
/// tip T(L) = A's body point (0, −√L): Newton on λB(T(L)) = B's own level from L, the normal
/// B's inward one. Not ok when Newton does not settle (to 1e-18 of L) in 30 steps.
inline LevelSolution PolishTip(const Posed& A, const Posed& B, bool tipOfA, LD L)
{
	LevelSolution sol;
	if (!tipOfA)
	{
		sol.point = World(B, V{0.0L, -std::sqrt(B.shape.Own())});
		sol.level = LevelAt(A, sol.point);
		sol.normal = ref::Unit(WorldDeriv(A, sol.point).grad);
		sol.ok = std::isfinite(sol.level) && sol.level > 0.0L;
		return sol;
	}
	const LD own = B.shape.Own();
	for (int it = 0; it < 30 && !sol.ok; ++it)
	{
		const LD r = std::sqrt(L);
		const V T = World(A, V{0.0L, -r});
		const Deriv b = WorldDeriv(B, T);
		// dT/dL = A's body direction (0, −1/(2√L)) in the world.
		const V dT = ref::RotateL(A.pose, V{0.0L, -0.5L / r});
		const LD slope = ref::Dot(b.grad, dT);
		const LD step = (b.value - own) / slope;
		if (!std::isfinite(step) || !(L - step > 0.0L))
			return sol;
		L -= step;
		sol.ok = std::fabs(step) <= 1e-18L * L;
	}
	sol.level = L;
	sol.point = World(A, V{0.0L, -std::sqrt(L)});
	const V nb = ref::Unit(WorldDeriv(B, sol.point).grad);
	sol.normal = V{-nb.x, -nb.y};
	return sol;
}

// ---------------------------------------------------------------------------------------------
// Contact points on the normal line, and the coincident-centre overlap depth
// ---------------------------------------------------------------------------------------------

/// Where the line X + s·dir leaves a convex shape's own surface last (largest s), as
/// ContactResult documents pointA (pointB: dir = −n). `grazing` is how close the line comes
/// to missing the shape (own − smallest level on the line, relative to the own level); where
/// the line misses, the documented fallback: the surface point on the ray from the centre
/// towards X. `reach` bounds the shape (its bounding radius).
struct LinePoint
{
	V point;             ///< the surface point
	LD grazing = 0.0L;   ///< 1 − (smallest level on the line)/own: ≤ 0 when the line misses
	bool fallback = false; ///< the line missed: radial point
};

inline LinePoint LineExtreme(const Posed& p, V X, V dir, LD reach)
{
	const LD own = p.shape.Own();
	// s in units of reach, so that Minimise1D sees arguments of order one.
	auto f = [&](LD s) { return LevelAt(p, X + (s * reach) * dir); };
	// Every point of the shape lies within `reach` of its centre, so the crossings lie within
	// [sc − reach, sc + reach] around the centre's projection sc.
	const LD sc = ref::Dot(p.pose.p - X, dir) / reach, lo = sc - 1.01L, hi = sc + 1.01L;
	const auto m = ref::Minimise1D(f, lo, hi);
	LinePoint r;
	r.grazing = 1.0L - m.second / own;
	if (m.second <= own)
	{
		LD a = m.first, b = hi; // f(a) ≤ own < f(b)
		for (int i = 0; i < 200 && b - a > 1e-20L * (1.0L + std::fabs(a) + std::fabs(b)); ++i)
		{
			const LD mid = 0.5L * (a + b);
			if (f(mid) <= own) a = mid; else b = mid;
		}
		r.point = X + (0.5L * (a + b) * reach) * dir;
		return r;
	}
	// Radial fallback: λ increases along every ray from the centre (star-shaped).
	r.fallback = true;
	const V ray = X - p.pose.p;
	const LD len = ref::Len(ray);
	LD a = 0.0L, b = 1.01L * reach / len;
	for (int i = 0; i < 200 && b - a > 1e-21L * b; ++i)
	{
		const LD mid = 0.5L * (a + b);
		if (LevelAt(p, p.pose.p + mid * ray) <= own) a = mid; else b = mid;
	}
	r.point = p.pose.p + (0.5L * (a + b)) * ray;
	return r;
}

/// Width of a shape along a world direction: max of n·(x − centre) over the own surface.
inline LD Width(const Posed& p, V n)
{
	const SupportPoint s = Support(p.shape, p.shape.Own(), BodyDir(p.pose, n));
	return ref::Dot(ref::RotateL(p.pose, s.x), n);
}

/// The overlap of two particles with a common centre along n: hA(n) + hB(−n), the distance B must
/// move along n to separate (the depth that OverlapAxisContact reports as −separation).
inline LD OverlapAlong(const Posed& A, const Posed& B, LD angle)
{
	const V n{std::cos(angle), std::sin(angle)};
	return Width(A, n) + Width(B, V{-n.x, -n.y});
}

/// Smallest overlap over all directions: 256 angles, the four lowest local minima polished by
/// golden section. Returns (depth, angle).
inline std::pair<LD, LD> OverlapDepth(const Posed& A, const Posed& B)
{
	const int N = 256;
	const LD step = 2.0L * ref::kPiL / N;
	std::vector<LD> value(N);
	for (int k = 0; k < N; ++k)
		value[k] = OverlapAlong(A, B, step * k);
	std::vector<int> minima;
	for (int k = 0; k < N; ++k)
		if (value[k] <= value[(k + N - 1) % N] && value[k] < value[(k + 1) % N])
			minima.push_back(k);
	std::sort(minima.begin(), minima.end(), [&](int i, int j) { return value[i] < value[j]; });
	std::pair<LD, LD> best{std::numeric_limits<LD>::infinity(), 0.0L};
	for (size_t i = 0; i < minima.size() && i < 4; ++i)
	{
		const LD t = step * minima[i];
		const auto r = ref::Minimise1D([&](LD a) { return OverlapAlong(A, B, a); }, t - step, t + step);
		if (r.second < best.first) best = {r.second, r.first};
	}
	return best;
}

} // namespace b2a::stress

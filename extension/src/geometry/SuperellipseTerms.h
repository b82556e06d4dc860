// b2analytic: the superellipse's raw level and its derivatives, inline (internal).
#pragma once

#include "b2analytic/SuperellipseShape.h"
#include "numerics/CodeLayout.h"
#include "numerics/Powers.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace b2a
{

/// |t|^e, with e given also as a small integer k (or −1): small integer powers by
/// multiplication, exact to rounding and several times faster than pow. Inline, since the
/// Newton solvers call it for every level they evaluate.
inline double PowAbs(double t, double e, int k)
{
	t = std::fabs(t);
	switch (k)
	{
	case 0: return 1.0;
	case 1: return t;
	case 2: return t * t;
	case 3: return t * t * t;
	case 4: { const double t2 = t * t; return t2 * t2; }
	case 6: { const double t3 = t * t * t; return t3 * t3; }
	case 7: { const double t2 = t * t, t3 = t2 * t; return t3 * t3 * t; }
	case 8: { const double t2 = t * t, t4 = t2 * t2; return t4 * t4; }
	default: break;
	}
	if (k < 0)
		return std::pow(t, e);
	// Exponentiation by squaring.
	double r = 1.0;
	while (k > 0)
	{
		if (k & 1) r *= t;
		t *= t;
		k >>= 1;
	}
	return r;
}

/// −1, 0 or 1.
inline double SignOf(double t) { return t > 0.0 ? 1.0 : (t < 0.0 ? -1.0 : 0.0); }

/// f = |x/a|^n + |y/b|^m at a body point, with its gradient and Hessian (the raw form, before
/// any ζ transform). With X = x/a, Y = y/b:
///   ∂f/∂x = (n/a) sgn(X)|X|^{n−1},  ∂²f/∂x² = n(n−1)/a² |X|^{n−2},  ∂²f/∂x∂y = 0   (same for y).
/// At a point on an axis where an exponent is below 2 the infinite second derivative is reported
/// as 0 (SuperellipseShape's documented convention).
inline LevelDerivatives RawSuperellipseDerivatives(const SuperellipseTerms& t, Vec2 x)
{
	const double X = x.x * t.invA, Y = x.y * t.invB;
	const double ax = std::fabs(X), ay = std::fabs(Y);
	const double xn2 = (t.n < 2.0 && ax == 0.0) ? 0.0 : PowAbs(ax, t.n - 2.0, t.nInt >= 2 ? t.nInt - 2 : -1);
	const double ym2 = (t.m < 2.0 && ay == 0.0) ? 0.0 : PowAbs(ay, t.m - 2.0, t.mInt >= 2 ? t.mInt - 2 : -1);
	const double xn1 = t.n >= 2.0 ? xn2 * ax : PowAbs(ax, t.n - 1.0, t.nInt >= 1 ? t.nInt - 1 : -1);
	const double ym1 = t.m >= 2.0 ? ym2 * ay : PowAbs(ay, t.m - 1.0, t.mInt >= 1 ? t.mInt - 1 : -1);
	LevelDerivatives d;
	d.value = xn1 * ax + ym1 * ay;
	// sgn(X)|X|^{n−1} as copysign where n ≥ 2 (|X|^{n−1} vanishes on the axis, so the sign of
	// zero does not matter there): no branch on the sign.
	d.gradient = Vec2(t.gradX * (t.n >= 2.0 ? std::copysign(xn1, X) : SignOf(X) * xn1),
	                  t.gradY * (t.m >= 2.0 ? std::copysign(ym1, Y) : SignOf(Y) * ym1));
	d.hessian.xx = t.hessX * xn2;
	d.hessian.yy = t.hessY * ym2;
	d.hessian.xy = 0.0;
	return d;
}

/// Whether both exponents are integers of at least 2 (IntegerSuperellipseDerivatives applies):
/// then f is a polynomial in |X| and |Y|, twice differentiable, with no pow and no branch on 2.
inline bool IntegerExponents(const SuperellipseTerms& t) { return t.nInt >= 2 && t.mInt >= 2; }

/// f, ∇f and the diagonal of ∇²f in the shape's own axes (∂²f/∂x∂y = 0).
struct AxisDerivatives
{
	double f, gx, gy, hx, hy;
};

/// RawSuperellipseDerivatives for integer exponents ≥ 2 (IntegerExponents), without its cases for
/// exponents below 2 and real ones: with X = x/a, |X|^{n−2} by multiplication, |X|^{n−1} = that
/// times |X|, f = |X|^n + |Y|^m, ∂f/∂x = (n/a) sgn(X)|X|^{n−1}, ∂²f/∂x² = n(n−1)/a² |X|^{n−2}
/// (the same operations in the same order, so the same values).
inline AxisDerivatives IntegerSuperellipseDerivatives(const SuperellipseTerms& t, double x, double y)
{
	const double X = x * t.invA, Y = y * t.invB;
	const double ax = std::fabs(X), ay = std::fabs(Y);
	const double xn2 = PowAbs(ax, 0.0, t.nInt - 2), ym2 = PowAbs(ay, 0.0, t.mInt - 2);
	const double xn1 = xn2 * ax, ym1 = ym2 * ay;
	return {xn1 * ax + ym1 * ay, t.gradX * std::copysign(xn1, X), t.gradY * std::copysign(ym1, Y), t.hessX * xn2,
	        t.hessY * ym2};
}

#if defined(B2A_SSE2_PAIRS)
/// PowAbs(t, ·, k) of both lanes of t ≥ 0 for one integer k ≥ 0: its products in its order, lane by
/// lane, so that each lane is PowAbs's bit for bit (k = 5 and k > 8 go to PowAbs lane by lane).
inline __m128d PowAbsPair(__m128d t, int k)
{
	switch (k)
	{
	case 0: return _mm_set1_pd(1.0);
	case 1: return t;
	case 2: return _mm_mul_pd(t, t);
	case 3: return _mm_mul_pd(_mm_mul_pd(t, t), t);
	case 4: { const __m128d t2 = _mm_mul_pd(t, t); return _mm_mul_pd(t2, t2); }
	case 6: { const __m128d t3 = _mm_mul_pd(_mm_mul_pd(t, t), t); return _mm_mul_pd(t3, t3); }
	case 7: { const __m128d t2 = _mm_mul_pd(t, t), t3 = _mm_mul_pd(t2, t); return _mm_mul_pd(_mm_mul_pd(t3, t3), t); }
	case 8: { const __m128d t2 = _mm_mul_pd(t, t), t4 = _mm_mul_pd(t2, t2); return _mm_mul_pd(t4, t4); }
	default: break;
	}
	const double t0 = _mm_cvtsd_f64(t), t1 = _mm_cvtsd_f64(_mm_unpackhi_pd(t, t));
	return _mm_set_pd(PowAbs(t1, 0.0, k), PowAbs(t0, 0.0, k));
}
#endif

/// IntegerSuperellipseDerivatives, bit for bit, where n = m (nInt = mInt): the x and y axes in the
/// two lanes of SSE2 registers (each lane's operations are the scalar code's, in its order), one
/// power for both. Half the instructions of the scalar code, in a contact's every Newton step.
inline AxisDerivatives IntegerSuperellipseDerivativesEqual(const SuperellipseTerms& t, double x, double y)
{
#if defined(B2A_SSE2_PAIRS)
	static_assert(offsetof(SuperellipseTerms, invB) == offsetof(SuperellipseTerms, invA) + sizeof(double) &&
	                  offsetof(SuperellipseTerms, gradY) == offsetof(SuperellipseTerms, gradX) + sizeof(double) &&
	                  offsetof(SuperellipseTerms, hessY) == offsetof(SuperellipseTerms, hessX) + sizeof(double),
	              "each pair of terms is two adjacent doubles");
	const __m128d sign = _mm_set1_pd(-0.0);
	const __m128d XY = _mm_mul_pd(_mm_set_pd(y, x), _mm_loadu_pd(&t.invA)); // X = x/a, Y = y/b
	const __m128d a = _mm_andnot_pd(sign, XY);                             // |X|, |Y|
	const __m128d p2 = PowAbsPair(a, t.nInt - 2), p1 = _mm_mul_pd(p2, a); // |X|^{n−2}, |X|^{n−1}
	const __m128d terms = _mm_mul_pd(p1, a);
	const __m128d grad = _mm_mul_pd(_mm_loadu_pd(&t.gradX), _mm_or_pd(p1, _mm_and_pd(sign, XY))); // copysign
	const __m128d hess = _mm_mul_pd(_mm_loadu_pd(&t.hessX), p2);
	AxisDerivatives d;
	d.f = _mm_cvtsd_f64(terms) + _mm_cvtsd_f64(_mm_unpackhi_pd(terms, terms));
	_mm_storeu_pd(&d.gx, grad);
	_mm_storeu_pd(&d.hx, hess);
	return d;
#else
	return IntegerSuperellipseDerivatives(t, x, y);
#endif
}

/// Whether both exponents are at least 2 (SmoothSuperellipseDerivatives applies): f is then
/// twice continuously differentiable, its Hessian finite everywhere.
inline bool SmoothExponents(const SuperellipseTerms& t) { return t.n >= 2.0 && t.m >= 2.0; }

/// An exponent's power |X|^{e−2} as PowAbs takes it: the small integer e − 2 where e is an integer
/// of at least 2 (powers by multiplication), else −1 (std::pow).
inline int PowerBelowTwo(int eInt) { return eInt >= 2 ? eInt - 2 : -1; }

/// IntegerSuperellipseDerivatives for any exponents ≥ 2 (SmoothExponents), integer or real, from
/// one power per axis. With X = x/a and P = |X|^{n−2} (std::pow for a real n, one call, the only
/// transcendental of the evaluation; by multiplication for an integer n):
///   |X|^{n−1} = P·|X|,   |X|^n = P·|X|²,
///   ∂f/∂x = (n/a) sgn(X)|X|^{n−1},   ∂²f/∂x² = n(n−1)/a² · P,
/// so the level, gradient and Hessian all come from the same value P and agree with each other
/// to rounding (no second pow for |X|^{n−1} whose rounding would differ from P·|X|). For n ≥ 2,
/// P is finite (P = 0 on the axis for n > 2, 1 for n = 2), so no case is needed for X = 0; and
/// sgn(X)|X|^{n−1} is copysign, as |X|^{n−1} vanishes there. For integer exponents the values
/// are IntegerSuperellipseDerivatives', bit for bit (the same operations).
inline AxisDerivatives SmoothSuperellipseDerivatives(const SuperellipseTerms& t, double x, double y)
{
	const double X = x * t.invA, Y = y * t.invB;
	const double ax = std::fabs(X), ay = std::fabs(Y);
	const double xn2 = PowAbs(ax, t.n - 2.0, PowerBelowTwo(t.nInt)), ym2 = PowAbs(ay, t.m - 2.0, PowerBelowTwo(t.mInt));
	const double xn1 = xn2 * ax, ym1 = ym2 * ay;
	return {xn1 * ax + ym1 * ay, t.gradX * std::copysign(xn1, X), t.gradY * std::copysign(ym1, Y), t.hessX * xn2,
	        t.hessY * ym2};
}

/// The terms of the same superellipse measured in units of `length` (semi-axes a/length and
/// b/length): f is unchanged at corresponding points, its gradient is `length` times and its
/// Hessian `length²` times the original's. Solvers that work in units of the pair's size use it.
inline SuperellipseTerms ScaledTerms(const SuperellipseTerms& t, double length)
{
	SuperellipseTerms s = t;
	s.invA *= length;
	s.invB *= length;
	s.gradX *= length;
	s.gradY *= length;
	s.hessX *= length * length;
	s.hessY *= length * length;
	return s;
}

/// The far crossing of the surface f = 1 by the body line x + t·d (SuperellipseShape::FarCrossing
/// for exponents other than n = m = 2): Newton on a convex function of t, from where it descends
/// monotonically; false when the line misses or only grazes the particle. `known`, where given,
/// is {f, ∇f·d} at t = 0, which a caller that has them saves an evaluation with.
inline bool SuperellipseFarCrossing(const SuperellipseTerms& s, Vec2 x, Vec2 d, double& t, const double* known = nullptr)
{
	// In scaled coordinates u = X + t·D, v = Y + t·E (X = x/a, D = dx/a, Y = y/b, E = dy/b) the
	// surface is f = |u|^n + |v|^m = 1 in both forms. With p = min(n, m),
	//   g(t) = f^{1/p} − 1 = ‖(|u|^{n/p}, |v|^{m/p})‖_p − 1
	// is convex in t: a p-norm of convex non-negative terms. So Newton descends monotonically onto
	// the far crossing from any point beyond it (g ≥ 0, g' > 0), and from a point inside (g < 0,
	// g' > 0) its first step lands beyond it. For n = m, f^{1/p} is a norm, linear along rays,
	// and nearly linear along the contact normal, which meets the surface square on: two or three
	// steps reach rounding there. g' = (f^{1/p}/(p·f))·f', f' = n|u|^{n−1}sgn(u)·D + m|v|^{m−1}sgn(v)·E.
	const double X = x.x * s.invA, Y = x.y * s.invB, D = d.x * s.invA, E = d.y * s.invB;
	const double dd = D * D + E * E;
	if (!(dd > 0.0) || !std::isfinite(dd) || !std::isfinite(X) || !std::isfinite(Y))
		return false;
	const double p = std::min(s.n, s.m);
	const int nk = s.nInt >= 1 ? s.nInt - 1 : -1, mk = s.mInt >= 1 ? s.mInt - 1 : -1;
	double g = 0.0, slope = 0.0;
	// (No finiteness test per evaluation: a NaN or infinite level makes the slope NaN or the
	// step non-finite, which the tests on the slope and the step below turn into `false`.)
	auto gauge = [&](double f, double df) {
		const double r = RootOf(f, p);
		g = r - 1.0;
		slope = f > 0.0 ? r / (p * f) * df : 0.0;
		return true;
	};
	auto evaluate = [&](double at) {
		const double u = X + at * D, v = Y + at * E;
		const double au = std::fabs(u), av = std::fabs(v);
		const double un1 = PowAbs(au, s.n - 1.0, nk), vm1 = PowAbs(av, s.m - 1.0, mk);
		// sgn(u)|u|^{n−1} as in RawSuperellipseDerivatives.
		const double su = s.n >= 2.0 ? std::copysign(un1, u) : SignOf(u) * un1;
		const double sv = s.m >= 2.0 ? std::copysign(vm1, v) : SignOf(v) * vm1;
		return gauge(un1 * au + vm1 * av, s.n * su * D + s.m * sv * E);
	};
	t = 0.0;
	if (!(known ? gauge(known[0], known[1]) : evaluate(0.0)))
		return false;
	if (!(slope > 0.0))
	{
		// Moving inwards or along: start where the line leaves the circle of radius √2 about the
		// centre, which holds the unit square and so the particle (|u|, |v| ≤ 1 on it): g ≥ 0 there,
		// and g' > 0 unless the line misses the particle or only grazes it.
		const double B = X * D + Y * E, C = X * X + Y * Y - 2.0;
		const double disc = B * B - dd * C;
		if (!(disc >= 0.0) || !std::isfinite(disc))
			return false;
		const double root = std::sqrt(disc);
		t = B > 0.0 ? -C / (B + root) : (root - B) / dd;
		if (!evaluate(t) || !(slope > 0.0))
			return false;
	}
	if (g == 0.0)
		return true;
	// The step tolerance: rounding of t itself, or 1e-15 of the particle's size along the line.
	const double unit = 1.0 / std::sqrt(dd);
	double previous = 0.0; // the last step's length (0: none yet)
	for (int it = 0; it < 60; ++it)
	{
		const double step = g / slope;
		const double tol = 1e-15 * (std::fabs(t) + unit);
		// After the first step every step goes backwards (monotone descent onto the root); one
		// forwards beyond rounding means the line misses the particle, or g lost its convexity to
		// rounding: the caller searches instead.
		if (it > 0 && step < -tol)
			return false;
		t -= step;
		if (std::fabs(step) <= tol)
			return std::isfinite(t);
		// Quadratic convergence: once a step was small against the particle (1e-3 of its size
		// along the line, where g is its own quadratic model to that order) and the next one
		// contracted, the error left is about K·step² with K ≈ |step|/previous²; with a factor 10
		// below the tolerance the step that would confirm it is not evaluated. (A large first
		// step, from inside along a grazing line, says nothing about K.)
		if (previous > 0.0 && previous <= 1e-3 * unit && std::fabs(step) < 0.25 * previous &&
		    10.0 * std::fabs(step) * (std::fabs(step) / previous) * (std::fabs(step) / previous) <= tol)
			return std::isfinite(t);
		previous = std::fabs(step);
		if (!evaluate(t) || !(slope > 0.0))
			return false;
		if (g == 0.0)
			return true;
	}
	return false;
}

/// The far crossing of f = 1 by the body line x + t·d for exponents ≥ 2 (SmoothExponents; the
/// powers as in SmoothSuperellipseDerivatives: by multiplication for integer exponents, one
/// std::pow per axis and step for real ones), by Halley's method on g(t) = f(x + t·d) − 1 from
/// t = 0, where `known` = {f, f', f''} (the caller's level solve ends with f, ∇f and ∇²f at x).
/// A warm contact's point lies within a small fraction of the size of both surfaces, where g is
/// smooth in t (a polynomial in |u|, |v| for integer exponents; for a real n in (2, 3),
/// g''' ∝ |u|^{n−3} grows near u = 0, but that term's share of a step's error is bounded by the
/// size of |u|^n itself over the step, O(|δ·D|^n), still of higher order than δ²), and Halley's
/// cubic convergence takes one step from the known values and one from an evaluation: the error
/// after a step δ is about K·|δ|³ with K ≈ |δ|/|δ_before|³, so a step whose predecessor was small
/// (5e-2 of `unit`) and that contracted tenfold ends the search when K·|δ|³ is below the
/// tolerance (1e-15 of |t| + unit; `unit` is the particle's smaller semi-axis). Where g·g'' is
/// large against g'² (far outside) the step is Newton's, which descends onto the far crossing
/// of the convex g from outside. It fails where g' ≤ 0 (the line misses or runs along the
/// particle), a step would leave 4 units, or it does not settle in 8 steps: the caller then
/// takes SuperellipseFarCrossing.
/// A step at a time (Step), so that the two crossings of a contact run interleaved
/// (SmoothFarCrossings): each step waits for a division and then for the level it evaluates,
/// and one crossing's chain fills the other's wait.
struct SmoothCrossing
{
	enum class State { running, found, failed };

	/// Starts at t = 0 with g, g', g'' from `known`.
	B2A_FORCE_INLINE
	SmoothCrossing(const SuperellipseTerms& s, Vec2 x, Vec2 d, const double known[3], double unit)
	    : X(x.x * s.invA), Y(x.y * s.invB), D(d.x * s.invA), E(d.y * s.invB), nD(s.n * D), mE(s.m * E),
	      nnDD(s.n * (s.n - 1.0) * D * D), mmEE(s.m * (s.m - 1.0) * E * E), g(known[0] - 1.0), g1(known[1]), g2(known[2]),
	      unit(unit), en(s.n - 2.0), em(s.m - 2.0), nk(PowerBelowTwo(s.nInt)), mk(PowerBelowTwo(s.mInt))
	{
	}

	/// One Halley step, and the derivatives at its end unless it ended the search. (It and the
	/// constructor are forced inline: GCC keeps them out of line for their two call sites, and
	/// the crossing's state then goes through memory on every step.)
	B2A_FORCE_INLINE
	void Step()
	{
		if (!(g1 > 0.0))
		{
			state = State::failed;
			return;
		}
		const double den = 2.0 * g1 * g1 - g * g2;
		const double step = den >= g1 * g1 ? 2.0 * g * g1 / den : g / g1; // Halley, at most twice Newton's
		t -= step;
		const double size = std::fabs(step), tol = 1e-15 * (std::fabs(t) + unit);
		if (!(size <= 4.0 * unit))
		{
			state = State::failed; // not near the surface, or not finite: the caller's search decides
			return;
		}
		if (size <= tol)
		{
			state = State::found;
			return;
		}
		if (previous > 0.0 && previous <= 0.05 * unit && size < 0.1 * previous)
		{
			const double ratio = size / previous;
			if (size * ratio * ratio * ratio <= 1e-15 * (std::fabs(t) + unit))
			{
				state = State::found;
				return;
			}
		}
		previous = size;
		const double u = X + t * D, v = Y + t * E;
		const double au = std::fabs(u), av = std::fabs(v);
		// |u|^{n−2} once (SmoothSuperellipseDerivatives), g, g' and g'' from it.
		const double un2 = PowAbs(au, en, nk), vm2 = PowAbs(av, em, mk);
		const double un1 = un2 * au, vm1 = vm2 * av;
		g = un1 * au + vm1 * av - 1.0;
		g1 = nD * std::copysign(un1, u) + mE * std::copysign(vm1, v);
		g2 = nnDD * un2 + mmEE * vm2;
	}

	double X, Y, D, E, nD, mE, nnDD, mmEE; // the line in scaled coordinates, and g's constant factors
	double g, g1, g2;                       // g, g' and g'' at t
	double t = 0.0;
	double previous = 0.0; // the last step's length (0: none yet)
	double unit;
	double en, em; // n − 2 and m − 2
	int nk, mk;    // the same as small integers, or −1 for real exponents (PowerBelowTwo)
	State state = State::running;
};

/// One crossing run alone: true with t where it is found.
inline bool SmoothFarCrossing(const SuperellipseTerms& s, Vec2 x, Vec2 d, const double known[3], double unit, double& t)
{
	SmoothCrossing c(s, x, d, known, unit);
	for (int it = 0; it < 8 && c.state == SmoothCrossing::State::running; ++it)
		c.Step();
	t = c.t;
	return c.state == SmoothCrossing::State::found;
}

/// The far crossing of f = 1 by the body line x + t·d for exponents ≥ 2 (SmoothExponents) from
/// x alone: f, f' and f'' at x from one evaluation (SmoothSuperellipseDerivatives), then
/// SmoothFarCrossing's Halley steps (one division a step, where SuperellipseFarCrossing's Newton
/// on f^(1/p) takes a root and two divisions); where they decline, SuperellipseFarCrossing from
/// the same f and f'. `unit` as SmoothFarCrossing's (the smaller semi-axis). For a point within
/// a small fraction of the size of the surface (a face point of a contact manifold).
inline bool SmoothFarCrossingFrom(const SuperellipseTerms& s, Vec2 x, Vec2 d, double unit, double& t)
{
	const AxisDerivatives e = SmoothSuperellipseDerivatives(s, x.x, x.y);
	const double known[3] = {e.f, e.gx * d.x + e.gy * d.y, d.x * d.x * e.hx + d.y * d.y * e.hy};
	return SmoothFarCrossing(s, x, d, known, unit, t) || SuperellipseFarCrossing(s, x, d, t, known);
}

/// Two independent crossings, interleaved a step at a time (up to 8 steps each: a's first, then
/// b's, then a's second, ...); each ends found or failed, with the same steps and the same answer
/// as when run alone.
/// One copy of the step serves both (a loop over the pair, not unrolled): a warm contact runs this
/// once among much other code, and two inlined copies of the step would take twice the
/// instruction cache lines it needs there. The two chains still overlap in the processor (a
/// step's division and evaluation wait on its own crossing only).
inline void SmoothFarCrossings(SmoothCrossing& a, SmoothCrossing& b)
{
	using State = SmoothCrossing::State;
	SmoothCrossing* const both[2] = {&a, &b};
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC unroll 1
#endif
	for (int k = 0; k < 16; ++k)
	{
		if (a.state != State::running && b.state != State::running)
			return;
		SmoothCrossing& c = *both[k & 1];
		if (c.state == State::running)
			c.Step();
	}
	if (a.state == State::running)
		a.state = State::failed;
	if (b.state == State::running)
		b.state = State::failed;
}

} // namespace b2a

// b2analytic: bracketed one-dimensional root finding and minimisation (internal).
#pragma once

#include <cmath>
#include <limits>
#include <utility>

namespace b2a
{

/// Outcome of a one-dimensional solve.
struct ScalarResult
{
	double x = 0.0;        ///< the root or the minimiser
	double fx = 0.0;       ///< f there
	int iterations = 0;    ///< function evaluations used
	bool converged = false;///< the bracket shrank below the tolerance within the cap
};

/// How a line meets an ellipse, from the quadratic A t² + 2B t + C of its level minus one.
enum class LineQuadratic
{
	crosses, ///< real roots: the larger one is returned
	misses,  ///< no real root, the discriminant below its rounding
	unknown  ///< a grazing line (discriminant within rounding of 0), A ≤ 0, or anything non-finite
};

/// The larger root t of A t² + 2B t + C = 0 in the cancellation-free form: (√(B² − AC) − B)/A,
/// or −C/(B + √(B² − AC)) where B > 0 (the product of the roots is C/A). The discriminant's
/// rounding is a few eps of B² + |AC|; below −1e-12 of that the line misses.
inline LineQuadratic QuadraticFarRoot(double A, double B, double C, double& t)
{
	const double disc = B * B - A * C;
	if (!(A > 0.0) || !std::isfinite(disc))
		return LineQuadratic::unknown;
	if (disc >= 0.0)
	{
		const double root = std::sqrt(disc);
		t = B > 0.0 ? -C / (B + root) : (root - B) / A;
		return std::isfinite(t) ? LineQuadratic::crosses : LineQuadratic::unknown;
	}
	return disc < -1e-12 * (B * B + std::fabs(A * C)) ? LineQuadratic::misses : LineQuadratic::unknown;
}

/// The bracketing solvers' first test: true, with the answer in r, when an end is a root
/// (converged) or [a, b] brackets nothing (the end with the smaller |f|, unconverged: equal
/// signs or a non-finite end).
inline bool SettledByEnds(double a, double b, double fa, double fb, ScalarResult& r)
{
	if (fa == 0.0 || fb == 0.0)
	{
		r.x = fa == 0.0 ? a : b;
		r.fx = 0.0;
		r.converged = true;
		return true;
	}
	if ((fa > 0.0) == (fb > 0.0) || !std::isfinite(fa) || !std::isfinite(fb))
	{
		r.x = std::fabs(fa) < std::fabs(fb) ? a : b;
		r.fx = std::fabs(fa) < std::fabs(fb) ? fa : fb;
		return true; // not bracketed
	}
	return false;
}

/// Brent's method (Brent 1973, "zeroin") for a root of f in [a, b] with f(a), f(b) of opposite
/// signs (or zero). Mixes bisection, secant and inverse quadratic steps; never leaves the
/// bracket, so it converges whenever f is continuous. Stops when the bracket is below
/// xtol + 4·eps·|x| or after maxIter evaluations.
template <class F>
ScalarResult FindRootBrent(F&& f, double a, double b, double fa, double fb, double xtol, int maxIter = 200)
{
	ScalarResult r;
	if (SettledByEnds(a, b, fa, fb, r))
		return r;
	const double eps = std::numeric_limits<double>::epsilon();
	double c = a, fc = fa, d = b - a, e = d;
	for (int it = 0; it < maxIter; ++it)
	{
		if ((fb > 0.0) == (fc > 0.0))
		{
			c = a; fc = fa; d = b - a; e = d;
		}
		if (std::fabs(fc) < std::fabs(fb))
		{
			a = b; b = c; c = a;
			fa = fb; fb = fc; fc = fa;
		}
		const double tol = 2.0 * eps * std::fabs(b) + 0.5 * xtol;
		const double m = 0.5 * (c - b);
		if (std::fabs(m) <= tol || fb == 0.0)
		{
			r.x = b; r.fx = fb; r.iterations = it; r.converged = true;
			return r;
		}
		if (std::fabs(e) >= tol && std::fabs(fa) > std::fabs(fb))
		{
			// Secant or inverse quadratic interpolation.
			double p, q;
			const double s = fb / fa;
			if (a == c)
			{
				p = 2.0 * m * s;
				q = 1.0 - s;
			}
			else
			{
				const double qa = fa / fc, rr = fb / fc;
				p = s * (2.0 * m * qa * (qa - rr) - (b - a) * (rr - 1.0));
				q = (qa - 1.0) * (rr - 1.0) * (s - 1.0);
			}
			if (p > 0.0) q = -q; else p = -p;
			if (2.0 * p < std::fmin(3.0 * m * q - std::fabs(tol * q), std::fabs(e * q)))
			{
				e = d; d = p / q;
			}
			else
			{
				d = m; e = m;
			}
		}
		else
		{
			d = m; e = m;
		}
		a = b; fa = fb;
		b += std::fabs(d) > tol ? d : (m > 0.0 ? tol : -tol);
		fb = f(b);
		if (!std::isfinite(fb))
		{
			r.x = a; r.fx = fa; r.iterations = it + 1;
			return r;
		}
	}
	r.x = b; r.fx = fb; r.iterations = maxIter;
	return r;
}

/// A root of f in [a, b] with f(a), f(b) of opposite signs (or zero), by Newton's method kept
/// inside the bracket, for functions whose derivative comes nearly free with the value:
/// `fdf(x, df)` returns f(x) and sets df = f'(x). It starts at the secant point of the ends (as
/// good as a first Newton step) and takes Newton steps while they stay inside the shrinking
/// bracket and at least halve the step before last, bisecting otherwise (a kink or a cusp, where
/// f' is huge or changes sign, so it converges whenever f is continuous). It stops when a step
/// falls below 2·eps·|x| + xtol/2 (Brent's tolerance), or, once in the quadratic regime, one step
/// early: after steps δₖ and δₖ₊₁ Newton's constant is K ≈ |δₖ₊₁|/|δₖ|², the error left after
/// δₖ₊₁ is about K·|δₖ₊₁|², and where that is ten times below the tolerance δₖ₊₁ is taken as the
/// last step without evaluating f again. On a smooth crossing bracketed to 1e-2 of its scale
/// that is 2 or 3 evaluations where Brent's method takes 7 or 8. After a last step taken without
/// evaluating, `fx` is f's first-order value there. Non-finite values end the solve at the
/// bracket's better end, unconverged, as Brent's method does.
template <class FDF>
ScalarResult FindRootNewtonSafe(FDF&& fdf, double a, double b, double fa, double fb, double xtol, int maxIter = 100)
{
	ScalarResult r;
	if (SettledByEnds(a, b, fa, fb, r))
		return r;
	const double eps = std::numeric_limits<double>::epsilon();
	// neg and pos: the bracket's ends where f < 0 and f > 0.
	double neg = fa < 0.0 ? a : b, pos = fa < 0.0 ? b : a;
	double fneg = fa < 0.0 ? fa : fb, fpos = fa < 0.0 ? fb : fa;
	double x = a - fa * ((b - a) / (fb - fa));
	if (!(x > std::min(a, b) && x < std::max(a, b)))
		x = 0.5 * (a + b);
	const double width = std::fabs(b - a);
	double before = width, last = width; // the steps before last and last
	bool lastNewton = false;             // the last step was Newton's (K can be read off it)
	auto betterEnd = [&](bool converged) {
		const bool negBetter = std::fabs(fneg) < std::fabs(fpos);
		r.x = negBetter ? neg : pos;
		r.fx = negBetter ? fneg : fpos;
		r.converged = converged;
		return r;
	};
	for (int it = 1; it <= maxIter; ++it)
	{
		double df = 0.0;
		const double fx = fdf(x, df);
		r.iterations = it;
		if (!std::isfinite(fx))
			return betterEnd(false);
		if (fx == 0.0)
		{
			r.x = x; r.fx = 0.0; r.converged = true;
			return r;
		}
		if (fx < 0.0) { neg = x; fneg = fx; }
		else { pos = x; fpos = fx; }
		const double lo = std::min(neg, pos), hi = std::max(neg, pos); // (finite: not fmin, a call)
		const double tol = 2.0 * eps * std::fabs(x) + 0.5 * xtol;
		double next = x - fx / df; // (NaN or infinite for df = 0 or non-finite: rejected below)
		const bool newton = next > lo && next < hi && 2.0 * std::fabs(next - x) <= before;
		if (!newton)
			next = 0.5 * (lo + hi);
		const double step = std::fabs(next - x);
		const bool settled = newton && lastNewton && last <= 0.1 * width && step < 0.25 * last &&
		                     10.0 * (step / (last * last)) * step * step <= tol;
		if (step <= tol || settled || hi - lo <= 2.0 * tol)
		{
			if (!newton)
				return betterEnd(true); // the bracket collapsed
			r.x = next; r.fx = fx + df * (next - x); r.converged = true;
			return r;
		}
		before = last;
		last = step;
		lastNewton = newton;
		x = next;
	}
	return betterEnd(false);
}

/// A root of f between a and b (f(a), f(b) of opposite signs) where the root may lie many orders
/// of magnitude closer to zero than the bracket's far end (a level of 1e-300 bracketed by
/// [-0.05, 0.2], a radius of 1e-78 by [0, 6]). Brent's method only halves such a bracket per
/// step once it cannot interpolate, and to reach 1e-300 at full relative precision it would need
/// a thousand halvings (it stops at its cap, after hundreds of evaluations). So the bracket is
/// first narrowed on a logarithmic scale: a bracket across zero is split at zero; from an end at
/// zero the far end is scaled by 4^(-2^k) (1/4, 1/16, 1/256, ...) until f changes sign; then
/// bisection at the geometric mean √(lo·hi) until the ends are within a factor 4. About
/// log2(log2(range)) + 2 evaluations, then Brent's method on an ordinary bracket.
template <class F>
ScalarResult FindRootScaleFree(F&& f, double a, double b, double fa, double fb, int maxIter = 300)
{
	if (!(std::isfinite(fa) && std::isfinite(fb)) || fa == 0.0 || fb == 0.0 || (fa > 0.0) == (fb > 0.0) ||
	    !(std::isfinite(a) && std::isfinite(b)))
		return FindRootBrent(f, a, b, fa, fb, 0.0, maxIter);
	double lo = a, hi = b, flo = fa, fhi = fb;
	if (lo > hi)
	{
		std::swap(lo, hi);
		std::swap(flo, fhi);
	}
	int used = 0;
	auto done = [&](double x, double fx) {
		ScalarResult r;
		r.x = x;
		r.fx = fx;
		r.iterations = used;
		r.converged = true;
		return r;
	};
	if (lo < 0.0 && hi > 0.0)
	{
		const double f0 = f(0.0);
		++used;
		if (f0 == 0.0 || !std::isfinite(f0))
			return f0 == 0.0 ? done(0.0, 0.0) : FindRootBrent(f, lo, hi, flo, fhi, 0.0, maxIter);
		if ((f0 > 0.0) == (flo > 0.0)) { lo = 0.0; flo = f0; }
		else { hi = 0.0; fhi = f0; }
	}
	// On [lo, hi] within one side of zero; mirror the negative side onto the positive one.
	const bool negative = hi <= 0.0;
	double n = negative ? -hi : lo, far = negative ? -lo : hi, fn = negative ? fhi : flo, ffar = negative ? flo : fhi;
	auto g = [&](double x) { return f(negative ? -x : x); };
	if (n == 0.0)
	{
		// Probe towards zero, squaring the ratio each time, until g changes sign.
		double ratio = 0.25;
		for (int k = 0; k < 11; ++k, ratio *= ratio)
		{
			const double t = far * ratio;
			if (!(t > 1e-300))
				break;
			const double ft = g(t);
			++used;
			if (ft == 0.0 || !std::isfinite(ft))
			{
				if (ft == 0.0)
					return done(negative ? -t : t, 0.0);
				break;
			}
			if ((ft > 0.0) == (fn > 0.0)) { n = t; fn = ft; break; }
			far = t;
			ffar = ft;
		}
	}
	while (n > 0.0 && far > 4.0 * n && used < maxIter / 2)
	{
		const double m = std::sqrt(n) * std::sqrt(far);
		const double fm = g(m);
		++used;
		if (fm == 0.0)
			return done(negative ? -m : m, 0.0);
		if (!std::isfinite(fm))
			break;
		if ((fm > 0.0) == (fn > 0.0)) { n = m; fn = fm; }
		else { far = m; ffar = fm; }
	}
	ScalarResult r = negative ? FindRootBrent(f, -far, -n, ffar, fn, 0.0, maxIter - used)
	                          : FindRootBrent(f, n, far, fn, ffar, 0.0, maxIter - used);
	r.iterations += used;
	return r;
}

/// Brent's method for a local minimum of f in [a, b] (golden section plus parabolic steps).
/// Converges to |x − x*| ≲ tol·|x| + atol, which for a smooth minimum means f is exact to
/// about eps·|f|; the argument is exact only to about √eps — use a derivative root where the
/// argument matters.
template <class F>
ScalarResult MinimizeBrent(F&& f, double a, double b, double rtol, double atol, int maxIter = 200)
{
	const double golden = 0.3819660112501051;
	double x = a + golden * (b - a), w = x, v = x;
	double fx = f(x), fw = fx, fv = fx;
	double d = 0.0, e = 0.0;
	ScalarResult r;
	for (int it = 0; it < maxIter; ++it)
	{
		const double xm = 0.5 * (a + b);
		const double tol1 = rtol * std::fabs(x) + atol, tol2 = 2.0 * tol1;
		if (std::fabs(x - xm) <= tol2 - 0.5 * (b - a))
		{
			r.x = x; r.fx = fx; r.iterations = it + 1; r.converged = true;
			return r;
		}
		bool golden_step = true;
		if (std::fabs(e) > tol1)
		{
			const double rr = (x - w) * (fx - fv);
			double q = (x - v) * (fx - fw);
			double p = (x - v) * q - (x - w) * rr;
			q = 2.0 * (q - rr);
			if (q > 0.0) p = -p; else q = -q;
			const double etemp = e;
			e = d;
			if (!(std::fabs(p) >= std::fabs(0.5 * q * etemp) || p <= q * (a - x) || p >= q * (b - x)))
			{
				d = p / q;
				const double u = x + d;
				if (u - a < tol2 || b - u < tol2) d = xm >= x ? tol1 : -tol1;
				golden_step = false;
			}
		}
		if (golden_step)
		{
			e = (x >= xm ? a : b) - x;
			d = golden * e;
		}
		const double u = std::fabs(d) >= tol1 ? x + d : x + (d >= 0.0 ? tol1 : -tol1);
		const double fu = f(u);
		if (fu <= fx)
		{
			if (u >= x) a = x; else b = x;
			v = w; fv = fw; w = x; fw = fx; x = u; fx = fu;
		}
		else
		{
			if (u < x) a = u; else b = u;
			if (fu <= fw || w == x) { v = w; fv = fw; w = u; fw = fu; }
			else if (fu <= fv || v == x || v == w) { v = u; fv = fu; }
		}
	}
	r.x = x; r.fx = fx; r.iterations = maxIter;
	return r;
}

} // namespace b2a

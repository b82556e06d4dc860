// FindRootBrent, FindRootNewtonSafe and MinimizeBrent (numerics/RootFinding.h) on functions with
// known answers.
#include <doctest/doctest.h>

#include "TestSupport.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
const double kEps = std::numeric_limits<double>::epsilon();

// Calls f through a counter and records every argument.
template <class F>
struct Recorded
{
	F f;
	std::vector<double> args;
	double operator()(double x)
	{
		args.push_back(x);
		return f(x);
	}
};
template <class F>
Recorded<F> Record(F f) { return Recorded<F>{f, {}}; }

template <class F>
ScalarResult Root(F&& f, double a, double b, double xtol, int maxIter = 200)
{
	return FindRootBrent(f, a, b, f(a), f(b), xtol, maxIter);
}
} // namespace

TEST_CASE("FindRootBrent: converges to known roots of smooth functions")
{
	struct Case
	{
		const char* name;
		double (*f)(double);
		double a, b, root;
	};
	const Case cases[] = {
		{"cos x - x (Dottie number)", [](double x) { return std::cos(x) - x; }, 0.0, 1.0, 0.739085133215160641655312087673873404},
		{"x^3 - 2", [](double x) { return x * x * x - 2.0; }, 0.0, 3.0, 1.259921049894873164767210607278228351},
		{"e^x - 10", [](double x) { return std::exp(x) - 10.0; }, -5.0, 5.0, 2.302585092994045684017991454684364208},
		{"1 - x^2 (decreasing)", [](double x) { return 1.0 - x * x; }, 0.0, 5.0, 1.0},
		{"x - 1e10 (large root)", [](double x) { return x - 1e10; }, 0.0, 1e11, 1e10},
		{"x - 1e-20 (tiny root)", [](double x) { return x - 1e-20; }, -1.0, 1.0, 1e-20},
		{"atan(x - 0.1) (flat far away)", [](double x) { return std::atan(x - 0.1); }, -100.0, 300.0, 0.1},
	};
	for (const Case& c : cases)
	{
		CAPTURE(c.name);
		auto f = Record(c.f);
		const ScalarResult r = Root(f, c.a, c.b, 0.0);
		CHECK(r.converged);
		// xtol = 0: the bracket shrinks to 4ε|x|, which contains the root.
		CHECK(std::fabs(r.x - c.root) <= 4 * kEps * std::fabs(c.root));
		CHECK(r.fx == c.f(r.x));
		// Superlinear: far fewer evaluations than bisection's ~60 (Brent never needs more than
		// a small multiple of them, and these are smooth simple roots).
		CHECK(r.iterations <= 40);
		CHECK(int(f.args.size()) == 2 + r.iterations); // the caller's two plus one per iteration
	}
	// On a smooth simple root Brent is much faster than bisection (which needs 52 halvings of
	// [0, 1] to reach 4ε): cos x − x takes fewer than 12.
	const ScalarResult dottie = Root([](double x) { return std::cos(x) - x; }, 0.0, 1.0, 0.0);
	CHECK(dottie.iterations < 12);
}

TEST_CASE("FindRootBrent: stops at the requested absolute tolerance")
{
	const double root = std::cbrt(2.0);
	auto f = [](double x) { return x * x * x - 2.0; };
	int previous = 0;
	for (double xtol : {1e-1, 1e-3, 1e-6, 1e-9, 1e-12})
	{
		CAPTURE(xtol);
		const ScalarResult r = Root(f, 0.0, 3.0, xtol);
		CHECK(r.converged);
		// Documented stop: bracket below xtol + 4ε|x|, and the root lies in the bracket.
		CHECK(std::fabs(r.x - root) <= xtol + 4 * kEps * root);
		CHECK(r.iterations >= previous); // a tighter tolerance never costs fewer evaluations
		previous = r.iterations;
	}
}

TEST_CASE("FindRootBrent: a discontinuous sign change is located to the tolerance")
{
	// No root, only a jump from −1 to 2 at s = √2 − 1: Brent keeps a sign-change bracket and
	// shrinks it onto the jump.
	const double s = std::sqrt(2.0) - 1.0;
	auto step = [s](double x) { return x < s ? -1.0 : 2.0; };
	for (double xtol : {0.0, 1e-10, 1e-4})
	{
		CAPTURE(xtol);
		const ScalarResult r = Root(step, 0.0, 1.0, xtol);
		CHECK(r.converged);
		CHECK(std::fabs(r.x - s) <= xtol + 4 * kEps * s);
		CHECK(r.iterations < 200);
	}
}

TEST_CASE("FindRootBrent: evaluates f only inside the bracket, in either orientation")
{
	auto f = Record([](double x) { return std::tanh(3.0 * (x - 0.25)) + 0.1 * x; });
	const ScalarResult r = FindRootBrent(f, 2.0, -1.0, f(2.0), f(-1.0), 0.0); // b < a
	CHECK(r.converged);
	CHECK(std::fabs(f.f(r.x)) <= 1e-15);
	for (double x : f.args)
	{
		CHECK(x >= -1.0);
		CHECK(x <= 2.0);
	}
}

TEST_CASE("FindRootBrent: an unbracketed interval is reported as not converged")
{
	// Both ends positive: nothing is solved, the end with the smaller |f| is returned.
	auto f = [](double x) { return x * x + 1.0; };
	const ScalarResult r = Root(f, -1.0, 2.0, 1e-12);
	CHECK(!r.converged);
	CHECK(r.x == -1.0);
	CHECK(r.fx == 2.0);
	CHECK(r.iterations == 0);
	// Both ends negative, other end smaller.
	const ScalarResult s = Root([](double x) { return -std::exp(x); }, -1.0, -3.0, 1e-12);
	CHECK(!s.converged);
	CHECK(s.x == -3.0);
	// A NaN end is not a bracket either.
	const ScalarResult n = FindRootBrent([](double x) { return x; }, -1.0, 1.0, -1.0, std::nan(""), 1e-12);
	CHECK(!n.converged);
}

TEST_CASE("FindRootBrent: a zero at an end of the bracket is returned at once")
{
	auto f = Record([](double x) { return x * (x - 1.0); });
	const ScalarResult a = FindRootBrent(f, 0.0, 0.5, 0.0, f(0.5), 1e-12);
	CHECK(a.converged);
	CHECK(a.x == 0.0);
	CHECK(a.fx == 0.0);
	const ScalarResult b = FindRootBrent(f, 0.5, 1.0, f(0.5), 0.0, 1e-12);
	CHECK(b.converged);
	CHECK(b.x == 1.0);
	CHECK(f.args.size() == 2); // only the caller's evaluations
}

TEST_CASE("FindRootBrent: the evaluation cap and non-finite values end the solve unconverged")
{
	// A cap of 3 evaluations cannot reach 4ε on [0, 3]: not converged, still inside the bracket.
	auto f = Record([](double x) { return x * x * x - 2.0; });
	const ScalarResult r = FindRootBrent(f, 0.0, 3.0, f(0.0), f(3.0), 0.0, 3);
	CHECK(!r.converged);
	CHECK(r.iterations == 3);
	CHECK(f.args.size() == 2 + 3);
	CHECK(r.x >= 0.0);
	CHECK(r.x <= 3.0);

	// f is NaN inside the bracket, on (0.6, 1), though finite at both ends: the solve stops
	// unconverged at the last finite point rather than returning a NaN.
	auto g = [](double x) { return x <= 0.6 ? x - 0.7 : (x < 1.0 ? std::nan("") : 0.3); };
	const ScalarResult s = FindRootBrent(g, 0.0, 1.0, g(0.0), g(1.0), 1e-12);
	CHECK(!s.converged);
	CHECK(std::isfinite(s.fx));
	CHECK(s.fx == g(s.x));
}

namespace
{
// A function and its derivative for FindRootNewtonSafe, recording every argument.
struct WithSlope
{
	double (*f)(double);
	double (*df)(double);
	std::vector<double> args;
	double operator()(double x, double& d)
	{
		args.push_back(x);
		d = df(x);
		return f(x);
	}
};
} // namespace

TEST_CASE("FindRootNewtonSafe: the known roots of Brent's cases, in fewer evaluations")
{
	struct Case
	{
		const char* name;
		double (*f)(double);
		double (*df)(double);
		double a, b, root;
		bool smooth; // a simple root Newton reaches from the secant start without bisecting
	};
	const Case cases[] = {
		{"cos x - x", [](double x) { return std::cos(x) - x; }, [](double x) { return -std::sin(x) - 1.0; }, 0.0, 1.0,
		 0.739085133215160641655312087673873404, true},
		{"x^3 - 2", [](double x) { return x * x * x - 2.0; }, [](double x) { return 3.0 * x * x; }, 0.0, 3.0,
		 1.259921049894873164767210607278228351, true},
		{"e^x - 10", [](double x) { return std::exp(x) - 10.0; }, [](double x) { return std::exp(x); }, -5.0, 5.0,
		 2.302585092994045684017991454684364208, false},
		{"1 - x^2", [](double x) { return 1.0 - x * x; }, [](double x) { return -2.0 * x; }, 0.0, 5.0, 1.0, true},
		// Linear: both methods land on the root from the secant point.
		{"x - 1e10", [](double x) { return x - 1e10; }, [](double) { return 1.0; }, 0.0, 1e11, 1e10, false},
		{"x - 1e-20", [](double x) { return x - 1e-20; }, [](double) { return 1.0; }, -1.0, 1.0, 1e-20, false},
		{"atan(x - 0.1)", [](double x) { return std::atan(x - 0.1); }, [](double x) { return 1.0 / (1.0 + (x - 0.1) * (x - 0.1)); },
		 -100.0, 300.0, 0.1, false},
	};
	for (const Case& c : cases)
	{
		const std::string name = c.name;
		CAPTURE(name);
		WithSlope f{c.f, c.df, {}};
		const ScalarResult r = FindRootNewtonSafe(f, c.a, c.b, c.f(c.a), c.f(c.b), 0.0);
		CHECK(r.converged);
		CHECK(std::fabs(r.x - c.root) <= 4 * kEps * std::fabs(c.root));
		CHECK(r.iterations == int(f.args.size()));
		for (double x : f.args)
		{
			CHECK(x > std::min(c.a, c.b));
			CHECK(x < std::max(c.a, c.b));
		}
		const ScalarResult brent = Root(c.f, c.a, c.b, 0.0);
		CHECK(r.iterations <= brent.iterations + 2);
		if (c.smooth)
			CHECK(r.iterations < brent.iterations);
	}
	// The line crossings it serves: a bracket of 1e-2 around a simple root takes 3 evaluations
	// or fewer (Newton's quadratic convergence from the secant point), Brent's method more.
	WithSlope cosine{[](double x) { return std::cos(x) - x; }, [](double x) { return -std::sin(x) - 1.0; }, {}};
	const ScalarResult near = FindRootNewtonSafe(cosine, 0.735, 0.745, cosine.f(0.735), cosine.f(0.745), 0.0);
	CHECK(near.converged);
	CHECK(std::fabs(near.x - 0.739085133215160641655312087673873404) <= 2 * kEps);
	CHECK(near.iterations <= 3);
	CHECK(Root(cosine.f, 0.735, 0.745, 0.0).iterations > near.iterations);
}

TEST_CASE("FindRootNewtonSafe: bisects where Newton cannot be trusted (cusp, jump, wrong slope)")
{
	// ∛(x − 0.3): an infinite slope at the root, where Newton's steps double the error and
	// alternate sides; the safeguard bisects.
	WithSlope cusp{[](double x) { return std::cbrt(x - 0.3); },
	               [](double x) { return 1.0 / (3.0 * std::cbrt((x - 0.3) * (x - 0.3))); }, {}};
	const ScalarResult c = FindRootNewtonSafe(cusp, 0.0, 1.0, cusp.f(0.0), cusp.f(1.0), 0.0);
	CHECK(c.converged);
	CHECK(std::fabs(c.x - 0.3) <= 4 * kEps * 0.3);
	CHECK(c.iterations < 100);
	// A jump from −1 to 2 at √2 − 1 with a zero slope: every Newton step is rejected.
	WithSlope jump{[](double x) { return x < std::sqrt(2.0) - 1.0 ? -1.0 : 2.0; }, [](double) { return 0.0; }, {}};
	const ScalarResult j = FindRootNewtonSafe(jump, 0.0, 1.0, -1.0, 2.0, 0.0);
	CHECK(j.converged);
	CHECK(std::fabs(j.x - (std::sqrt(2.0) - 1.0)) <= 4 * kEps);
	// A derivative of the wrong sign sends Newton away from the root: still solved, inside.
	WithSlope wrong{[](double x) { return x * x * x - 2.0; }, [](double x) { return -3.0 * x * x; }, {}};
	const ScalarResult w = FindRootNewtonSafe(wrong, 3.0, 0.0, 25.0, -2.0, 0.0); // b < a
	CHECK(w.converged);
	CHECK(std::fabs(w.x - std::cbrt(2.0)) <= 4 * kEps * std::cbrt(2.0));
	for (double x : wrong.args)
	{
		CHECK(x > 0.0);
		CHECK(x < 3.0);
	}
	// An absolute tolerance stops it there.
	WithSlope cube{[](double x) { return x * x * x - 2.0; }, [](double x) { return 3.0 * x * x; }, {}};
	const ScalarResult t = FindRootNewtonSafe(cube, 0.0, 3.0, -2.0, 25.0, 1e-3);
	CHECK(t.converged);
	CHECK(std::fabs(t.x - std::cbrt(2.0)) <= 1e-3);
}

TEST_CASE("FindRootNewtonSafe: no bracket, a zero at an end, NaN inside and the cap, as Brent's method")
{
	WithSlope f{[](double x) { return x * x + 1.0; }, [](double x) { return 2.0 * x; }, {}};
	const ScalarResult u = FindRootNewtonSafe(f, -1.0, 2.0, 2.0, 5.0, 0.0);
	CHECK(!u.converged);
	CHECK(u.x == -1.0);
	CHECK(u.iterations == 0);
	const ScalarResult z = FindRootNewtonSafe(f, 0.5, 1.0, 0.0, 2.0, 0.0);
	CHECK(z.converged);
	CHECK(z.x == 0.5);
	CHECK(f.args.empty());
	// NaN on (0.6, 1) though finite at both ends: unconverged at the bracket's better end.
	WithSlope g{[](double x) { return x <= 0.6 ? x - 0.7 : (x < 1.0 ? std::nan("") : 0.3); }, [](double) { return 1.0; }, {}};
	const ScalarResult n = FindRootNewtonSafe(g, 0.0, 1.0, -0.7, 0.3, 0.0);
	CHECK(!n.converged);
	CHECK(std::isfinite(n.fx));
	CHECK(n.fx == g.f(n.x));
	// The cap.
	WithSlope cube{[](double x) { return x * x * x - 2.0; }, [](double x) { return 3.0 * x * x; }, {}};
	const ScalarResult capped = FindRootNewtonSafe(cube, 0.0, 3.0, -2.0, 25.0, 0.0, 2);
	CHECK(!capped.converged);
	CHECK(capped.iterations == 2);
	CHECK(cube.args.size() == 2);
}

TEST_CASE("MinimizeBrent: finds known minima of smooth functions")
{
	struct Case
	{
		const char* name;
		double (*f)(double);
		double a, b, xmin, fmin;
	};
	const double c = std::cbrt(0.75);
	const Case cases[] = {
		{"(x-2)^2 + 1", [](double x) { return (x - 2.0) * (x - 2.0) + 1.0; }, 0.0, 5.0, 2.0, 1.0},
		{"cos x on [2, 5]", [](double x) { return std::cos(x); }, 2.0, 5.0, kPi, -1.0},
		{"x^4 - 3x", [](double x) { return x * x * x * x - 3.0 * x; }, 0.0, 2.0, c, c * c * c * c - 3.0 * c},
		{"e^x - 2x", [](double x) { return std::exp(x) - 2.0 * x; }, -1.0, 3.0, std::log(2.0), 2.0 - 2.0 * std::log(2.0)},
		{"-x e^-x (asymmetric)", [](double x) { return -x * std::exp(-x); }, 0.0, 10.0, 1.0, -std::exp(-1.0)},
	};
	for (const Case& k : cases)
	{
		CAPTURE(k.name);
		for (double rtol : {1e-4, 1e-6, 1e-8})
		{
			CAPTURE(rtol);
			const double atol = 1e-3 * rtol;
			const ScalarResult r = MinimizeBrent(k.f, k.a, k.b, rtol, atol);
			CHECK(r.converged);
			// At exit the bracket is at most 4 (rtol |x| + atol) wide and holds both x and x*.
			CHECK(std::fabs(r.x - k.xmin) <= 4 * (rtol * std::fabs(r.x) + atol));
			CHECK(r.fx == k.f(r.x));
			// The value is second order in the argument's error: ~f''/2 (4 tol)², plus rounding.
			CHECK(r.fx - k.fmin <= 10 * (rtol * rtol * (1 + k.xmin * k.xmin)) + 4 * kEps * std::fabs(k.fmin) + 1e-300);
			CHECK(r.fx >= k.fmin - 4 * kEps * std::fabs(k.fmin));
		}
		// With the tightest tolerances the value is exact to rounding (the argument to ~√ε).
		const ScalarResult t = MinimizeBrent(k.f, k.a, k.b, 1e-15, 1e-15);
		CHECK(t.fx - k.fmin <= 4 * kEps * std::max(1.0, std::fabs(k.fmin)));
		CHECK(std::fabs(t.x - k.xmin) <= 1e-7 * std::max(1.0, std::fabs(k.xmin)));
	}
}

TEST_CASE("MinimizeBrent: minima at an end of the interval and at a kink")
{
	// Monotone on [1, 2]: the minimum is the left end.
	const ScalarResult e = MinimizeBrent([](double x) { return x; }, 1.0, 2.0, 1e-10, 1e-12);
	CHECK(e.converged);
	CHECK(e.x - 1.0 <= 4 * (1e-10 * 1.0 + 1e-12));
	CHECK(e.x >= 1.0);
	// |x − 0.3|: no parabola fits a kink, golden sections must do.
	auto f = Record([](double x) { return std::fabs(x - 0.3); });
	const ScalarResult k = MinimizeBrent(f, -1.0, 2.0, 1e-10, 1e-12);
	CHECK(k.converged);
	CHECK(std::fabs(k.x - 0.3) <= 4 * (1e-10 * 0.3 + 1e-12));
	for (double x : f.args)
	{
		CHECK(x >= -1.0);
		CHECK(x <= 2.0);
	}
}

TEST_CASE("MinimizeBrent: the iteration cap ends the search unconverged")
{
	auto f = Record([](double x) { return std::cos(x); });
	const ScalarResult r = MinimizeBrent(f, 2.0, 5.0, 1e-12, 1e-14, 4);
	CHECK(!r.converged);
	CHECK(r.iterations == 4);
	CHECK(f.args.size() == 1 + 4); // the initial golden point plus one per iteration
	CHECK(r.fx == std::cos(r.x));
	CHECK(r.fx < std::cos(2.0 + 0.3819660112501051 * 3.0) + 1e-300); // never worse than the start
}

// FindRootBrent and MinimizeBrent (numerics/RootFinding.h) on functions with known answers.
#include <doctest/doctest.h>

#include "TestSupport.h"
#include "numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

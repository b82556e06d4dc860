// b2analytic tests: the flow-law fits of the validation programs recover known parameters.
#include "common/FlowFit.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace b2a::demo;

TEST_CASE("FitCurve: Beverloo's C and k from exact data, and their errors from noisy data")
{
	const double rho = 0.8e-3, g = 9810.0, d = 2.0;
	const Model beverloo = BeverlooModel(rho, g, d);
	std::vector<double> D, Q, sigma;
	for (double k = 3.0; k <= 16.0; k += 1.0)
	{
		D.push_back(k * d);
		Q.push_back(beverloo(k * d, {0.65, 1.8}));
		sigma.push_back(0.01 * Q.back());
	}
	const CurveFit exact = FitCurve(beverloo, D, Q, sigma, {1.0, 0.5});
	REQUIRE(exact.converged);
	CHECK(exact.p[0] == doctest::Approx(0.65).epsilon(1e-6));
	CHECK(exact.p[1] == doctest::Approx(1.8).epsilon(1e-6));
	CHECK(exact.chi2 < 1e-8);
	// Alternate ±1 σ offsets: χ²/dof near one, and the errors follow (J^T W J)^-1.
	std::vector<double> noisy = Q;
	for (size_t i = 0; i < noisy.size(); ++i)
		noisy[i] += (i % 2 == 0 ? 1.0 : -1.0) * sigma[i];
	const CurveFit fit = FitCurve(beverloo, D, noisy, sigma, {1.0, 0.5});
	REQUIRE(fit.converged);
	CHECK(fit.chi2 / fit.dof == doctest::Approx(1.0).epsilon(0.3));
	CHECK(std::fabs(fit.p[1] - 1.8) < 3.0 * fit.se[1]);
	CHECK(fit.se[1] > 0.0);
	CHECK(fit.se[1] < 0.2);
}

TEST_CASE("FitCurve: the Mankoc et al. form's b, and a straight line's known standard errors")
{
	const double rho = 0.8e-3, g = 9810.0, d = 1.0;
	const Model mankoc = MankocModel(rho, g, d);
	std::vector<double> D, Q, sigma;
	for (double k = 2.0; k <= 20.0; k += 2.0)
	{
		D.push_back(k);
		Q.push_back(mankoc(k, {0.7, 0.4}));
		sigma.push_back(0.01 * Q.back());
	}
	const CurveFit m = FitCurve(mankoc, D, Q, sigma, {1.0, 1.0});
	REQUIRE(m.converged);
	CHECK(m.p[0] == doctest::Approx(0.7).epsilon(1e-6));
	CHECK(m.p[1] == doctest::Approx(0.4).epsilon(1e-5));

	// y = 1 + 2x + r at x = 0..4 with σ = 1 and offsets r = (+1, -1, 0, -1, +1).
	const std::vector<double> x = {0, 1, 2, 3, 4}, r = {1, -1, 0, -1, 1};
	std::vector<double> y, s(5, 1.0);
	for (size_t i = 0; i < x.size(); ++i)
		y.push_back(1.0 + 2.0 * x[i] + r[i]);
	const Model line = [](double v, const std::vector<double>& p) { return p[0] + p[1] * v; };
	const CurveFit f = FitCurve(line, x, y, s, {0.0, 0.0});
	// The residuals are symmetric about x = 2 and sum to zero, so the line is unchanged: slope 2,
	// intercept 1; χ² = 4 over 3 degrees of freedom scales the errors: se(slope) = √(4/3 / Sxx),
	// Sxx = 10; se(intercept) = √(4/3 (1/5 + 4/10)).
	CHECK(f.p[0] == doctest::Approx(1.0).epsilon(1e-6));
	CHECK(f.p[1] == doctest::Approx(2.0).epsilon(1e-6));
	CHECK(f.se[1] == doctest::Approx(std::sqrt(4.0 / 3.0 / 10.0)).epsilon(1e-5));
	CHECK(f.se[0] == doctest::Approx(std::sqrt(4.0 / 3.0 * (0.2 + 0.4))).epsilon(1e-5));
}

TEST_CASE("MeanAndError: the standard error of the mean")
{
	double mean = 0.0, se = 0.0;
	MeanAndError({1.0, 2.0, 3.0, 4.0}, mean, se);
	CHECK(mean == doctest::Approx(2.5));
	CHECK(se == doctest::Approx(std::sqrt((2.25 + 0.25 + 0.25 + 2.25) / 3.0 / 4.0)));
}

// Solve3, SolveBordered and SolveBorderedSolution (numerics/SmallLinear.h) against Eigen's
// pivoted LU: solutions, and the exact 1-norm condition number from Eigen's explicit inverse.
#include <doctest/doctest.h>

#include "TestSupport.h"
#include "numerics/SmallLinear.h"

#include <Eigen/Dense>

#include <cmath>

using namespace b2a;
using namespace b2a::test;

namespace
{
// rcond = 1 / (‖J‖₁ ‖J⁻¹‖₁) from Eigen.
double EigenRcond(const Eigen::Matrix3d& J)
{
	const Eigen::Matrix3d inv = J.partialPivLu().inverse();
	return 1.0 / (J.cwiseAbs().colwise().sum().maxCoeff() * inv.cwiseAbs().colwise().sum().maxCoeff());
}
} // namespace

TEST_CASE("small linear: Solve3 and SolveBordered match Eigen on bordered Newton matrices, solution and condition; SolveBorderedSolution is SolveBordered's solution")
{
	// The matrices the common-level Newton builds: [[H, g], [dᵀ, 0]] with H symmetric (positive
	// or not), entries spread over six orders of magnitude, and conditions down to ~1e-10.
	Random rng(17);
	double worstX = 0.0, worstRcond = 0.0, worstAgree = 0.0;
	for (int k = 0; k < 2000; ++k)
	{
		auto entry = [&] { return (rng.Uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0) * rng.LogUniform(1e-3, 1e3); };
		const double h11 = entry(), h12 = entry(), h22 = entry(), g1 = entry(), g2 = entry(), d1 = entry();
		// Some nearly singular: d almost along a direction that makes det vanish.
		const double d2 = k % 4 == 0 ? d1 * (h12 * g2 - g1 * h22) / (h11 * g2 - g1 * h12) * (1.0 + 1e-8 * rng.Uniform(-1.0, 1.0)) : entry();
		const double r[3] = {entry(), entry(), entry()};
		Eigen::Matrix3d J;
		J << h11, h12, g1, h12, h22, g2, d1, d2, 0.0;
		const Eigen::Vector3d want = J.partialPivLu().solve(Eigen::Vector3d(r[0], r[1], r[2]));
		const double rcond = EigenRcond(J);
		const double Jr[3][3] = {{h11, h12, g1}, {h12, h22, g2}, {d1, d2, 0.0}};
		const Solve3Result full = Solve3(Jr, r);
		const Solve3Result bordered = SolveBordered(h11, h12, h22, g1, g2, d1, d2, r);
		// Without the condition number: the same solution, bit for bit.
		double alone[3] = {0.0, 0.0, 0.0};
		REQUIRE(SolveBorderedSolution(h11, h12, h22, g1, g2, d1, d2, r, alone));
		CHECK(alone[0] == bordered.x[0]);
		CHECK(alone[1] == bordered.x[1]);
		CHECK(alone[2] == bordered.x[2]);
		REQUIRE(full.rcond > 0.0);
		REQUIRE(bordered.rcond > 0.0);
		// A solve loses about eps / rcond of the solution's size.
		const double scale = want.cwiseAbs().maxCoeff();
		for (int i = 0; i < 3; ++i)
		{
			worstX = std::max(worstX, std::fabs(bordered.x[i] - want(i)) / scale * rcond);
			worstAgree = std::max(worstAgree, std::fabs(bordered.x[i] - full.x[i]) / scale * rcond);
		}
		worstRcond = std::max({worstRcond, RelativeError(bordered.rcond, rcond), RelativeError(full.rcond, rcond)});
	}
	CAPTURE(worstX);
	CAPTURE(worstAgree);
	CAPTURE(worstRcond);
	CHECK(worstX <= 1e-13);      // i.e. the error is within ~500 eps / rcond
	CHECK(worstAgree <= 1e-13);
	// The condition number itself, to a relative 1e-4: near-singular matrices lose digits in both
	// computations (measured 2.6e-5); the solvers only compare it with 1e-14.
	CHECK(worstRcond <= 1e-4);
}

TEST_CASE("small linear: singular and non-finite matrices give rcond 0 and a zero solution, or no solution")
{
	const double r[3] = {1.0, 2.0, 3.0};
	// d parallel to what makes the determinant vanish exactly: H = I, g = (1, 0), d = (0, 0).
	const Solve3Result singular = SolveBordered(1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, r);
	CHECK(singular.rcond == 0.0);
	CHECK(singular.x[0] == 0.0);
	double x[3] = {7.0, 7.0, 7.0};
	CHECK_FALSE(SolveBorderedSolution(1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, r, x));
	CHECK_FALSE(SolveBorderedSolution(std::nan(""), 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, r, x));
	CHECK(x[0] == 7.0); // untouched
	const Solve3Result nan = SolveBordered(std::nan(""), 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, r);
	CHECK(nan.rcond == 0.0);
	// A regular one, for contrast: [[1, 0, 1], [0, 1, 0], [1, 0, 0]] x = (1, 2, 3) has x = (3, 2, −2).
	const Solve3Result regular = SolveBordered(1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, r);
	CHECK(regular.rcond > 0.0);
	CHECK(std::fabs(regular.x[0] - 3.0) <= 1e-15);
	CHECK(std::fabs(regular.x[1] - 2.0) <= 1e-15);
	CHECK(std::fabs(regular.x[2] + 2.0) <= 1e-15);
	const double huge = 1e300;
	const Solve3Result overflow = SolveBordered(huge, huge, huge, huge, huge, huge, -huge, r);
	CHECK(overflow.rcond == 0.0);
}

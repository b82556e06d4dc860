// b2analytic demos: weighted least-squares fits of flow laws (Beverloo, Mankoc et al.) and of
// exponential growth, with standard errors.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace b2a::demo
{

/// The result of a weighted nonlinear least-squares fit.
struct CurveFit
{
	std::vector<double> p;    ///< fitted parameters
	std::vector<double> se;   ///< their standard errors: √ of the covariance's diagonal, scaled by χ²/(n − p) where that exceeds 1; NaN for a parameter the data leave undetermined
	double chi2 = 0.0;        ///< Σ ((y − f)/σ)²
	int dof = 0;              ///< points minus parameters
	int iterations = 0;       ///< Levenberg–Marquardt iterations taken
	bool converged = false;   ///< the relative change of χ² fell below 1e-12 within the iteration cap
	std::vector<double> normalisedResiduals; ///< (y − f)/σ at each point
};

/// A model y = f(x; p).
using Model = std::function<double(double x, const std::vector<double>& p)>;

/// Fit `model` to points (x, y ± sigma) from the start `p0` by Levenberg–Marquardt with a
/// forward-difference Jacobian, at most 200 iterations. Points with sigma <= 0 get the mean
/// positive sigma.
CurveFit FitCurve(const Model& model, const std::vector<double>& x, const std::vector<double>& y, std::vector<double> sigma,
                  std::vector<double> p0);

/// Beverloo's 2D law Q = C ρ √g (D − k d)^{3/2} as a model of D (mm) with p = {C, k}; zero where
/// D <= k d.
Model BeverlooModel(double rho, double g, double d);

/// The 2D form of Mankoc et al. (2007): Q = C ρ √g [1 − ½ exp(−b (D − d)/d)] (D − d)^{3/2}, p = {C, b}.
Model MankocModel(double rho, double g, double d);

/// Mean and standard error of the mean of `values` (0 for fewer than two).
void MeanAndError(const std::vector<double>& values, double& mean, double& se);

} // namespace b2a::demo

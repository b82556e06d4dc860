// b2analytic demos: weighted least-squares fits of flow laws.
#include "FlowFit.h"

#include <algorithm>
#include <cmath>

namespace b2a::demo
{

namespace
{
// Solve the small symmetric positive definite system A x = b by Gaussian elimination with
// partial pivoting; returns false if A is singular.
bool Solve(std::vector<std::vector<double>> A, std::vector<double> b, std::vector<double>& x)
{
	const size_t n = b.size();
	for (size_t c = 0; c < n; ++c)
	{
		size_t pivot = c;
		for (size_t r = c + 1; r < n; ++r)
			if (std::fabs(A[r][c]) > std::fabs(A[pivot][c]))
				pivot = r;
		if (!(std::fabs(A[pivot][c]) > 0.0))
			return false;
		std::swap(A[c], A[pivot]);
		std::swap(b[c], b[pivot]);
		for (size_t r = c + 1; r < n; ++r)
		{
			const double f = A[r][c] / A[c][c];
			for (size_t k = c; k < n; ++k)
				A[r][k] -= f * A[c][k];
			b[r] -= f * b[c];
		}
	}
	x.assign(n, 0.0);
	for (size_t c = n; c-- > 0;)
	{
		double s = b[c];
		for (size_t k = c + 1; k < n; ++k)
			s -= A[c][k] * x[k];
		x[c] = s / A[c][c];
	}
	return true;
}

double Chi2(const Model& f, const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& s,
            const std::vector<double>& p)
{
	double c = 0.0;
	for (size_t i = 0; i < x.size(); ++i)
	{
		const double r = (y[i] - f(x[i], p)) / s[i];
		c += r * r;
	}
	return c;
}
} // namespace

CurveFit FitCurve(const Model& model, const std::vector<double>& x, const std::vector<double>& y, std::vector<double> sigma,
                  std::vector<double> p0)
{
	const size_t n = x.size(), m = p0.size();
	double meanSigma = 0.0;
	int positive = 0;
	for (double s : sigma)
		if (s > 0.0)
		{
			meanSigma += s;
			++positive;
		}
	meanSigma = positive > 0 ? meanSigma / positive : 1.0;
	for (double& s : sigma)
		if (!(s > 0.0))
			s = meanSigma;

	// Jacobian of the residuals' model values, by forward differences.
	const auto jacobian = [&](const std::vector<double>& p) {
		std::vector<std::vector<double>> J(n, std::vector<double>(m));
		for (size_t k = 0; k < m; ++k)
		{
			std::vector<double> q = p;
			const double h = 1e-7 * std::max(1e-3, std::fabs(p[k]));
			q[k] += h;
			for (size_t i = 0; i < n; ++i)
				J[i][k] = (model(x[i], q) - model(x[i], p)) / h;
		}
		return J;
	};
	const auto normal = [&](const std::vector<std::vector<double>>& J, std::vector<std::vector<double>>& A) {
		A.assign(m, std::vector<double>(m, 0.0));
		for (size_t i = 0; i < n; ++i)
			for (size_t a = 0; a < m; ++a)
				for (size_t b = 0; b < m; ++b)
					A[a][b] += J[i][a] * J[i][b] / (sigma[i] * sigma[i]);
	};

	CurveFit fit;
	std::vector<double> p = p0;
	double chi2 = Chi2(model, x, y, sigma, p), lambda = 1e-3;
	for (fit.iterations = 0; fit.iterations < 200; ++fit.iterations)
	{
		const auto J = jacobian(p);
		std::vector<std::vector<double>> A;
		normal(J, A);
		std::vector<double> g(m, 0.0);
		for (size_t i = 0; i < n; ++i)
			for (size_t a = 0; a < m; ++a)
				g[a] += J[i][a] * (y[i] - model(x[i], p)) / (sigma[i] * sigma[i]);
		bool improved = false;
		for (int tries = 0; tries < 30 && !improved; ++tries)
		{
			auto B = A;
			for (size_t a = 0; a < m; ++a)
				B[a][a] *= 1.0 + lambda;
			std::vector<double> step;
			if (!Solve(B, g, step))
				break;
			std::vector<double> q = p;
			for (size_t a = 0; a < m; ++a)
				q[a] += step[a];
			const double c = Chi2(model, x, y, sigma, q);
			if (std::isfinite(c) && c <= chi2)
			{
				const double change = (chi2 - c) / std::max(1e-300, chi2);
				p = q;
				chi2 = c;
				lambda = std::max(1e-12, lambda * 0.3);
				improved = true;
				if (change < 1e-12)
					fit.converged = true;
			}
			else
				lambda *= 10.0;
		}
		if (!improved)
			fit.converged = true; // no step lowers χ²: a minimum to the solver's resolution
		if (fit.converged)
			break;
	}
	fit.p = p;
	fit.chi2 = chi2;
	fit.dof = int(n) - int(m);
	std::vector<std::vector<double>> A;
	normal(jacobian(p), A);
	const double scale = fit.dof > 0 ? std::max(1.0, chi2 / fit.dof) : 1.0;
	fit.se.assign(m, 0.0);
	for (size_t k = 0; k < m; ++k)
	{
		std::vector<double> e(m, 0.0), col;
		e[k] = 1.0;
		// A singular normal matrix: the parameter is not determined by the data (no error to give).
		fit.se[k] = Solve(A, e, col) && col[k] > 0.0 ? std::sqrt(col[k] * scale) : std::nan("");
	}
	for (size_t i = 0; i < n; ++i)
		fit.normalisedResiduals.push_back((y[i] - model(x[i], p)) / sigma[i]);
	return fit;
}

Model BeverlooModel(double rho, double g, double d)
{
	return [=](double D, const std::vector<double>& p) { return p[0] * rho * std::sqrt(g) * std::pow(std::max(0.0, D - p[1] * d), 1.5); };
}

Model MankocModel(double rho, double g, double d)
{
	return [=](double D, const std::vector<double>& p) {
		return p[0] * rho * std::sqrt(g) * (1.0 - 0.5 * std::exp(-p[1] * (D - d) / d)) * std::pow(std::max(0.0, D - d), 1.5);
	};
}

void MeanAndError(const std::vector<double>& values, double& mean, double& se)
{
	const double n = double(values.size());
	mean = 0.0;
	se = 0.0;
	if (values.empty())
		return;
	for (double v : values)
		mean += v / n;
	if (values.size() < 2)
		return;
	double ss = 0.0;
	for (double v : values)
		ss += (v - mean) * (v - mean);
	se = std::sqrt(ss / (n - 1.0) / n);
}

} // namespace b2a::demo

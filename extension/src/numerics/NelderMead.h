// b2analytic: Nelder–Mead minimisation in two variables (internal).
#pragma once

#include <algorithm>
#include <cmath>

namespace b2a
{

/// Outcome of a two-variable minimisation.
struct Minimum2
{
	double x[2] = {0.0, 0.0}; ///< the minimiser
	double fx = 0.0;          ///< f there
	int evaluations = 0;      ///< evaluations of f
	bool converged = false;   ///< the simplex shrank below the tolerance within the cap
};

/// Nelder and Mead's simplex method (standard coefficients: reflection 1, expansion 2,
/// contraction 1/2, shrink 1/2) for a local minimum of f(x, y) from (x0, y0) with a first
/// simplex of size `step`. Needs no derivatives, so it serves where the function has kinks (a
/// superellipsoid's edges, exponents below 2). Stops when the simplex is below `xtol` across
/// (absolute) or after `maxEvaluations`.
template <class F>
Minimum2 MinimizeNelderMead(F&& f, double x0, double y0, double step, double xtol, int maxEvaluations = 400)
{
	double p[3][2] = {{x0, y0}, {x0 + step, y0}, {x0, y0 + step}};
	double v[3];
	Minimum2 out;
	for (int i = 0; i < 3; ++i)
		v[i] = f(p[i][0], p[i][1]);
	out.evaluations = 3;
	auto order = [&]() {
		for (int i = 0; i < 2; ++i)
			for (int j = 0; j < 2 - i; ++j)
				if (v[j + 1] < v[j])
				{
					std::swap(v[j], v[j + 1]);
					std::swap(p[j][0], p[j + 1][0]);
					std::swap(p[j][1], p[j + 1][1]);
				}
	};
	while (out.evaluations < maxEvaluations)
	{
		order();
		const double size = std::max({std::fabs(p[1][0] - p[0][0]), std::fabs(p[1][1] - p[0][1]), std::fabs(p[2][0] - p[0][0]),
		                              std::fabs(p[2][1] - p[0][1])});
		if (size <= xtol)
		{
			out.converged = true;
			break;
		}
		const double c[2] = {0.5 * (p[0][0] + p[1][0]), 0.5 * (p[0][1] + p[1][1])}; // centroid of the best two
		auto along = [&](double t, double q[2]) {
			q[0] = c[0] + t * (p[2][0] - c[0]);
			q[1] = c[1] + t * (p[2][1] - c[1]);
			return f(q[0], q[1]);
		};
		double r[2], e[2], k[2];
		const double vr = along(-1.0, r);
		++out.evaluations;
		if (vr < v[0])
		{
			const double ve = along(-2.0, e);
			++out.evaluations;
			const bool expand = ve < vr;
			p[2][0] = expand ? e[0] : r[0];
			p[2][1] = expand ? e[1] : r[1];
			v[2] = expand ? ve : vr;
			continue;
		}
		if (vr < v[1])
		{
			p[2][0] = r[0];
			p[2][1] = r[1];
			v[2] = vr;
			continue;
		}
		const bool outside = vr < v[2];
		const double vk = along(outside ? -0.5 : 0.5, k);
		++out.evaluations;
		if (vk < (outside ? vr : v[2]))
		{
			p[2][0] = k[0];
			p[2][1] = k[1];
			v[2] = vk;
			continue;
		}
		for (int i = 1; i < 3; ++i) // shrink towards the best
		{
			p[i][0] = 0.5 * (p[0][0] + p[i][0]);
			p[i][1] = 0.5 * (p[0][1] + p[i][1]);
			v[i] = f(p[i][0], p[i][1]);
		}
		out.evaluations += 2;
	}
	order();
	out.x[0] = p[0][0];
	out.x[1] = p[0][1];
	out.fx = v[0];
	return out;
}

} // namespace b2a

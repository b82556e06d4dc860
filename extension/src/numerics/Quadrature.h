// b2analytic: adaptive Gauss–Kronrod quadrature of vector-valued integrands (internal).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <vector>

namespace b2a
{

/// Result of an adaptive quadrature.
template <int K>
struct QuadratureResult
{
	std::array<double, K> value{}; ///< the integrals
	std::array<double, K> error{}; ///< estimated absolute errors
	int intervals = 0;             ///< subintervals used
	bool converged = false;        ///< every component met the tolerance within the cap
};

namespace detail
{
// Gauss–Kronrod 7/15 nodes and weights (Kronrod 1965; as tabulated in QUADPACK).
inline constexpr double kGkNodes[8] = {
	0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
	0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
	0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
	0.207784955007898467600689403773245, 0.0};
inline constexpr double kKronrodWeights[8] = {
	0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
	0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
	0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
	0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss weights for nodes 1, 3, 5, 7 of the Kronrod set.
inline constexpr double kGaussWeights[4] = {
	0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
	0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <int K>
struct GkInterval
{
	double a, b;
	std::array<double, K> value, error, absValue;
	double priority;
	bool operator<(const GkInterval& o) const { return priority < o.priority; }
};

template <int K, class F>
GkInterval<K> GkRule(F& f, double a, double b)
{
	const double c = 0.5 * (a + b), h = 0.5 * (b - a);
	std::array<double, K> kron{}, gauss{}, absv{};
	auto add = [&](double x, double wk, double wg) {
		const std::array<double, K> v = f(x);
		for (int k = 0; k < K; ++k)
		{
			kron[k] += wk * v[k];
			gauss[k] += wg * v[k];
			absv[k] += wk * std::fabs(v[k]);
		}
	};
	add(c, kKronrodWeights[7], kGaussWeights[3]);
	for (int i = 0; i < 7; ++i)
	{
		const double wg = (i % 2 == 1) ? kGaussWeights[i / 2] : 0.0;
		add(c - h * kGkNodes[i], kKronrodWeights[i], wg);
		add(c + h * kGkNodes[i], kKronrodWeights[i], wg);
	}
	GkInterval<K> iv;
	iv.a = a;
	iv.b = b;
	iv.priority = 0.0;
	for (int k = 0; k < K; ++k)
	{
		iv.value[k] = h * kron[k];
		iv.absValue[k] = std::fabs(h) * absv[k];
		iv.error[k] = std::fabs(h * (kron[k] - gauss[k]));
	}
	return iv;
}
} // namespace detail

/// Integrate the K-vector function f over the breakpoints [x0, x1, ..., xn] (split at each,
/// e.g. at corners of a surface) to relative tolerance rtol of ∫|f| per component.
/// Subdivides the interval with the largest error first, at most maxIntervals times.
template <int K, class F>
QuadratureResult<K> IntegrateAdaptive(F&& f, const std::vector<double>& breaks, double rtol, int maxIntervals = 4000)
{
	using Interval = detail::GkInterval<K>;
	std::priority_queue<Interval> queue;
	std::array<double, K> total{}, totalErr{}, totalAbs{};
	// Priority: the interval's error relative to the whole integral's size, worst component.
	// (Its own relative error times its width would starve a narrow interval at a singularity.)
	auto push = [&](Interval iv) {
		for (int k = 0; k < K; ++k)
		{
			total[k] += iv.value[k];
			totalErr[k] += iv.error[k];
			totalAbs[k] += iv.absValue[k];
		}
		double pr = 0.0;
		for (int k = 0; k < K; ++k)
			pr = std::max(pr, iv.error[k] / (totalAbs[k] + 1e-300));
		iv.priority = pr;
		queue.push(iv);
	};
	for (size_t i = 0; i + 1 < breaks.size(); ++i)
		push(detail::GkRule<K>(f, breaks[i], breaks[i + 1]));

	QuadratureResult<K> r;
	auto done = [&] {
		for (int k = 0; k < K; ++k)
			if (totalErr[k] > rtol * totalAbs[k]) return false;
		return true;
	};
	while (!done() && int(queue.size()) < maxIntervals)
	{
		Interval worst = queue.top();
		queue.pop();
		for (int k = 0; k < K; ++k)
		{
			total[k] -= worst.value[k];
			totalErr[k] -= worst.error[k];
			totalAbs[k] -= worst.absValue[k];
		}
		const double mid = 0.5 * (worst.a + worst.b);
		push(detail::GkRule<K>(f, worst.a, mid));
		push(detail::GkRule<K>(f, mid, worst.b));
	}
	// Re-sum from the remaining intervals to avoid drift from the running subtraction.
	total = {};
	totalErr = {};
	r.intervals = int(queue.size());
	while (!queue.empty())
	{
		const Interval& iv = queue.top();
		for (int k = 0; k < K; ++k)
		{
			total[k] += iv.value[k];
			totalErr[k] += iv.error[k];
		}
		queue.pop();
	}
	r.value = total;
	r.error = totalErr;
	r.converged = true;
	for (int k = 0; k < K; ++k)
		if (totalErr[k] > rtol * totalAbs[k] * 1.0000001) r.converged = false;
	return r;
}

} // namespace b2a

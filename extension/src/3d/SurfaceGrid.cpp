// b2analytic: spreading the nodes of a surface parameter grid.
#include "3d/SurfaceGrid.h"

#include <algorithm>
#include <cmath>

namespace b2a
{

namespace
{
// Cumulative weight along a densely sampled curve, normalised to end at 1: half arc length, half
// turning (the angle between consecutive chords), each normalised by its total.
std::vector<double> CumulativeWeight(const std::vector<Vec3>& p)
{
	const size_t m = p.size();
	std::vector<double> arc(m, 0.0), turn(m, 0.0);
	for (size_t j = 1; j < m; ++j)
	{
		arc[j] = arc[j - 1] + Distance(p[j], p[j - 1]);
		double angle = 0.0;
		if (j + 1 < m)
		{
			const Vec3 u = Normalize(p[j] - p[j - 1]), v = Normalize(p[j + 1] - p[j]);
			if (LengthSquared(u) > 0.0 && LengthSquared(v) > 0.0)
				angle = std::atan2(Length(Cross(u, v)), Dot(u, v));
		}
		turn[j] = turn[j - 1] + angle;
	}
	const double arcTotal = arc.back(), turnTotal = turn.back();
	std::vector<double> w(m, 0.0);
	for (size_t j = 0; j < m; ++j)
	{
		const double a = arcTotal > 0.0 ? arc[j] / arcTotal : double(j) / double(m - 1);
		const double t = turnTotal > 0.0 ? turn[j] / turnTotal : a;
		w[j] = 0.5 * (a + t);
	}
	w.back() = 1.0;
	return w;
}
} // namespace

std::vector<double> SpreadParameters(const std::vector<std::function<Vec3(double)>>& curves, double lo, double hi, int count,
                                     bool cyclic)
{
	const int dense = 2048;
	std::vector<double> param(dense + 1), weight(dense + 1, 0.0);
	for (int j = 0; j <= dense; ++j)
		param[j] = lo + (hi - lo) * j / dense;
	for (const auto& curve : curves)
	{
		std::vector<Vec3> p(dense + 1);
		for (int j = 0; j <= dense; ++j)
			p[j] = curve(param[j]);
		const std::vector<double> w = CumulativeWeight(p);
		for (int j = 0; j <= dense; ++j)
			weight[j] += w[j] / double(curves.size());
	}
	std::vector<double> out(count);
	int j = 0;
	for (int k = 0; k < count; ++k)
	{
		const double target = cyclic ? double(k) / count : double(k + 1) / (count + 1);
		while (j + 1 < dense && weight[j + 1] < target)
			++j;
		const double span = weight[j + 1] - weight[j];
		const double f = span > 0.0 ? std::clamp((target - weight[j]) / span, 0.0, 1.0) : 0.0;
		out[k] = param[j] + f * (param[j + 1] - param[j]);
	}
	return out;
}

SurfaceSamples3 BuildLatitudeLongitudeSamples(const std::function<Vec3(double, double)>& point, int count)
{
	SurfaceSamples3 s;
	int perRing = 4 * int(std::ceil(std::sqrt(2.0 * std::max(count, 16)) / 4.0));
	perRing = std::max(perRing, 8);
	s.perRing = perRing;
	s.rings = perRing / 2 - 1;
	const double half = 0.5 * 3.14159265358979323846;
	s.omega = SpreadParameters({[&](double w) { return point(0.0, w); }}, -2.0 * half, 2.0 * half, perRing, true);
	s.eta = SpreadParameters({[&](double e) { return point(e, 0.0); }, [&](double e) { return point(e, half); }}, -half, half,
	                         s.rings, false);
	s.point.reserve(size_t(s.rings) * perRing + 2);
	for (int r = 0; r < s.rings; ++r)
		for (int k = 0; k < perRing; ++k)
			s.point.push_back(point(s.eta[r], s.omega[k]));
	s.point.push_back(point(-half, 0.0));
	s.point.push_back(point(half, 0.0));
	std::vector<int> nb;
	for (int i = 0; i < s.Count(); ++i)
	{
		s.Neighbours(i, nb);
		for (int j : nb)
			s.maxSpacing = std::max(s.maxSpacing, Distance(s.point[i], s.point[j]));
	}
	return s;
}

} // namespace b2a

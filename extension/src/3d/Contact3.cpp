// b2analytic: the 3D contact from a level solution (points on both surfaces, normal,
// separation), and the axis of least overlap for coincident centres.
#include "3d/Solvers3.h"

#include "numerics/NelderMead.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace b2a
{

namespace
{
// The surface point of a shape on the ray from its centre towards X (always exists).
Vec3 RadialPoint(const Shape3& s, const Pose3& p, Vec3 X)
{
	Vec3 x = ToBody(p, X);
	if (!(LengthSquared(x) > 0.0))
		x = Vec3(1.0, 0.0, 0.0);
	return ToWorld(p, s.PointOnRay(x, s.SurfaceLevel()));
}

// A convex shape's extreme point along `dir` on the line through X (its far crossing), else the
// radial point towards X where the line misses it.
Vec3 LineExtreme(const Shape3& s, const Pose3& p, Vec3 X, Vec3 dir)
{
	double t = 0.0;
	if (s.FarCrossing(ToBody(p, X), InvRotate(p.q, dir), t))
		return X + t * dir;
	return RadialPoint(s, p, X);
}

// Depth of the overlap along the unit n: hA(n) + hB(−n) − (pB − pA)·n.
double OverlapDepth(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, Vec3 n)
{
	return a.SupportValue(InvRotate(pa.q, n)) + b.SupportValue(InvRotate(pb.q, -n)) - Dot(pb.p - pa.p, n);
}

Vec3 UnitFromAngles(double theta, double phi)
{
	return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}
} // namespace

ContactResult3 OverlapAxisContact3(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb)
{
	// Coincident centres: no level point lies between them. The axis along which the overlap is
	// least (the separating-axis depth): the best of 256 directions spread over the sphere
	// (Fibonacci), the four lowest refined by Nelder–Mead in polar angles.
	const int count = 256;
	std::vector<std::pair<double, Vec3>> samples;
	samples.reserve(count);
	const double golden = kPi * (3.0 - std::sqrt(5.0));
	for (int k = 0; k < count; ++k)
	{
		const double z = 1.0 - (2.0 * k + 1.0) / count, r = std::sqrt(std::max(0.0, 1.0 - z * z));
		const Vec3 n(r * std::cos(golden * k), r * std::sin(golden * k), z);
		samples.push_back({OverlapDepth(a, pa, b, pb, n), n});
	}
	std::sort(samples.begin(), samples.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
	Vec3 best = samples[0].second;
	double bestDepth = samples[0].first;
	for (int c = 0; c < 4; ++c)
	{
		const Vec3 n0 = samples[c].second;
		const double theta0 = std::acos(std::clamp(n0.z, -1.0, 1.0)), phi0 = std::atan2(n0.y, n0.x);
		auto depth = [&](double t, double p) { return OverlapDepth(a, pa, b, pb, UnitFromAngles(t, p)); };
		const Minimum2 m = MinimizeNelderMead(depth, theta0, phi0, 0.1, 1e-13, 800);
		if (m.fx < bestDepth)
		{
			bestDepth = m.fx;
			best = UnitFromAngles(m.x[0], m.x[1]);
		}
	}
	ContactResult3 c;
	c.status = SolveStatus::converged;
	c.method = SolveMethod::overlapAxis;
	c.iterations = 1;
	c.normal = best;
	c.pointA = ToWorld(pa, a.Support(InvRotate(pa.q, best)));
	c.pointB = ToWorld(pb, b.Support(InvRotate(pb.q, -best)));
	c.point = 0.5 * (pa.p + pb.p);
	c.separation = Dot(c.pointB - c.pointA, best);
	c.touching = c.separation <= 0.0;
	c.level = 0.0;
	return c;
}

ContactResult3 ContactFromLevel(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const LevelResult3& level,
                                bool touching, bool pointOnB)
{
	ContactResult3 c;
	c.status = level.status;
	c.method = level.method;
	c.failure = level.failure;
	c.iterations = level.iterations;
	c.level = level.level;
	c.point = level.point;
	if (!level.Ok())
		return c;
	const Vec3 X = level.point;
	// The mean of A's outward and B's inward unit normals, which agree at a tangency. Where they
	// point the same way one centre lies inside the other: B's inward normal for a point on B's
	// surface (A leaves B fastest through it), else A's outward one.
	const Vec3 na = Normalize(Rotate(pa.q, a.Gradient(ToBody(pa, X))));
	const Vec3 nb = Normalize(Rotate(pb.q, b.Gradient(ToBody(pb, X))));
	const bool hasA = LengthSquared(na) > 0.0, hasB = LengthSquared(nb) > 0.0;
	Vec3 n;
	if (hasA && hasB)
		n = Dot(na, nb) < 0.0 ? Normalize(na - nb) : (pointOnB ? -nb : na);
	else if (hasA)
		n = na;
	else if (hasB)
		n = -nb;
	if (!(LengthSquared(n) > 0.0))
		n = Normalize(pb.p - pa.p);
	if (!(LengthSquared(n) > 0.0))
		n = Vec3(1.0, 0.0, 0.0);
	c.normal = n;
	c.pointA = LineExtreme(a, pa, X, n);
	c.pointB = LineExtreme(b, pb, X, -n);
	c.separation = Dot(c.pointB - c.pointA, n);
	// The level's verdict decides; the separation's sign follows it at rounding level.
	if (touching && c.separation > 0.0)
		c.separation = 0.0;
	else if (!touching && !(c.separation > 0.0))
		c.separation = std::numeric_limits<double>::denorm_min();
	c.touching = touching;
	return c;
}

ContactResult3 FlipContact(const ContactResult3& c)
{
	ContactResult3 f = c;
	f.normal = -c.normal;
	f.pointA = c.pointB;
	f.pointB = c.pointA;
	return f;
}

} // namespace b2a

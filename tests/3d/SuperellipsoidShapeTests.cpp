// The superellipsoid family's geometry against independent references: finite differences,
// closed forms (sphere, ellipsoid, the cube limit), tanh–sinh quadrature of the volume and
// second moments, long-double bisection, brute-force maxima over dense surface samples.
#include <doctest/doctest.h>

#include "b2analytic/3d/SuperellipsoidShape.h"
#include "Reference3.h"
#include "3d/Random3.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;
namespace r3 = b2a::test::ref3;

namespace
{
std::vector<std::shared_ptr<SuperellipsoidShape>> Family()
{
	return {MakeSphere(1.5),
	        MakeEllipsoid(3.0, 1.0, 0.5),
	        MakeEllipsoid(100.0, 1.0, 1.0),
	        MakeSuperellipsoid(4, 4, 4, 6, 6, 12),    // the paper's Figure 17, particle i
	        MakeSuperellipsoid(2, 3, 2, 8, 8, 8),     // particle j
	        MakeSuperellipsoid(1.0, 2.5, 0.7, 2.5, 3.7, 5.3),
	        MakeSuperellipsoid(2.0, 1.0, 1.0, 20, 20, 20),
	        MakeSuperellipsoid(1.0, 1.2, 0.8, 1.5, 3.0, 1.2),
	        MakeSuperellipsoid(1.0, 1.0, 1.0, 1, 1, 1)};
}



// ∫₀¹ f by tanh–sinh (double-exponential) quadrature: exact to ~1e-15 for integrands with
// algebraic singularities at the ends, as the superellipsoid's profiles have.
double TanhSinh01(const std::function<double(double)>& f, int levels = 7)
{
	const double h0 = 1.0;
	double sum = 0.0, h = h0;
	auto term = [&](double t) {
		const double u = 0.5 * kPi * std::sinh(t);
		const double x = 0.5 * (1.0 + std::tanh(u)); // in (0, 1)
		const double w = 0.25 * kPi * std::cosh(t) / (std::cosh(u) * std::cosh(u));
		return (x > 0.0 && x < 1.0) ? w * f(x) : 0.0;
	};
	for (int k = -40; k <= 40; ++k)
		sum += term(k * h);
	double result = sum * h;
	for (int level = 1; level <= levels; ++level)
	{
		h *= 0.5;
		for (int k = 1 - int(40 / h); k <= int(40 / h); k += 2)
			sum += term(k * h);
		result = sum * h;
	}
	return result;
}
} // namespace

TEST_CASE("superellipsoid: invalid parameters name the field and the value")
{
	auto message = [](const std::function<void()>& make) {
		try
		{
			make();
		}
		catch (const InvalidParameter& e)
		{
			return std::string(e.what()) + " | " + e.Field();
		}
		return std::string("no exception");
	};
	CHECK(message([] { MakeSuperellipsoid(0, 1, 1, 2, 2, 2); }) == "superellipsoid: field 'a' must be finite and > 0, got 0 | a");
	CHECK(message([] { MakeSuperellipsoid(1, -2, 1, 2, 2, 2); }) == "superellipsoid: field 'b' must be finite and > 0, got -2 | b");
	CHECK(message([] { MakeSuperellipsoid(1, 1, NAN, 2, 2, 2); }) == "superellipsoid: field 'c' must be finite and > 0, got nan | c");
	CHECK(message([] { MakeSuperellipsoid(1, 1, 1, 0.5, 2, 2); }) == "superellipsoid: field 'n1' must be finite and >= 1, got 0.5 | n1");
	CHECK(message([] { MakeSuperellipsoid(1, 1, 1, 2, INFINITY, 2); }) == "superellipsoid: field 'n2' must be finite and >= 1, got inf | n2");
	CHECK(message([] { MakeSphere(0.0); }) == "sphere: field 'r' must be finite and > 0, got 0 | r");
	// Powers beyond double precision's range: |1/a|^n overflows.
	CHECK(message([] { MakeSuperellipsoid(1e-30, 1, 1, 100, 2, 2); }).find("field 'a'") != std::string::npos);
	CHECK(message([] { MakeSuperellipsoid(1, 1, 1, 2, 2, 1e6); }).find("field 'n3'") != std::string::npos);
}

TEST_CASE("superellipsoid: kinds and descriptions")
{
	CHECK(std::string(MakeSphere(2)->KindName()) == "sphere");
	CHECK(std::string(MakeEllipsoid(2, 1, 1)->KindName()) == "ellipsoid");
	CHECK(std::string(MakeSuperellipsoid(2, 1, 1, 4, 4, 2)->KindName()) == "superellipsoid");
	CHECK(std::string(MakeSuperellipsoid(2, 1, 1, 4, 1.5, 2)->KindName()) == "convex_superellipsoid");
	CHECK(MakeSphere(2)->Describe() == "sphere(r=2)");
	CHECK(MakeSuperellipsoid(4, 4, 4, 6, 6, 12)->Describe() == "superellipsoid(a=4, b=4, c=4, n1=6, n2=6, n3=12)");
	CHECK(MakeSuperellipsoid(4, 4, 4, 6, 6, 12)->IsSmoothConvex());
	CHECK_FALSE(MakeSuperellipsoid(4, 4, 4, 6, 1.5, 12)->IsSmoothConvex());
}

TEST_CASE("superellipsoid: derivatives against central differences")
{
	Random rng(11);
	for (const auto& s : Family())
	{
		for (int k = 0; k < 40; ++k)
		{
			// Points off the coordinate planes (where exponents below 2 have no second derivative).
			Vec3 x = rng.Uniform(0.3, 1.4) * RandomUnit(rng);
			for (int i = 0; i < 3; ++i)
				x[i] = s->Axis(i) * (std::fabs(x[i]) < 0.05 ? 0.05 : x[i]);
			const LevelDerivatives3 d = s->Derivatives(x);
			CHECK(d.value == doctest::Approx(s->Level(x)).epsilon(1e-14));
			const Vec3 g = s->Gradient(x);
			for (int i = 0; i < 3; ++i)
			{
				const double h = 1e-6 * s->Axis(i);
				Vec3 xp = x, xm = x;
				xp[i] += h;
				xm[i] -= h;
				const double fd = (s->Level(xp) - s->Level(xm)) / (2 * h);
				const double scale = Length(d.gradient) + 1e-12;
				CHECK(std::fabs(d.gradient[i] - fd) / scale < 1e-7);
				CHECK(g[i] == doctest::Approx(d.gradient[i]).epsilon(1e-14));
				const Vec3 gp = s->Gradient(xp), gm = s->Gradient(xm);
				const double hess[3] = {d.hessian.xx, d.hessian.yy, d.hessian.zz};
				const double hscale = std::fabs(hess[0]) + std::fabs(hess[1]) + std::fabs(hess[2]) + 1e-12;
				CHECK(std::fabs(hess[i] - (gp[i] - gm[i]) / (2 * h)) / hscale < 1e-6);
				for (int j = 0; j < 3; ++j)
					if (j != i)
						CHECK(std::fabs(gp[j] - gm[j]) / (2 * h) / hscale < 1e-9); // no mixed terms
			}
			CHECK(d.hessian.xy == 0.0);
			CHECK(d.hessian.xz == 0.0);
			CHECK(d.hessian.yz == 0.0);
		}
	}
}

TEST_CASE("superellipsoid: volume and inertia against closed forms")
{
	// Sphere: 4/3 π r³, inertia 2/5 r² per unit mass on every axis.
	const double r = 1.7;
	const auto sphere = MakeSphere(r);
	const double V = 4.0 / 3.0 * kPi * r * r * r;
	CHECK(sphere->Mass().volume == doctest::Approx(V).epsilon(1e-14));
	CHECK(sphere->Mass().inertia.xx == doctest::Approx(0.4 * V * r * r).epsilon(1e-14));
	CHECK(sphere->Mass().inertia.zz == doctest::Approx(0.4 * V * r * r).epsilon(1e-14));
	// Ellipsoid: 4/3 π abc, Ixx = V (b² + c²)/5.
	const double a = 3, b = 1.2, c = 0.5;
	const auto e = MakeEllipsoid(a, b, c);
	const double Ve = 4.0 / 3.0 * kPi * a * b * c;
	CHECK(e->Mass().volume == doctest::Approx(Ve).epsilon(1e-14));
	CHECK(e->Mass().inertia.xx == doctest::Approx(Ve * (b * b + c * c) / 5).epsilon(1e-14));
	CHECK(e->Mass().inertia.yy == doctest::Approx(Ve * (a * a + c * c) / 5).epsilon(1e-14));
	CHECK(e->Mass().inertia.zz == doctest::Approx(Ve * (a * a + b * b) / 5).epsilon(1e-14));
	CHECK(e->Mass().inertia.xy == 0.0);
	CHECK(LengthSquared(e->Mass().centroid) == 0.0);
	// The cube limit: exponents → ∞ give the box 8abc with Ixx = V (b² + c²)/3; the gap closes
	// like 1/n² (Γ(1+1/n)³/Γ(1+3/n) = 1 − π²/2n² + …: 1.2e-4 at n = 200).
	const double Vb = 8 * a * b * c, Ib = Vb * (b * b + c * c) / 3;
	double gapBefore = 1.0;
	for (double n : {50.0, 100.0, 200.0})
	{
		const auto box = MakeSuperellipsoid(a, b, c, n, n, n);
		const double gap = RelativeError(box->Mass().volume, Vb);
		CHECK(gap < 5.0 / (n * n));
		CHECK(gap < 0.3 * gapBefore);
		CHECK(RelativeError(box->Mass().inertia.xx, Ib) < 20.0 / (n * n));
		gapBefore = gap;
	}
	// An octahedron: all exponents 1, volume 4/3 abc.
	const auto oct = MakeSuperellipsoid(a, b, c, 1, 1, 1);
	CHECK(oct->Mass().volume == doctest::Approx(4.0 / 3.0 * a * b * c).epsilon(1e-14));
}

TEST_CASE("superellipsoid: volume and second moments against quadrature")
{
	// V/8 = ∫₀ᵃ ∫₀^{y(x)} z(x, y) dy dx with y(x) = b(1 − |x/a|^n1)^{1/n2} and
	// z(x, y) = c(1 − |x/a|^n1 − |y/b|^n2)^{1/n3}, by nested tanh–sinh quadrature.
	for (const auto& s : {MakeSuperellipsoid(1.0, 2.5, 0.7, 2.5, 3.7, 5.3), MakeSuperellipsoid(4, 4, 4, 6, 6, 12),
	                      MakeSuperellipsoid(1.0, 1.2, 0.8, 1.5, 3.0, 1.2)})
	{
		const double a = s->A(), b = s->B(), c = s->C(), n1 = s->Exponent(0), n2 = s->Exponent(1), n3 = s->Exponent(2);
		auto integral = [&](int power, int axis) {
			// ∫ x_axis^power dV over the first octant.
			return TanhSinh01([&](double u) {
				const double x = a * u, restX = 1.0 - std::pow(u, n1);
				const double ymax = b * std::pow(restX, 1.0 / n2);
				return a * TanhSinh01([&](double v) {
					const double y = ymax * v, rest = restX - std::pow(y / b, n2);
					const double zmax = c * std::pow(std::max(rest, 0.0), 1.0 / n3);
					// ∫₀^zmax z^k dz = zmax^{k+1}/(k+1)
					double value = zmax;
					if (power == 2 && axis == 2)
						value = zmax * zmax * zmax / 3.0;
					else if (power == 2)
						value = zmax * (axis == 0 ? x * x : y * y);
					return ymax * value;
				}, 6);
			}, 6);
		};
		CHECK(s->Mass().volume == doctest::Approx(8 * integral(0, 0)).epsilon(1e-9));
		CHECK(s->Mass().secondMoment.xx == doctest::Approx(8 * integral(2, 0)).epsilon(1e-9));
		CHECK(s->Mass().secondMoment.yy == doctest::Approx(8 * integral(2, 1)).epsilon(1e-9));
		CHECK(s->Mass().secondMoment.zz == doctest::Approx(8 * integral(2, 2)).epsilon(1e-9));
	}
}

TEST_CASE("superellipsoid: samples lie on the surface, spread over it")
{
	for (const auto& s : Family())
	{
		const SurfaceSamples3& samples = s->Samples(256);
		CHECK(samples.Count() >= 256);
		CHECK(samples.Count() == samples.rings * samples.perRing + 2);
		CHECK(&samples == &s->Samples(256)); // cached
		const r3::Shape ref(*s);
		for (const Vec3& p : samples.point)
			CHECK(std::fabs(double(ref.Level(r3::From(p))) - 1.0) < 1e-13);
		// The poles are the ends of the z axis; every sample's neighbours are within maxSpacing.
		CHECK(samples.point[samples.NorthPole()].z == doctest::Approx(s->C()));
		CHECK(samples.point[samples.SouthPole()].z == doctest::Approx(-s->C()));
		CHECK(samples.maxSpacing < s->BoundingRadius());
		CHECK(samples.maxSpacing > 0.0);
		// More samples, finer spacing.
		CHECK(s->Samples(4096).maxSpacing < 0.5 * samples.maxSpacing);
	}
}

TEST_CASE("superellipsoid: radius, ray points and far crossings against long-double bisection")
{
	Random rng(5);
	for (const auto& s : Family())
	{
		const r3::Shape ref(*s);
		for (int k = 0; k < 30; ++k)
		{
			const Vec3 u = RandomUnit(rng);
			const double level = rng.LogUniform(0.01, 100.0);
			const r3::V3 x = r3::OnLevel(ref, r3::From(u), level);
			CHECK(s->RadiusAt(u, level) == doctest::Approx(double(r3::Len(x))).epsilon(1e-14));
			const Vec3 p = s->PointOnRay(3.0 * u, level);
			CHECK(double(r3::Len(r3::From(p) - x)) < 1e-14 * s->BoundingRadius() * std::sqrt(level + 1));
			// The far crossing of a line through an interior point: on the surface, beyond it the
			// line is outside.
			const Vec3 inside = 0.5 * s->PointOnRay(RandomUnit(rng), 1.0);
			const Vec3 d = RandomUnit(rng);
			double t = 0.0;
			REQUIRE(s->FarCrossing(inside, d, t));
			CHECK(std::fabs(double(ref.Level(r3::From(inside + t * d))) - 1.0) < 1e-12);
			CHECK(t > 0.0);
			CHECK(double(ref.Level(r3::From(inside + (t * (1 + 1e-9)) * d))) > 1.0);
			// A line far outside misses.
			CHECK_FALSE(s->FarCrossing(inside + 3.0 * s->BoundingRadius() * Normalize(Cross(d, RandomUnit(rng))), d, t));
		}
	}
}

TEST_CASE("superellipsoid: support, bounding radius and AABB against brute force over dense samples")
{
	Random rng(7);
	for (const auto& s : Family())
	{
		const SurfaceSamples3& dense = s->Samples(60000);
		const r3::Shape ref(*s);
		// Bounding radius: at least every sample's distance, and attained within the samples'
		// resolution (exact where every exponent is at least 2).
		double farthest = 0.0;
		for (const Vec3& p : dense.point)
			farthest = std::max(farthest, Length(p));
		CHECK(s->BoundingRadius() >= farthest);
		bool smoothExponents = true;
		for (int i = 0; i < 3; ++i)
			smoothExponents = smoothExponents && s->Exponent(i) >= 2.0;
		if (smoothExponents)
			CHECK(s->BoundingRadius() <= farthest + dense.maxSpacing * dense.maxSpacing / s->BoundingRadius());
		for (int k = 0; k < 20; ++k)
		{
			// Support: on the surface, and the maximum of d·x over the samples to their spacing.
			const Vec3 d = RandomUnit(rng);
			const Vec3 sp = s->Support(d);
			CHECK(std::fabs(double(ref.Level(r3::From(sp))) - 1.0) < 1e-12);
			double best = -1e300;
			for (const Vec3& p : dense.point)
				best = std::max(best, Dot(p, d));
			CHECK(Dot(sp, d) >= best - 1e-12 * s->BoundingRadius());
			CHECK(Dot(sp, d) <= best + dense.maxSpacing);
			CHECK(s->SupportValue(d) == doctest::Approx(Dot(sp, d)).epsilon(1e-13));
			// AABB at a random pose: contains every sample, and each face is touched by the
			// support point along its axis.
			const Pose3 pose(Vec3(rng.Uniform(-5, 5), rng.Uniform(-5, 5), rng.Uniform(-5, 5)), RandomRotation(rng));
			const Box3 box = s->ComputeAABB(pose);
			Vec3 lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
			for (const Vec3& p : dense.point)
			{
				const Vec3 w = ToWorld(pose, p);
				for (int i = 0; i < 3; ++i)
				{
					lo[i] = std::min(lo[i], w[i]);
					hi[i] = std::max(hi[i], w[i]);
				}
			}
			for (int i = 0; i < 3; ++i)
			{
				CHECK(box.lower[i] <= lo[i] + 1e-12 * s->BoundingRadius());
				CHECK(box.upper[i] >= hi[i] - 1e-12 * s->BoundingRadius());
				CHECK(box.lower[i] >= lo[i] - dense.maxSpacing);
				CHECK(box.upper[i] <= hi[i] + dense.maxSpacing);
				Vec3 e;
				e[i] = 1.0;
				const Vec3 touch = ToWorld(pose, s->Support(InvRotate(pose.q, e)));
				CHECK(touch[i] == doctest::Approx(box.upper[i]).epsilon(1e-13));
			}
		}
	}
}

TEST_CASE("z-x-z Euler angles: R = Rz(psi) Rx(theta) Rz(phi), and back")
{
	auto Rz = [](double t) {
		Mat33 m;
		m.m[0][0] = std::cos(t); m.m[0][1] = -std::sin(t);
		m.m[1][0] = std::sin(t); m.m[1][1] = std::cos(t);
		return m;
	};
	auto Rx = [](double t) {
		Mat33 m;
		m.m[1][1] = std::cos(t); m.m[1][2] = -std::sin(t);
		m.m[2][1] = std::sin(t); m.m[2][2] = std::cos(t);
		return m;
	};
	Random rng(3);
	for (int k = 0; k < 50; ++k)
	{
		const double psi = rng.Uniform(-3, 3), theta = rng.Uniform(0.01, 3.1), phi = rng.Uniform(-3, 3);
		const Mat33 expected = Rz(psi) * Rx(theta) * Rz(phi);
		const Mat33 got = ToMatrix(EulerZXZ(psi, theta, phi));
		for (int i = 0; i < 3; ++i)
			for (int j = 0; j < 3; ++j)
				CHECK(got.m[i][j] == doctest::Approx(expected.m[i][j]).epsilon(1e-14));
		const Vec3 back = ToEulerZXZ(EulerZXZ(psi, theta, phi));
		CHECK(back.x == doctest::Approx(psi).epsilon(1e-12));
		CHECK(back.y == doctest::Approx(theta).epsilon(1e-12));
		CHECK(back.z == doctest::Approx(phi).epsilon(1e-12));
		// The quaternion rotates vectors as its matrix does.
		const Vec3 v = RandomUnit(rng);
		const Vec3 a = Rotate(EulerZXZ(psi, theta, phi), v), b = got * v;
		CHECK(Distance(a, b) < 1e-15 * 4);
		CHECK(Distance(InvRotate(EulerZXZ(psi, theta, phi), a), v) < 1e-15 * 4);
	}
}

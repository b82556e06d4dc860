// The 3D kinds in the one shape-kind registry, and the 3D dispatch table (the same PairTable as
// 2D's): built-in kinds, a kind registered at run time with its default cell and its own
// functions, flipped pairs, and the errors naming the field.
#include <doctest/doctest.h>

#include "b2analytic/3d/Contact3.h"
#include "b2analytic/3d/ShapeKind3.h"
#include "b2analytic/3d/SuperellipsoidShape.h"
#include "b2analytic/ShapeKind.h"

#include <cmath>
#include <string>

using namespace b2a;

namespace
{
// A ball of radius r, λ = |x|²/r², of a kind registered by the test: a shape a user could add.
class Ball final : public Shape3
{
public:
	Ball(ShapeKind kind, double r) : Shape3(kind, 1.0, true, true, 1.0), m_r(r)
	{
		MassProperties3 m;
		m.volume = 4.0 / 3.0 * kPi * r * r * r;
		Finalize(r, m);
	}
	std::string Describe() const override { return "ball(r=" + FormatNumber(m_r) + ")"; }
	double Level(Vec3 x) const override { return LengthSquared(x) / (m_r * m_r); }
	LevelDerivatives3 Derivatives(Vec3 x) const override
	{
		LevelDerivatives3 d;
		d.value = Level(x);
		d.gradient = (2.0 / (m_r * m_r)) * x;
		d.hessian.xx = d.hessian.yy = d.hessian.zz = 2.0 / (m_r * m_r);
		return d;
	}
	double RadiusAt(Vec3, double level) const override { return m_r * std::sqrt(level); }
	bool FarCrossing(Vec3 x, Vec3 d, double& t) const override
	{
		const double a = LengthSquared(d), b = Dot(x, d), c = LengthSquared(x) - m_r * m_r, disc = b * b - a * c;
		if (!(disc > 0.0))
			return false;
		t = (-b + std::sqrt(disc)) / a;
		return true;
	}
	Vec3 Support(Vec3 d) const override { return m_r * Normalize(d); }

private:
	SurfaceSamples3 BuildSamples(int) const override { return MakeSphere(m_r)->Samples(64); }
	double m_r;
};

int g_calls = 0;
ContactResult3 CountingContact(const Shape3& a, const Pose3& pa, const Shape3& b, const Pose3& pb, const SolverOptions& options,
                               WarmStart3* warm)
{
	++g_calls;
	// The Newton chain's answer, as a registered function might build on it.
	ContactResult3 c = ComputeContact(a, pa, b, pb, MethodChoice::newton, options, warm);
	c.iterations = 4242; // a mark: this function answered
	return c;
}
} // namespace

TEST_CASE("3D kinds: built in, of dimension 3, chosen by the superellipsoid's parameters")
{
	CHECK(FindShapeKind("sphere") == BuiltinKinds3::sphere);
	CHECK(FindShapeKind("ellipsoid") == BuiltinKinds3::ellipsoid);
	CHECK(FindShapeKind("superellipsoid") == BuiltinKinds3::superellipsoid);
	CHECK(FindShapeKind("convex_superellipsoid") == BuiltinKinds3::convexSuperellipsoid);
	for (int i = 0; i < BuiltinKinds3::count; ++i)
	{
		CHECK(KindDimension(BuiltinKinds3::all[i]) == 3);
		CHECK(std::string(KindName(BuiltinKinds3::all[i])) == BuiltinKinds3::names[i]);
		CHECK(KindSolverClass(BuiltinKinds3::all[i]) == BuiltinKinds3::solverClasses[i]);
	}
	CHECK(KindDimension(BuiltinKinds::circle) == 2);
	CHECK(MakeSphere(1)->Kind() == BuiltinKinds3::sphere);
	CHECK(MakeEllipsoid(1, 2, 3)->Kind() == BuiltinKinds3::ellipsoid);
	CHECK(MakeSuperellipsoid(1, 2, 3, 2, 2, 4)->Kind() == BuiltinKinds3::superellipsoid);
	CHECK(MakeSuperellipsoid(1, 2, 3, 2, 1.5, 4)->Kind() == BuiltinKinds3::convexSuperellipsoid);
	CHECK(std::string(MakeSuperellipsoid(1, 2, 3, 2, 1.5, 4)->KindName()) == "convex_superellipsoid");
}

TEST_CASE("3D table: a kind registered at run time, its default cell, its own function, flipped")
{
	const ShapeKind ballKind = RegisterShapeKind("test_ball3", 3, SolverClass::smoothConvex);
	const Ball ball(ballKind, 1.0);
	const auto sphere = MakeSphere(0.5);
	const Pose3 pa(Vec3(0, 0, 0), Quat()), pb(Vec3(2, 0, 0), EulerZXZ(0.1, 0.2, 0.3));
	// The default by solver classes: the Newton chain, exact against the closed form (3 / 1.5)².
	const ContactResult3 d = ComputeContact(ball, pa, *sphere, pb);
	REQUIRE(d.Ok());
	CHECK(d.method == SolveMethod::newton);
	CHECK(d.level == doctest::Approx(16.0 / 9.0).epsilon(1e-13));
	CHECK(d.separation == doctest::Approx(0.5).epsilon(1e-13));
	// Its own function for (ball, sphere); (sphere, ball) answers through it, flipped.
	RegisterContactFunction(ballKind, BuiltinKinds3::sphere, &CountingContact);
	CHECK((GetContactFunction3(ballKind, BuiltinKinds3::sphere) == &CountingContact));
	g_calls = 0;
	const ContactResult3 mine = ComputeContact(ball, pa, *sphere, pb);
	CHECK(g_calls == 1);
	CHECK(mine.iterations == 4242);
	const ContactResult3 flipped = ComputeContact(*sphere, pb, ball, pa);
	CHECK(g_calls == 2);
	CHECK(flipped.iterations == 4242);
	CHECK(Distance(flipped.normal, -mine.normal) < 1e-15);
	CHECK(Distance(flipped.pointA, mine.pointB) < 1e-15);
	// Other pairs keep their cells.
	CHECK(ComputeContact(*sphere, pa, *sphere, pb).method == SolveMethod::closedForm);
}

TEST_CASE("3D table: errors name the field")
{
	auto message = [](auto&& call) {
		try
		{
			call();
		}
		catch (const InvalidParameter& e)
		{
			return std::string(e.Field()) + ": " + e.what();
		}
		return std::string("no exception");
	};
	CHECK(message([] { RegisterContactFunction(BuiltinKinds::circle, BuiltinKinds3::sphere, &CountingContact); }) ==
	      "a: RegisterContactFunction: field 'a' must be a kind of dimension 3, got \"circle\" of dimension 2");
	CHECK(message([] { RegisterContactFunction(BuiltinKinds3::sphere, ShapeKind(), &CountingContact); }).rfind("b: ", 0) == 0);
	CHECK(message([] { RegisterContactFunction(BuiltinKinds3::sphere, BuiltinKinds3::sphere, ContactFunction3(nullptr)); }) ==
	      "function: RegisterContactFunction: field 'function' is null");
	CHECK(message([] { Ball(BuiltinKinds::circle, 1.0); }) ==
	      "kind: 3D shape: field 'kind' must be a registered kind of dimension 3, got \"circle\"");
}

// The dispatch table: its built-in cells, the defaults of a registered kind by its solver class,
// functions registered for a kind (and only for it, flipped for the pair the other way round),
// and misuse of the registration functions.
//
// Reference for the registered functions: a disc of radius r (a user shape of its own kind)
// against a circle is two circles, whose common level, point, normal and separation have closed
// forms (CircleContactTests): C = (d/(rA + rB))², X = cA + rA/(rA + rB)·(cB − cA), n along the
// centre line, separation d − rA − rB, computed here in long double.
#include <doctest/doctest.h>

#include "b2analytic/b2analytic.h"
#include "TestSupport.h"
#include "ContactChecks.h"

#include <algorithm>
#include <cmath>
#include <string>

using namespace b2a;
using namespace b2a::test;

namespace
{
using LD = long double;

// A kind registered once per process under `name` (test cases may run in one process).
ShapeKind KindOnce(const std::string& name, SolverClass solverClass)
{
	const ShapeKind found = FindShapeKind(name);
	return found.Valid() ? found : RegisterShapeKind(name, 2, solverClass);
}

// The closed form of two circles, as a registered contact function and a level function would
// give it; counts its calls.
int g_contactCalls = 0, g_levelCalls = 0;
LevelResult DiscLevel(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb)
{
	LevelResult r;
	const double ra = a.BoundingRadius(), rb = b.BoundingRadius(), d = Distance(pa.p, pb.p);
	r.status = SolveStatus::converged;
	r.method = SolveMethod::closedForm;
	r.normal = (pb.p - pa.p) / d;
	r.point = pa.p + (ra / (ra + rb)) * (pb.p - pa.p);
	r.level = (d / (ra + rb)) * (d / (ra + rb));
	r.multiplier = rb / ra;
	return r;
}
ContactResult DiscContact(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions&, WarmStart*)
{
	++g_contactCalls;
	const LevelResult level = DiscLevel(a, pa, b, pb);
	ContactResult c;
	c.status = level.status;
	c.method = level.method;
	c.level = level.level;
	c.point = level.point;
	c.normal = level.normal;
	c.pointA = pa.p + a.BoundingRadius() * c.normal;
	c.pointB = pb.p - b.BoundingRadius() * c.normal;
	c.separation = Distance(pa.p, pb.p) - a.BoundingRadius() - b.BoundingRadius();
	c.touching = c.separation <= 0.0;
	return c;
}
LevelResult DiscLevelFunction(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions&,
                              const WarmStart*, LevelSlide*)
{
	++g_levelCalls;
	return DiscLevel(a, pa, b, pb);
}

// A disc of radius r as a user shape of `kind` (none: the built-in kind of its declarations).
ShapePtr MakeDisc(double r, ShapeKind kind)
{
	UserShapeDef def;
	def.name = "disc";
	def.function = [r](Vec2 x, double L) { return (x.x * x.x + x.y * x.y) / (r * r) - L; };
	def.levelOf = [r](Vec2 x) { return (x.x * x.x + x.y * x.y) / (r * r); };
	def.gradient = [r](Vec2 x, double) { return Vec2(2.0 * x.x / (r * r), 2.0 * x.y / (r * r)); };
	def.hessian = [r](Vec2, double) { return Sym22{2.0 / (r * r), 0.0, 2.0 / (r * r)}; };
	def.convex = true;
	def.smooth = true;
	def.lengthScale = r;
	def.kind = kind;
	return MakeUserShape(def);
}

// The field an InvalidParameter named ("" where none was thrown).
template <class F>
std::string RefusedField(F&& f)
{
	try
	{
		f();
	}
	catch (const InvalidParameter& e)
	{
		return e.Field();
	}
	return "";
}

bool Same(ContactFunction f, ContactFunction g) { return f == g; } // (doctest cannot print them)
bool Same(LevelFunction f, LevelFunction g) { return f == g; }
} // namespace

TEST_CASE("contact table: the built-in cells are the table's grid")
{
	const ShapeKind circle = BuiltinKinds::circle, ellipse = BuiltinKinds::ellipse, superellipse = BuiltinKinds::superellipse;
	const ShapeKind smooth = BuiltinKinds::smoothConvex, convex = BuiltinKinds::convex, nonConvex = BuiltinKinds::nonConvex;
	CHECK(Same(GetContactFunction(circle, circle), &CircleContact));
	CHECK(Same(GetContactFunction(circle, ellipse), &EllipseContact));
	CHECK(Same(GetContactFunction(circle, superellipse), &SuperellipseContact));
	for (const ShapeKind k : {circle, ellipse, superellipse, smooth})
	{
		CHECK(Same(GetContactFunction(smooth, k), &NewtonContact));
		CHECK(Same(GetContactFunction(k, smooth), &NewtonContact));
		CHECK(Same(GetContactFunction(convex, k), &GridContact));
		CHECK(Same(GetContactFunction(k, nonConvex), &GridContact));
	}
	CHECK(Same(GetContactFunction(convex, convex), &GridContact));
	CHECK(Same(GetContactFunction(nonConvex, nonConvex), &GridContact));
	// The level functions of the same cells: the ellipse pair's and Newton's chains differ.
	CHECK_FALSE(Same(GetLevelFunction(ellipse, ellipse), GetLevelFunction(superellipse, ellipse)));
	CHECK(Same(GetLevelFunction(superellipse, ellipse), GetLevelFunction(smooth, smooth)));
	CHECK(Same(GetLevelFunction(convex, ellipse), GetLevelFunction(nonConvex, nonConvex)));
}

TEST_CASE("contact table: a registered kind's pairs default to its solver class until a function is registered")
{
	const ShapeKind smoothKind = KindOnce("test_table_smooth", SolverClass::smoothConvex);
	const ShapeKind convexKind = KindOnce("test_table_convex", SolverClass::convex);
	const ShapeKind nonConvexKind = KindOnce("test_table_non_convex", SolverClass::nonConvex);
	CHECK(Same(GetContactFunction(smoothKind, BuiltinKinds::ellipse), &NewtonContact));
	CHECK(Same(GetContactFunction(BuiltinKinds::superellipse, smoothKind), &NewtonContact));
	CHECK(Same(GetContactFunction(smoothKind, smoothKind), &NewtonContact));
	CHECK(Same(GetContactFunction(smoothKind, convexKind), &GridContact));
	CHECK(Same(GetContactFunction(convexKind, BuiltinKinds::circle), &GridContact));
	CHECK(Same(GetContactFunction(nonConvexKind, smoothKind), &GridContact));
	CHECK(Same(GetLevelFunction(smoothKind, BuiltinKinds::circle), GetLevelFunction(BuiltinKinds::smoothConvex, BuiltinKinds::circle)));

	// A disc of the smooth kind against an ellipse is solved as the built-in smooth kind's is:
	// the same answer, bit for bit.
	const ShapePtr kinded = MakeDisc(0.7, smoothKind), plain = MakeDisc(0.7, ShapeKind());
	const auto ellipse = MakeEllipse(1.3, 0.6);
	const Pose pa(Vec2(0.2, -0.1), 0.4), pb(Vec2(1.6, 0.5), -0.3);
	const ContactResult viaDefault = ComputeContact(*kinded, pa, *ellipse, pb);
	const ContactResult builtin = ComputeContact(*plain, pa, *ellipse, pb);
	REQUIRE(viaDefault.Ok());
	CHECK(viaDefault.method == SolveMethod::newton);
	CHECK(viaDefault.separation == builtin.separation);
	CHECK(viaDefault.pointA.x == builtin.pointA.x);
	CHECK(viaDefault.pointB.y == builtin.pointB.y);
}

TEST_CASE("contact table: a function registered for a kind serves that kind's shapes only, flipped the other way round")
{
	const ShapeKind discKind = KindOnce("test_table_disc", SolverClass::smoothConvex);
	RegisterContactFunction(discKind, BuiltinKinds::circle, &DiscContact);
	RegisterLevelFunction(discKind, BuiltinKinds::circle, &DiscLevelFunction);
	CHECK(Same(GetContactFunction(discKind, BuiltinKinds::circle), &DiscContact));
	CHECK(Same(GetContactFunction(BuiltinKinds::circle, discKind), &DiscContact)); // stored flipped
	CHECK(Same(GetContactFunction(discKind, BuiltinKinds::ellipse), &NewtonContact));

	const double ra = 0.8, rb = 0.5;
	const ShapePtr disc = MakeDisc(ra, discKind), otherDisc = MakeDisc(ra, ShapeKind());
	const auto circle = MakeCircle(rb);
	Random rng(40);
	for (int k = 0; k < 20; ++k)
	{
		const Pose pa(Vec2(rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)), rng.Angle());
		const double dir = rng.Angle(), d = rng.Uniform(0.5, 2.0) * (ra + rb);
		const Pose pb(pa.p + d * Vec2(std::cos(dir), std::sin(dir)), rng.Angle());
		// The closed form in long double.
		const LD dx = LD(pb.p.x) - pa.p.x, dy = LD(pb.p.y) - pa.p.y, dist = std::sqrt(dx * dx + dy * dy);
		const LD wantSeparation = dist - LD(ra) - LD(rb), wantLevel = (dist / (LD(ra) + rb)) * (dist / (LD(ra) + rb));
		const Vec2 wantNormal(double(dx / dist), double(dy / dist));
		INFO("case " << k);

		const int calls = g_contactCalls;
		const ContactResult c = ComputeContact(*disc, pa, *circle, pb);
		CHECK(g_contactCalls == calls + 1);
		REQUIRE(c.Ok());
		CHECK(c.method == SolveMethod::closedForm);
		CHECK(std::fabs(LD(c.separation) - wantSeparation) <= 1e-15L * (LD(ra) + rb + dist));
		CHECK(MaxDiff(c.normal, wantNormal) <= 1e-15);
		// The pair the other way round: the same function, swapped, and its answer flipped.
		const ContactResult swapped = ComputeContact(*circle, pb, *disc, pa);
		CHECK(g_contactCalls == calls + 2);
		CHECK(swapped.separation == c.separation);
		CHECK(swapped.normal.x == -c.normal.x);
		CHECK(swapped.pointA.y == c.pointB.y);
		CHECK(swapped.pointB.x == c.pointA.x);
		// A disc of another kind is not served by it: the built-in smooth kind's Newton, which
		// agrees with the closed form to its rounding.
		const ContactResult other = ComputeContact(*otherDisc, pa, *circle, pb);
		CHECK(g_contactCalls == calls + 2);
		REQUIRE(other.Ok());
		CHECK(other.method == SolveMethod::newton);
		CHECK(std::fabs(LD(other.separation) - wantSeparation) <= 1e-12L * (LD(ra) + rb));
		// Explicit methods do not consult the table.
		CHECK(ComputeContact(*disc, pa, *circle, pb, MethodChoice::grid).method == SolveMethod::grid);
		CHECK(g_contactCalls == calls + 2);

		// The level function: SolveCommonLevel takes it, and turns it back for (circle, disc).
		const int levelCalls = g_levelCalls;
		const LevelResult level = SolveCommonLevel(*disc, pa, *circle, pb);
		const LevelResult flipped = SolveCommonLevel(*circle, pb, *disc, pa);
		CHECK(g_levelCalls == levelCalls + 2);
		REQUIRE(level.Ok());
		CHECK(std::fabs(LD(level.level) - wantLevel) <= 1e-15L * wantLevel);
		CHECK(flipped.level == level.level);
		CHECK(flipped.normal.y == -level.normal.y);
		CHECK(RelativeError(flipped.multiplier, 1.0 / level.multiplier) <= 1e-15);
		CHECK(RelativeError(SolveCommonLevel(*otherDisc, pa, *circle, pb).level, double(wantLevel)) <= 1e-12);
		CHECK(g_levelCalls == levelCalls + 2);
	}
}

TEST_CASE("contact table: misuse of the registration functions is refused, naming the field")
{
	const ShapeKind solid = FindShapeKind("test_table_solid_3d").Valid() ? FindShapeKind("test_table_solid_3d")
	                                                                     : RegisterShapeKind("test_table_solid_3d", 3, SolverClass::smoothConvex);
	const ShapeKind circle = BuiltinKinds::circle;
	CHECK(RefusedField([&] { RegisterContactFunction(ShapeKind(), circle, &DiscContact); }) == "a");
	CHECK(RefusedField([&] { RegisterContactFunction(circle, solid, &DiscContact); }) == "b");
	CHECK(RefusedField([&] { RegisterContactFunction(circle, circle, nullptr); }) == "function");
	CHECK(RefusedField([&] { RegisterLevelFunction(solid, circle, &DiscLevelFunction); }) == "a");
	CHECK(RefusedField([&] { RegisterLevelFunction(circle, circle, nullptr); }) == "function");
	CHECK(RefusedField([&] { GetContactFunction(circle, ShapeKind()); }) == "b");
	CHECK(RefusedField([&] { GetLevelFunction(solid, solid); }) == "a");
	try
	{
		RegisterContactFunction(circle, solid, &DiscContact);
	}
	catch (const InvalidParameter& e)
	{
		CHECK(std::string(e.what()).find("\"test_table_solid_3d\" of dimension 3") != std::string::npos);
	}
	// Nothing changed by the refusals.
	CHECK(Same(GetContactFunction(circle, circle), &CircleContact));
}

namespace
{
// A disc against a polygon's nearest edge, in closed form (the disc's centre outside the
// polygon): the distance from the centre to the nearest edge, minus the radius. Counts its calls.
int g_polygonCalls = 0;
ContactResult DiscPolygonContact(const Shape& a, const Pose& pa, const Vec2* vertices, int count, const Pose& pb, const Vec2*)
{
	++g_polygonCalls;
	double best = 1e300;
	Vec2 nearest;
	for (int j = 0; j < count; ++j)
	{
		const Vec2 p = ToWorld(pb, vertices[j]), q = ToWorld(pb, vertices[(j + 1) % count]);
		const double t = std::clamp(Dot(pa.p - p, q - p) / LengthSquared(q - p), 0.0, 1.0);
		const Vec2 x = p + t * (q - p);
		if (Distance(pa.p, x) < best)
		{
			best = Distance(pa.p, x);
			nearest = x;
		}
	}
	ContactResult c;
	c.status = SolveStatus::converged;
	c.method = SolveMethod::closedForm;
	c.normal = (nearest - pa.p) / best;
	c.pointA = pa.p + a.BoundingRadius() * c.normal;
	c.pointB = nearest;
	c.point = 0.5 * (c.pointA + c.pointB);
	c.separation = best - a.BoundingRadius();
	c.touching = c.separation <= 0.0;
	return c;
}
} // namespace

TEST_CASE("contact table: the polygon column is the separating axis until a kind registers its own")
{
	for (const ShapeKind k : BuiltinKinds::all)
		CHECK(bool(GetPolygonContactFunction(k) == &SeparatingAxisContact));
	const ShapeKind discKind = KindOnce("test_table_polygon_disc", SolverClass::smoothConvex);
	CHECK(bool(GetPolygonContactFunction(discKind) == &SeparatingAxisContact));
	RegisterPolygonContactFunction(discKind, &DiscPolygonContact);
	CHECK(bool(GetPolygonContactFunction(discKind) == &DiscPolygonContact));

	const double r = 0.4;
	const ShapePtr disc = MakeDisc(r, discKind), otherDisc = MakeDisc(r, ShapeKind());
	const Vec2 box[4] = {Vec2(-1.0, -0.5), Vec2(1.0, -0.5), Vec2(1.0, 0.5), Vec2(-1.0, 0.5)};
	const Pose pb(Vec2(0.3, -0.2), 0.25);
	Random rng(41);
	for (int k = 0; k < 16; ++k)
	{
		// A centre outside the box, at a distance from its boundary of 0.5 r to 2 r.
		const double dir = rng.Angle();
		Pose pa(ToWorld(pb, Vec2(0.0, 0.0)), rng.Angle());
		const Vec2 u(std::cos(dir), std::sin(dir));
		const double reach = std::min(1.0 / std::max(std::fabs(u.x), 1e-300), 0.5 / std::max(std::fabs(u.y), 1e-300));
		const double gap = rng.Uniform(0.5, 2.0) * r;
		pa.p = ToWorld(pb, (reach + gap / std::max(std::fabs(u.x), std::fabs(u.y))) * u);
		INFO("case " << k);
		const int calls = g_polygonCalls;
		const ContactResult exact = ComputePolygonContact(*disc, pa, box, 4, pb);
		CHECK(g_polygonCalls == calls + 1);
		CHECK(exact.method == SolveMethod::closedForm);
		// The other disc's kind keeps the separating axis, which agrees to its tolerance.
		const ContactResult axis = ComputePolygonContact(*otherDisc, pa, box, 4, pb);
		CHECK(g_polygonCalls == calls + 1);
		CHECK(axis.method == SolveMethod::separatingAxis);
		CHECK(std::fabs(axis.separation - exact.separation) <= 1e-10);
	}
	CHECK(RefusedField([] { RegisterPolygonContactFunction(ShapeKind(), &DiscPolygonContact); }) == "kind");
	CHECK(RefusedField([&] { RegisterPolygonContactFunction(discKind, nullptr); }) == "function");
}

// The registry of shape kinds: the built-in kinds, registering new ones, and misuse (each an
// InvalidParameter naming the field and the value).
#include <doctest/doctest.h>

#include "GeometryReference.h"

#include <string>

using namespace b2a;
using namespace b2a::test;

namespace
{
// The field an InvalidParameter named and its message ("" where none was thrown).
struct Refusal
{
	std::string field, what;
};
template <class F>
Refusal Refused(F&& f)
{
	try
	{
		f();
	}
	catch (const InvalidParameter& e)
	{
		return {e.Field(), e.what()};
	}
	return {};
}

// A kind registered once per process under `name` (test cases may run in one process).
ShapeKind KindOnce(const std::string& name, int dimension, SolverClass solverClass)
{
	const ShapeKind found = FindShapeKind(name);
	return found.Valid() ? found : RegisterShapeKind(name, dimension, solverClass);
}
} // namespace

TEST_CASE("shape kinds: the built-in kinds have their fixed ids, names, dimension and solver classes")
{
	const struct
	{
		ShapeKind kind;
		const char* name;
		SolverClass solverClass;
	} builtin[] = {{BuiltinKinds::circle, "circle", SolverClass::smoothConvex},
	               {BuiltinKinds::ellipse, "ellipse", SolverClass::smoothConvex},
	               {BuiltinKinds::superellipse, "superellipse", SolverClass::smoothConvex},
	               {BuiltinKinds::smoothConvex, "smooth_convex", SolverClass::smoothConvex},
	               {BuiltinKinds::convex, "convex", SolverClass::convex},
	               {BuiltinKinds::nonConvex, "non_convex", SolverClass::nonConvex}};
	int id = 0;
	for (const auto& b : builtin)
	{
		INFO(b.name);
		CHECK(b.kind.Id() == id++);
		CHECK(b.kind.Valid());
		CHECK(std::string(KindName(b.kind)) == b.name);
		CHECK(FindShapeKind(b.name) == b.kind);
		CHECK(KindDimension(b.kind) == 2);
		CHECK(KindSolverClass(b.kind) == b.solverClass);
	}
	CHECK(ShapeKindCount() >= BuiltinKinds::count);
	CHECK_FALSE(ShapeKind().Valid());
	CHECK_FALSE(FindShapeKind("no_such_kind").Valid());
	CHECK(std::string(KindName(ShapeKind())) == "none");
	CHECK(KindDimension(ShapeKind()) == 0);
	CHECK(std::string(SolverClassName(SolverClass::convex)) == "convex");
}

TEST_CASE("shape kinds: the library's shapes compute their kind from their parameters")
{
	CHECK(MakeCircle(1.0)->Kind() == BuiltinKinds::circle);
	CHECK(MakeEllipse(1.0, 0.5)->Kind() == BuiltinKinds::ellipse);
	CHECK(SuperellipseShape::FromZeta(1.0, 0.5, 1.0)->Kind() == BuiltinKinds::ellipse); // level f^1 = f
	CHECK(MakeSuperellipse(1.0, 0.5, 4.0, 2.5)->Kind() == BuiltinKinds::superellipse);
	CHECK(SuperellipseShape::FromZeta(1.0, 0.5, 3.0)->Kind() == BuiltinKinds::smoothConvex); // level f^{1/3}
	CHECK(MakeSuperellipse(1.0, 0.5, 1.5, 4.0)->Kind() == BuiltinKinds::convex);             // n < 2: corners' curvature
	CHECK(SuperellipseShape::FromZeta(1.0, 0.5, 0.75)->Kind() == BuiltinKinds::convex);
	CHECK(MakeHeart(1.0)->Kind() == BuiltinKinds::nonConvex);
	UserShapeDef def = UserEllipseDef(1.0, 0.5); // declared convex, not smooth
	CHECK(MakeUserShape(def)->Kind() == BuiltinKinds::convex);
	def.smooth = true;
	CHECK(MakeUserShape(def)->Kind() == BuiltinKinds::smoothConvex);
	CHECK(MakeUserShape(UserHeartDef(1.0))->Kind() == BuiltinKinds::nonConvex);
}

TEST_CASE("shape kinds: a new kind gets the next dense id and keeps its name, dimension and class")
{
	const int before = ShapeKindCount();
	const ShapeKind lens = RegisterShapeKind("test_lens_2d", 2, SolverClass::smoothConvex);
	CHECK(lens.Id() == before);
	const ShapeKind cube = RegisterShapeKind("test_rounded_cube_3d", 3, SolverClass::convex);
	CHECK(cube.Id() == before + 1);
	CHECK(ShapeKindCount() == before + 2);
	CHECK(std::string(KindName(lens)) == "test_lens_2d");
	CHECK(KindDimension(lens) == 2);
	CHECK(KindDimension(cube) == 3);
	CHECK(KindSolverClass(lens) == SolverClass::smoothConvex);
	CHECK(KindSolverClass(cube) == SolverClass::convex);
	CHECK(FindShapeKind("test_rounded_cube_3d") == cube);
	CHECK(lens != cube);
}

TEST_CASE("shape kinds: misuse of the registry is refused, naming the field and the value")
{
	for (const std::string& bad : {std::string(), std::string("Capsule"), std::string("round-box"), std::string(33, 'x')})
	{
		const Refusal r = Refused([&] { RegisterShapeKind(bad, 2, SolverClass::convex); });
		INFO("name \"" << bad << "\": " << r.what);
		CHECK(r.field == "name");
		CHECK(r.what.find("\"" + bad + "\"") != std::string::npos);
	}
	const Refusal taken = Refused([] { RegisterShapeKind("circle", 2, SolverClass::smoothConvex); });
	CHECK(taken.field == "name");
	CHECK(taken.what.find("registered already") != std::string::npos);
	for (const int dimension : {0, 1, 4})
	{
		const Refusal r = Refused([&] { RegisterShapeKind("test_bad_dimension", dimension, SolverClass::convex); });
		CHECK(r.field == "dimension");
		CHECK(r.what.find("got " + std::to_string(dimension)) != std::string::npos);
	}
	const Refusal cls = Refused([] { RegisterShapeKind("test_bad_class", 2, SolverClass(7)); });
	CHECK(cls.field == "solverClass");
	CHECK(cls.what.find("got 7") != std::string::npos);
	CHECK_FALSE(FindShapeKind("test_bad_dimension").Valid()); // nothing registered by a refusal
	CHECK(Refused([] { KindSolverClass(ShapeKind()); }).field == "kind");
}

TEST_CASE("shape kinds: a user shape names a registered kind, which must not claim more than the shape declares")
{
	const ShapeKind smoothKind = KindOnce("test_smooth_blob", 2, SolverClass::smoothConvex);
	const ShapeKind convexKind = KindOnce("test_blocky_blob", 2, SolverClass::convex);
	const ShapeKind solid = KindOnce("test_solid_3d", 3, SolverClass::smoothConvex);

	UserShapeDef def = UserEllipseDef(1.0, 0.5); // convex, not smooth
	def.kind = convexKind;
	CHECK(MakeUserShape(def)->Kind() == convexKind);
	def.kind = smoothKind;
	const Refusal notSmooth = Refused([&] { MakeUserShape(def); });
	CHECK(notSmooth.field == "kind");
	CHECK(notSmooth.what.find("test_smooth_blob") != std::string::npos);
	CHECK(notSmooth.what.find("'smooth'") != std::string::npos);
	def.smooth = true;
	CHECK(MakeUserShape(def)->Kind() == smoothKind);

	UserShapeDef heart = UserHeartDef(1.0); // declared neither
	heart.kind = convexKind;
	CHECK(Refused([&] { MakeUserShape(heart); }).field == "kind");
	def.kind = solid;
	const Refusal wrongDimension = Refused([&] { MakeUserShape(def); });
	CHECK(wrongDimension.field == "kind");
	CHECK(wrongDimension.what.find("dimension 2") != std::string::npos);
}

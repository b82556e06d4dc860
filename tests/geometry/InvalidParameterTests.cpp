// Invalid parameters: each is an InvalidParameter (a std::invalid_argument) whose message names
// the field and the offending value.
#include <doctest/doctest.h>

#include "GeometryReference.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

using namespace b2a;
using namespace b2a::test;

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

struct Caught
{
	bool invalidParameter = false; ///< an InvalidParameter was thrown
	bool invalidArgument = false;  ///< it is also a std::invalid_argument
	std::string what;
	std::string field;
};

template <class F>
Caught Catch(F&& make)
{
	Caught c;
	try
	{
		make();
	}
	catch (const std::invalid_argument& e)
	{
		c.invalidArgument = true;
		c.what = e.what();
		if (const auto* ip = dynamic_cast<const InvalidParameter*>(&e))
		{
			c.invalidParameter = true;
			c.field = ip->Field();
		}
	}
	catch (const std::exception& e)
	{
		c.what = std::string("other exception: ") + e.what();
	}
	return c;
}

// An invalid value and how the message must print it (FormatNumber, "%.17g").
struct Bad
{
	double value;
	const char* text;
};

bool EndsWith(const std::string& s, const std::string& tail)
{
	return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool Contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// The message names the field ('field') and ends with "got <value>"; Field() returns it.
void CheckNamed(const Caught& c, const std::string& field, const std::string& value)
{
	CAPTURE(c.what);
	CHECK(c.invalidParameter);
	CHECK(c.invalidArgument);
	CHECK(Contains(c.what, "field '" + field + "'"));
	CHECK(EndsWith(c.what, "got " + value));
	CHECK(c.field == field);
}

UserShapeDef ValidUser()
{
	UserShapeDef def = UserEllipseDef(2.0, 1.0);
	def.name = "blob";
	return def;
}
} // namespace

TEST_CASE("invalid parameters: superellipse semi-axes and exponents")
{
	for (const Bad& bad : {Bad{0.0, "0"}, Bad{-1.0, "-1"}, Bad{kNaN, "nan"}, Bad{kInf, "inf"}, Bad{-kInf, "-inf"}})
	{
		INFO("value: " << bad.text);
		CheckNamed(Catch([&] { MakeSuperellipse(bad.value, 1.0, 2.0, 2.0); }), "a", bad.text);
		CheckNamed(Catch([&] { MakeSuperellipse(1.0, bad.value, 2.0, 2.0); }), "b", bad.text);
		CheckNamed(Catch([&] { MakeEllipse(bad.value, 1.0); }), "a", bad.text);
		CheckNamed(Catch([&] { MakeEllipse(1.0, bad.value); }), "b", bad.text);
		CheckNamed(Catch([&] { SuperellipseShape::FromZeta(bad.value, 1.0, 1.0); }), "a", bad.text);
		CheckNamed(Catch([&] { MakeCircle(bad.value); }), "r", bad.text);
	}
	for (const Bad& bad : {Bad{0.5, "0.5"}, Bad{0.0, "0"}, Bad{-2.0, "-2"}, Bad{kNaN, "nan"}, Bad{kInf, "inf"}})
	{
		INFO("value: " << bad.text);
		CheckNamed(Catch([&] { MakeSuperellipse(1.0, 1.0, bad.value, 2.0); }), "n", bad.text);
		CheckNamed(Catch([&] { MakeSuperellipse(1.0, 1.0, 2.0, bad.value); }), "m", bad.text);
	}
	for (const Bad& bad : {Bad{0.25, "0.25"}, Bad{0.0, "0"}, Bad{kNaN, "nan"}, Bad{kInf, "inf"}})
	{
		INFO("value: " << bad.text);
		CheckNamed(Catch([&] { SuperellipseShape::FromZeta(1.0, 1.0, bad.value); }), "zeta", bad.text);
	}
	// Each message says which shape complained.
	CHECK(Contains(Catch([] { MakeSuperellipse(1.0, 1.0, 0.5, 2.0); }).what, "superellipse"));
	CHECK(Contains(Catch([] { MakeCircle(-3.0); }).what, "circle"));
	// The boundaries themselves are valid: n = m = 1, ζ = 1/2.
	CHECK_NOTHROW(MakeSuperellipse(1.0, 1.0, 1.0, 1.0));
	CHECK_NOTHROW(SuperellipseShape::FromZeta(1.0, 1.0, 0.5));
}

TEST_CASE("invalid parameters: heart alpha")
{
	for (const Bad& bad : {Bad{0.0, "0"}, Bad{-2.0, "-2"}, Bad{kNaN, "nan"}, Bad{kInf, "inf"}})
	{
		INFO("value: " << bad.text);
		const Caught c = Catch([&] { MakeHeart(bad.value); });
		CheckNamed(c, "alpha", bad.text);
		CHECK(Contains(c.what, "heart"));
	}
	CHECK_NOTHROW(MakeHeart(1e-3));
}

TEST_CASE("invalid parameters: user shape fields")
{
	CHECK_NOTHROW(MakeUserShape(ValidUser()));

	// G must be finite and negative at the centre at the own level.
	for (const Bad& bad : {Bad{kNaN, "nan"}, Bad{kInf, "inf"}, Bad{0.0, "0"}, Bad{2.5, "2.5"}})
	{
		INFO("value: " << bad.text);
		UserShapeDef def = ValidUser();
		auto g = def.function;
		def.function = [g, g0 = bad.value](Vec2 x, double L) { return x.x == 0.0 && x.y == 0.0 ? g0 : g(x, L); };
		const Caught c = Catch([&] { MakeUserShape(def); });
		CheckNamed(c, "function", bad.text);
		CHECK(Contains(c.what, "user shape 'blob'"));
	}
	for (const Bad& bad : {Bad{kNaN, "nan"}, Bad{kInf, "inf"}, Bad{-kInf, "-inf"}})
	{
		INFO("value: " << bad.text);
		UserShapeDef def = ValidUser();
		def.level = bad.value;
		CheckNamed(Catch([&] { MakeUserShape(def); }), "level", bad.text);
	}
	for (const Bad& bad : {Bad{0.0, "0"}, Bad{-1.0, "-1"}, Bad{kNaN, "nan"}, Bad{kInf, "inf"}})
	{
		INFO("value: " << bad.text);
		UserShapeDef def = ValidUser();
		def.lengthScale = bad.value;
		CheckNamed(Catch([&] { MakeUserShape(def); }), "lengthScale", bad.text);
	}
	for (const Bad& bad : {Bad{0.5, "0.5"}, Bad{0.0, "0"}, Bad{kNaN, "nan"}, Bad{kInf, "inf"}})
	{
		INFO("value: " << bad.text);
		UserShapeDef def = ValidUser();
		def.levelPower = bad.value;
		CheckNamed(Catch([&] { MakeUserShape(def); }), "levelPower", bad.text);
	}
	{
		UserShapeDef def = ValidUser();
		def.cornerAngles = {0.3, kNaN};
		CheckNamed(Catch([&] { MakeUserShape(def); }), "cornerAngles", "nan");
	}
	{
		// levelOf must put the centre below the own level.
		UserShapeDef def = ValidUser();
		def.levelOf = [](Vec2) { return 5.0; };
		CheckNamed(Catch([&] { MakeUserShape(def); }), "levelOf", "5");
	}
}

namespace
{
Caught UserWithoutFunction()
{
	UserShapeDef def = ValidUser();
	def.function = nullptr;
	return Catch([&] { MakeUserShape(def); });
}

Caught UserWithUnboundedFunction()
{
	UserShapeDef def = ValidUser();
	def.function = [](Vec2, double) { return -1.0; }; // G < 0 everywhere: no surface on any ray
	return Catch([&] { MakeUserShape(def); });
}
} // namespace

TEST_CASE("invalid parameters: user shape without a function or with an unbounded one")
{
	// These have no single offending number; the message must still name the field.
	const Caught empty = UserWithoutFunction();
	CAPTURE(empty.what);
	CHECK(empty.invalidParameter);
	CHECK(empty.invalidArgument);
	CHECK(Contains(empty.what, "field 'function'"));
	CHECK(Contains(empty.what, "user shape 'blob'"));

	const Caught unbounded = UserWithUnboundedFunction();
	CAPTURE(unbounded.what);
	CHECK(unbounded.invalidParameter);
	CHECK(Contains(unbounded.what, "field 'function'"));
	CHECK(Contains(unbounded.what, "user shape 'blob'"));
}

TEST_CASE("invalid parameters: Field() names the field also when the message has no value")
{
	// InvalidParameter::Field() is documented as "the offending field's name"; the free-form
	// constructor used for these two errors must set it too.
	CHECK(UserWithoutFunction().field == "function");
	CHECK(UserWithUnboundedFunction().field == "function");
}

TEST_CASE("invalid parameters: fewer than 3 surface samples")
{
	const auto s = MakeEllipse(2.0, 1.0);
	for (const Bad& bad : {Bad{2, "2"}, Bad{0, "0"}, Bad{-5, "-5"}})
	{
		INFO("value: " << bad.text);
		CheckNamed(Catch([&] { s->Samples(int(bad.value)); }), "count", bad.text);
	}
	CHECK(s->Samples(3)->Count() == 3);
}

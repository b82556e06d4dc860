// b2analytic tests: b2a_contact with 3D shapes, and its toi mode in 2D and 3D, through the
// request handler, against closed forms and the paper's Figure 17.
#include "ContactTool.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using nlohmann::json;

namespace
{
json Ask3(const std::string& line, bool expectOk = true)
{
	bool ok = false;
	const std::string answer = b2a::tool::AnswerContactRequest(line, ok);
	INFO("request: " << line);
	INFO("answer: " << answer);
	CHECK(ok == expectOk);
	return json::parse(answer);
}
} // namespace

TEST_CASE("3D shapes: spheres in closed form, 3-vectors in the answer")
{
	const json r = Ask3(R"({"id":1,"a":{"type":"sphere","r":1},"b":{"type":"sphere","r":0.5,"x":2,"y":2,"z":1}})");
	CHECK(r["method"] == "closed_form");
	CHECK(r["scale"].get<double>() == doctest::Approx(4.0).epsilon(1e-14)); // (3 / 1.5)²
	CHECK(r["separation"].get<double>() == doctest::Approx(1.5).epsilon(1e-14));
	REQUIRE(r["point_a"].size() == 3);
	CHECK(r["point_a"][0].get<double>() == doctest::Approx(2.0 / 3.0).epsilon(1e-14));
	CHECK(r["normal"][2].get<double>() == doctest::Approx(1.0 / 3.0).epsilon(1e-14));
	CHECK(r["touching"] == false);
}

TEST_CASE("3D shapes: every mode and method on an ellipsoid and a superellipsoid, quat and Euler angles alike")
{
	const std::string a = R"("a":{"type":"ellipsoid","a":2,"b":1,"c":0.5})";
	const std::string quat = R"("b":{"type":"superellipsoid","a":1,"b":1,"c":1,"n":[4,6,8],"x":2.6,"y":0.3,"z":0.1,"quat":[0.9238795325112867,0,0,0.3826834323650898]})";
	// The same turn (π/4 about z) as z-x-z Euler angles (ψ, 0, 0).
	const std::string euler = R"("b":{"type":"superellipsoid","a":1,"b":1,"c":1,"n":[4,6,8],"x":2.6,"y":0.3,"z":0.1,"euler_zxz":[0.7853981633974483,0,0]})";
	double common = 0.0;
	for (const char* mode : {"common", "contact", "scale_a"})
		for (const char* method : {"auto", "newton", "grid"})
		{
			if (std::string(mode) == "scale_a" && std::string(method) == "newton")
				continue;
			const json q = Ask3(std::string(R"({"mode":")") + mode + R"(","method":")" + method + R"(",)" + a + "," + quat + "}");
			const json e = Ask3(std::string(R"({"mode":")") + mode + R"(","method":")" + method + R"(",)" + a + "," + euler + "}");
			CHECK(q["scale"].get<double>() == doctest::Approx(e["scale"].get<double>()).epsilon(1e-12));
			if (std::string(mode) != "scale_a")
			{
				if (common == 0.0)
					common = q["scale"];
				CHECK(q["scale"].get<double>() == doctest::Approx(common).epsilon(1e-12)); // every method, one level
			}
		}
}

TEST_CASE("mode toi: 2D circles and 3D spheres against the quadratic root, null without contact")
{
	// Gap 3 closed at speed 4: t = 0.75.
	json r = Ask3(R"({"mode":"toi","t_max":1,"a":{"type":"circle","r":1,"v":[2,0],"w":5},"b":{"type":"circle","r":1,"x":5,"v":[-2,0]}})");
	CHECK(r["time"].get<double>() == doctest::Approx(0.75).epsilon(1e-12));
	CHECK(r["point"][0].get<double>() == doctest::Approx(2.5).epsilon(1e-9));
	CHECK(r["normal"][0].get<double>() == doctest::Approx(1.0).epsilon(1e-12));
	r = Ask3(R"({"mode":"toi","t_max":0.5,"a":{"type":"circle","r":1,"v":[2,0]},"b":{"type":"circle","r":1,"x":5,"v":[-2,0]}})");
	CHECK(r["time"].is_null());
	CHECK(r["point"].is_null());
	CHECK(r["separation_at_t_max"].get<double>() == doctest::Approx(1.0).epsilon(1e-12));
	r = Ask3(R"({"mode":"toi","t_max":2,"a":{"type":"sphere","r":1,"w":[1,2,3]},"b":{"type":"sphere","r":2,"x":6,"y":0,"z":0,"v":[-3,0,0]}})");
	CHECK(r["time"].get<double>() == doctest::Approx(1.0).epsilon(1e-12));
	CHECK(r["point"].size() == 3);
}

TEST_CASE("mode toi: the paper's Figure 17 touches within 1e-3 ms of 0.1924 ms")
{
	const json r = Ask3(
		R"({"id":17,"mode":"toi","t_max":1,)"
		R"("a":{"type":"superellipsoid","a":4,"b":4,"c":4,"n":[6,6,12],"x":-10,"y":-15,"z":-10,)"
		R"("euler_zxz":[0.3490658503988659,0.39269908169872414,0.4487989505128276],"v":[-20,-10,-15],"w":[20,-30,2]},)"
		R"("b":{"type":"superellipsoid","a":2,"b":3,"c":2,"n":8,"x":-20,"y":-25,"z":-20,)"
		R"("euler_zxz":[0.5235987755982988,0.6283185307179586,0.7853981633974483],"v":[10,20,15],"w":[-10,20,-2]}})");
	CHECK(r["id"] == 17);
	CHECK(std::fabs(r["time"].get<double>() - 0.1924) < 1e-3);
	CHECK(std::fabs(r["separation"].get<double>()) < 1e-9);
	CHECK(r["scale"].get<double>() == doctest::Approx(1.0).epsilon(1e-11));
}

TEST_CASE("mode toi: a spin that needs more than the tool's step cap is an error naming the cap and t_max")
{
	// A needle (half-length 4, half-thickness 0.1) spins at 50 rad/s in the plane z = 0 under a
	// sphere whose lowest point is at z = 0.5: they never touch, the bounding spheres overlap, and
	// each conservative step is at most the distance (under 2.3) over |w|·R = 200: a tenth of a
	// unit of time takes over 8 steps, a thousand units over 80,000.
	const std::string shapes = R"("a":{"type":"superellipsoid","a":4,"b":0.1,"c":0.1,"n":2,"w":[0,0,50]},)"
	                           R"("b":{"type":"sphere","r":1,"y":3,"z":1.5}})";
	json r = Ask3(R"({"mode":"toi","t_max":0.1,)" + shapes);
	CHECK(r["time"].is_null());
	// The gap at t_max: from the needle's top face (z = 0.1 at most) to the sphere's bottom.
	CHECK(r["separation_at_t_max"].get<double>() >= 0.4 - 1e-9);
	CHECK(r["iterations"].get<int>() > 8);
	CHECK(r["iterations"].get<int>() < 200);
	r = Ask3(R"({"mode":"toi","t_max":1000,)" + shapes, false);
	CHECK(r["error"].get<std::string>() ==
	      "time of impact failed: conservative advancement reached the tool's cap of 200 steps before field 't_max' = 1000 "
	      "(a shorter t_max needs fewer steps)");
}

TEST_CASE("3D and toi requests: bad fields are named")
{
	auto error = [](const std::string& line) { return Ask3(line, false)["error"].get<std::string>(); };
	CHECK(error(R"({"a":{"type":"sphere","r":1},"b":{"type":"circle","r":1}})") ==
	      "field 'b.type': shape 'a' is 3D; both shapes of a request are 2D or both 3D");
	CHECK(error(R"({"a":{"type":"superellipsoid","a":1,"b":1,"c":1,"n":[0.5,2,2]},"b":{"type":"sphere","r":1}})") ==
	      "shape 'a': superellipsoid: field 'n1' must be finite and >= 1, got 0.5");
	CHECK(error(R"({"a":{"type":"sphere","r":1,"quat":[1,1,0,0]},"b":{"type":"sphere","r":1}})").find("field 'a.quat' must be a unit quaternion") == 0);
	CHECK(error(R"({"a":{"type":"superellipsoid","a":1,"b":1,"c":1,"n":[4,4]},"b":{"type":"sphere","r":1}})").find("field 'a.n' must be an array of 3") == 0);
	CHECK(error(R"({"t_max":1,"a":{"type":"sphere","r":1},"b":{"type":"sphere","r":1}})") == "field 't_max' belongs to mode 'toi' only (mode is 'contact')");
	CHECK(error(R"({"mode":"toi","a":{"type":"sphere","r":1},"b":{"type":"sphere","r":1,"x":3}})") == "field 't_max' is missing");
	CHECK(error(R"({"mode":"toi","t_max":-1,"a":{"type":"circle","r":1},"b":{"type":"circle","r":1,"x":3}})") == "field 't_max' must be >= 0, got -1");
	CHECK(error(R"({"a":{"type":"sphere","r":1,"v":[1,0,0]},"b":{"type":"sphere","r":1,"x":3}})").find("field 'a.v' is not a field of a sphere") == 0);
	CHECK(error(R"({"mode":"toi","t_max":1,"a":{"type":"circle","r":1,"w":[1,2,3]},"b":{"type":"circle","r":1,"x":3}})") ==
	      "field 'a.w' must be a number, got [1,2,3]");
}

// b2analytic tests: the long run of the hopper scene in its quick mode (4000 steps, 120
// particles, the outlet open and its discharge recycled to the top) keeps every particle finite
// and inside, accounts for every particle and its energy, and creates no energy beyond Box2D's
// position-correction bound.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using nlohmann::json;

TEST_CASE("b2a_demo_longrun: the quick long run loses nothing, stays finite and creates no energy")
{
	const std::string out = "demo_out/longrun";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("demo_out");
	const std::string cmd = std::string("\"") + B2A_DEMO_LONGRUN + "\" --quick --out " + out + " > " + out + ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0); // it exits 1 on NaN, escapes, losses or a rise above its bound
	std::ifstream f(out + "/summary.json");
	REQUIRE(f.good());
	const json s = json::parse(f);

	CHECK(s["finished"] == true);
	CHECK(s["steps"] == 4000);
	CHECK(s["nan_count"] == 0);
	CHECK(s["escaped"] == 0);
	CHECK(s["lost"] == 0);
	CHECK(s["remaining"] == s["particles"]); // recycled, never removed
	// The outlet flowed: more particles went round than the container holds.
	const int recycled = s["recycled"], particles = s["particles"];
	CHECK(recycled > particles);
	// No fling: nothing much faster than the free fall from the top of the insertion band.
	CHECK(s["max_speed"].get<double>() > 0.5 * s["free_fall_speed"].get<double>());
	CHECK(s["max_speed_over_free_fall"].get<double>() < 1.1);

	const json& e = s["energy"];
	// The balance (mechanical energy minus what recycling put in) never rose above its start,
	// no step created more than the bound, and all the rises together are a small part of
	// what the flow dissipated.
	CHECK(e["max_excess_over_initial"].get<double>() <= 1e-9 * e["initial_total"].get<double>());
	CHECK(e["max_rise_in_one_step"].get<double>() <= e["rise_bound_per_step"].get<double>());
	CHECK(e["created_over_dissipated"].get<double>() < 0.01);
	CHECK(e["dissipated"].get<double>() > 0.0);
	// The recycling's energy, independently bounded: each recycled particle (mass at most
	// density × the largest particle's area, the +10 % size of a superellipse n = 4 of aspect
	// 1.6: area 4ab Γ(5/4)² / Γ(3/2) with a = 1.1 mm) is lifted at most from the recycling level
	// (−2 mm) to the top of the band (95 mm), and the kinetic energy taken out only lowers it.
	const double a = 1.1, b = a / 1.6;
	const double area = 4.0 * a * b * std::pow(std::tgamma(1.25), 2) / std::tgamma(1.5);
	const double mMax = 1e-3 * area;
	const double injected = e["injected_by_recycling"];
	CHECK(injected > 0.0);
	CHECK(injected <= recycled * mMax * 9810.0 * (95.0 + 2.0));
	// The figures add up: final balance = final kinetic + potential − injected.
	CHECK(e["final_balance"].get<double>() ==
	      doctest::Approx(e["final_kinetic"].get<double>() + e["final_potential"].get<double>() - injected).epsilon(1e-9));
	for (const char* file : {"energy.csv", "final.svg"})
		CHECK(std::filesystem::file_size(out + "/" + file) > 100);
}

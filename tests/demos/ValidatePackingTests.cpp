// b2analytic tests: the packing validation program in a tiny mode (the full and short runs are
// tests/validation's, labelled validation).
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using nlohmann::json;

TEST_CASE("b2a_validate_packing: 150 frictional disks pour into a packing near the published fraction and write their tables")
{
	const std::string out = "demo_out/validate_packing_tiny";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("demo_out");
	const std::string cmd = "\"" B2A_VALIDATE_PACKING "\" --families disk --frictions 0.5 --counts 150 --seeds 1 --margin 1.5 "
	                        "--duration 0.8 --out " + out + " > " + out + ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);
	std::ifstream f(out + "/summary.json");
	REQUIRE(f.good());
	const json s = json::parse(f);
	REQUIRE(s["groups"].size() == 1);
	const json& g = s["groups"][0];
	CHECK(g["at_rest_fraction"].get<double>() == 1.0);
	// Frictional bidisperse disks: about 0.80 (docs/validation/packing.md); a small window of one
	// seed varies by about ±0.01, and anything outside 0.76–0.86 would be a different packing.
	CHECK(g["phi_mean"].get<double>() > 0.76);
	CHECK(g["phi_mean"].get<double>() < 0.86);
	CHECK(g["phi_union_mean"].get<double>() <= g["phi_mean"].get<double>());
	for (const char* file : {"runs.csv", "summary.csv", "packing_friction.svg", "snapshot_disk.svg"})
		CHECK(std::filesystem::exists(out + "/" + file));
}

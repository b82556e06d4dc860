// b2analytic validation tests (label validation): the flow validations in their quick modes obey
// the physical relations they exist to measure.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using nlohmann::json;

namespace
{
// Run a validation program with --quick (and `args`) into a fresh folder; returns its summary.json.
json RunQuick(const std::string& exe, const std::string& name, const std::string& args = "")
{
	const std::string out = "validation_out/" + name;
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("validation_out");
	const std::string cmd = "\"" + exe + "\" --quick --out " + out + " " + args + " > " + out + ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);
	std::ifstream f(out + "/summary.json");
	REQUIRE(f.good());
	return json::parse(f);
}
} // namespace

TEST_CASE("b2a_validate_beverloo --quick: the flow grows with the outlet as Beverloo's law, for ellipses and disks")
{
	const json s = RunQuick(B2A_VALIDATE_BEVERLOO, "beverloo");
	for (const char* kind : {"ellipse", "disk"})
	{
		CAPTURE(kind);
		const json& k = s["kinds"][kind];
		CHECK(k["flow_grows_with_outlet"] == true);
		// The packing of a settled bed of hard, frictional particles (2D random packings: 0.75 to 0.85).
		CHECK(k["packing_fraction"].get<double>() > 0.7);
		CHECK(k["packing_fraction"].get<double>() < 0.9);
		// Beverloo's C is of order one in 2D and the empty annulus k d under a few particle sizes;
		// the quick windows (five blocks of 0.03 s) measure the rates to some ten per cent.
		const json& b = k["beverloo"];
		REQUIRE(b.is_object());
		CHECK(b["converged"] == true);
		CHECK(b["C"].get<double>() > 0.2);
		CHECK(b["C"].get<double>() < 2.0);
		CHECK(b["k"].get<double>() > -1.0);
		CHECK(b["k"].get<double>() < 4.0);
		for (const json& o : k["outlets"])
			CHECK(o["Q_se"].get<double>() < 0.3 * o["Q_g_per_s"].get<double>());
	}
	// --refit of its own flow.csv gives the same fits without simulating.
	const json r = RunQuick(B2A_VALIDATE_BEVERLOO, "beverloo_refit", "--refit validation_out/beverloo/flow.csv");
	CHECK(r["kinds"]["disk"]["beverloo"]["k"].get<double>() == doctest::Approx(s["kinds"]["disk"]["beverloo"]["k"].get<double>()));
}

TEST_CASE("b2a_validate_jamming --quick: disks jam less and their avalanches grow as the outlet widens")
{
	const json s = RunQuick(B2A_VALIDATE_JAMMING, "jamming");
	const json& widths = s["kinds"]["disk"]["widths"];
	REQUIRE(widths.size() == 3);
	// An outlet of two diameters arches at once in 2D; one of four lets many more particles pass.
	CHECK(widths[0]["J"].get<double>() >= widths[2]["J"].get<double>());
	CHECK(widths[0]["J"].get<double>() > 0.5);
	REQUIRE(widths[0]["mean_avalanche"].is_number());
	CHECK(widths[0]["mean_avalanche"].get<double>() < 20.0);
	CHECK(widths[2]["particles"].get<double>() / std::max(1, widths[2]["jams"].get<int>()) >
	      3.0 * widths[0]["mean_avalanche"].get<double>());
}

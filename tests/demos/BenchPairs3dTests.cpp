// b2analytic tests: the 3D pair benchmark in a reduced run: the columns of pairs.csv, a row for
// every method, our exact methods against the long-double references, Bullet's hulls
// measurably approximate.
#include <doctest/doctest.h>

#include "CsvTable.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#ifdef B2A_BENCH_PAIRS3D // the benchmark needs Bullet (libbullet-dev)

using namespace b2a::test;

TEST_CASE("b2a_bench_pairs3d: Figure 17's pair and ellipsoids, every method timed and checked")
{
	const std::string out = "demo_out/bench_pairs3d";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("demo_out");
	const std::string cmd = std::string("\"") + B2A_BENCH_PAIRS3D + "\" --quick --poses 3 --repeats 1 --families " +
	                        "ellipsoid_a10,superellipsoid_fig17 --out " + out + " > " + out + ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);
	std::vector<std::string> header;
	const std::vector<CsvRow> rows = ReadCsv(out + "/pairs3d.csv", header);
	// The columns of the 2D pairs.csv, the ratio against the 3D baseline last.
	CHECK(header == std::vector<std::string>{"pair", "method", "ns_per_query", "max_point_error", "max_normal_error",
	                                         "max_separation_error", "failures", "queries", "compared", "x_bullet64"});
	std::set<std::string> methods;
	for (const CsvRow& r : rows)
	{
		CAPTURE(r.at("pair"));
		CAPTURE(r.at("method"));
		methods.insert(r.at("method"));
		CHECK(CsvNumber(r, "ns_per_query") > 0.0);
		CHECK(CsvNumber(r, "x_bullet64") > 0.0);
		const std::string& m = r.at("method");
		if (m == "newton_cold" || m == "newton_warm" || m == "auto" || m == "auto_warm" || m == "grid_refined")
		{
			CHECK(CsvNumber(r, "failures") == 0);
			CHECK(CsvNumber(r, "max_point_error") < 1e-9);
			CHECK(CsvNumber(r, "max_normal_error") < 1e-8);
			CHECK(CsvNumber(r, "max_separation_error") < 1e-9);
		}
		if (m.rfind("bullet_gjk_epa", 0) == 0)
			CHECK(CsvNumber(r, "max_separation_error") > 1e-6); // an inscribed polytope is off by construction
		if (m == "bullet_gjk_epa64")
			CHECK(CsvNumber(r, "x_bullet64") == 1.0);
	}
	CHECK(methods == std::set<std::string>{"newton_cold", "newton_warm", "auto", "auto_warm", "grid_256", "grid_1024", "grid_4096",
	                                       "grid_refined", "bullet_gjk_epa32", "bullet_gjk_epa64", "bullet_gjk_epa128",
	                                       "bullet_gjk_epa256", "bullet_gjk_epa512"});
	CHECK(std::filesystem::exists(out + "/pairs3d_superellipsoid_fig17.svg"));
	CHECK(std::filesystem::exists(out + "/pairs3d.md"));
}

#endif

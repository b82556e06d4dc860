// b2analytic tests: the pair benchmark in a reduced run: its table has the promised columns and
// a row for every method, our exact methods agree with the long-double references, and the
// approximations it compares against are measurably approximate.
#include <doctest/doctest.h>

#include "CsvTable.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <sys/wait.h>

#ifdef B2A_BENCH_PAIRS // the benchmarks are optional (B2A_BUILD_BENCHMARKS)

using namespace b2a::test;

TEST_CASE("b2a_bench_pairs: ellipse and heart pairs, every method timed and checked against the references")
{
	const std::string out = "demo_out/bench_pairs";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("demo_out");
	const std::string cmd = std::string("\"") + B2A_BENCH_PAIRS + "\" --quick --poses 4 --repeats 1 --families " +
	                        "ellipse_a3,heart_heart --out " + out + " > " + out + ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);

	std::vector<std::string> header;
	const std::vector<CsvRow> rows = ReadCsv(out + "/pairs.csv", header);
	const std::vector<std::string> promised = {"pair", "method", "ns_per_query", "max_point_error", "max_normal_error",
	                                           "max_separation_error", "failures"};
	REQUIRE(header.size() >= promised.size());
	CHECK(std::vector<std::string>(header.begin(), header.begin() + promised.size()) == promised);

	std::set<std::string> ellipseMethods, heartMethods;
	for (const CsvRow& r : rows)
	{
		CAPTURE(r.at("pair"));
		CAPTURE(r.at("method"));
		(r.at("pair") == "ellipse_a3" ? ellipseMethods : heartMethods).insert(r.at("method"));
		const double ns = CsvNumber(r, "ns_per_query");
		CHECK(std::isfinite(ns));
		CHECK(ns > 0.0);
		const std::string& m = r.at("method");
		const bool exact = m == "newton_cold" || m == "newton_warm" || m == "auto" || m == "auto_warm" || m == "grid_refined";
		if (exact)
		{
			// Against references computed independently in long double (PairReference.h).
			CHECK(CsvNumber(r, "failures") == 0);
			CHECK(CsvNumber(r, "max_point_error") < 1e-8);
			CHECK(CsvNumber(r, "max_normal_error") < 1e-7);
			CHECK(CsvNumber(r, "max_separation_error") < 1e-8);
		}
		// The ratio to the 8-gons, timed alongside on the same poses: positive for every row
		// (1 for the 8-gons themselves; for hearts, the hull of their 8-gon).
		CHECK(CsvNumber(r, "x_polygon8") > 0.0);
		if (m == "box2d_polygon8")
			CHECK(CsvNumber(r, "x_polygon8") == 1.0);
		if (m == "box2d_polygon8" && r.at("pair") == "heart_heart")
		{
			// A time baseline only: the hull's answers are not the hearts', and are not compared.
			CHECK(r.at("failures").empty());
			CHECK(r.at("max_point_error") == "n/a");
			CHECK(CsvNumber(r, "compared") == 0);
		}
		if (m == "grid_64")
			CHECK(CsvNumber(r, "max_point_error") > 1e-4); // the paper's plain grid: off by about a sample spacing
		if (m == "box2d_gjk8" && r.at("max_point_error") != "n/a")
			CHECK(CsvNumber(r, "max_point_error") > 1e-3); // an octagon is not an ellipse
	}
	const std::set<std::string> convex = {"newton_cold", "newton_warm", "auto", "auto_warm", "grid_64", "grid_256",
	                                      "grid_1024", "grid_4096", "grid_refined", "box2d_polygon8", "box2d_obb",
	                                      "box2d_gjk8", "box2d_gjk16", "box2d_gjk32", "box2d_gjk64"};
	const std::set<std::string> hearts = {"auto",     "grid_64",      "grid_256",      "grid_1024",
	                                      "grid_4096", "grid_refined", "box2d_polygon8"};
	CHECK(ellipseMethods == convex);
	CHECK(heartMethods == hearts);
	CHECK(std::filesystem::exists(out + "/pairs.md"));
	CHECK(std::filesystem::exists(out + "/pairs_heart_heart.svg"));

	// A family's poses do not depend on which families run with it: heart_heart alone gives the
	// same answers, so the same error columns, as after ellipse_a3 (a generator shared by the
	// families in turn would pose it differently).
	const std::string alone = out + "_alone";
	std::filesystem::remove_all(alone);
	const std::string cmdAlone = std::string("\"") + B2A_BENCH_PAIRS + "\" --quick --poses 4 --repeats 1 --families " +
	                             "heart_heart --out " + alone + " > /dev/null 2>&1";
	REQUIRE(std::system(cmdAlone.c_str()) == 0);
	std::vector<std::string> headerAlone;
	const std::vector<CsvRow> rowsAlone = ReadCsv(alone + "/pairs.csv", headerAlone);
	int matched = 0;
	for (const CsvRow& r : rowsAlone)
		for (const CsvRow& s : rows)
			if (s.at("pair") == r.at("pair") && s.at("method") == r.at("method"))
			{
				CAPTURE(r.at("method"));
				for (const char* column : {"max_point_error", "max_normal_error", "max_separation_error", "failures"})
					CHECK(r.at(column) == s.at(column));
				++matched;
			}
	CHECK(matched == int(hearts.size()));

	// A pair family that does not exist is an error naming it, with exit status 2.
	const std::string bad = std::string("\"") + B2A_BENCH_PAIRS + "\" --families no_such_pair --out " + out +
	                        "_bad > /dev/null 2>&1";
	CHECK(WEXITSTATUS(std::system(bad.c_str())) == 2);
}

#endif

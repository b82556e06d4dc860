// b2analytic tests: the whole-scene benchmark in its quick mode: its table has the promised
// columns and rows, its timings are finite and positive, both variants keep every particle, and
// the 8-gons are the inscribed polygons of the particles' shapes.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "CsvTable.h"
#include "common/GranularScene.h"

#include "b2analytic/HeartShape.h"
#include "b2analytic/SuperellipseShape.h"

TEST_CASE("MixedParticle: the mixed scenes' families, sizes and exponents from its two draws")
{
	using namespace b2a;
	const double a = 1.1, b = 0.6875;
	// 2 % hearts about 2a wide (the heart of alpha = 1 is 2.278 wide; the outline is not a pure
	// scaling in alpha, so near alpha = 1 the width is √alpha times that to within half a percent).
	const ShapePtr heart = demo::MixedParticle(a, b, 0.01, 0.5);
	REQUIRE(dynamic_cast<const HeartShape*>(heart.get()));
	const Box hb = heart->ComputeAABB(Pose());
	CHECK(hb.upper.x - hb.lower.x == doctest::Approx(2.0 * a).epsilon(5e-3));
	// 30 % circles of radius (a + b)/2, 30 % ellipses a x b, the rest superellipses with n = m
	// = 2.5 + 3 u.
	const auto circle = std::dynamic_pointer_cast<const SuperellipseShape>(demo::MixedParticle(a, b, 0.2, 0.5));
	REQUIRE(circle);
	CHECK(circle->A() == doctest::Approx(0.5 * (a + b)));
	CHECK(circle->B() == doctest::Approx(0.5 * (a + b)));
	CHECK(circle->N() == 2.0);
	const auto ellipse = std::dynamic_pointer_cast<const SuperellipseShape>(demo::MixedParticle(a, b, 0.5, 0.5));
	REQUIRE(ellipse);
	CHECK(ellipse->A() == a);
	CHECK(ellipse->B() == b);
	CHECK(ellipse->N() == 2.0);
	const auto super = std::dynamic_pointer_cast<const SuperellipseShape>(demo::MixedParticle(a, b, 0.9, 0.25));
	REQUIRE(super);
	CHECK(super->N() == 3.25);
	CHECK(super->M() == 3.25);
}

#ifdef B2A_BENCH_SCENES // the benchmarks are optional (B2A_BUILD_BENCHMARKS)

namespace
{
using Row = b2a::test::CsvRow;
using b2a::test::ReadCsv;

double Number(const Row& row, const std::string& column) { return b2a::test::CsvNumber(row, column); }

int ExitStatus(const std::string& args)
{
	const std::string cmd = std::string("\"") + B2A_BENCH_SCENES + "\" " + args + " > /dev/null 2>&1";
	return WEXITSTATUS(std::system(cmd.c_str()));
}
} // namespace

TEST_CASE("b2a_bench_scenes: the quick run times both scenes in all three variants and keeps every particle")
{
	const std::string out = "demo_out/bench_scenes";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("demo_out");
	const std::string cmd =
		std::string("\"") + B2A_BENCH_SCENES + "\" --quick --threads 2 --out " + out + " > " + out + ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);

	std::vector<std::string> header;
	const std::vector<Row> rows = ReadCsv(out + "/scenes.csv", header);
	const std::vector<std::string> columns = {
		"scene", "particle", "count", "variant", "box_width_mm", "outlet_mm", "window_start_step", "window_steps", "bodies",
		"touching_contacts_per_particle", "contact_pairs_per_particle", "step_ms", "step_mean_ms", "collide_ms", "solve_ms",
		"broadphase_ms", "collide_median_ms", "solve_median_ms", "solve_toi_ms", "step_cpu_ms", "us_per_particle_step",
		"step_vs_polygon8", "collide_vs_polygon8", "solve_vs_polygon8", "cpu_vs_polygon8", "growth_vs_smallest",
		"growth_cpu_vs_smallest", "particles_end", "discharged", "nonfinite", "escaped", "run_s", "threads", "wall_step_ms",
		"wall_vs_polygon8", "wall_speedup"};
	CHECK(header == columns);

	// Quick: the smallest count only, each scene once per variant, in that order.
	REQUIRE(rows.size() == 6);
	const char* scenes[] = {"packing", "packing", "packing", "hopper", "hopper", "hopper"};
	const char* variants[] = {"analytic", "analytic_2threads", "polygon8", "analytic", "analytic_2threads", "polygon8"};
	std::map<std::string, double> polygonStep, polygonCollide, polygonCpu;
	for (size_t i = 0; i < rows.size(); ++i)
	{
		const Row& r = rows[i];
		CAPTURE(i);
		CHECK(r.at("scene") == scenes[i]);
		CHECK(r.at("variant") == variants[i]);
		const double count = Number(r, "count");
		CHECK(count == 250);
		for (const char* c : {"box_width_mm", "window_start_step", "window_steps", "bodies", "touching_contacts_per_particle",
		                      "contact_pairs_per_particle", "step_ms", "step_mean_ms", "collide_ms", "solve_ms", "broadphase_ms",
		                      "collide_median_ms", "solve_median_ms", "solve_toi_ms", "step_cpu_ms", "us_per_particle_step",
		                      "step_vs_polygon8", "collide_vs_polygon8", "solve_vs_polygon8", "cpu_vs_polygon8",
		                      "growth_vs_smallest", "growth_cpu_vs_smallest", "run_s", "threads", "wall_step_ms", "wall_vs_polygon8",
		                      "wall_speedup"})
		{
			CAPTURE(c);
			const double v = Number(r, c);
			CHECK(std::isfinite(v));
			CHECK(v > 0.0);
		}
		CHECK(Number(r, "window_steps") == 30);
		CHECK(Number(r, "threads") == (r.at("variant") == "analytic_2threads" ? 2 : 1));
		// The particles: none lost or made up, none non-finite, none outside the container.
		CHECK(Number(r, "particles_end") == count);
		CHECK(Number(r, "nonfinite") == 0);
		CHECK(Number(r, "escaped") == 0);
		CHECK(Number(r, "bodies") <= count);
		CHECK(Number(r, "bodies") + Number(r, "discharged") >= count - 1e-9);
		// Particles in a pile touch about two others (Box2D counts each contact once).
		CHECK(Number(r, "touching_contacts_per_particle") > 0.5);
		CHECK(Number(r, "touching_contacts_per_particle") < 4.0);
		CHECK(Number(r, "growth_vs_smallest") == 1.0); // the only count is the smallest
		CHECK(Number(r, "growth_cpu_vs_smallest") == 1.0);
		// The phases measured inside Box2D's step fit in its mean step time (timer rounding aside).
		const double phases = Number(r, "collide_ms") + Number(r, "solve_ms") + Number(r, "solve_toi_ms");
		CHECK(phases <= 1.01 * Number(r, "step_mean_ms") + 1e-3);
		CHECK(Number(r, "broadphase_ms") <= Number(r, "solve_ms") * 1.001);
		if (r.at("variant") == "polygon8")
		{
			CHECK(Number(r, "step_vs_polygon8") == 1.0);
			CHECK(Number(r, "cpu_vs_polygon8") == 1.0);
			polygonStep[r.at("scene")] = Number(r, "step_ms");
			polygonCpu[r.at("scene")] = Number(r, "step_cpu_ms");
			polygonCollide[r.at("scene")] = Number(r, "collide_ms");
		}
	}
	// Ratios: the analytic time over the polygon time of the same scene (4 significant digits).
	for (size_t i = 0; i < rows.size(); ++i)
	{
		const Row& r = rows[i];
		if (r.at("variant") == "polygon8")
			continue;
		const std::string scene = r.at("scene");
		CHECK(Number(r, "step_vs_polygon8") == doctest::Approx(Number(r, "step_ms") / polygonStep[scene]).epsilon(2e-3));
		CHECK(Number(r, "collide_vs_polygon8") == doctest::Approx(Number(r, "collide_ms") / polygonCollide[scene]).epsilon(2e-3));
		CHECK(Number(r, "cpu_vs_polygon8") == doctest::Approx(Number(r, "step_cpu_ms") / polygonCpu[scene]).epsilon(2e-3));
	}
	// All variants of a scene run the same steps of the same container.
	for (size_t i : {0, 3})
	{
		CHECK(rows[i].at("window_start_step") == rows[i + 1].at("window_start_step"));
		CHECK(rows[i].at("window_start_step") == rows[i + 2].at("window_start_step"));
		// Contacts prepared on two threads step bit-identically: the same particles in the box,
		// the same discharge and the same contacts over the window, to every printed digit.
		for (const char* c : {"bodies", "touching_contacts_per_particle", "contact_pairs_per_particle", "particles_end", "discharged"})
		{
			CAPTURE(c);
			CHECK(rows[i].at(c) == rows[i + 1].at(c));
		}
		CHECK(Number(rows[i], "wall_speedup") == 1.0);
		CHECK(Number(rows[i + 1], "wall_speedup") ==
		      doctest::Approx(Number(rows[i], "wall_step_ms") / Number(rows[i + 1], "wall_step_ms")).epsilon(2e-3));
	}
	CHECK(Number(rows[3], "outlet_mm") > 0.0); // the hopper has an outlet, the packing box none
	CHECK(Number(rows[0], "outlet_mm") == 0.0);

	std::ifstream f(out + "/summary.json");
	REQUIRE(f.good());
	const nlohmann::json s = nlohmann::json::parse(f);
	CHECK(s["particles_intact"] == true);
	for (const auto& run : s["runs"])
		CHECK(run["fixtures_ok"] == true); // analytic runs analytic fixtures, polygon runs plain 8-gons
	// The 8-gons: vertices on the shapes' surfaces, and the areas of the inscribed polygons.
	// Ellipse: the affine image of the regular octagon, 2√2 ab, over π ab. Superellipse n = 4:
	// vertices (±a, 0), (0, ±b), (±c a, ±c b) with c = 2^(-1/4), area 4 c ab, over the
	// superellipse's 4 ab Γ(1 + 1/4)² / Γ(1 + 1/2).
	const double ellipseRatio = 2.0 * std::sqrt(2.0) / M_PI;
	const double superRatio = std::pow(2.0, -0.25) * std::tgamma(1.5) / (std::tgamma(1.25) * std::tgamma(1.25));
	CHECK(s["polygon_check"]["hopper"]["max_vertex_radial_error"].get<double>() < 1e-6);
	CHECK(s["polygon_check"]["packing"]["max_vertex_radial_error"].get<double>() < 1e-6);
	CHECK(s["polygon_check"]["hopper"]["mean_area_over_analytic"].get<double>() == doctest::Approx(ellipseRatio).epsilon(1e-6));
	CHECK(s["polygon_check"]["packing"]["mean_area_over_analytic"].get<double>() == doctest::Approx(superRatio).epsilon(1e-6));
	CHECK(s["machine"]["cpu"].is_string());

	std::ifstream md(out + "/scenes.md");
	std::stringstream text;
	text << md.rdbuf();
	CHECK(text.str().find("Machine: ") != std::string::npos);
	CHECK(text.str().find("Build: ") != std::string::npos);
	CHECK(text.str().find("| hopper | 250 | analytic |") != std::string::npos);
}

TEST_CASE("b2a_bench_scenes: the layer scene keeps its depth at every count, so the growth compares like with like")
{
	// Two counts whose lattices fill whole rows: 24 rows of 10 and of 20 particles.
	const std::string out = "demo_out/bench_scenes_layer";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("demo_out");
	const std::string cmd = std::string("\"") + B2A_BENCH_SCENES + "\" --counts 480,240 --steps 10 --scenes layer --out " + out +
	                        " > " + out + ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);
	std::vector<std::string> header;
	const std::vector<Row> rows = ReadCsv(out + "/scenes.csv", header);
	REQUIRE(rows.size() == 4); // counts sorted: 240 analytic, 240 polygon8, 480 analytic, 480 polygon8
	const double cell = 1.15 * 2.0; // GranularScene's lattice cell for 2 mm particles
	for (size_t i = 0; i < rows.size(); ++i)
	{
		const Row& r = rows[i];
		CAPTURE(i);
		CHECK(r.at("scene") == "layer");
		const double count = Number(r, "count");
		CHECK(count == (i < 2 ? 240 : 480));
		// The box holds count/24 lattice columns (and half a cell to spare), closed: no outlet.
		CHECK(Number(r, "box_width_mm") == doctest::Approx(2.0 + (count / 24 + 0.5) * cell).epsilon(1e-3));
		CHECK(Number(r, "outlet_mm") == 0.0);
		CHECK(Number(r, "particles_end") == count);
		CHECK(Number(r, "nonfinite") == 0);
		CHECK(Number(r, "escaped") == 0);
		// The same depth: the lattice's top falls for the same time at both counts, and the
		// window starts at the same step.
		CHECK(r.at("window_start_step") == rows[0].at("window_start_step"));
		// The growth column: cost per particle-step over the same variant's at the smallest count.
		const Row& smallest = rows[i % 2];
		CHECK(Number(r, "growth_vs_smallest") ==
		      doctest::Approx(Number(r, "us_per_particle_step") / Number(smallest, "us_per_particle_step")).epsilon(2e-3));
	}
	// The same local physics: about as many touching contacts per particle at both counts
	// (the walls' share halves from 240 to 480; it is small either way).
	for (size_t i : {0, 1})
	{
		CAPTURE(i);
		CHECK(Number(rows[i + 2], "touching_contacts_per_particle") ==
		      doctest::Approx(Number(rows[i], "touching_contacts_per_particle")).epsilon(0.15));
	}
}

TEST_CASE("b2a_bench_scenes rejects bad options with exit status 2")
{
	CHECK(ExitStatus("--counts 12.5 --out demo_out/bench_scenes_bad") == 2);
	CHECK(ExitStatus("--scenes packing,bogus --out demo_out/bench_scenes_bad") == 2);
	CHECK(ExitStatus("--steps 0 --out demo_out/bench_scenes_bad") == 2);
	CHECK(ExitStatus("--threads 1 --out demo_out/bench_scenes_bad") == 2);   // 1 thread is the analytic variant
	CHECK(ExitStatus("--threads 2.5 --out demo_out/bench_scenes_bad") == 2);
	CHECK(ExitStatus("--game --game-families ellipse,bogus --out demo_out/bench_scenes_bad") == 2);
	CHECK(ExitStatus("--game --game-only both --out demo_out/bench_scenes_bad") == 2);
	CHECK(ExitStatus("--game --repeats 0 --out demo_out/bench_scenes_bad") == 2);
	CHECK(ExitStatus("--help") == 0);
}

TEST_CASE("b2a_bench_scenes --game: each family beside its 8-gons, every particle kept, ratios in the same run")
{
	const std::string out = "demo_out/bench_scenes_game";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("demo_out");
	const std::string cmd = std::string("\"") + B2A_BENCH_SCENES +
	                        "\" --game --quick --game-families heart,mixed --game-steps 40 --repeats 2 --out " + out + " > " + out +
	                        ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);
	std::vector<std::string> header;
	const std::vector<Row> rows = ReadCsv(out + "/game.csv", header);
	REQUIRE(rows.size() == 4);
	const char* families[] = {"heart", "heart", "mixed", "mixed"};
	for (size_t i = 0; i < rows.size(); ++i)
	{
		CAPTURE(i);
		const Row& r = rows[i];
		CHECK(r.at("family") == families[i]);
		CHECK(r.at("variant") == (i % 2 == 0 ? "analytic" : "polygon8"));
		CHECK(Number(r, "count") == 300);
		CHECK(Number(r, "steps") == 40);
		CHECK(Number(r, "repeats") == 2);
		CHECK(Number(r, "step_cpu_ms") > 0.0);
		CHECK(std::isfinite(Number(r, "step_cpu_ms")));
		// The ratios are this run's: each row's time over its 8-gon row's.
		const Row& base = rows[i - i % 2 + 1];
		CHECK(Number(r, "cpu_vs_polygon8") == doctest::Approx(Number(r, "step_cpu_ms") / Number(base, "step_cpu_ms")).epsilon(1e-3));
		// In 40 steps (0.67 s) the lattice is still falling: every body awake, none asleep.
		CHECK(Number(r, "awake_mean") == doctest::Approx(300.0));
		CHECK(Number(r, "nonfinite") == 0);
		CHECK(Number(r, "escaped") == 0);
	}
	std::ifstream summary(out + "/game.json");
	const nlohmann::json j = nlohmann::json::parse(summary);
	CHECK(j["particles_intact"].get<bool>());
	CHECK(j["runs"].size() == 4);
	CHECK(j["runs"][0]["step_cpu_ms_repeats"].size() == 2);
}

TEST_CASE("b2a_bench_scenes: the mixed scene runs both variants and keeps every particle")
{
	const std::string out = "demo_out/bench_scenes_mixed";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("demo_out");
	const std::string cmd = std::string("\"") + B2A_BENCH_SCENES + "\" --quick --scenes mixed --out " + out + " > " + out +
	                        ".stdout 2> " + out + ".stderr";
	INFO("command: " << cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);
	std::vector<std::string> header;
	const std::vector<Row> rows = ReadCsv(out + "/scenes.csv", header);
	REQUIRE(rows.size() == 2);
	for (const Row& r : rows)
	{
		CHECK(r.at("scene") == "mixed");
		CHECK(Number(r, "particles_end") == 250);
		CHECK(Number(r, "nonfinite") == 0);
		CHECK(Number(r, "escaped") == 0);
	}
	std::ifstream f(out + "/summary.json");
	REQUIRE(f.good());
	const nlohmann::json s = nlohmann::json::parse(f);
	CHECK(s["particles_intact"] == true);
	// Hulls of the hearts' 8 points have fewer vertices; every vertex lies on its surface.
	CHECK(s["polygon_check"]["mixed"]["max_vertex_radial_error"].get<double>() < 1e-6);
}

#endif

#include "GameScenes.h"

#include "BenchCommon.h"
#include "common/GameBucket.h"

#include "b2analytic/b2analytic.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace b2a::bench
{
using namespace b2a::demo;

const char* kGameScenesHelp = R"(
With --game, instead: the bucket of b2a_demo_game in a game's units (metres, g = 10 m/s^2,
60 Hz, 8 velocity and 3 position iterations, sleeping on), at every --game-counts N: N
particles of one family (ellipses 0.5 x 0.3 m, superellipses n = 4 0.5 x 0.3 m, hearts
alpha 0.2, circles r 0.4 m) or of the four in turn (mixed), dropped from a lattice into a
b2ChainShape bucket 16*sqrt(N/300) m wide; beside the same scene of Box2D 8-gons inscribed
in the same shapes (MakeInscribedPolygon; for hearts the convex hull of 8 points of the
outline). Every step of --game-steps is timed by the stepping thread's CPU time; each variant
runs --repeats times, alternated with the other, and the figures are medians over the repeats
of the mean per step. Writes DIR/game.csv, DIR/game.md and DIR/game.json.
)";

namespace
{
/// One variant of one game scene, and what its repeats measured (medians over the repeats).
struct GameRun
{
	std::string family;
	int count = 0;
	bool polygons = false;
	std::vector<double> cpu, collide, solve, broadphase; // ms per step, mean over the run's steps, one per repeat
	std::vector<double> awakeMean;                       // bodies awake after a step, mean over the run's steps
	double touching = 0.0, pairs = 0.0;                  // at the end of the last repeat, per particle
	int awake = 0, nonFinite = 0, escaped = 0, bodies = 0;
};

double Width(int count) { return 16.0 * std::sqrt(count / 300.0); }

/// One run: every step timed; the means per step appended to the run's lists.
void RunOnce(GameRun& run, int steps, std::uint64_t seed)
{
	std::unique_ptr<b2World> world = MakeGameBucket(GameFamilies(run.family), run.count, run.polygons, seed, Width(run.count));
	double cpu = 0.0, collide = 0.0, solve = 0.0, broadphase = 0.0, awake = 0.0;
	for (int s = 0; s < steps; ++s)
	{
		const double before = ThreadCpuNanoseconds();
		world->Step(kGameStep, kGameVelocityIterations, kGamePositionIterations);
		cpu += 1e-6 * (ThreadCpuNanoseconds() - before);
		const b2Profile& p = world->GetProfile();
		collide += p.collide;
		solve += p.solve;
		broadphase += p.broadphase;
		awake += AwakeBodies(*world);
	}
	run.cpu.push_back(cpu / steps);
	run.collide.push_back(collide / steps);
	run.solve.push_back(solve / steps);
	run.broadphase.push_back(broadphase / steps);
	run.awakeMean.push_back(awake / steps);
	int touching = 0;
	for (b2Contact* c = world->GetContactList(); c; c = c->GetNext())
		touching += c->IsTouching() ? 1 : 0;
	run.touching = double(touching) / run.count;
	run.pairs = double(world->GetContactCount()) / run.count;
	run.awake = AwakeBodies(*world);
	run.nonFinite = run.escaped = run.bodies = 0;
	const double half = 0.5 * Width(run.count) + 1.0;
	for (b2Body* b = world->GetBodyList(); b; b = b->GetNext())
	{
		if (b->GetType() != b2_dynamicBody)
			continue;
		++run.bodies;
		const b2Vec2 p = b->GetPosition();
		if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(b->GetAngle()))
			++run.nonFinite;
		else if (std::fabs(p.x) > half || p.y < -1.0)
			++run.escaped;
	}
}
} // namespace

int RunGameScenes(const DemoOptions& opt, const GameSceneOptions& options, Progress& progress)
{
	std::vector<GameRun> runs;
	for (int count : options.counts)
		for (const std::string& family : options.families)
			for (bool polygons : {false, true})
			{
				GameRun r;
				r.family = family;
				r.count = count;
				r.polygons = polygons;
				runs.push_back(r);
			}
	double total = 0.0, done = 0.0;
	for (const GameRun& r : runs)
		total += r.count;
	total *= options.repeats;
	// Each repeat runs the analytic scene and then its 8-gons, so that a change of load on the
	// machine touches both alike.
	for (size_t i = 0; i < runs.size(); i += 2)
		for (int k = 0; k < options.repeats; ++k)
			for (size_t j = i; j < i + 2; ++j)
			{
				GameRun& r = runs[j];
				if (!options.only.empty() && options.only != (r.polygons ? "polygon8" : "analytic"))
				{
					r.cpu = r.collide = r.solve = r.broadphase = r.awakeMean = {std::numeric_limits<double>::quiet_NaN()};
					r.bodies = r.count;
					continue;
				}
				progress.Report(done / total, "game " + r.family + " " + std::to_string(r.count) + (r.polygons ? " 8-gons" : " analytic") +
				                                  ", repeat " + std::to_string(k + 1));
				RunOnce(r, options.steps, opt.seed);
				done += r.count;
				std::fprintf(stderr, "b2a_bench_scenes: game %s %d %s: %.3f ms/step CPU (collide %.3f, solve %.3f)\n", r.family.c_str(),
				             r.count, r.polygons ? "polygon8" : "analytic", r.cpu.back(), r.collide.back(), r.solve.back());
			}

	Table csv, md;
	csv.columns = {"family", "count", "variant", "steps", "repeats", "step_cpu_ms", "collide_ms", "solve_ms", "broadphase_ms",
	               "cpu_vs_polygon8", "collide_vs_polygon8", "solve_vs_polygon8", "awake_mean", "cpu_us_per_awake_body",
	               "cpu_per_awake_vs_polygon8", "touching_per_particle", "pairs_per_particle", "awake_at_end", "nonfinite",
	               "escaped"};
	md.columns = {"family", "N", "variant", "CPU ms/step", "collide ms", "solve ms (broadphase)", "CPU × 8-gon", "collide × 8-gon",
	              "solve × 8-gon", "awake (mean)", "CPU µs/awake body", "per awake body × 8-gon", "touching/particle",
	              "pairs/particle", "awake at end"};
	Json list = Json::array();
	bool intact = true;
	std::string line, sleeping;
	for (size_t i = 0; i < runs.size(); ++i)
	{
		const GameRun& r = runs[i];
		const GameRun& base = runs[i - i % 2 + 1];
		const double cpu = Median(r.cpu), collide = Median(r.collide), solve = Median(r.solve), broad = Median(r.broadphase);
		const double cpuRatio = cpu / Median(base.cpu), collideRatio = collide / Median(base.collide),
		             solveRatio = solve / Median(base.solve);
		// CPU per awake body-step: sleeping bodies cost Box2D nothing, so a scene whose bodies
		// sleep sooner is cheaper for that alone; this ratio is the cost of the bodies that move.
		const double awake = Median(r.awakeMean), perAwake = 1e3 * cpu / std::max(awake, 1.0),
		             perAwakeRatio = perAwake / (1e3 * Median(base.cpu) / std::max(Median(base.awakeMean), 1.0));
		intact = intact && r.nonFinite == 0 && r.escaped == 0 && r.bodies == r.count;
		const std::string variant = r.polygons ? "polygon8" : "analytic";
		csv.rows.push_back({r.family, std::to_string(r.count), variant, std::to_string(options.steps), std::to_string(options.repeats),
		                    FormatNumber(cpu), FormatNumber(collide), FormatNumber(solve), FormatNumber(broad), FormatNumber(cpuRatio),
		                    FormatNumber(collideRatio), FormatNumber(solveRatio), FormatNumber(awake), FormatNumber(perAwake),
		                    FormatNumber(perAwakeRatio), FormatNumber(r.touching), FormatNumber(r.pairs),
		                    std::to_string(r.awake), std::to_string(r.nonFinite), std::to_string(r.escaped)});
		md.rows.push_back({r.family, std::to_string(r.count), r.polygons ? "8-gon" : "analytic", FormatNumber(cpu, 3),
		                   FormatNumber(collide, 3), FormatNumber(solve, 3) + " (" + FormatNumber(broad, 2) + ")",
		                   FormatNumber(cpuRatio, 3), FormatNumber(collideRatio, 3), FormatNumber(solveRatio, 3),
		                   FormatNumber(awake, 3), FormatNumber(perAwake, 3), FormatNumber(perAwakeRatio, 3), FormatNumber(r.touching, 3), FormatNumber(r.pairs, 3), std::to_string(r.awake)});
		list.push_back({{"family", r.family}, {"count", r.count}, {"variant", variant}, {"step_cpu_ms", cpu}, {"collide_ms", collide},
		                {"solve_ms", solve}, {"broadphase_ms", broad}, {"cpu_vs_polygon8", cpuRatio},
		                {"collide_vs_polygon8", collideRatio}, {"solve_vs_polygon8", solveRatio}, {"awake_mean", awake},
		                {"cpu_us_per_awake_body", perAwake}, {"cpu_per_awake_vs_polygon8", perAwakeRatio},
		                {"touching_per_particle", r.touching}, {"pairs_per_particle", r.pairs}, {"awake_at_end", r.awake},
		                {"nonfinite", r.nonFinite}, {"escaped", r.escaped}, {"step_cpu_ms_repeats", r.cpu}});
		// An analytic pile that keeps more bodies awake than its 8-gons pays for them every step:
		// named below the table, with its cost per awake body, the part its contacts decide.
		if (!r.polygons && awake > 1.1 * Median(base.awakeMean))
			sleeping += "- " + r.family + " " + std::to_string(r.count) + ": the analytic pile keeps " + FormatNumber(awake, 3) +
			            " bodies awake on average (" + std::to_string(r.awake) + " at the end of the " +
			            std::to_string(options.steps) + " steps), its 8-gons " + FormatNumber(Median(base.awakeMean), 3) + " (" +
			            std::to_string(base.awake) + " at the end): " + FormatNumber(cpuRatio, 3) + " × per step, " +
			            FormatNumber(perAwakeRatio, 3) + " × per awake body.\n";
		if (!r.polygons)
			line += "; " + r.family + " " + std::to_string(r.count) + " " + FormatNumber(cpuRatio, 3) + "x (per awake body " +
			        FormatNumber(perAwakeRatio, 3) + "x)";
	}
	WriteText(opt.out + "/game.csv", csv.Csv());
	const MachineInfo machine = GetMachineInfo();
	std::string text = "# b2a_bench_scenes --game\n\nMachine: " + machine.cpu + ", " + std::to_string(machine.cores) +
	                   " hardware threads.  \nBuild: " + machine.buildFlags + ".  \n" + std::to_string(options.steps) +
	                   " steps of 1/60 s from the drop, every one timed (CPU time of the stepping thread); medians over " +
	                   std::to_string(options.repeats) +
	                   " repeats of the mean per step. Bodies asleep cost Box2D nothing: `awake (mean)` is the mean number "
	                   "of bodies awake after a step, and `per awake body` the CPU time per step over it, the cost of the "
	                   "bodies that move whichever scene sleeps sooner. collide and solve: Box2D's profile (wall-clock; solve includes the "
	                   "broadphase). `× 8-gon`: over the same scene of Box2D 8-gons inscribed in the same shapes (hearts: the "
	                   "convex hull of 8 points of the outline).\n\n" +
	                   md.Markdown();
	if (!sleeping.empty())
		text += "\nPiles that sleep later than their 8-gons (the time per step then counts bodies the 8-gons let sleep; "
		        "compare per awake body):\n\n" +
		        sleeping;
	WriteText(opt.out + "/game.md", text);
	Json summary;
	summary["benchmark"] = "b2a_bench_scenes --game";
	summary["machine"] = MachineJson(machine);
	summary["seed"] = opt.seed;
	summary["quick"] = opt.quick;
	summary["steps"] = options.steps;
	summary["repeats"] = options.repeats;
	summary["runs"] = list;
	summary["particles_intact"] = intact;
	WriteJson(opt.out + "/game.json", summary);
	std::printf("b2a_bench_scenes --game: CPU per step over 8-gons%s; particles %s -> %s/game.md\n", line.c_str(),
	            intact ? "intact" : "LOST OR BROKEN", opt.out.c_str());
	return intact ? 0 : 1;
}

} // namespace b2a::bench

// b2analytic benchmark: whole granular simulations (the packing and hopper scenes of the demos),
// each run with analytic particles and with Box2D 8-gons inscribed in the same shapes; step time
// split by Box2D's own profile, at growing particle counts.
#include "BenchCommon.h"
#include "GameScenes.h"
#include "common/CommandLine.h"
#include "common/GameBucket.h"
#include "common/GranularScene.h"

#include "b2analytic/b2analytic.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <time.h>

using namespace b2a;
using namespace b2a::bench;
using namespace b2a::demo;

namespace
{
const std::string kHelp = std::string(R"(b2a_bench_scenes: whole simulations, analytic particles against Box2D 8-gons.

Two scenes of the demos (GranularScene, millimetre units, g = 9810 mm/s^2, step 2e-4 s, 8
velocity and 3 position iterations, sleeping off), each at every particle count:
  packing  superellipses n = 4, 2 mm wide, aspect 1.6, sizes +-10 % (b2a_demo_packing) fall
           from a loose lattice into a closed box 2*sqrt(N) mm wide (the demo's 60 mm at 900);
           measured while the pile settles: the window starts when the lattice's top would
           have fallen to the floor, sqrt(2 h/g).
  hopper   ellipses 2 x 0.66 mm, sizes +-5 %, friction 0.5 on particles and walls
           (b2a_demo_beverloo) fill a box 80*sqrt(N/4000) mm wide (the demo's 80 mm at 4000)
           with the outlet (0.3 of the width) gated; 0.05 s after that fall the gate opens,
           and after 0.02 s of flow the window measures the discharge.
  layer    the packing's superellipses in a box as wide as N/24 lattice columns, so that
           the layer is 24 particles deep at every count and each particle's neighbourhood,
           drop height and speeds are the same at every N (in the packing and the hopper
           they grow as sqrt(N)): the scene for how the cost per particle-step grows with N.
           Measured as the packing is, while the layer settles.
  mixed    the packing's box and schedule with mixed particles of the same sizes
           (MixedParticle): 38 % superellipses with exponents n = m drawn from
           [2.5, 5.5), 30 % ellipses, 30 % circles, 2 % hearts; the hearts' 8-gons are
           their convex hulls'.
Each scene runs twice from the same lattice (same sizes, orientations and places): with
analytic fixtures, and with plain Box2D b2PolygonShapes of 8 vertices on the same surfaces
(MakeInscribedPolygon: the outline inscribed; same density, friction and restitution; Box2D's
skin b2_polygonRadius). Both run the same steps; the window's steps are timed with
b2World::GetProfile() (milliseconds): step is the median over the window, collide, solve
(broadphase is part of it) and solveTOI are means (collide and solve also as medians in the
CSV). Box2D's profile is wall-clock time, which on a shared machine counts other processes'
time too; so each step's CPU time of this thread is taken as well (its median: step_cpu_ms).
The cost per particle-step is the median step time over the mean number of particles in the
box; growth is that cost at a count over the cost at the smallest count. After each
run every particle is checked: none lost (in the box plus discharged = N), none non-finite,
none outside the container.

Writes DIR/scenes.csv, DIR/scenes.md and DIR/summary.json, and DIR/<scene>_<N>_<variant>.svg
pictures at the end of the window for the smallest count. Exits 1 if a particle was lost,
left the container or became non-finite.
)") + kGameScenesHelp;

// The issue's target for the hopper of ellipses: step and collide time over the 8-gons'.
constexpr double kTargetStepRatio = 1.5;
constexpr double kTargetCollideRatio = 2.0;
constexpr int kPolygonVertices = 8;

/// One scene at one count with one kind of particle, and what its window measured.
struct Run
{
	std::string scene, particle, variant;
	int count = 0;
	GranularConfig config;
	int openAt = -1; // step at which the outlet opens (hopper), -1: never
	int windowStart = 0, windowSteps = 0;

	double stepMedian = 0.0, stepMean = 0.0, collide = 0.0, solve = 0.0, broadphase = 0.0, solveTOI = 0.0; // ms
	double collideMedian = 0.0, solveMedian = 0.0; // ms, robust against a busy machine's interruptions
	double cpuMedian = 0.0; // ms of this thread's CPU time per step (median): blind to other processes' load
	double wallMedian = 0.0; // ms of wall-clock time per step (median), contact preparation included
	double bodies = 0.0;   // mean particles in the box over the window
	double touching = 0.0; // mean touching contacts per particle over the window
	double pairs = 0.0;    // mean Box2D contacts (fat AABBs overlapping: each evaluated every step) per particle
	int particlesEnd = 0, discharged = 0, nonFinite = 0, escaped = 0;
	bool fixturesOk = true;
	double runSeconds = 0.0;

	double MicrosecondsPerParticleStep() const { return 1000.0 * stepMedian / bodies; }
	double CpuMicrosecondsPerParticleStep() const { return 1000.0 * cpuMedian / bodies; }
	bool Intact() const { return particlesEnd == count && nonFinite == 0 && escaped == 0 && fixturesOk; }
};

/// The packing demo's particles in a closed box whose width grows as sqrt(N), so that the pile
/// keeps its aspect at every count.
GranularConfig PackingConfig(int count)
{
	GranularConfig c; // defaults: superellipses n = 4, 2 mm, aspect 1.6, ±10 %
	c.particles = count;
	c.boxWidth = 2.0 * std::sqrt(double(count));
	c.boxHeight = 10.0 * c.boxWidth; // above the initial lattice at every count
	c.outletWidth = 0.0;
	return c;
}

/// The Beverloo demo's ellipses in a box whose width and outlet grow as sqrt(N).
GranularConfig HopperConfig(int count)
{
	GranularConfig c = BeverlooEllipses();
	c.particles = count;
	c.boxWidth = 80.0 * std::sqrt(count / 4000.0);
	c.boxHeight = 10.0 * c.boxWidth;
	c.outletWidth = 0.3 * c.boxWidth;
	return c;
}

/// Rows of the layer scene's lattice, at every count.
constexpr int kLayerRows = 24;

/// The packing's particles in a box kLayerRows lattice rows deep: as wide as N/kLayerRows
/// lattice cells (GranularScene's cell, 1.15 particle widths), centred on x = 0, so that the
/// scene's local physics do not change with N.
GranularConfig LayerConfig(int count)
{
	GranularConfig c;
	c.particles = count;
	const double cell = 1.15 * c.width;
	const int perRow = (count + kLayerRows - 1) / kLayerRows;
	c.boxWidth = c.width + (perRow + 0.5) * cell; // GranularScene fits int((boxWidth - width)/cell) = perRow
	c.boxHeight = 3.0 * kLayerRows * cell;
	c.outletWidth = 0.0;
	return c;
}

/// The scenes --scenes may name, and the list as its messages print it.
const std::vector<std::string> kSceneNames = {"packing", "hopper", "layer", "mixed"};

/// The scene's configuration at a particle count.
GranularConfig SceneConfig(const std::string& scene, int count)
{
	if (scene == "hopper")
		return HopperConfig(count);
	if (scene == "mixed")
	{
		GranularConfig c = PackingConfig(count);
		c.mixed = true;
		return c;
	}
	return scene == "layer" ? LayerConfig(count) : PackingConfig(count);
}

/// The steps of a scene: its window starts when the top of the lattice (`top` mm above the
/// floor) would have fallen to the floor; the hopper first fills for 0.05 s more, then flows.
void Schedule(Run& run, double top, int windowSteps)
{
	const GranularConfig& c = run.config;
	const int fall = int(std::lround(std::sqrt(2.0 * top / c.gravity) / c.dt));
	if (run.scene == "hopper")
	{
		run.openAt = fall + int(std::lround(0.05 / c.dt));
		run.windowStart = run.openAt + int(std::lround(0.02 / c.dt));
	}
	else
		run.windowStart = fall;
	run.windowSteps = windowSteps;
}

// CPU time of this thread (ms). Box2D's profile is wall-clock time, which on a shared machine
// also counts the time other processes held the core.
double ThreadCpuMilliseconds()
{
	timespec t{};
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

int TouchingContacts(b2World& world)
{
	int n = 0;
	for (b2Contact* contact = world.GetContactList(); contact; contact = contact->GetNext())
		n += contact->IsTouching() ? 1 : 0;
	return n;
}

bool Finite(const b2Body& b)
{
	const b2Vec2 p = b.GetPosition(), v = b.GetLinearVelocity();
	return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(b.GetAngle()) && std::isfinite(v.x) && std::isfinite(v.y) &&
	       std::isfinite(b.GetAngularVelocity());
}

/// The particle's fixture is what the variant says: one analytic fixture, or one plain 8-gon
/// (`hulls`: or fewer vertices, the convex hull of a non-convex particle's 8 points).
bool FixtureMatches(const b2Body& b, bool polygon, bool hulls)
{
	const b2Fixture* f = b.GetFixtureList();
	if (!f || f->GetNext())
		return false;
	if (!polygon)
		return GetAnalyticShape(f) != nullptr;
	if (GetAnalyticShape(f) || f->GetType() != b2Shape::e_polygon)
		return false;
	const int32 count = static_cast<const b2PolygonShape*>(f->GetShape())->m_count;
	return count == kPolygonVertices || (hulls && count >= 3 && count < kPolygonVertices);
}

/// Every particle of the world: finite, inside the container (or falling through the outlet),
/// with the variant's fixture; and the count kept.
void CheckParticles(GranularScene& scene, Run& run)
{
	const GranularConfig& c = run.config;
	int inBox = 0;
	for (b2Body* b = scene.World().GetBodyList(); b; b = b->GetNext())
	{
		if (b->GetType() != b2_dynamicBody)
			continue;
		++inBox;
		run.fixturesOk = run.fixturesOk && FixtureMatches(*b, c.polygonVertices > 0, c.mixed);
		if (!Finite(*b))
		{
			++run.nonFinite;
			continue;
		}
		const b2Vec2 p = b->GetPosition();
		const bool throughWall = std::fabs(p.x) > 0.5 * c.boxWidth + c.width;
		const bool throughFloor = p.y < -c.width && (c.outletWidth <= 0.0 || std::fabs(p.x) > 0.5 * c.outletWidth + c.width);
		run.escaped += throughWall || throughFloor ? 1 : 0;
	}
	run.discharged = scene.Discharged();
	run.particlesEnd = inBox + run.discharged;
	run.fixturesOk = run.fixturesOk && inBox == scene.Remaining();
}

/// One step of an analytic run, and of a polygon run: two functions (never merged or inlined)
/// so that a profile tells the variants apart, e.g. `valgrind --tool=callgrind
/// --toggle-collect='*StepAnalyticVariant*'`.
__attribute__((noipa)) void StepAnalyticVariant(GranularScene& scene)
{
	scene.Step();
}
__attribute__((noipa)) void StepPolygonVariant(GranularScene& scene)
{
	scene.Step();
}

/// Simulate one run: all its steps, the window's timed by Box2D's profile.
void Simulate(Run& run, bool picture, const std::string& out, Progress& progress, double doneBefore, double totalWork)
{
	const auto start = std::chrono::steady_clock::now();
	GranularScene scene(run.config);
	b2World& world = scene.World();
	std::vector<double> steps, collides, solves, cpu, wall;
	double sumStep = 0.0, sumCollide = 0.0, sumSolve = 0.0, sumBroadphase = 0.0, sumTOI = 0.0, sumBodies = 0.0, sumTouching = 0.0,
	       sumPairs = 0.0;
	const int total = run.windowStart + run.windowSteps;
	for (int s = 0; s < total; ++s)
	{
		if (s == run.openAt)
			scene.OpenOutlet();
		const double cpuBefore = ThreadCpuMilliseconds();
		const auto wallBefore = std::chrono::steady_clock::now();
		if (run.config.polygonVertices > 0)
			StepPolygonVariant(scene);
		else
			StepAnalyticVariant(scene);
		const double wallStep = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wallBefore).count();
		const double cpuStep = ThreadCpuMilliseconds() - cpuBefore;
		if (s >= run.windowStart)
		{
			const b2Profile& p = world.GetProfile();
			cpu.push_back(cpuStep);
			wall.push_back(wallStep);
			steps.push_back(p.step);
			collides.push_back(p.collide);
			solves.push_back(p.solve);
			sumStep += p.step;
			sumCollide += p.collide;
			sumSolve += p.solve;
			sumBroadphase += p.broadphase;
			sumTOI += p.solveTOI;
			sumBodies += scene.Remaining();
			sumTouching += double(TouchingContacts(world)) / std::max(1, scene.Remaining());
			sumPairs += double(world.GetContactCount()) / std::max(1, scene.Remaining());
		}
		if (s % 50 == 0)
			progress.Report((doneBefore + double(run.count) * s) / totalWork,
			                run.scene + " " + std::to_string(run.count) + " " + run.variant + ": step " + std::to_string(s) + "/" +
			                    std::to_string(total));
	}
	const double n = run.windowSteps;
	run.stepMedian = Median(steps);
	run.collideMedian = Median(collides);
	run.solveMedian = Median(solves);
	run.cpuMedian = Median(cpu);
	run.wallMedian = Median(wall);
	run.stepMean = sumStep / n;
	run.collide = sumCollide / n;
	run.solve = sumSolve / n;
	run.broadphase = sumBroadphase / n;
	run.solveTOI = sumTOI / n;
	run.bodies = sumBodies / n;
	run.touching = sumTouching / n;
	run.pairs = sumPairs / n;
	CheckParticles(scene, run);
	run.runSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	if (picture)
		scene.WriteSnapshot(out + "/" + run.scene + "_" + std::to_string(run.count) + "_" + run.variant + ".svg",
		                    run.scene + ", " + std::to_string(run.count) + " " + run.particle + " (" + run.variant +
		                        "), end of the window");
}

/// How well the 8-gons follow the scene's shapes: the largest distance of a vertex from the
/// surface (along its ray, over the bounding radius) and the mean polygon area over the shape's.
Json PolygonCheck(const GranularConfig& config)
{
	GranularScene scene(config); // the same shapes as the runs (same seed)
	double worstRadial = 0.0, areaRatio = 0.0;
	int shapes = 0;
	for (const ParticleState& p : scene.SaveState())
	{
		const Shape& shape = *p.shape;
		const b2PolygonShape polygon = MakeInscribedPolygon(shape, kPolygonVertices);
		for (int32 k = 0; k < polygon.m_count; ++k)
		{
			const Vec2 v(polygon.m_vertices[k].x, polygon.m_vertices[k].y);
			const double r = Length(v);
			const double surface = shape.RadiusAt(v / r, shape.SurfaceLevel());
			worstRadial = std::max(worstRadial, std::fabs(r - surface) / shape.BoundingRadius());
		}
		b2MassData mass;
		polygon.ComputeMass(&mass, 1.0f);
		areaRatio += mass.mass / shape.Mass().area;
		++shapes;
		if (polygon.m_count != kPolygonVertices && shape.IsConvex())
			worstRadial = 1.0 / 0.0; // Box2D welded vertices: not the 8-gon we asked for
	}
	return {{"vertices", kPolygonVertices},
	        {"max_vertex_radial_error", worstRadial},
	        {"mean_area_over_analytic", areaRatio / shapes}};
}

/// Each name once, in the order first given.
std::vector<std::string> Distinct(const std::vector<std::string>& names)
{
	std::vector<std::string> distinct;
	for (const std::string& name : names)
		if (std::find(distinct.begin(), distinct.end(), name) == distinct.end())
			distinct.push_back(name);
	return distinct;
}

/// The particle counts to run, smallest first, each once; --quick keeps the smallest.
std::vector<int> Counts(std::vector<int> counts, bool quick)
{
	std::sort(counts.begin(), counts.end());
	counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
	if (quick)
		counts.resize(1);
	return counts;
}

std::string F(double v, int digits = 4) { return bench::FormatNumber(v, digits); }

/// The analytic and polygon runs of one scene and count.
struct Pair
{
	const Run* analytic = nullptr;
	const Run* polygon = nullptr;
	double StepRatio() const { return analytic->stepMedian / polygon->stepMedian; }
	double CollideRatio() const { return analytic->collide / polygon->collide; }
	double SolveRatio() const { return analytic->solve / polygon->solve; }
	double CpuRatio() const { return analytic->cpuMedian / polygon->cpuMedian; }
};

Pair FindPair(const std::vector<Run>& runs, const std::string& scene, int count)
{
	Pair p;
	for (const Run& r : runs)
		if (r.scene == scene && r.count == count)
		{
			if (r.variant == "analytic")
				p.analytic = &r;
			else if (r.variant == "polygon8")
				p.polygon = &r;
		}
	return p;
}

/// Cost per particle-step (wall-clock or CPU) over the same scene and variant at the smallest count.
double Growth(const std::vector<Run>& runs, const Run& run, double (Run::*cost)() const = &Run::MicrosecondsPerParticleStep)
{
	for (const Run& r : runs) // runs are in increasing count: the first match is the smallest
		if (r.scene == run.scene && r.variant == run.variant)
			return (run.*cost)() / (r.*cost)();
	return 0.0;
}
} // namespace

int main(int argc, char** argv)
{
	std::vector<int> givenCounts, threadCounts;
	std::vector<std::string> sceneNames = {"packing", "hopper"};
	int windowSteps = 0;
	CommandLine cli("b2a_bench_scenes", kHelp);
	cli.Add("--counts", givenCounts, {1000, 4000, 16000}, {250}, "N,N,...",
	        "particle counts (default 1000,4000,16000; quick: the smallest given,\nelse 250)", WholeNumber(10, 1e6));
	cli.Add("--steps", windowSteps, 200, 30, "N", "steps in the timed window (default 200, quick 30)", WholeNumber(1, 100000));
	cli.Add("--scenes", sceneNames, "S,S", "scenes to run: packing, hopper, layer, mixed (default packing,hopper)", OneOf(kSceneNames));
	cli.Add("--threads", threadCounts, "N,N",
	        "also run the analytic variant with its contacts computed on N threads\n"
	        "before each step (b2a::PrepareContacts; variant analytic_<N>threads),\n"
	        "e.g. --threads 2; the steps are bit-identical, so only time changes.\n"
	        "Wall-clock time per step (preparation included) is what these\n"
	        "save: wall_step_ms, and wall_speedup (analytic's over the variant's)",
	        WholeNumber(2, 256));
	bool game = false;
	GameSceneOptions gameOptions;
	cli.App().add_flag("--game", game, "run the game scenes instead (see below)");
	cli.Add("--game-counts", gameOptions.counts, {300, 3000}, {300}, "N,N", "--game: particles (default 300,3000; quick 300)",
	        WholeNumber(10, 100000));
	cli.Add("--game-families", gameOptions.families, GameFamilyNames(), GameFamilyNames(), "F,F",
	        "--game: ellipse, superellipse, heart, circle, mixed (default all)", OneOf(GameFamilyNames()));
	cli.Add("--game-steps", gameOptions.steps, 600, 240, "N", "--game: steps of each run (default 600, quick 240)",
	        WholeNumber(1, 100000));
	cli.Add("--repeats", gameOptions.repeats, 3, 1, "N", "--game: runs of each variant (default 3, quick 1)", WholeNumber(1, 100));
	cli.Add("--game-only", gameOptions.only, "V", "--game: run only the variant V, analytic or polygon8 (for profiles)",
	        OneOf({"analytic", "polygon8"}));
	const DemoOptions opt = cli.Parse(argc, argv);
	if (game)
	{
		Progress gameProgress("b2a_bench_scenes");
		return RunGameScenes(opt, gameOptions, gameProgress);
	}
	const MachineInfo machine = GetMachineInfo();
	Progress progress("b2a_bench_scenes");
	const std::vector<int> counts = Counts(givenCounts, opt.quick);
	const std::vector<std::string> scenes = Distinct(sceneNames);

	// Every run planned first (for the progress fraction); analytic and polygon runs of a scene
	// follow each other so that a change of load on the machine touches both alike.
	std::vector<Run> runs;
	Json polygonChecks;
	for (const std::string& name : scenes)
		for (int count : counts)
		{
			Run run;
			run.scene = name;
			run.count = count;
			run.config = SceneConfig(name, count);
			run.config.seed = opt.seed;
			run.particle = name == "hopper" ? "ellipses 2x0.66 mm"
			               : name == "mixed" ? "mixed shapes"
			                                 : "superellipses n=4";
			Schedule(run, GranularScene(run.config).PileHeight(), windowSteps);
			run.variant = "analytic";
			runs.push_back(run);
			for (int t : threadCounts)
			{
				Run threaded = run;
				threaded.variant = "analytic_" + std::to_string(t) + "threads";
				threaded.config.threads = t;
				runs.push_back(threaded);
			}
			run.variant = "polygon8";
			run.config.polygonVertices = kPolygonVertices;
			runs.push_back(run);
			if (count == counts.front())
				polygonChecks[name] = PolygonCheck(run.config);
		}
	double totalWork = 0.0, done = 0.0;
	for (const Run& r : runs)
		totalWork += double(r.count) * (r.windowStart + r.windowSteps);
	for (Run& r : runs)
	{
		Simulate(r, r.count == counts.front(), opt.out, progress, done, totalWork);
		done += double(r.count) * (r.windowStart + r.windowSteps);
		std::fprintf(stderr, "b2a_bench_scenes: %s %d %s: %.3f ms/step (collide %.3f, solve %.3f, TOI %.3f), %.1f s%s\n",
		             r.scene.c_str(), r.count, r.variant.c_str(), r.stepMedian, r.collide, r.solve, r.solveTOI, r.runSeconds,
		             r.Intact() ? "" : " -- PARTICLES LOST OR BROKEN");
	}

	// Tables: one row per run, ratios against the polygon run of the same scene and count.
	Table csv;
	csv.columns = {"scene", "particle", "count", "variant", "box_width_mm", "outlet_mm", "window_start_step", "window_steps",
	               "bodies", "touching_contacts_per_particle", "contact_pairs_per_particle", "step_ms", "step_mean_ms",
	               "collide_ms", "solve_ms", "broadphase_ms", "collide_median_ms", "solve_median_ms", "solve_toi_ms",
	               "step_cpu_ms", "us_per_particle_step", "step_vs_polygon8", "collide_vs_polygon8", "solve_vs_polygon8",
	               "cpu_vs_polygon8", "growth_vs_smallest", "growth_cpu_vs_smallest", "particles_end", "discharged",
	               "nonfinite", "escaped", "run_s", "threads", "wall_step_ms", "wall_vs_polygon8", "wall_speedup"};
	Table md;
	md.columns = {"scene", "N", "variant", "step ms", "collide ms", "solve ms (broadphase)", "TOI ms", "CPU ms",
	              "µs/particle-step", "step × 8-gon", "collide × 8-gon", "CPU × 8-gon", "growth (CPU)", "contacts/particle",
	              "wall ms (speed-up)"};
	Json runList = Json::array();
	bool intact = true;
	for (const Run& r : runs)
	{
		const Pair p = FindPair(runs, r.scene, r.count);
		const double growth = Growth(runs, r), growthCpu = Growth(runs, r, &Run::CpuMicrosecondsPerParticleStep);
		intact = intact && r.Intact();
		csv.rows.push_back({r.scene, r.particle, std::to_string(r.count), r.variant, F(r.config.boxWidth), F(r.config.outletWidth),
		                    std::to_string(r.windowStart), std::to_string(r.windowSteps), F(r.bodies), F(r.touching), F(r.pairs),
		                    F(r.stepMedian), F(r.stepMean), F(r.collide), F(r.solve), F(r.broadphase), F(r.collideMedian),
		                    F(r.solveMedian), F(r.solveTOI), F(r.cpuMedian),
		                    F(r.MicrosecondsPerParticleStep()), F(r.stepMedian / p.polygon->stepMedian),
		                    F(r.collide / p.polygon->collide), F(r.solve / p.polygon->solve),
		                    F(r.cpuMedian / p.polygon->cpuMedian), F(growth), F(growthCpu),
		                    std::to_string(r.particlesEnd), std::to_string(r.discharged), std::to_string(r.nonFinite),
		                    std::to_string(r.escaped), F(r.runSeconds, 3), std::to_string(r.config.threads), F(r.wallMedian),
		                    F(r.wallMedian / p.polygon->wallMedian), F(p.analytic->wallMedian / r.wallMedian)});
		md.rows.push_back({r.scene, std::to_string(r.count), r.variant, F(r.stepMedian, 3), F(r.collide, 3),
		                   F(r.solve, 3) + " (" + F(r.broadphase, 2) + ")", F(r.solveTOI, 2), F(r.cpuMedian, 3),
		                   F(r.MicrosecondsPerParticleStep(), 3), F(r.stepMedian / p.polygon->stepMedian, 3),
		                   F(r.collide / p.polygon->collide, 3), F(r.cpuMedian / p.polygon->cpuMedian, 3),
		                   F(growth, 3) + " (" + F(growthCpu, 3) + ")", F(r.touching, 3),
		                   F(r.wallMedian, 3) + " (" + F(p.analytic->wallMedian / r.wallMedian, 3) + ")"});
		runList.push_back({{"scene", r.scene}, {"particle", r.particle}, {"count", r.count}, {"variant", r.variant},
		                   {"box_width_mm", r.config.boxWidth}, {"outlet_mm", r.config.outletWidth},
		                   {"outlet_opens_at_step", r.openAt}, {"window_start_step", r.windowStart},
		                   {"window_steps", r.windowSteps},
		                   {"bodies", r.bodies}, {"touching_contacts_per_particle", r.touching},
		                   {"contact_pairs_per_particle", r.pairs}, {"step_ms", r.stepMedian},
		                   {"step_mean_ms", r.stepMean}, {"collide_ms", r.collide}, {"solve_ms", r.solve},
		                   {"broadphase_ms", r.broadphase}, {"collide_median_ms", r.collideMedian},
		                   {"solve_median_ms", r.solveMedian}, {"solve_toi_ms", r.solveTOI}, {"step_cpu_ms", r.cpuMedian},
		                   {"us_per_particle_step", r.MicrosecondsPerParticleStep()}, {"growth_vs_smallest", growth},
		                   {"growth_cpu_vs_smallest", growthCpu},
		                   {"particles_end", r.particlesEnd}, {"discharged", r.discharged}, {"nonfinite", r.nonFinite},
		                   {"escaped", r.escaped}, {"fixtures_ok", r.fixturesOk}, {"intact", r.Intact()}, {"run_s", r.runSeconds},
		                   {"threads", r.config.threads}, {"wall_step_ms", r.wallMedian},
		                   {"wall_vs_polygon8", r.wallMedian / p.polygon->wallMedian},
		                   {"wall_speedup", p.analytic->wallMedian / r.wallMedian}});
	}
	WriteText(opt.out + "/scenes.csv", csv.Csv());

	// Ratios per scene and count, and the issue's target for the hopper at 4000 ellipses (or at
	// the count nearest to it that was run).
	Json ratios = Json::array();
	for (const std::string& name : scenes)
		for (int count : counts)
		{
			const Pair p = FindPair(runs, name, count);
			ratios.push_back({{"scene", name}, {"count", count}, {"step", p.StepRatio()}, {"collide", p.CollideRatio()},
			                  {"solve", p.SolveRatio()}, {"step_cpu", p.CpuRatio()}});
		}
	Json target = nullptr;
	int targetCount = counts.front();
	for (int c : counts)
		targetCount = std::abs(c - 4000) < std::abs(targetCount - 4000) ? c : targetCount;
	if (std::find(scenes.begin(), scenes.end(), "hopper") != scenes.end())
	{
		const Pair p = FindPair(runs, "hopper", targetCount);
		target = {{"scene", "hopper"},
		          {"count", targetCount},
		          {"step_ratio", p.StepRatio()},
		          {"step_target", kTargetStepRatio},
		          {"collide_ratio", p.CollideRatio()},
		          {"collide_target", kTargetCollideRatio},
		          {"step_cpu_ratio", p.CpuRatio()},
		          {"meets", p.StepRatio() <= kTargetStepRatio && p.CollideRatio() <= kTargetCollideRatio}};
	}

	std::string text = "# b2a_bench_scenes\n\n";
	text += "Machine: " + machine.cpu + ", " + std::to_string(machine.cores) + " hardware threads.  \n";
	text += "Build: " + machine.buildFlags + ".  \n";
	// A comma-separated list of numbers or names, as the options take them.
	auto joined = [](const auto& list) {
		std::string t;
		for (const auto& v : list)
		{
			if constexpr (std::is_convertible_v<decltype(v), std::string>)
				t += (t.empty() ? "" : ",") + std::string(v);
			else
				t += (t.empty() ? "" : ",") + std::to_string(v);
		}
		return t;
	};
	text += "Run: `b2a_bench_scenes" + std::string(opt.quick ? " --quick" : "") + " --seed " + std::to_string(opt.seed) +
	        " --counts " + joined(counts) + " --steps " + std::to_string(windowSteps) + " --scenes " + joined(scenes) +
	        (threadCounts.empty() ? std::string() : " --threads " + joined(threadCounts)) + "`, " + F(progress.Elapsed(), 3) +
	        " s.\n\n";
	text += "Box2D's b2World::GetProfile() in milliseconds over a window of " + std::to_string(windowSteps) +
	        " steps (the same steps for both variants): step is the median, the phases are means (solve includes the "
	        "broadphase). packing: superellipses n = 4 settling in a closed box 2√N mm wide; hopper: 2 × 0.66 mm "
	        "ellipses discharging through an outlet of 0.3 of a box 80√(N/4000) mm wide; layer: the packing's "
	        "superellipses settling in a layer " + std::to_string(kLayerRows) + " lattice rows deep at every N (box 2.3·N/" +
	        std::to_string(kLayerRows) + " mm wide); mixed: the packing's box with 38 % superellipses of n = m in "
	        "[2.5, 5.5), 30 % ellipses, 30 % circles and 2 % hearts. `8-gon` rows are the same "
	        "scenes with plain Box2D polygons of 8 vertices on the same surfaces. `× 8-gon`: the analytic time over "
	        "the 8-gons'. CPU ms: the median CPU time of the stepping thread (the profile is wall-clock time, which on "
	        "a shared machine includes other processes' turns). growth: µs per particle-step over that at the smallest "
	        "count (in brackets: from CPU time). contacts/particle: touching Box2D contacts (walls included) per "
	        "particle. wall ms: the median wall-clock time of a whole step, contact preparation included; `analytic_<N>threads` "
	        "rows compute the analytic contacts on N threads before each step (b2a::PrepareContacts: the same steps, bit "
	        "for bit; Box2D's profile and CPU ms then miss the helper threads' share), and the speed-up in brackets is "
	        "the single-threaded analytic wall time over theirs.\n\n";
	text += md.Markdown();
	if (!target.is_null())
		text += "\nHopper of " + std::to_string(targetCount) + " ellipses against the target (step ≤ " + F(kTargetStepRatio, 2) +
		        " × 8-gon, collide ≤ " + F(kTargetCollideRatio, 2) + " ×): step " + F(target["step_ratio"].get<double>(), 3) +
		        " ×, collide " + F(target["collide_ratio"].get<double>(), 3) + " × — " +
		        (target["meets"].get<bool>() ? "met" : "not met") + ".\n";
	WriteText(opt.out + "/scenes.md", text);

	Json summary;
	summary["benchmark"] = "b2a_bench_scenes";
	summary["quick"] = opt.quick;
	summary["seed"] = opt.seed;
	summary["machine"] = MachineJson(machine);
	summary["window_steps"] = windowSteps;
	summary["counts"] = counts;
	summary["runs"] = runList;
	summary["ratios_analytic_over_polygon8"] = ratios;
	summary["hopper_target"] = target;
	summary["polygon_check"] = polygonChecks;
	summary["particles_intact"] = intact;
	summary["run_time_s"] = progress.Elapsed();
	WriteJson(opt.out + "/summary.json", summary);

	std::string line;
	for (const std::string& name : scenes)
	{
		const Pair p = FindPair(runs, name, targetCount);
		const Pair largest = FindPair(runs, name, counts.back());
		char part[320];
		std::snprintf(part, sizeof part,
		              "; %s %d: %.3g vs %.3g ms/step (%.2fx, collide %.2fx, CPU %.2fx), cost per particle-step at %d: %.2fx",
		              name.c_str(), targetCount, p.analytic->stepMedian, p.polygon->stepMedian, p.StepRatio(), p.CollideRatio(),
		              p.CpuRatio(), counts.back(), Growth(runs, *largest.analytic));
		line += part;
	}
	std::printf("b2a_bench_scenes: %zu runs in %.0f s, analytic vs polygon8%s; particles %s -> %s/scenes.md\n", runs.size(),
	            progress.Elapsed(), line.c_str(), intact ? "intact" : "LOST OR BROKEN", opt.out.c_str());
	return intact ? 0 : 1;
}

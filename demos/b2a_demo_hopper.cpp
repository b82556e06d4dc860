// b2analytic demo: superellipses packed in a container, then discharged through an outlet of
// 12 particle widths (the paper's Figure 13): does an arch stop the flow?
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/GranularScene.h"
#include "common/Plot.h"
#include "common/Svg.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace b2a;
using namespace b2a::demo;

namespace
{
const char* kHelp = R"(b2a_demo_hopper: hopper discharge of analytic particles (the paper's Figure 13).

Superellipses (|x/a|^4 + |y/b|^4 <= 1, width 2a = 2 mm on average, aspect 1.6, sizes +-10 %)
are dropped into a 60 mm wide container and settle under gravity (millimetre units:
g = 9810 mm/s^2, step 2e-4 s; walls frictionless, floor and particles friction 0.5). Then a
centred outlet of 12 particle widths (24 mm) opens and the particles flow out. The demo
records the discharged count against time and says why the flow stopped: an arch (no particle
left for 0.1 s while particles at rest still lie over the outlet), drained (nothing left over
the outlet: the rest lies on the floor beside it at its angle of repose), emptied, or still
flowing when the simulated time ran out. The paper's own particle parameters (its Table 1) are
missing from its text: these are ours, of the same kind; its result was 67 particles out and
an arch after 0.11 s.

Writes to DIR: summary.json (outlet_width, discharged, arched, flow_stopped_at, ...),
discharge.csv (time, discharged), discharge.svg (the count against time) and
snapshot_<t>.svg pictures of the container (moving particles orange, resting blue).
)";

std::string TimeTag(double t)
{
	char b[32];
	std::snprintf(b, sizeof(b), "%.3f", t);
	return b;
}

std::string Short(double v)
{
	char b[32];
	std::snprintf(b, sizeof(b), "%g", v);
	return b;
}
} // namespace

int main(int argc, char** argv)
{
	GranularConfig config;
	double outletWidths = 12.0, duration = 0.0;
	std::vector<double> snapshots = {0.0, 0.11, 0.32};
	CommandLine cli("b2a_demo_hopper", kHelp);
	cli.Add("--particles", config.particles, 900, 160, "N", "number of particles (default 900, quick 160)", WholeNumber(1, 20000));
	cli.Add("--outlet-widths", outletWidths, "K", "outlet width in mean particle widths (default 12)", RealNumber(0.5, 39.0));
	cli.Add("--snapshots", snapshots, "T,T,...", "snapshot times in seconds after the outlet opens (default 0,0.11,0.32)",
	        RealNumber(0.0, 100.0));
	cli.Add("--duration", duration, 0.6, 0.3, "T", "seconds of discharge to simulate at most (default 0.6, quick 0.3)",
	        RealNumber(0.01, 100.0));
	cli.Add("--threads", config.threads, "N",
	        "threads that compute the analytic contacts before each step\n"
	        "(b2a::PrepareContacts; default 1; any N gives the same run, bit for bit)",
	        WholeNumber(1, 256));
	const DemoOptions opt = cli.Parse(argc, argv);
	const auto wallStart = std::chrono::steady_clock::now();
	Progress progress("b2a_demo_hopper");

	config.seed = opt.seed;
	config.boxWidth = opt.quick ? 40.0 : 60.0;
	config.outletWidth = outletWidths * config.width;
	if (config.outletWidth >= config.boxWidth)
	{
		std::fprintf(stderr, "b2a_demo_hopper: option '--outlet-widths' makes the outlet (%g mm) as wide as the box (%g mm)\n",
		             config.outletWidth, config.boxWidth);
		return 2;
	}

	GranularScene scene(config);
	const Energies e0 = scene.ComputeEnergies();

	// 1. Packing: settle until the kinetic energy is a millionth of what the fall released
	//    (checked every 0.02 s), at most 0.8 s.
	const double maxPacking = opt.quick ? 0.5 : 0.8;
	double released = 0.0, ke = 0.0;
	while (scene.Time() < maxPacking)
	{
		scene.Step();
		if (int(std::lround(scene.Time() / config.dt)) % 100 == 0)
		{
			const Energies e = scene.ComputeEnergies();
			released = e0.Total() - e.potential;
			ke = e.translational + e.rotational;
			progress.Report(0.5 * scene.Time() / maxPacking, "packing: kinetic energy " + std::to_string(ke));
			if (scene.Time() > 0.2 && ke < 1e-6 * released)
				break;
		}
	}
	for (int i = 0; i < 100; ++i) // 0.02 s of floor force at rest
		scene.Step();
	const double bottomForce = scene.TakeBottomForce();
	const double weight = scene.Weight();
	const double packedAt = scene.Time();
	const double packingFraction = scene.PackingFraction();
	const Energies packed = scene.ComputeEnergies();

	// 2. Discharge: open the outlet, count what leaves, take snapshots (those at time 0 just
	//    before the gate goes, so that they show it closed).
	const double t0 = scene.Time();
	std::sort(snapshots.begin(), snapshots.end());
	size_t nextSnapshot = 0;
	for (; nextSnapshot < snapshots.size() && snapshots[nextSnapshot] < 0.5 * config.dt; ++nextSnapshot)
		scene.WriteSnapshot(opt.out + "/snapshot_" + TimeTag(snapshots[nextSnapshot]) + ".svg", "hopper discharge", t0,
		                    "(the gate about to open)");
	scene.OpenOutlet();
	std::vector<double> times, counts;
	std::ofstream csv = OpenOutput(opt.out + "/discharge.csv");
	csv << "time_s,discharged\n";
	double lastDischarge = 0.0;
	int lastCount = 0;
	bool stopped = false;
	const double window = 0.1; // s without a discharge, with the particles at the outlet at rest
	int step = 0;
	while (true)
	{
		const double t = scene.Time() - t0;
		while (nextSnapshot < snapshots.size() && t >= snapshots[nextSnapshot] - 0.5 * config.dt)
		{
			scene.WriteSnapshot(opt.out + "/snapshot_" + TimeTag(snapshots[nextSnapshot]) + ".svg", "hopper discharge", t0,
			                    "after the outlet opened");
			++nextSnapshot;
		}
		if (step % 20 == 0)
		{
			times.push_back(t);
			counts.push_back(scene.Discharged());
			csv << t << "," << scene.Discharged() << "\n";
			progress.Report(0.5 + 0.5 * t / duration, "discharged " + std::to_string(scene.Discharged()));
		}
		if (scene.Discharged() != lastCount)
		{
			lastCount = scene.Discharged();
			lastDischarge = t;
		}
		if (scene.Remaining() == 0)
			break;
		if (t - lastDischarge > window && scene.KineticEnergyNearOutlet(config.outletWidth) < 1e-6 * released)
		{
			stopped = true;
			break;
		}
		if (t >= duration)
			break;
		scene.Step();
		++step;
	}
	const double tEnd = scene.Time() - t0;
	scene.WriteSnapshot(opt.out + "/snapshot_final.svg", "hopper discharge, final state", t0, "after the outlet opened");
	times.push_back(tEnd);
	counts.push_back(scene.Discharged());
	csv << tEnd << "," << scene.Discharged() << "\n";
	csv.close();
	WriteText(opt.out + "/discharge.svg",
	          LinePlot({{"discharged particles", palette::blue, times, counts, false}},
	                   "Particles discharged through an outlet of " + Short(outletWidths) + " particle widths",
	                   "time after the outlet opened (s)", "particles discharged (count)"));

	const double runSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
	Json summary = scene.SummaryHead("b2a_demo_hopper", opt);
	summary["outlet_width"] = config.outletWidth;
	summary["outlet_width_particle_widths"] = outletWidths;
	summary["packed_at_s"] = packedAt;
	summary["packing"] = {{"kinetic_energy", packed.translational + packed.rotational},
	                      {"potential_energy", packed.potential},
	                      {"energy_released", released},
	                      {"bottom_force", bottomForce},
	                      {"weight", weight},
	                      {"packing_fraction", packingFraction}};
	// Why the flow stopped: an arch holds particles over the outlet; without any there, the rest
	// lies beside the outlet at its angle of repose.
	const int overOutlet = scene.ParticlesOverOutlet(0.5 * config.outletWidth);
	const bool arched = stopped && overOutlet > 0;
	const char* reason = arched ? "arch" : stopped ? "drained" : scene.Remaining() == 0 ? "emptied" : "still_flowing";
	summary["discharged"] = scene.Discharged();
	summary["remaining"] = scene.Remaining();
	summary["over_outlet"] = overOutlet;
	summary["arched"] = arched;
	summary["stop_reason"] = reason;
	summary["flow_stopped_at"] = stopped ? Json(lastDischarge) : Json(nullptr);
	summary["simulated_discharge_s"] = tEnd;
	summary["paper"] = {{"discharged", 67}, {"flow_stopped_at", 0.11},
	                    {"note", "the paper's particle parameters are missing; ours are of the same kind (superellipses, 2 mm wide, "
	                             "outlet of 12 widths)"}};
	summary["units"] = "mm, g, s (forces in g*mm/s^2 = 1e-6 N)";
	summary["run_time_s"] = runSeconds;
	WriteJson(opt.out + "/summary.json", summary);

	const std::string outcome = arched    ? "an arch stopped the flow at " + TimeTag(lastDischarge) + " s"
	                            : stopped ? "the flow stopped at " + TimeTag(lastDischarge) + " s with nothing left over the outlet"
	                            : scene.Remaining() == 0 ? std::string("the container emptied")
	                                                     : std::string("still flowing at the end");
	std::printf("b2a_demo_hopper: %d particles packed (floor force %.4g vs weight %.4g), outlet %.0f mm: %d discharged, %s; "
	            "pictures and summary.json in %s\n",
	            config.particles, bottomForce, weight, config.outletWidth, scene.Discharged(), outcome.c_str(), opt.out.c_str());
	return 0;
}

// b2analytic demo: random packing of superellipses under gravity (the paper's Figures 11 and 12):
// energies against time and the mechanical equilibrium at the end.
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/GranularScene.h"
#include "common/Plot.h"
#include "common/Svg.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace b2a;
using namespace b2a::demo;

namespace
{
const char* kHelp = R"(b2a_demo_packing: random packing of superellipses under gravity (the paper's Figures 11, 12).

Superellipses (|x/a|^4 + |y/b|^4 <= 1, width 2 mm on average, aspect 1.6, sizes +-10 %,
random orientations) start on a loose lattice in a closed container 60 mm wide and fall
(millimetre units: g = 9810 mm/s^2, step 2e-4 s; frictionless walls, so that the floor alone
carries the weight). The demo records the translational, rotational, potential and total
energies against time and ends at mechanical equilibrium: kinetic energy gone (below 1e-6 of
the energy the fall released) and the force on the floor equal to the weight. The paper's
particle parameters (its Table 1) are missing from its text: these are ours, of the same kind.

Writes to DIR: summary.json (particles, kinetic_energy, potential_energy, bottom_force,
weight, packing_fraction, ...), energies.csv, energies.svg (log scale), initial.svg and
final.svg snapshots. Energies are in g*mm^2/s^2 (1e-9 J), forces in g*mm/s^2 (1e-6 N).
)";
} // namespace

int main(int argc, char** argv)
{
	GranularConfig config;
	double duration = 0.0;
	CommandLine cli("b2a_demo_packing", kHelp);
	cli.Add("--particles", config.particles, 900, 200, "N", "number of particles (default 900, quick 200)", WholeNumber(1, 20000));
	cli.Add("--duration", duration, 1.0, 0.5, "T", "seconds to simulate at most (default 1.0, quick 0.5)", RealNumber(0.01, 100.0));
	const DemoOptions opt = cli.Parse(argc, argv);
	const auto wallStart = std::chrono::steady_clock::now();
	Progress progress("b2a_demo_packing");
	config.seed = opt.seed;
	config.boxWidth = opt.quick ? 40.0 : 60.0;
	config.outletWidth = 0.0; // a closed container

	GranularScene scene(config);
	scene.WriteSnapshot(opt.out + "/initial.svg", "random packing, initial state");
	const Energies e0 = scene.ComputeEnergies();
	std::vector<double> t, translational, rotational, potential, total;
	std::ofstream csv = OpenOutput(opt.out + "/energies.csv");
	csv << "time_s,translational,rotational,potential,total\n";
	double released = 0.0, bottomForce = 0.0;
	int step = 0;
	const int sample = 25, window = 250; // energies every 5 ms; floor force over the last 50 ms
	while (true)
	{
		bool atRest = false;
		if (step % sample == 0)
		{
			const Energies e = scene.ComputeEnergies();
			t.push_back(scene.Time());
			translational.push_back(e.translational);
			rotational.push_back(e.rotational);
			potential.push_back(e.potential);
			total.push_back(e.Total());
			csv << scene.Time() << "," << e.translational << "," << e.rotational << "," << e.potential << "," << e.Total() << "\n";
			released = e0.Total() - e.potential;
			progress.Report(scene.Time() / duration, "kinetic energy " + std::to_string(e.translational + e.rotational));
			// At rest: the kinetic energy is a millionth of what the fall released, at the end of a
			// full window of floor force.
			atRest = scene.Time() > 0.2 && e.translational + e.rotational < 1e-6 * released && step % window == 0;
		}
		if (atRest || scene.Time() >= duration)
		{
			bottomForce = scene.TakeBottomForce();
			break;
		}
		if (step % window == 0)
			scene.TakeBottomForce(); // start a new window
		scene.Step();
		++step;
	}
	csv.close();
	const Energies end = scene.ComputeEnergies();
	scene.WriteSnapshot(opt.out + "/final.svg", "random packing, final state");
	WriteText(opt.out + "/energies.svg",
	          LinePlot({{"translational", palette::blue, t, translational, false},
	                    {"rotational", palette::vermillion, t, rotational, false},
	                    {"potential", palette::green, t, potential, false},
	                    {"total", palette::black, t, total, false}},
	                   "Energies of the packing", "time (s)", "energy (g mm²/s² = 10⁻⁹ J)", true));

	const double weight = scene.Weight();
	const double kinetic = end.translational + end.rotational;
	Json summary = scene.SummaryHead("b2a_demo_packing", opt);
	summary["settled_at_s"] = scene.Time();
	summary["kinetic_energy"] = kinetic;
	summary["translational_energy"] = end.translational;
	summary["rotational_energy"] = end.rotational;
	summary["potential_energy"] = end.potential;
	summary["energy_released"] = released;
	summary["bottom_force"] = bottomForce;
	summary["weight"] = weight;
	summary["bottom_force_over_weight"] = bottomForce / weight;
	summary["packing_fraction"] = scene.PackingFraction();
	summary["pile_height_mm"] = scene.PileHeight();
	summary["units"] = "mm, g, s: energies in g*mm^2/s^2 (1e-9 J), forces in g*mm/s^2 (1e-6 N)";
	summary["paper"] = "kinetic energy almost 0 at the end and the force on the bottom equal to the weight (its Figures 11, 12)";
	summary["run_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
	WriteJson(opt.out + "/summary.json", summary);
	std::printf("b2a_demo_packing: %d particles at rest after %.3f s: kinetic energy %.3g (%.2g of the %.4g released), floor force "
	            "%.5g vs weight %.5g (ratio %.5f), packing fraction %.3f; pictures and summary.json in %s\n",
	            config.particles, scene.Time(), kinetic, kinetic / released, released, bottomForce, weight, bottomForce / weight,
	            scene.PackingFraction(), opt.out.c_str());
	return 0;
}

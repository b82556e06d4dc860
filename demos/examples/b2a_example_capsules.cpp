// b2analytic example: a shape kind registered outside the library. Capsules (CapsuleShape.h) fall
// into a container among superellipses and circles; their pairs with capsules and circles take
// the capsule's own closed forms, every other pair the library's solvers for its solver class.
#include "CapsuleScene.h"

#include "common/CommandLine.h"
#include "common/DemoCommon.h"

#include <chrono>
#include <cstdio>

using namespace b2a;
using namespace b2a::demo;
using namespace example;

namespace
{
const char* kHelp = R"(b2a_example_capsules: a shape kind of one's own, registered outside the library.

A capsule (a segment thickened by a radius; demos/examples/CapsuleShape.h) registers the kind
"capsule" with the solver class convex, and closed-form contact and common-level functions for
capsule-capsule and capsule-circle pairs. Capsules, superellipses (n = m = 4) and circles (half
of them analytic, half Box2D's own) fall into a container of chain links with a tilted box
across it, in SI units (g = 10 m/s^2, 120 steps a second). Capsules meet capsules and circles
through their closed forms, superellipses through the grid method (the table's default for a
convex kind), walls through the separating axis.

Writes to DIR: summary.json (contacts summed over the steps by pair of kinds, the closed forms'
count, the deepest manifold point's overlap over the run and at the end, bodies not finite or
outside the container, the kinetic energy at the end) and scene.svg (the scene at the end).
)";
} // namespace

int main(int argc, char** argv)
{
	CapsuleSceneConfig config;
	double duration = 0.0;
	CommandLine cli("b2a_example_capsules", kHelp);
	cli.Add("--particles", config.particles, 60, 30, "N", "number of particles (default 60, quick 30)", WholeNumber(1, 2000));
	cli.Add("--duration", duration, 4.0, 1.5, "T", "seconds to simulate (default 4, quick 1.5)", RealNumber(0.01, 600.0));
	const DemoOptions opt = cli.Parse(argc, argv);
	const auto wallStart = std::chrono::steady_clock::now();
	Progress progress("b2a_example_capsules");
	config.seed = opt.seed;
	CapsuleScene scene(config);
	const int steps = int(std::ceil(duration / config.dt));
	for (int k = 0; k < steps; ++k)
	{
		scene.Step();
		if (k % 30 == 0)
			progress.Report(double(k) / steps, "t = " + std::to_string((k + 1) * config.dt) + " s");
	}
	const CapsuleSceneReport r = scene.Report();
	WriteText(opt.out + "/scene.svg", scene.Svg("capsules among superellipses and circles, t = " + std::to_string(r.time) + " s"));
	Json summary;
	summary["program"] = "b2a_example_capsules";
	summary["seed"] = opt.seed;
	summary["quick"] = opt.quick;
	summary["particles"] = config.particles;
	summary["steps"] = r.steps;
	summary["time_s"] = r.time;
	Json contacts = Json::object();
	for (const auto& [pair, count] : r.contacts)
		contacts[pair] = count;
	summary["touching_contacts_by_kinds"] = contacts;
	summary["closed_form_contacts"] = r.closedFormContacts;
	summary["max_penetration_m"] = r.maxPenetration;
	summary["penetration_at_end_m"] = r.lastPenetration;
	summary["non_finite_bodies"] = r.nonFinite;
	summary["escaped_bodies"] = r.escaped;
	summary["kinetic_energy_j"] = r.kineticEnergy;
	summary["units"] = "m, kg, s";
	summary["run_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
	WriteJson(opt.out + "/summary.json", summary);
	const auto count = [&](const char* pair) { return r.contacts.count(pair) ? r.contacts.at(pair) : 0L; };
	std::printf("b2a_example_capsules: %d particles, %.2f s: capsule contacts with superellipses %ld, capsules %ld, circles %ld "
	            "(%ld by the closed forms), deepest overlap %.2g m, %d not finite, %d escaped; summary.json and scene.svg in %s\n",
	            config.particles, r.time, count("capsule-superellipse"), count("capsule-capsule"),
	            count("box2d_circle-capsule") + count("capsule-circle"), r.closedFormContacts, r.maxPenetration, r.nonFinite,
	            r.escaped, opt.out.c_str());
	return r.nonFinite == 0 && r.escaped == 0 ? 0 : 1;
}

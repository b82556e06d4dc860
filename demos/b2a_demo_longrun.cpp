// b2analytic demo: the hopper scene run for a long time with its discharge recycled to the top,
// checking on every step that nothing turns NaN, nothing leaves the container except through
// the outlet, and the mechanical energy never grows beyond what the recycling put in.
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/GranularScene.h"
#include "common/SiloFlow.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

using namespace b2a;
using namespace b2a::demo;

namespace
{
const char* kHelp = R"(b2a_demo_longrun: a long run of the hopper scene, for reliability.

The hopper scene of b2a_demo_hopper (superellipses n = 4, 2 mm wide, aspect 1.6, millimetre
units, step 2e-4 s, outlet of 12 particle widths) settles for --settle seconds with the gate
closed, then flows through the open outlet. A particle whose centre falls one particle width
below the floor has left through the outlet; it is recycled: put back at rest, at its own
angle, at a free random place in the insertion band near the top of the container (70 % to 95 %
of the wall height). The recycling is the only source of energy, and it is counted exactly:
injected = sum of m g (y_new - y_old) - (its kinetic energy when taken out). So
  balance = (kinetic + potential of all particles) - injected
can only fall (friction, inelastic impacts, and symplectic Euler's -1/2 m g^2 dt^2 per step of
free fall all take energy away). Box2D's position correction can raise it: pushing overlapping
particles apart lifts them without a force doing work. It resolves overlaps of the order of
Box2D's linear slop (0.005 mm), so no step may raise the balance by more than lifting every
particle by one slop (M g slop) in a settled pile. A particle landing at speed v overlaps by up
to v dt, which the correction removes, so a step with impacts may create up to M g v_f dt, v_f
the free-fall speed below (the bound checked). The run measures the largest rise and the sum of
all rises, which should stay a small part of what the flow dissipates.

Checked on every step: NaN or infinite positions, angles or velocities (the run stops at the
first); escapes (a centre beyond a side wall, or below the floor outside the outlet, or above
the walls); the largest speed, against the free-fall speed from the top of the insertion band
to the recycling level (impacts may pass a little more on); the balance against its initial
value and its largest rise in one step against M g v_f dt.

Writes to DIR: summary.json (steps, wall time, max speed, nan count, escaped count, energy
figures; rewritten every minute while running, with "finished": false), energy.csv (every
1000 steps) and final.svg (a snapshot at the end).
)";

// The run's running figures.
struct Figures
{
	long steps = 0;
	double maxSpeed = 0.0;
	double maxSpeedAt = 0.0;
	int nanBodies = 0;
	int escaped = 0;
	long recycled = 0;
	long insertRetries = 0;
	double injected = 0.0;
	double balance0 = 0.0;
	double maxExcess = 0.0;   // max(balance - balance0)
	double maxStepRise = 0.0; // largest rise of the balance in one step
	double maxStepRiseAt = 0.0;
	double created = 0.0; // sum of the balance's rises
};

bool Finite(const b2Body* b)
{
	const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity();
	return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(b->GetAngle()) && std::isfinite(v.x) && std::isfinite(v.y) &&
	       std::isfinite(b->GetAngularVelocity());
}

double KineticEnergy(const b2Body* b)
{
	const double Ic = b->GetInertia() - b->GetMass() * b2Dot(b->GetLocalCenter(), b->GetLocalCenter());
	const double w = b->GetAngularVelocity();
	return 0.5 * b->GetMass() * b2Dot(b->GetLinearVelocity(), b->GetLinearVelocity()) + 0.5 * Ic * w * w;
}
} // namespace

int main(int argc, char** argv)
{
	GranularConfig config;
	long steps = 0;
	double minutes = 1e9, settle = 0.0;
	CommandLine cli("b2a_demo_longrun", kHelp);
	cli.Add("--steps", steps, 1000000, 4000, "N", "steps to run (default 1000000, quick 4000)", WholeNumber(1, 1e10));
	cli.Add("--minutes", minutes, "M", "stop earlier after M minutes of wall time (default: no limit)", RealNumber(0.01, 1e9));
	cli.Add("--particles", config.particles, 900, 120, "N", "number of particles (default 900, quick 120)", WholeNumber(1, 20000));
	cli.Add("--settle", settle, 0.3, 0.15, "T", "seconds with the gate closed before the outlet opens (default 0.3, quick 0.15)",
	        RealNumber(0.0, 100.0));
	const DemoOptions opt = cli.Parse(argc, argv);
	Progress progress("b2a_demo_longrun");
	const auto wallStart = std::chrono::steady_clock::now();
	const auto wallSeconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count(); };

	config.seed = opt.seed;
	config.boxWidth = opt.quick ? 40.0 : 60.0;
	config.boxHeight = opt.quick ? 100.0 : 200.0;
	config.outletWidth = 12.0 * config.width;
	// The lattice must fit below the insertion band, or the first particles start inside it.
	const int perRow = std::max(1, int((config.boxWidth - config.width) / (1.15 * config.width)));
	const double latticeTop = config.width + 1.15 * config.width * (config.particles / perRow + 1);
	const double bandLow = 0.7 * config.boxHeight, bandHigh = 0.95 * config.boxHeight;
	if (latticeTop > bandLow)
	{
		std::fprintf(stderr, "b2a_demo_longrun: option '--particles' (%d) fills the container above its insertion band (%g mm)\n",
		             config.particles, bandLow);
		return 2;
	}

	GranularScene scene(config);
	b2World& world = scene.World();
	const double g = config.gravity, w = 0.5 * config.boxWidth, o = 0.5 * config.outletWidth;
	const double recycleBelow = -config.width;
	// A particle gains at most the fall from the top of the band to the recycling level; impacts
	// with restitution 0.1 pass on little more. Anything far above it is a fling.
	const double freeFall = std::sqrt(2.0 * g * (bandHigh - recycleBelow));
	// Position correction lifts particles by at most the overlap an impact makes in one step:
	// the bound on the energy one step may create (see the help).
	const double riseBound = scene.Weight() * freeFall * config.dt;
	std::mt19937_64 rng(opt.seed * 7919u + 1u);
	std::uniform_real_distribution<double> U(0.0, 1.0);

	Figures fig;
	fig.balance0 = scene.ComputeEnergies().Total();
	const double energy0 = fig.balance0;
	double balancePrev = fig.balance0;
	std::ofstream csv = OpenOutput(opt.out + "/energy.csv");
	csv << "step,time_s,kinetic,potential,injected,balance,recycled\n";

	const auto summary = [&](bool finished, const char* stoppedBy) {
		const Energies e = scene.ComputeEnergies();
		const double wall = wallSeconds();
		Json s = scene.SummaryHead("b2a_demo_longrun", opt);
		s["finished"] = finished;
		s["stopped_by"] = stoppedBy;
		s["steps"] = fig.steps;
		s["simulated_s"] = scene.Time();
		s["wall_time_s"] = wall;
		s["steps_per_s"] = wall > 0.0 ? double(fig.steps) / wall : 0.0;
		s["outlet_width"] = config.outletWidth;
		s["box_height_mm"] = config.boxHeight;
		s["settle_s"] = settle;
		s["max_speed"] = fig.maxSpeed;
		s["max_speed_at_s"] = fig.maxSpeedAt;
		s["free_fall_speed"] = freeFall;
		s["max_speed_over_free_fall"] = fig.maxSpeed / freeFall;
		s["nan_count"] = fig.nanBodies;
		s["escaped"] = fig.escaped;
		s["lost"] = scene.Discharged(); // removed by the scene below the outlet before recycling: should be 0
		s["recycled"] = fig.recycled;
		s["insert_retries"] = fig.insertRetries;
		s["remaining"] = scene.Remaining();
		const double balance = e.Total() - fig.injected;
		s["energy"] = {{"initial_total", energy0},
		               {"final_kinetic", e.translational + e.rotational},
		               {"final_potential", e.potential},
		               {"injected_by_recycling", fig.injected},
		               {"final_balance", balance},
		               {"dissipated", energy0 - balance},
		               {"max_excess_over_initial", fig.maxExcess},
		               {"max_excess_relative", fig.maxExcess / energy0},
		               {"max_rise_in_one_step", fig.maxStepRise},
		               {"max_rise_in_one_step_at_s", fig.maxStepRiseAt},
		               {"rise_bound_per_step", riseBound},
		               {"created_by_position_correction", fig.created},
		               {"created_over_dissipated", fig.created / std::max(1e-300, energy0 - balance + fig.created)}};
		s["units"] = "mm, g, s (energies in g*mm^2/s^2 = 1e-9 J)";
		WriteJson(opt.out + "/summary.json", s);
	};

	const char* stoppedBy = "steps";
	double lastSummary = 0.0;
	bool opened = false;
	for (long step = 0; step < steps; ++step)
	{
		if (!opened && scene.Time() >= settle - 0.5 * config.dt)
		{
			scene.OpenOutlet();
			opened = true;
		}
		scene.Step();
		fig.steps = step + 1;

		// Every particle: finite, inside, its speed; recycle those that left through the outlet.
		bool nan = false;
		for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
		{
			if (b->GetType() != b2_dynamicBody)
				continue;
			if (!Finite(b))
			{
				++fig.nanBodies;
				nan = true;
				continue;
			}
			const b2Vec2 p = b->GetPosition();
			const double speed = b->GetLinearVelocity().Length();
			if (speed > fig.maxSpeed)
			{
				fig.maxSpeed = speed;
				fig.maxSpeedAt = scene.Time();
			}
			const bool outside = std::fabs(p.x) > w || p.y > config.boxHeight || (p.y < 0.0f && std::fabs(p.x) > o + config.width);
			if (outside)
				++fig.escaped;
			if (!outside && p.y >= recycleBelow)
				continue;
			// Recycle: a free place in the insertion band, at rest (tried a few times a step).
			const float r = float(GetAnalyticShape(b->GetFixtureList())->BoundingRadius() + 0.2);
			for (int attempt = 0; attempt < 20; ++attempt)
			{
				const b2Vec2 c(float(-w + r + (2.0 * (w - r)) * U(rng)), float(bandLow + (bandHigh - bandLow) * U(rng)));
				if (!IsFree(world, b, c, r))
				{
					++fig.insertRetries;
					continue;
				}
				const double yOld = b->GetWorldCenter().y;
				const double ke = KineticEnergy(b);
				b->SetTransform(c, b->GetAngle());
				b->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
				b->SetAngularVelocity(0.0f);
				fig.injected += b->GetMass() * g * (b->GetWorldCenter().y - yOld) - ke;
				++fig.recycled;
				break;
			}
		}
		if (nan)
		{
			stoppedBy = "nan";
			break;
		}

		// Energy balance on every step.
		const Energies e = scene.ComputeEnergies();
		const double balance = e.Total() - fig.injected;
		fig.maxExcess = std::max(fig.maxExcess, balance - fig.balance0);
		fig.created += std::max(0.0, balance - balancePrev);
		if (balance - balancePrev > fig.maxStepRise)
		{
			fig.maxStepRise = balance - balancePrev;
			fig.maxStepRiseAt = scene.Time();
		}
		balancePrev = balance;
		if (fig.steps % 1000 == 0)
		{
			csv << fig.steps << "," << scene.Time() << "," << e.translational + e.rotational << "," << e.potential << "," << fig.injected
			    << "," << balance << "," << fig.recycled << "\n";
			progress.Report(double(fig.steps) / double(steps),
			                "step " + std::to_string(fig.steps) + ", recycled " + std::to_string(fig.recycled) + ", max speed " +
			                    std::to_string(int(fig.maxSpeed)) + " mm/s, escaped " + std::to_string(fig.escaped));
			const double wall = wallSeconds();
			if (wall - lastSummary > 60.0)
			{
				csv.flush();
				summary(false, "running");
				lastSummary = wall;
			}
			if (wall > 60.0 * minutes)
			{
				stoppedBy = "minutes";
				break;
			}
		}
	}
	csv.close();
	scene.WriteSnapshot(opt.out + "/final.svg", "long run: final state");
	summary(true, stoppedBy);
	std::printf("b2a_demo_longrun: %ld steps (%.1f s simulated) in %.0f s: %ld recycled, max speed %.0f mm/s (free fall %.0f), "
	            "%d NaN, %d escaped, %d lost, energy above the initial %.3g, largest rise in a step %.3g (bound %.3g); "
	            "summary.json in %s\n",
	            fig.steps, scene.Time(), wallSeconds(), fig.recycled, fig.maxSpeed, freeFall, fig.nanBodies, fig.escaped,
	            scene.Discharged(), fig.maxExcess, fig.maxStepRise, riseBound, opt.out.c_str());
	const bool sound = fig.nanBodies == 0 && fig.escaped == 0 && scene.Discharged() == 0 && fig.maxStepRise <= riseBound;
	return sound ? 0 : 1;
}

// b2analytic validation: the random packing fraction of poured particles (disks, ellipses,
// superellipses) against the friction and the count, measured in a window away from the walls,
// the floor and the free surface, beside published 2D values (docs/validation/packing.md).
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/GranularScene.h"
#include "common/Plot.h"
#include "common/Svg.h"
#include "validation/PackingWindow.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

using namespace b2a;
using namespace b2a::demo;

namespace
{
const char* kHelp = R"(b2a_validate_packing: random packing fractions of poured particles against friction and count.

Each run pours N particles of one family from a loose jittered lattice into a closed box
(the packing demo's scene: millimetre units, g = 9810 mm/s^2, step 2e-4 s, restitution 0.1,
frictionless side walls, the floor with the particles' friction) and waits until they rest
(kinetic energy below 1e-6 of the energy the fall released, or --duration). The box is as
wide as a square pile of the particles at 0.82 would be tall. The area fraction is measured in
a window --margin mean diameters clear of the walls, the floor and the lowest point of the
free surface, by sampling the window on a grid (spacing 1/40 of the small particle's
diameter) against each particle's level function.

Families (sizes: the small particle's area equals a 2 mm disk's):
  disk       bidisperse disks, half of them 1.4 times larger (the usual 2D glass former)
  ellipse15  bidisperse ellipses of aspect 1.5, same areas
  ellipse20  bidisperse ellipses of aspect 2, same areas
  superell   bidisperse superellipses |x/a|^4 + |y/b|^4 <= 1 of aspect 1.6, same areas
  demo       the packing demo's own particles: superellipses n = 4, width 2 mm, aspect 1.6,
             sizes uniform within +-10 %
  disk10     disks of 2 mm, sizes uniform within +-10 % (nearly monodisperse: they order)

Writes to DIR: runs.csv (one line per run, with flat_order: <cos 2 theta> of the long axes'
angles from the horizontal in the window, 1 all lying flat, 0 isotropic), summary.csv and summary.json (mean, standard
deviation and standard error over seeds per family, friction and count, with the published
values), packing_friction.svg (fraction against friction), packing_count.svg (against the
count, when there are several), and a snapshot of each family's first run at the highest
friction and count (snapshot_<family>.svg). --replot DIR runs nothing and writes the tables and
plots of DIR/runs.csv (an earlier run's) to --out.
)";

// One family of particles.
struct Family
{
	std::string name, label, colour;
	double aspect = 1.0, exponent = 2.0;
	bool bidisperse = true; // else sizes uniform within ±10 %
	bool demo = false;      // the packing demo's own particles (GranularScene builds them)
	Marker marker = Marker::circle;
};

const std::vector<Family>& Families()
{
	static const std::vector<Family> families = {
		{"disk", "disks, bidisperse 1:1.4", palette::blue, 1.0, 2.0, true, false, Marker::circle},
		{"ellipse15", "ellipses 1.5, bidisperse", palette::vermillion, 1.5, 2.0, true, false, Marker::square},
		{"ellipse20", "ellipses 2, bidisperse", palette::green, 2.0, 2.0, true, false, Marker::triangle},
		{"superell", "superellipses n=4, 1.6, bidisperse", palette::orange, 1.6, 4.0, true, false, Marker::diamond},
		{"demo", "packing demo's superellipses (±10 %)", palette::purple, 1.6, 4.0, false, true, Marker::triangleDown},
		{"disk10", "disks ±10 % (near monodisperse)", palette::skyBlue, 1.0, 2.0, false, false, Marker::circle},
	};
	return families;
}

const Family& FindFamily(const std::string& name)
{
	for (const Family& f : Families())
		if (f.name == name)
			return f;
	return Families().front(); // unreachable: the command line accepts only the names above
}

// What one run measured.
struct RunResult
{
	std::string family;
	double friction = 0.0;
	int particles = 0;
	std::uint64_t seed = 0;
	double phi = std::nan("");      // Σ particle area inside the window / window area
	double phiUnion = std::nan(""); // covered fraction of the window (overlaps counted once)
	// ⟨cos 2θ⟩ of the long axes' angles θ from the horizontal over the particles centred in the
	// window: 1 all lying flat, 0 isotropic, −1 all upright (NaN for disks).
	double flatOrder = std::nan("");
	double boxWidth = 0.0, windowWidth = 0.0, windowHeight = 0.0, surface = 0.0, meanDiameter = 0.0;
	double settledAt = 0.0, kineticRatio = 0.0, wallSeconds = 0.0;
	bool settled = false;
};

// The shapes of a bidisperse or ±10 % family, small particle of area π (2 mm disk), half large.
std::vector<ShapePtr> MakeShapes(const Family& f, int count, std::mt19937_64& rng)
{
	std::uniform_real_distribution<double> U(0.0, 1.0);
	std::vector<double> scale(size_t(count), 1.0);
	if (f.bidisperse)
	{
		for (int i = count / 2; i < count; ++i)
			scale[size_t(i)] = 1.4;
		std::shuffle(scale.begin(), scale.end(), rng);
	}
	else
		for (double& s : scale)
			s = 1.0 + 0.1 * (2.0 * U(rng) - 1.0);
	// Semi-axes a = s √α r₀, b = s r₀ / √α of area π s² r₀² for the ellipse; the superellipse's
	// r₀ is chosen so that its area (ClosedFormMass) equals the 1 mm disk's.
	const double unitArea = SuperellipseShape::ClosedFormMass(std::sqrt(f.aspect), 1.0 / std::sqrt(f.aspect), f.exponent,
	                                                          f.exponent)
	                            .area;
	const double r0 = std::sqrt(kPi / unitArea);
	std::vector<ShapePtr> shapes;
	for (double s : scale)
	{
		const double a = s * r0 * std::sqrt(f.aspect), b = s * r0 / std::sqrt(f.aspect);
		if (f.aspect == 1.0 && f.exponent == 2.0)
			shapes.push_back(MakeCircle(a));
		else if (f.exponent == 2.0)
			shapes.push_back(MakeEllipse(a, b));
		else
			shapes.push_back(MakeSuperellipse(a, b, f.exponent, f.exponent));
	}
	return shapes;
}

// The particles on a jittered lattice above the floor, random orientations (as GranularScene's
// own lattice, with the cell fitted to the largest particle).
std::vector<ParticleState> Lattice(const std::vector<ShapePtr>& shapes, double boxWidth, std::mt19937_64& rng)
{
	std::uniform_real_distribution<double> U(0.0, 1.0);
	double largest = 0.0;
	for (const ShapePtr& s : shapes)
		largest = std::max(largest, 2.0 * s->BoundingRadius());
	const double cell = 1.15 * largest;
	const int perRow = std::max(1, int((boxWidth - largest) / cell));
	std::vector<ParticleState> out;
	for (size_t i = 0; i < shapes.size(); ++i)
	{
		const int row = int(i) / perRow, col = int(i) % perRow;
		const double x = -0.5 * (perRow - 1) * cell + col * cell + 0.1 * largest * (U(rng) - 0.5);
		const double y = largest + row * cell + 0.1 * largest * U(rng);
		out.push_back({shapes[i], Pose(Vec2(x, y), 2.0 * kPi * U(rng))});
	}
	return out;
}

struct RunSettings
{
	double margin = 4.0;   // window margin in mean diameters
	double duration = 2.0; // seconds of simulated time at most
	std::string snapshot;  // path of a snapshot of the final state, empty for none
};

RunResult RunOne(const Family& f, double friction, int count, std::uint64_t seed, const RunSettings& settings)
{
	const auto wallStart = std::chrono::steady_clock::now();
	RunResult r;
	r.family = f.name;
	r.friction = friction;
	r.particles = count;
	r.seed = seed;
	GranularConfig c;
	c.particles = count;
	c.friction = friction;
	c.outletWidth = 0.0; // closed
	c.seed = seed;
	std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 7);
	std::vector<ShapePtr> shapes;
	if (f.demo)
		c.exponent = f.exponent, c.aspect = f.aspect; // GranularScene's defaults: width 2, ±10 %
	else
		shapes = MakeShapes(f, count, rng);
	// Mean area and area-equivalent diameter of the family (the demo's from its mean size).
	double meanArea = 0.0;
	if (f.demo)
		meanArea = SuperellipseShape::ClosedFormMass(1.0, 1.0 / f.aspect, f.exponent, f.exponent).area * (1.0 + 0.01 / 3.0);
	else
	{
		for (const ShapePtr& s : shapes)
			meanArea += s->Mass().area;
		meanArea /= double(count);
	}
	r.meanDiameter = 2.0 * std::sqrt(meanArea / kPi);
	c.boxWidth = std::max(12.0 * r.meanDiameter, std::sqrt(count * meanArea / 0.82));
	c.boxHeight = 1e4; // walls above any lattice
	r.boxWidth = c.boxWidth;
	std::unique_ptr<GranularScene> scene =
		f.demo ? std::make_unique<GranularScene>(c) : std::make_unique<GranularScene>(c, Lattice(shapes, c.boxWidth, rng));
	const Energies e0 = scene->ComputeEnergies();
	int step = 0;
	while (scene->Time() < settings.duration)
	{
		if (step % 25 == 0 && scene->Time() > 0.1)
		{
			const Energies e = scene->ComputeEnergies();
			const double released = e0.Total() - e.potential;
			r.kineticRatio = (e.translational + e.rotational) / released;
			if (r.kineticRatio < 1e-6)
			{
				r.settled = true;
				break;
			}
		}
		scene->Step();
		++step;
	}
	r.settledAt = scene->Time();
	const std::vector<ParticleState> packing = scene->SaveState();
	r.surface = FreeSurface(packing, c.boxWidth, 4.0 * r.meanDiameter);
	const double m = settings.margin * r.meanDiameter;
	const Box window{Vec2(-0.5 * c.boxWidth + m, m), Vec2(0.5 * c.boxWidth - m, r.surface - m)};
	const WindowFraction w = MeasureWindow(packing, window, r.meanDiameter / 40.0);
	r.phi = w.sum;
	r.phiUnion = w.covered;
	if (f.aspect != 1.0)
	{
		// Every family's long axis is its body x axis (a > b).
		double sum = 0.0;
		int n = 0;
		for (const ParticleState& p : packing)
			if (p.pose.p.x > window.lower.x && p.pose.p.x < window.upper.x && p.pose.p.y > window.lower.y &&
			    p.pose.p.y < window.upper.y)
			{
				sum += p.pose.q.c * p.pose.q.c - p.pose.q.s * p.pose.q.s;
				++n;
			}
		r.flatOrder = n > 0 ? sum / n : std::nan("");
	}
	r.windowWidth = w.width;
	r.windowHeight = w.height;
	if (!settings.snapshot.empty())
	{
		char title[160];
		std::snprintf(title, sizeof(title), "%s, friction %g, %d particles", f.label.c_str(), friction, count);
		scene->WriteSnapshot(settings.snapshot, title);
	}
	r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
	return r;
}
} // namespace

namespace
{
// Published 2D values to set beside the measurements: what they are and where from. The
// numbers are approximate (read from the papers' text and figures, protocol-dependent).
struct Reference
{
	std::string family;
	double frictionLo, frictionHi; // the friction range it applies to
	double lo, hi;                 // the range of φ
	std::string source;
};

const std::vector<Reference>& References()
{
	static const std::vector<Reference> refs = {
		{"disk", 0.0, 0.0, 0.83, 0.85,
		 "frictionless bidisperse 1:1.4 disks jam at 0.84 (O'Hern et al., PRE 68, 011306, 2003); 0.82-0.86 over protocols"},
		{"disk", 0.5, 1.0, 0.77, 0.80,
		 "frictional disks: phi_J falls with friction towards random loose packing, about 0.77-0.80 at mu >= 0.5 "
		 "(approximate; e.g. Papanikolaou, O'Hern and Shattuck, PRL 110, 198002, 2013)"},
		{"ellipse15", 0.0, 0.0, 0.86, 0.90,
		 "frictionless ellipses: phi_J rises from the disks' 0.84 to a maximum near aspect 1.5, then falls "
		 "(approximate; Delaney et al., Phil. Mag. Lett. 85, 89, 2005; Donev et al., PRE 75, 051304, 2007; "
		 "Mailman et al., PRL 102, 255501, 2009)"},
	};
	return refs;
}

struct Stats
{
	double mean = std::nan(""), sd = std::nan(""), sem = std::nan("");
	int n = 0;
};

Stats Summarise(const std::vector<double>& values)
{
	Stats s;
	std::vector<double> v;
	for (double x : values)
		if (std::isfinite(x))
			v.push_back(x);
	s.n = int(v.size());
	if (v.empty())
		return s;
	double sum = 0.0;
	for (double x : v)
		sum += x;
	s.mean = sum / s.n;
	if (s.n > 1)
	{
		double ss = 0.0;
		for (double x : v)
			ss += (x - s.mean) * (x - s.mean);
		s.sd = std::sqrt(ss / (s.n - 1));
		s.sem = s.sd / std::sqrt(double(s.n));
	}
	return s;
}

// One group of runs: a family, a friction and a count over the seeds.
struct Group
{
	std::string family;
	double friction;
	int particles;
	Stats phi, phiUnion, flatOrder;
	double settledFraction = 0.0;
};

// φ against the friction (at the largest count) for each family, with ±1 standard deviation
// bars over the seeds and the published ranges as boxes.
std::string FrictionPlot(const std::vector<Group>& groups, const std::vector<std::string>& families, int count)
{
	std::vector<Series> series;
	Series bars{"±1 s.d. over seeds", palette::black, {}, {}, false};
	for (size_t k = 0; k < families.size(); ++k)
	{
		const Family& f = FindFamily(families[k]);
		Series s{f.label, f.colour, {}, {}, true, f.marker};
		// The families side by side, 0.012 apart in μ, so that their bars stay apart.
		const double shift = 0.012 * (double(k) - 0.5 * double(families.size() - 1));
		for (const Group& g : groups)
			if (g.family == families[k] && g.particles == count && std::isfinite(g.phi.mean))
			{
				s.x.push_back(g.friction + shift);
				s.y.push_back(g.phi.mean);
				if (std::isfinite(g.phi.sd))
				{
					bars.x.insert(bars.x.end(), {g.friction + shift, g.friction + shift, std::nan("")});
					bars.y.insert(bars.y.end(), {g.phi.mean - g.phi.sd, g.phi.mean + g.phi.sd, std::nan("")});
				}
			}
		series.push_back(s);
	}
	if (!bars.x.empty())
		series.push_back(bars);
	// Each published range as a box over its friction range (±0.02 where it is one value), in
	// its family's colour.
	for (const std::string& name : families)
	{
		const Family& f = FindFamily(name);
		Series box{f.label + ": published range", f.colour, {}, {}, false};
		for (const Reference& r : References())
			if (r.family == name)
			{
				const double x0 = r.frictionLo - 0.02, x1 = r.frictionHi + 0.02;
				box.x.insert(box.x.end(), {x0, x1, x1, x0, x0, std::nan("")});
				box.y.insert(box.y.end(), {r.lo, r.lo, r.hi, r.hi, r.lo, std::nan("")});
			}
		if (!box.x.empty())
			series.push_back(box);
	}
	char title[120];
	std::snprintf(title, sizeof(title), "Packing fraction of poured particles (%d particles)", count);
	return LinePlot(series, title, "friction coefficient μ (families side by side)", "area fraction φ in the window");
}

// φ against the count for each family and friction, with ±1 standard deviation bars over the seeds.
std::string CountPlot(const std::vector<Group>& groups, const std::vector<std::string>& families,
                      const std::vector<double>& frictions)
{
	std::vector<Series> series;
	Series bars{"±1 s.d. over seeds", palette::black, {}, {}, false};
	const Marker markers[] = {Marker::circle, Marker::square, Marker::triangle, Marker::diamond, Marker::triangleDown};
	for (const std::string& name : families)
		for (size_t k = 0; k < frictions.size(); ++k)
		{
			const Family& f = FindFamily(name);
			char label[160];
			std::snprintf(label, sizeof(label), "%s, μ = %g", f.label.c_str(), frictions[k]);
			Series s{label, f.colour, {}, {}, false, markers[k % 5]};
			for (const Group& g : groups)
				if (g.family == name && g.friction == frictions[k] && std::isfinite(g.phi.mean))
				{
					s.x.push_back(g.particles);
					s.y.push_back(g.phi.mean);
					if (std::isfinite(g.phi.sd))
					{
						bars.x.insert(bars.x.end(), {double(g.particles), double(g.particles), std::nan("")});
						bars.y.insert(bars.y.end(), {g.phi.mean - g.phi.sd, g.phi.mean + g.phi.sd, std::nan("")});
					}
				}
			series.push_back(s);
		}
	if (!bars.x.empty())
		series.push_back(bars);
	return LinePlot(series, "Packing fraction against the number of particles", "particles", "area fraction φ in the window",
	                false, true);
}


// One run to do; `snapshot` is empty for none.
struct Task
{
	std::string family;
	double friction;
	int particles;
	std::uint64_t seed;
	std::string snapshot;
};

// Runs the tasks on `jobs` threads, reporting each as it ends.
std::vector<RunResult> RunAll(const std::vector<Task>& tasks, const RunSettings& settings, int jobs)
{
	Progress progress("b2a_validate_packing");
	std::vector<RunResult> results(tasks.size());
	std::atomic<size_t> next{0}, done{0};
	std::mutex lock;
	auto worker = [&]() {
		for (size_t i = next++; i < tasks.size(); i = next++)
		{
			RunSettings s = settings;
			s.snapshot = tasks[i].snapshot;
			results[i] = RunOne(FindFamily(tasks[i].family), tasks[i].friction, tasks[i].particles, tasks[i].seed, s);
			const std::lock_guard<std::mutex> guard(lock);
			char note[200];
			std::snprintf(note, sizeof(note), "%s mu=%g N=%d seed %llu: phi %.4f (%s at %.2f s, %.0f s wall)",
			              results[i].family.c_str(), results[i].friction, results[i].particles,
			              (unsigned long long)results[i].seed, results[i].phi, results[i].settled ? "rest" : "not at rest",
			              results[i].settledAt, results[i].wallSeconds);
			progress.Report(double(++done) / double(tasks.size()), note);
		}
	};
	std::vector<std::thread> threads;
	for (int t = 0; t < std::min<int>(jobs, int(tasks.size())); ++t)
		threads.emplace_back(worker);
	for (std::thread& t : threads)
		t.join();
	return results;
}

const char* const kRunsHeader = "family,friction,particles,seed,phi,phi_union,box_width_mm,window_width_mm,window_height_mm,"
                                "surface_mm,mean_diameter_mm,at_rest,settled_at_s,kinetic_ratio,wall_s";

void WriteRuns(const std::string& path, const std::vector<RunResult>& results)
{
	std::ofstream runs = OpenOutput(path);
	runs << kRunsHeader << ",flat_order\n";
	for (const RunResult& r : results)
	{
		char line[400];
		std::snprintf(line, sizeof(line), "%s,%.15g,%d,%llu,%.6f,%.6f,%.3f,%.3f,%.3f,%.3f,%.4f,%d,%.4f,%.3g,%.2f,%.4f\n", r.family.c_str(),
		              r.friction, r.particles, (unsigned long long)r.seed, r.phi, r.phiUnion, r.boxWidth, r.windowWidth,
		              r.windowHeight, r.surface, r.meanDiameter, r.settled ? 1 : 0, r.settledAt, r.kineticRatio, r.wallSeconds, r.flatOrder);
		runs << line;
	}
}

// The runs of an earlier runs.csv (--replot); exits 1 naming the file and line it cannot read.
std::vector<RunResult> ReadRuns(const std::string& path)
{
	std::ifstream in(path);
	std::string line;
	if (!in || !std::getline(in, line) || line.rfind(kRunsHeader, 0) != 0)
	{
		std::fprintf(stderr, "b2a_validate_packing: --replot: %s is not a runs.csv of this program\n", path.c_str());
		std::exit(1);
	}
	std::vector<RunResult> results;
	for (int number = 2; std::getline(in, line); ++number)
	{
		RunResult r;
		char family[64] = {};
		unsigned long long seed = 0;
		int settled = 0;
		if (std::sscanf(line.c_str(), "%63[^,],%lf,%d,%llu,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%d,%lf,%lf,%lf,%lf", family, &r.friction, &r.particles,
		                &seed, &r.phi, &r.phiUnion, &r.boxWidth, &r.windowWidth, &r.windowHeight, &r.surface, &r.meanDiameter,
		                &settled, &r.settledAt, &r.kineticRatio, &r.wallSeconds, &r.flatOrder) < 15 ||
		    FindFamily(family).name != family)
		{
			std::fprintf(stderr, "b2a_validate_packing: --replot: cannot read line %d of %s: '%s'\n", number, path.c_str(), line.c_str());
			std::exit(1);
		}
		r.family = family;
		r.seed = seed;
		r.settled = settled != 0;
		results.push_back(r);
	}
	return results;
}

// The families, frictions and counts of a set of runs, in the order they first appear.
void Axes(const std::vector<RunResult>& results, std::vector<std::string>& families, std::vector<double>& frictions,
          std::vector<int>& counts)
{
	families.clear(), frictions.clear(), counts.clear();
	for (const RunResult& r : results)
	{
		if (std::find(families.begin(), families.end(), r.family) == families.end())
			families.push_back(r.family);
		if (std::find(frictions.begin(), frictions.end(), r.friction) == frictions.end())
			frictions.push_back(r.friction);
		if (std::find(counts.begin(), counts.end(), r.particles) == counts.end())
			counts.push_back(r.particles);
	}
}

std::vector<Group> GroupRuns(const std::vector<RunResult>& results)
{
	std::vector<std::string> families;
	std::vector<double> frictions;
	std::vector<int> counts;
	Axes(results, families, frictions, counts);
	std::vector<Group> groups;
	for (const std::string& f : families)
		for (int n : counts)
			for (double mu : frictions)
			{
				Group g{f, mu, n, {}, {}, {}, 0.0};
				std::vector<double> phi, phiUnion, flatOrder;
				int settled = 0;
				for (const RunResult& r : results)
					if (r.family == f && r.friction == mu && r.particles == n)
					{
						phi.push_back(r.phi);
						phiUnion.push_back(r.phiUnion);
						flatOrder.push_back(r.flatOrder);
						settled += r.settled ? 1 : 0;
					}
				if (phi.empty())
					continue;
				g.phi = Summarise(phi);
				g.phiUnion = Summarise(phiUnion);
				g.flatOrder = Summarise(flatOrder);
				g.settledFraction = double(settled) / double(phi.size());
				groups.push_back(g);
			}
	return groups;
}

// summary.csv and the groups and published values of summary.json.
void WriteGroups(const std::string& csvPath, const std::vector<Group>& groups, Json& summary)
{
	std::ofstream csv = OpenOutput(csvPath);
	csv << "family,friction,particles,seeds,phi_mean,phi_sd,phi_sem,phi_union_mean,at_rest_fraction,flat_order_mean\n";
	auto number = [](double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); };
	Json table = Json::array();
	for (const Group& g : groups)
	{
		char line[300];
		std::snprintf(line, sizeof(line), "%s,%g,%d,%d,%.5f,%.5f,%.5f,%.5f,%.2f,%.4f\n", g.family.c_str(), g.friction, g.particles,
		              g.phi.n, g.phi.mean, g.phi.sd, g.phi.sem, g.phiUnion.mean, g.settledFraction, g.flatOrder.mean);
		csv << line;
		table.push_back({{"family", g.family}, {"friction", g.friction}, {"particles", g.particles}, {"seeds", g.phi.n},
		                 {"phi_mean", number(g.phi.mean)}, {"phi_sd", number(g.phi.sd)}, {"phi_sem", number(g.phi.sem)},
		                 {"phi_union_mean", number(g.phiUnion.mean)}, {"at_rest_fraction", g.settledFraction},
		                 {"flat_order_mean", number(g.flatOrder.mean)}});
	}
	summary["groups"] = table;
	Json refs = Json::array();
	for (const Reference& r : References())
		refs.push_back({{"family", r.family}, {"friction_range", {r.frictionLo, r.frictionHi}}, {"phi_range", {r.lo, r.hi}},
		                {"source", r.source}});
	summary["published"] = refs;
}
} // namespace

int main(int argc, char** argv)
{
	std::vector<std::string> families;
	std::vector<double> frictions;
	std::vector<int> counts;
	int seeds = 0, jobs = 1;
	std::string replot;
	RunSettings settings;
	std::vector<std::string> names;
	for (const Family& f : Families())
		names.push_back(f.name);
	CommandLine cli("b2a_validate_packing", kHelp);
	cli.Add("--families", families, std::vector<std::string>{"disk", "ellipse15", "ellipse20", "superell", "demo"},
	        std::vector<std::string>{"disk", "ellipse15"}, "LIST",
	        "families (default disk,ellipse15,ellipse20,superell,demo; quick disk,ellipse15)", ListOf(OneOf(names)));
	cli.Add("--frictions", frictions, std::vector<double>{0.0, 0.1, 0.5, 1.0}, std::vector<double>{0.0, 1.0}, "LIST",
	        "friction coefficients (default 0,0.1,0.5,1; quick 0,1)", ListOf(RealNumber(0.0, 10.0)));
	cli.Add("--counts", counts, std::vector<int>{800}, std::vector<int>{250}, "LIST",
	        "numbers of particles (default 800, quick 250)", ListOf(WholeNumber(10, 20000)));
	cli.Add("--seeds", seeds, 3, 1, "N", "seeds per family, friction and count: --seed, --seed + 1, ... (default 3, quick 1)",
	        WholeNumber(1, 1000));
	cli.Add("--margin", settings.margin, 4.0, 4.0, "D", "window margin in mean particle diameters (default 4)",
	        RealNumber(0.0, 100.0));
	cli.Add("--duration", settings.duration, 2.0, 1.0, "T", "simulated seconds at most per run (default 2, quick 1)",
	        RealNumber(0.05, 100.0));
	cli.Add("--jobs", jobs, "N", "runs in parallel, each on its own thread (default 1)", WholeNumber(1, 256));
	cli.App().add_option("--replot", replot,
	                     "run nothing: read DIR/runs.csv of an earlier run and write its tables and plots to --out")
		->type_name("DIR");
	const DemoOptions opt = cli.Parse(argc, argv);
	const auto wallStart = std::chrono::steady_clock::now();

	std::vector<RunResult> results;
	if (!replot.empty())
	{
		results = ReadRuns(replot + "/runs.csv");
		Axes(results, families, frictions, counts);
	}
	else
	{
		// Every run, in order; each family's snapshot from its first run at the highest friction and count.
		std::vector<Task> tasks;
		const double maxFriction = *std::max_element(frictions.begin(), frictions.end());
		const int maxCount = *std::max_element(counts.begin(), counts.end());
		for (const std::string& f : families)
			for (int n : counts)
				for (double mu : frictions)
					for (int k = 0; k < seeds; ++k)
					{
						const bool snap = k == 0 && mu == maxFriction && n == maxCount;
						tasks.push_back({f, mu, n, opt.seed + std::uint64_t(k), snap ? opt.out + "/snapshot_" + f + ".svg" : ""});
					}
		results = RunAll(tasks, settings, jobs);
	}
	WriteRuns(opt.out + "/runs.csv", results);
	const std::vector<Group> groups = GroupRuns(results);
	const int maxCount = *std::max_element(counts.begin(), counts.end());
	Json summary;
	summary["program"] = "b2a_validate_packing";
	summary["replotted_from"] = replot.empty() ? Json(nullptr) : Json(replot + "/runs.csv");
	summary["seed"] = opt.seed;
	summary["quick"] = opt.quick;
	summary["families"] = families;
	summary["frictions"] = frictions;
	summary["counts"] = counts;
	summary["runs"] = results.size();
	summary["margin_diameters"] = settings.margin;
	summary["duration_s"] = settings.duration;
	WriteGroups(opt.out + "/summary.csv", groups, summary);
	summary["run_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
	WriteJson(opt.out + "/summary.json", summary);
	WriteText(opt.out + "/packing_friction.svg", FrictionPlot(groups, families, maxCount));
	if (counts.size() > 1)
		WriteText(opt.out + "/packing_count.svg", CountPlot(groups, families, frictions));

	std::string line;
	for (const Group& g : groups)
		if (g.particles == maxCount)
		{
			char item[96];
			std::snprintf(item, sizeof(item), "%s%s mu=%g %.3f", line.empty() ? "" : ", ", g.family.c_str(), g.friction, g.phi.mean);
			line += item;
		}
	std::printf("b2a_validate_packing: %zu runs, packing fractions at %d particles: %s; tables and plots in %s\n", results.size(),
	            maxCount, line.c_str(), opt.out.c_str());
	return 0;
}

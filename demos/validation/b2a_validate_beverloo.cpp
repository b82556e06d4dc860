// b2analytic validation: steady discharge of a silo whose outflow is recycled to the top, against
// Beverloo's law and the form of Mankoc et al. (2007), for ellipses, disks and superellipses.
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/FlowFit.h"
#include "common/Plot.h"
#include "common/SiloFlow.h"
#include "common/Svg.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::demo;

namespace
{
const char* kHelp = R"(b2a_validate_beverloo: flow rate through a silo outlet on a bed of constant height.

For each particle kind (ellipse: the paper's 2 x 0.66 mm ellipses, +-5 %; disk: disks of the
same mean area, diameter 1.15 mm; superellipse: the hopper's n = 4 particles, 2 mm wide, aspect
1.6, +-10 %), and each seed, a bed --bed mm deep settles in a flat-bottomed silo --width mm wide
(friction 0.5 on particles, floor and walls; millimetre units, g = 9810 mm/s^2, step 2e-4 s).
From that bed a centred outlet of D = --outlets x 2 mm opens (the ellipses' major axis; the same
widths in mm for every kind). A particle whose centre falls one size below the floor has left:
it is counted and put back at rest at a free place 2 to 12 mm above the bed, so the bed keeps
its height. After --transient seconds the count is taken over --window seconds of flow, cut into
--blocks equal blocks; the flow rate of an outlet is the mean of the block rates of all seeds
and its uncertainty their standard error. Should an arch stop the flow for 0.1 s, the particles
over the outlet are moved to the top (counted as a jam) and the clock of the flow stands still
until the next particle leaves, so the rates are those of flowing periods.

Two laws are fitted to Q(D) (mass per second, with the outlets' standard errors as weights) by
Levenberg-Marquardt: Beverloo's 2D law Q = C rho sqrt(g) (D - k d)^(3/2) with C and k free, and
the 2D form of Mankoc et al. (2007), Q = C rho sqrt(g) [1 - exp(-b (D - d)/d)/2] (D - d)^(3/2)
with C and b free; rho is the bed's areal bulk density (packing fraction times the particles'
areal density 1e-3 g/mm^2), d the kind's size (major axis, diameter, width).

--fit-up-to K leaves the outlets wider than K major axes out of the fits (they are still
plotted and listed). --refit CSV reads a flow.csv of an earlier run and redoes the fits and pictures without
simulating.

Writes to DIR: summary.json (per kind: bed, outlets with Q and its standard error, both fits
with standard errors, chi^2 per degree of freedom), flow.csv (every block of every run),
flow.svg (Q / (rho sqrt(g) d^1.5) against D/d with the fits), residuals_beverloo.svg and
residuals_mankoc.svg (normalised residuals), snapshot_<kind>.svg (a silo in flow).
)";

// One row of flow.csv: the particles that left in one block of one run.
struct Block
{
	std::string kind;
	double d = 0.0, area = 0.0, fraction = 0.0;
	unsigned long seed = 0;
	double D = 0.0;
	int block = 0;
	double seconds = 0.0;
	int exits = 0;
	int jams = 0;
};

const char* kCsvHeader = "kind,d_mm,particle_area_mm2,packing_fraction,seed,D_mm,block,block_s,exits,jams_in_run";
constexpr double kDensity = 1e-3; // g/mm², the particles' areal density
constexpr double kGravity = 9810.0;

std::vector<Block> ReadCsv(const std::string& path)
{
	std::ifstream f(path);
	if (!f)
	{
		std::fprintf(stderr, "b2a_validate_beverloo: option '--refit': cannot read '%s'\n", path.c_str());
		std::exit(2);
	}
	std::string line;
	std::getline(f, line);
	if (line != kCsvHeader)
	{
		std::fprintf(stderr, "b2a_validate_beverloo: option '--refit': '%s' is not a flow.csv (header '%s')\n", path.c_str(),
		             line.c_str());
		std::exit(2);
	}
	std::vector<Block> rows;
	while (std::getline(f, line))
	{
		std::stringstream s(line);
		std::string cell;
		std::vector<std::string> cells;
		while (std::getline(s, cell, ','))
			cells.push_back(cell);
		if (cells.size() != 10)
		{
			std::fprintf(stderr, "b2a_validate_beverloo: option '--refit': line '%s' of '%s' has %zu fields, not 10\n", line.c_str(),
			             path.c_str(), cells.size());
			std::exit(2);
		}
		Block b;
		b.kind = cells[0];
		b.d = std::stod(cells[1]);
		b.area = std::stod(cells[2]);
		b.fraction = std::stod(cells[3]);
		b.seed = std::stoul(cells[4]);
		b.D = std::stod(cells[5]);
		b.block = std::stoi(cells[6]);
		b.seconds = std::stod(cells[7]);
		b.exits = std::stoi(cells[8]);
		b.jams = std::stoi(cells[9]);
		rows.push_back(b);
	}
	return rows;
}

void WriteRow(std::ofstream& csv, const Block& b)
{
	csv << b.kind << "," << b.d << "," << b.area << "," << b.fraction << "," << b.seed << "," << b.D << "," << b.block << ","
	    << b.seconds << "," << b.exits << "," << b.jams << "\n";
	csv.flush();
}

struct RunSettings
{
	double transient = 0.1, window = 0.5, width = 80.0, bed = 30.0, jamTime = 0.1;
	int blocks = 10;
};

// One outlet of one bed: open, flow with recycling, count each block of the window.
std::vector<Block> RunOutlet(const ParticleKind& kind, GranularConfig c, const std::vector<ParticleState>& bed, double depth,
                             double fraction, double D, const RunSettings& rs, std::uint64_t seed, const std::string& snapshot)
{
	c.outletWidth = D;
	RecyclingSilo silo(c, bed, depth + 2.0, depth + 12.0, seed);
	const double total = rs.transient + rs.window, blockTime = rs.window / rs.blocks;
	std::vector<int> counts(size_t(rs.blocks), 0);
	double clock = 0.0, lastExit = 0.0; // the flow's clock: stands still while an arch holds
	bool paused = false;
	int jams = 0;
	const long maxSteps = long(std::ceil(5.0 * total / c.dt)) + 1000; // an outlet that keeps jamming ends the run
	for (long step = 0; step < maxSteps && clock < total; ++step)
	{
		const int exits = silo.Step();
		if (!paused)
			clock += c.dt;
		if (exits > 0)
		{
			paused = false;
			lastExit = clock;
			if (clock >= rs.transient)
				counts[std::min(size_t(rs.blocks) - 1, size_t((clock - rs.transient) / blockTime))] += exits;
		}
		else if (!paused && clock - lastExit > rs.jamTime)
		{
			++jams;
			clock = lastExit;
			paused = true;
			silo.ClearOutlet(D + 2.0 * kind.d);
		}
	}
	if (!snapshot.empty())
		silo.Scene().WriteSnapshot(snapshot, kind.name + "s flowing through D = " + std::to_string(int(std::lround(D))) + " mm, recycled to the top");
	std::vector<Block> rows;
	const int complete = clock >= total ? rs.blocks : int((clock - rs.transient) / blockTime);
	for (int i = 0; i < complete; ++i)
		rows.push_back({kind.name, kind.d, kind.area, fraction, (unsigned long)seed, D, i, blockTime, counts[size_t(i)], jams});
	return rows;
}

// Mass flow rate per outlet from the blocks of one kind, and both fits.
struct KindResult
{
	std::string name;
	double d = 0.0, area = 0.0, fraction = 0.0, rho = 0.0;
	std::vector<double> D, Q, Qse;
	std::vector<int> jams, blocks;
	CurveFit beverloo, mankoc;
};

KindResult Analyse(const std::string& name, const std::vector<Block>& rows, double fitUpTo)
{
	KindResult r;
	r.name = name;
	std::map<double, std::vector<double>> rates;
	std::map<double, std::map<unsigned long, int>> jams;
	std::map<unsigned long, double> fractions;
	for (const Block& b : rows)
		if (b.kind == name)
		{
			r.d = b.d;
			r.area = b.area;
			fractions[b.seed] = b.fraction;
			rates[b.D].push_back(b.exits / b.seconds * b.area * kDensity); // g/s
			jams[b.D][b.seed] = b.jams;
		}
	for (const auto& [seed, f] : fractions)
		r.fraction += f / double(fractions.size());
	r.rho = r.fraction * kDensity;
	for (const auto& [D, q] : rates)
	{
		double mean = 0.0, se = 0.0;
		MeanAndError(q, mean, se);
		r.D.push_back(D);
		r.Q.push_back(mean);
		r.Qse.push_back(se);
		r.blocks.push_back(int(q.size()));
		int j = 0;
		for (const auto& [seed, n] : jams[D])
			j += n;
		r.jams.push_back(j);
	}
	const size_t fitted = size_t(std::upper_bound(r.D.begin(), r.D.end(), fitUpTo) - r.D.begin());
	if (fitted >= 3)
	{
		const std::vector<double> D(r.D.begin(), r.D.begin() + long(fitted)), Q(r.Q.begin(), r.Q.begin() + long(fitted)),
			Qse(r.Qse.begin(), r.Qse.begin() + long(fitted));
		r.beverloo = FitCurve(BeverlooModel(r.rho, kGravity, r.d), D, Q, Qse, {0.6, 1.5});
		r.mankoc = FitCurve(MankocModel(r.rho, kGravity, r.d), D, Q, Qse, {0.6, 0.5});
	}
	return r;
}

Json FitJson(const CurveFit& f, const char* first, const char* second)
{
	if (f.p.empty())
		return nullptr;
	Json j;
	j[first] = f.p[0];
	j[std::string(first) + "_se"] = f.se[0];
	j[second] = f.p[1];
	j[std::string(second) + "_se"] = f.se[1];
	j["chi2"] = f.chi2;
	j["dof"] = f.dof;
	j["chi2_per_dof"] = f.dof > 0 ? f.chi2 / f.dof : 0.0;
	j["converged"] = f.converged;
	j["iterations"] = f.iterations;
	j["normalised_residuals"] = f.normalisedResiduals;
	return j;
}

// summary.json and the pictures from the blocks of every run.
Json Report(const std::vector<Block>& rows, double fitUpTo, const std::string& out, std::string& line)
{
	std::vector<std::string> names;
	for (const Block& b : rows)
		if (std::find(names.begin(), names.end(), b.kind) == names.end())
			names.push_back(b.kind);
	Json kinds = Json::object();
	std::vector<Series> flow, resB, resM;
	const Marker markers[] = {Marker::circle, Marker::square, Marker::triangle};
	size_t index = 0;
	char buffer[256];
	for (const std::string& name : names)
	{
		const KindResult r = Analyse(name, rows, fitUpTo);
		const char* colour = palette::series[index % 6];
		const Marker marker = markers[index % 3];
		++index;
		Json k;
		k["d_mm"] = r.d;
		k["particle_area_mm2"] = r.area;
		k["packing_fraction"] = r.fraction;
		k["bulk_density_g_per_mm2"] = r.rho;
		Json outlets = Json::array();
		bool grows = true;
		std::vector<double> x, y;
		const double scale = r.rho * std::sqrt(kGravity) * std::pow(r.d, 1.5);
		for (size_t i = 0; i < r.D.size(); ++i)
		{
			outlets.push_back({{"D_mm", r.D[i]}, {"D_over_d", r.D[i] / r.d}, {"Q_g_per_s", r.Q[i]}, {"Q_se", r.Qse[i]}, {"fitted", r.D[i] <= fitUpTo},
			                   {"particles_per_s", r.Q[i] / (r.area * kDensity)}, {"blocks", r.blocks[i]}, {"jams", r.jams[i]}});
			grows = grows && (i == 0 || r.Q[i] > r.Q[i - 1]);
			x.push_back(r.D[i] / r.d);
			y.push_back(r.Q[i] / scale);
		}
		k["outlets"] = outlets;
		k["flow_grows_with_outlet"] = grows;
		k["beverloo"] = FitJson(r.beverloo, "C", "k");
		k["mankoc"] = FitJson(r.mankoc, "C", "b");
		kinds[name] = k;
		flow.push_back({name + "s (simulated)", colour, x, y, true, marker});
		if (!r.beverloo.p.empty())
		{
			std::vector<double> fx, fb, fm;
			const Model bev = BeverlooModel(r.rho, kGravity, r.d), man = MankocModel(r.rho, kGravity, r.d);
			for (int j = 0; j <= 80; ++j)
			{
				const double D = r.d * (1.0 + (x.back() * 1.03 - 1.0) * j / 80.0);
				fx.push_back(D / r.d);
				fb.push_back(bev(D, r.beverloo.p) / scale);
				fm.push_back(man(D, r.mankoc.p) / scale);
			}
			std::snprintf(buffer, sizeof(buffer), "%ss: Beverloo, k = %.2f ± %.2f", name.c_str(), r.beverloo.p[1], r.beverloo.se[1]);
			flow.push_back({buffer, colour, fx, fb, false});
			std::snprintf(buffer, sizeof(buffer), "%ss: Mankoc et al., b = %.2f ± %.2f", name.c_str(), r.mankoc.p[1], r.mankoc.se[1]);
			flow.push_back({buffer, palette::series[(index + 2) % 6], fx, fm, false});
			const std::vector<double> xf(x.begin(), x.begin() + long(r.beverloo.normalisedResiduals.size()));
			resB.push_back({name + "s", colour, xf, r.beverloo.normalisedResiduals, true, marker});
			resM.push_back({name + "s", colour, xf, r.mankoc.normalisedResiduals, true, marker});
			std::snprintf(buffer, sizeof(buffer), "%s k = %.2f ± %.2f (chi2/dof %.1f), Mankoc b = %.2f ± %.2f (%.1f); ", name.c_str(),
			              r.beverloo.p[1], r.beverloo.se[1], r.beverloo.dof > 0 ? r.beverloo.chi2 / r.beverloo.dof : 0.0, r.mankoc.p[1],
			              r.mankoc.se[1], r.mankoc.dof > 0 ? r.mankoc.chi2 / r.mankoc.dof : 0.0);
			line += buffer;
		}
	}
	WriteText(out + "/flow.svg", LinePlot(flow, "Silo flow on a bed of constant height, and fits of two laws", "outlet width D / d",
	                                      "Q / (ρ √g d^1.5)", true, true));
	WriteText(out + "/residuals_beverloo.svg", LinePlot(resB, "Beverloo fit: (Q − fit) / standard error", "outlet width D / d",
	                                                     "normalised residual"));
	WriteText(out + "/residuals_mankoc.svg", LinePlot(resM, "Mankoc et al. fit: (Q − fit) / standard error", "outlet width D / d",
	                                                   "normalised residual"));
	return kinds;
}
} // namespace

int main(int argc, char** argv)
{
	std::vector<std::string> kindNames;
	std::vector<double> outlets;
	RunSettings rs;
	int seeds = 2, threads = 1;
	std::string refit;
	double fitUpTo = 1e9;
	CommandLine cli("b2a_validate_beverloo", kHelp);
	cli.Add("--kinds", kindNames, {"ellipse", "disk", "superellipse"}, {"ellipse", "disk"}, "NAME,...",
	        "particle kinds (default ellipse,disk,superellipse; quick ellipse,disk)", OneOf({"ellipse", "disk", "superellipse"}));
	cli.Add("--outlets", outlets, {3, 4, 5, 6, 8, 10, 12, 16}, {3, 5, 8}, "K,K,...",
	        "outlet widths in the ellipses' major axes, 2 mm (default 3,4,5,6,8,10,12,16; quick 3,5,8)", RealNumber(0.5, 100.0));
	cli.Add("--seeds", seeds, 2, 1, "N", "beds per kind, seeds SEED to SEED+N-1 (default 2, quick 1)", WholeNumber(1, 1000));
	cli.Add("--transient", rs.transient, 0.08, 0.05, "T", "seconds of flow before the count (default 0.08, quick 0.05)", RealNumber(0.0, 100.0));
	cli.Add("--window", rs.window, 0.4, 0.15, "T", "seconds of flow counted (default 0.4, quick 0.15)", RealNumber(0.01, 1000.0));
	cli.Add("--blocks", rs.blocks, 10, 5, "N", "blocks the window is cut into (default 10, quick 5)", WholeNumber(2, 10000));
	cli.Add("--width", rs.width, 80.0, 40.0, "W", "silo width in mm (default 80, quick 40)", RealNumber(5.0, 1000.0));
	cli.Add("--bed", rs.bed, 50.0, 20.0, "H", "bed depth in mm (default 50, quick 20)", RealNumber(2.0, 1000.0));
	cli.Add("--threads", threads, "N", "threads computing contacts before each step (default 1; same run for any N)", WholeNumber(1, 256));
	cli.Add("--fit-up-to", fitUpTo, "K", "fit only the outlets up to K major axes (default: all)", RealNumber(0.5, 100.0));
	cli.Add("--refit", refit, "CSV", "refit a flow.csv of an earlier run instead of simulating", CLI::Validator());
	const DemoOptions opt = cli.Parse(argc, argv);
	const auto wallStart = std::chrono::steady_clock::now();
	Progress progress("b2a_validate_beverloo");

	std::vector<Block> rows;
	if (!refit.empty())
		rows = ReadCsv(refit);
	else
	{
		for (double k : outlets)
			if (2.0 * k >= rs.width)
			{
				std::fprintf(stderr, "b2a_validate_beverloo: option '--outlets': an outlet of %g major axes (%g mm) is as wide as the silo (%g mm)\n",
				             k, 2.0 * k, rs.width);
				return 2;
			}
		if (outlets.size() < 3)
		{
			std::fprintf(stderr, "b2a_validate_beverloo: option '--outlets' needs at least three outlets to fit two parameters\n");
			return 2;
		}
		std::sort(outlets.begin(), outlets.end());
		std::ofstream csv = OpenOutput(opt.out + "/flow.csv");
		csv << kCsvHeader << "\n";
		const double runs = double(kindNames.size() * size_t(seeds) * outlets.size());
		int done = 0;
		for (const std::string& name : kindNames)
		{
			ParticleKind kind;
			MakeParticleKind(name, kind);
			for (int s = 0; s < seeds; ++s)
			{
				GranularConfig c = kind.config;
				c.seed = opt.seed + std::uint64_t(s);
				c.threads = threads;
				c.boxWidth = rs.width;
				c.outletWidth = 2.0 * outlets.front(); // closed by the gate while the bed settles
				c.particles = ParticlesForBed(kind, rs.width, rs.bed, 0.8);
				c.boxHeight = rs.bed + 40.0;
				double fraction = 0.0, depth = 0.0;
				progress.Report(done / runs, name + "s: settling a bed of " + std::to_string(c.particles));
				const std::vector<ParticleState> bed = SettleBed(c, 0.15, 0.6, 1e-4, fraction, depth);
				c.boxHeight = depth + 20.0;
				for (size_t i = 0; i < outlets.size(); ++i)
				{
					const double D = 2.0 * outlets[i];
					const std::string snapshot = s == 0 && i == outlets.size() / 2 ? opt.out + "/snapshot_" + name + ".svg" : "";
					const auto blocks = RunOutlet(kind, c, bed, depth, fraction, D, rs, c.seed, snapshot);
					int exits = 0;
					for (const Block& b : blocks)
					{
						WriteRow(csv, b);
						exits += b.exits;
					}
					rows.insert(rows.end(), blocks.begin(), blocks.end());
					++done;
					progress.Report(done / runs, name + "s, seed " + std::to_string(c.seed) + ", D = " + std::to_string(int(D)) +
					                                 " mm: " + std::to_string(exits) + " counted" +
					                                 (blocks.empty() ? "" : ", " + std::to_string(blocks[0].jams) + " jams"));
				}
			}
		}
	}

	std::string line;
	Json summary = Json::object();
	summary["demo"] = "b2a_validate_beverloo";
	summary["quick"] = opt.quick;
	summary["refit_of"] = refit.empty() ? Json(nullptr) : Json(refit);
	summary["seed"] = opt.seed;
	summary["seeds"] = seeds;
	summary["silo"] = {{"width_mm", rs.width}, {"bed_mm", rs.bed}, {"transient_s", rs.transient}, {"window_s", rs.window},
	                   {"blocks", rs.blocks}, {"jam_s", rs.jamTime}, {"time_step_s", 2e-4}};
	summary["fit_up_to_mm"] = fitUpTo < 1e9 ? Json(2.0 * fitUpTo) : Json(nullptr);
	summary["kinds"] = Report(rows, 2.0 * fitUpTo, opt.out, line);
	summary["paper"] = {{"k", 2.21}, {"note", "the paper's ellipses in its 800 mm channel; its particle parameters are not given"}};
	summary["run_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
	WriteJson(opt.out + "/summary.json", summary);
	std::printf("b2a_validate_beverloo: %s%zu blocks; summary.json and pictures in %s\n", line.c_str(), rows.size(), opt.out.c_str());
	return 0;
}

// b2analytic validation: how often a silo outlet arches against its width, and the mean
// avalanche size, for disks, ellipses and superellipses (To, Lai and Pak 2001; Zuriguel et al.
// 2005; Janda et al. 2008 measured both for disks).
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
const char* kHelp = R"(b2a_validate_jamming: arches at a silo outlet against its width.

For each particle kind (disk, ellipse, superellipse: the particles of b2a_validate_beverloo)
and each run (seeds SEED to SEED+runs-1) a bed --bed mm deep settles in a flat-bottomed silo
--width mm wide (friction 0.5; millimetre units, g = 9810 mm/s^2, step 2e-4 s). From that bed,
for each outlet width D = --widths x d (d the kind's size: diameter, major axis, width), the
outlet opens; discharged particles go back to the top at rest, so the bed keeps its height. The
outlet has jammed when no particle has left for --jam-time s (0.05: at least 2.5 times the
time a particle takes to fall its own size from rest); the particles that passed since the flow
last started form an avalanche. The arch is then broken (the particles over the outlet move to
the top, as blowing air does in the experiments) and the flow goes on, until --exits particles
have left or --avalanches jams have happened.

Measured per kind and width: J(N), the fraction of runs whose first avalanche (from the settled
bed, as in the paper's hopper) ended in a jam before N = --jam-before particles had passed,
with its 95 % Wilson interval; the mean avalanche size <s> from every avalanche, an exponential
distribution's maximum-likelihood estimate with the last, unfinished avalanche of each run
counted as censored: <s> = (sum of all sizes) / (number of jams), standard error <s>/sqrt(jams).
Fitted: ln <s> = a + D/(lambda d) (exponential growth with width) and ln <s> = a + c (D/d)^2
(Janda et al. 2008's form for disks), weighted by the jams; with either, the width at which an
arch after 67 particles (the paper's hopper) is the median outcome, <s> = 67/ln 2.

--refit CSV redoes the statistics and pictures from an earlier runs.csv.

Writes to DIR: summary.json, runs.csv (every avalanche), jamming.svg (J(N) against D/d),
avalanches.svg (<s> against D/d, logarithmic, with the fits).
)";

const char* kCsvHeader = "kind,d_mm,D_over_d,seed,avalanche,size,jammed";

struct Avalanche
{
	std::string kind;
	double d = 0.0, width = 0.0; // width in d
	unsigned long seed = 0;
	int index = 0, size = 0;
	bool jammed = false;
};

std::vector<Avalanche> ReadCsv(const std::string& path)
{
	std::ifstream f(path);
	std::string line;
	if (!f || !std::getline(f, line) || line != kCsvHeader)
	{
		std::fprintf(stderr, "b2a_validate_jamming: option '--refit': '%s' is not a readable runs.csv\n", path.c_str());
		std::exit(2);
	}
	std::vector<Avalanche> rows;
	while (std::getline(f, line))
	{
		std::stringstream s(line);
		std::string cell;
		std::vector<std::string> c;
		while (std::getline(s, cell, ','))
			c.push_back(cell);
		if (c.size() != 7)
		{
			std::fprintf(stderr, "b2a_validate_jamming: option '--refit': line '%s' has %zu fields, not 7\n", line.c_str(), c.size());
			std::exit(2);
		}
		rows.push_back({c[0], std::stod(c[1]), std::stod(c[2]), std::stoul(c[3]), std::stoi(c[4]), std::stoi(c[5]), c[6] == "1"});
	}
	return rows;
}

struct Settings
{
	double width = 30.0, bed = 20.0, jamTime = 0.05;
	int exits = 200, avalanches = 5, jamBefore = 100;
};

// One outlet from one bed: the avalanches until the exits or the jams are used up.
std::vector<Avalanche> RunOutlet(const ParticleKind& kind, GranularConfig c, const std::vector<ParticleState>& bed, double depth,
                                 double widthInD, const Settings& s)
{
	c.outletWidth = widthInD * kind.d;
	RecyclingSilo silo(c, bed, depth + 3.0, depth + 15.0, c.seed);
	std::vector<Avalanche> out;
	Avalanche a{kind.name, kind.d, widthInD, (unsigned long)c.seed, 0, 0, false};
	double lastExit = 0.0;
	long total = 0;
	const long maxSteps = long((s.exits * 0.05 + (s.avalanches + 1) * 2.0 * s.jamTime) / c.dt); // a cap: 20 particles/s at least
	for (long step = 0; step < maxSteps; ++step)
	{
		const int exits = silo.Step();
		if (exits > 0)
		{
			a.size += exits;
			total += exits;
			lastExit = silo.Time();
			if (total >= s.exits)
				break;
		}
		else if (silo.Time() - lastExit > s.jamTime)
		{
			a.jammed = true;
			out.push_back(a);
			if (int(out.size()) >= s.avalanches)
				return out;
			a.jammed = false;
			a.size = 0;
			++a.index;
			silo.ClearOutlet(c.outletWidth + 2.0 * kind.d);
			lastExit = silo.Time(); // the flow starts again
		}
	}
	out.push_back(a); // unfinished: censored
	return out;
}

// 95 % Wilson score interval of a binomial proportion k/n.
void Wilson(int k, int n, double& lo, double& hi)
{
	const double z = 1.96, p = n > 0 ? double(k) / n : 0.0, z2 = z * z / std::max(1, n);
	const double centre = (p + 0.5 * z2) / (1.0 + z2), half = z * std::sqrt(p * (1.0 - p) / std::max(1, n) + 0.25 * z2 / std::max(1, n)) / (1.0 + z2);
	lo = std::max(0.0, centre - half);
	hi = std::min(1.0, centre + half);
}

struct WidthResult
{
	double width = 0.0;
	int runs = 0, firstJammed = 0, jams = 0;
	long sizes = 0;
	double J = 0.0, Jlo = 0.0, Jhi = 0.0, meanSize = 0.0, meanSizeSe = 0.0;
};

Json Report(const std::vector<Avalanche>& rows, int jamBefore, const std::string& out, std::string& line)
{
	std::vector<std::string> names;
	for (const Avalanche& a : rows)
		if (std::find(names.begin(), names.end(), a.kind) == names.end())
			names.push_back(a.kind);
	Json kinds = Json::object();
	std::vector<Series> jPlot, sPlot;
	const Marker markers[] = {Marker::circle, Marker::square, Marker::triangle};
	size_t index = 0;
	char buffer[256];
	for (const std::string& name : names)
	{
		std::map<double, WidthResult> widths;
		double d = 0.0;
		for (const Avalanche& a : rows)
		{
			if (a.kind != name)
				continue;
			d = a.d;
			WidthResult& w = widths[a.width];
			w.width = a.width;
			if (a.index == 0)
			{
				++w.runs;
				if (a.jammed && a.size < jamBefore)
					++w.firstJammed;
			}
			w.sizes += a.size;
			w.jams += a.jammed ? 1 : 0;
		}
		Json list = Json::array();
		std::vector<double> x, J, xs, lnS, sigma, S;
		for (auto& [width, w] : widths)
		{
			w.J = double(w.firstJammed) / std::max(1, w.runs);
			Wilson(w.firstJammed, w.runs, w.Jlo, w.Jhi);
			Json o = {{"D_over_d", width}, {"D_mm", width * d}, {"runs", w.runs}, {"jammed_before_N", w.firstJammed}, {"J", w.J},
			          {"J_95_low", w.Jlo}, {"J_95_high", w.Jhi}, {"jams", w.jams}, {"particles", w.sizes}};
			x.push_back(width);
			J.push_back(w.J);
			if (w.jams > 0)
			{
				w.meanSize = double(w.sizes) / w.jams;
				w.meanSizeSe = w.meanSize / std::sqrt(double(w.jams));
				o["mean_avalanche"] = w.meanSize;
				o["mean_avalanche_se"] = w.meanSizeSe;
				o["J_exponential_model"] = 1.0 - std::exp(-jamBefore / w.meanSize);
				xs.push_back(width);
				S.push_back(w.meanSize);
				lnS.push_back(std::log(w.meanSize));
				sigma.push_back(1.0 / std::sqrt(double(w.jams)));
			}
			else
			{
				o["mean_avalanche"] = nullptr;
				o["mean_avalanche_lower_bound"] = double(w.sizes); // no jam in all these particles
			}
			list.push_back(o);
		}
		Json k;
		k["d_mm"] = d;
		k["jam_before_N"] = jamBefore;
		k["widths"] = list;
		const char* colour = palette::series[index % 6];
		const Marker marker = markers[index % 3];
		++index;
		jPlot.push_back({name + "s", colour, x, J, true, marker});
		sPlot.push_back({name + "s", colour, xs, S, true, marker});
		if (xs.size() >= 3)
		{
			const Model linear = [](double v, const std::vector<double>& p) { return p[0] + p[1] * v; };
			const Model square = [](double v, const std::vector<double>& p) { return p[0] + p[1] * v * v; };
			const CurveFit fe = FitCurve(linear, xs, lnS, sigma, {0.0, 1.0});
			const CurveFit fq = FitCurve(square, xs, lnS, sigma, {0.0, 0.1});
			const double target = std::log(67.0 / std::log(2.0));
			const double we = (target - fe.p[0]) / fe.p[1], wq = fq.p[1] > 0.0 ? std::sqrt(std::max(0.0, (target - fq.p[0]) / fq.p[1])) : 0.0;
			k["fit_exponential"] = {{"a", fe.p[0]},           {"a_se", fe.se[0]},
			                        {"slope", fe.p[1]},       {"slope_se", fe.se[1]},
			                        {"lambda", 1.0 / fe.p[1]}, {"chi2_per_dof", fe.dof > 0 ? fe.chi2 / fe.dof : 0.0},
			                        {"width_for_median_arch_at_67", we}, {"ln_mean_avalanche_at_12", fe.p[0] + 12.0 * fe.p[1]}};
			k["fit_square"] = {{"a", fq.p[0]},     {"a_se", fq.se[0]},
			                   {"c", fq.p[1]},     {"c_se", fq.se[1]},
			                   {"chi2_per_dof", fq.dof > 0 ? fq.chi2 / fq.dof : 0.0},
			                   {"width_for_median_arch_at_67", wq}, {"ln_mean_avalanche_at_12", fq.p[0] + 144.0 * fq.p[1]}};
			std::vector<double> fx, fyE, fyQ;
			for (int j = 0; j <= 60; ++j)
			{
				const double v = xs.front() + (xs.back() - xs.front()) * j / 60.0;
				fx.push_back(v);
				fyE.push_back(std::exp(linear(v, fe.p)));
				fyQ.push_back(std::exp(square(v, fq.p)));
			}
			std::snprintf(buffer, sizeof(buffer), "%ss: exp(a + D/(λ d)), λ = %.2f", name.c_str(), 1.0 / fe.p[1]);
			sPlot.push_back({buffer, colour, fx, fyE, false});
			std::snprintf(buffer, sizeof(buffer), "%ss: exp(a + c (D/d)²), c = %.2f", name.c_str(), fq.p[1]);
			sPlot.push_back({buffer, palette::series[(index + 2) % 6], fx, fyQ, false});
			std::snprintf(buffer, sizeof(buffer), "%s: <s> ~ exp(%.2f D/d) (chi2/dof %.1f), median arch at 67 for D = %.2f d; ", name.c_str(),
			              fe.p[1], fe.dof > 0 ? fe.chi2 / fe.dof : 0.0, we);
			line += buffer;
		}
		kinds[name] = k;
	}
	WriteText(out + "/jamming.svg", LinePlot(jPlot, "Outlet jammed before " + std::to_string(jamBefore) + " particles passed",
	                                         "outlet width D / d", "fraction of runs J"));
	WriteText(out + "/avalanches.svg", LinePlot(sPlot, "Mean avalanche size between jams", "outlet width D / d",
	                                            "mean avalanche <s> (particles)", true));
	return kinds;
}
} // namespace

int main(int argc, char** argv)
{
	std::vector<std::string> kindNames;
	std::vector<double> widths;
	Settings s;
	int runs = 50, threads = 1;
	std::string refit;
	CommandLine cli("b2a_validate_jamming", kHelp);
	cli.Add("--kinds", kindNames, {"disk", "ellipse", "superellipse"}, {"disk"}, "NAME,...",
	        "particle kinds (default disk,ellipse,superellipse; quick disk)", OneOf({"ellipse", "disk", "superellipse"}));
	cli.Add("--widths", widths, {2, 2.5, 3, 3.5, 4}, {2, 3, 4}, "K,K,...",
	        "outlet widths in particle sizes d (default 2,2.5,3,3.5,4; quick 2,3,4)", RealNumber(0.5, 20.0));
	cli.Add("--runs", runs, 50, 5, "N", "beds (seeds) per kind (default 50, quick 5)", WholeNumber(1, 100000));
	cli.Add("--exits", s.exits, 120, 100, "N", "particles per outlet and bed at most (default 120, quick 100)", WholeNumber(1, 1e7));
	cli.Add("--avalanches", s.avalanches, 3, 3, "N", "jams per outlet and bed at most (default 3)", WholeNumber(1, 100000));
	cli.Add("--jam-time", s.jamTime, "T", "seconds without a particle leaving that make a jam (default 0.05)", RealNumber(0.001, 10.0));
	cli.Add("--jam-before", s.jamBefore, "N", "J(N): jammed before N particles passed (default 100)", WholeNumber(1, 1e7));
	cli.Add("--width", s.width, "W", "silo width in mm (default 30)", RealNumber(5.0, 1000.0));
	cli.Add("--bed", s.bed, "H", "bed depth in mm (default 20)", RealNumber(2.0, 1000.0));
	cli.Add("--threads", threads, "N", "threads computing contacts before each step (default 1; same run for any N)", WholeNumber(1, 256));
	cli.Add("--refit", refit, "CSV", "redo the statistics from a runs.csv of an earlier run instead of simulating", CLI::Validator());
	const DemoOptions opt = cli.Parse(argc, argv);
	const auto wallStart = std::chrono::steady_clock::now();
	Progress progress("b2a_validate_jamming");

	std::vector<Avalanche> rows;
	if (!refit.empty())
		rows = ReadCsv(refit);
	else
	{
		std::ofstream csv = OpenOutput(opt.out + "/runs.csv");
		csv << kCsvHeader << "\n";
		const double total = double(kindNames.size()) * runs;
		int done = 0;
		for (const std::string& name : kindNames)
		{
			ParticleKind kind;
			MakeParticleKind(name, kind);
			for (double w : widths)
				if (w * kind.d >= s.width)
				{
					std::fprintf(stderr, "b2a_validate_jamming: option '--widths': %g sizes of a %s (%g mm) is as wide as the silo (%g mm)\n",
					             w, name.c_str(), w * kind.d, s.width);
					return 2;
				}
			int jamsSoFar = 0;
			for (int r = 0; r < runs; ++r)
			{
				GranularConfig c = kind.config;
				c.seed = opt.seed + std::uint64_t(r);
				c.threads = threads;
				c.boxWidth = s.width;
				c.outletWidth = widths.empty() ? 0.0 : *std::max_element(widths.begin(), widths.end()) * kind.d;
				c.particles = ParticlesForBed(kind, s.width, s.bed, 0.8);
				c.boxHeight = s.bed + 30.0;
				double fraction = 0.0, depth = 0.0;
				const std::vector<ParticleState> bed = SettleBed(c, 0.12, 0.5, 1e-4, fraction, depth);
				c.boxHeight = depth + 20.0;
				for (double w : widths)
					for (const Avalanche& a : RunOutlet(kind, c, bed, depth, w, s))
					{
						csv << a.kind << "," << a.d << "," << a.width << "," << a.seed << "," << a.index << "," << a.size << ","
						    << (a.jammed ? 1 : 0) << "\n";
						jamsSoFar += a.jammed ? 1 : 0;
						rows.push_back(a);
					}
				csv.flush();
				++done;
				progress.Report(done / total, name + "s: bed " + std::to_string(r + 1) + " of " + std::to_string(runs) + ", " +
				                                  std::to_string(jamsSoFar) + " jams so far");
			}
		}
	}
	std::string line;
	Json summary = Json::object();
	summary["demo"] = "b2a_validate_jamming";
	summary["quick"] = opt.quick;
	summary["refit_of"] = refit.empty() ? Json(nullptr) : Json(refit);
	summary["seed"] = opt.seed;
	summary["silo"] = {{"width_mm", s.width}, {"bed_mm", s.bed}, {"jam_s", s.jamTime}, {"exits_per_outlet", s.exits},
	                   {"avalanches_per_outlet", s.avalanches}, {"time_step_s", 2e-4}};
	summary["kinds"] = Report(rows, s.jamBefore, opt.out, line);
	summary["paper"] = {{"hopper_outlet_widths", 12}, {"discharged_before_arch", 67},
	                    {"note", "superellipses n = 4; the paper's particle parameters are not given"}};
	summary["run_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
	WriteJson(opt.out + "/summary.json", summary);
	std::printf("b2a_validate_jamming: %s%zu avalanches; summary.json and pictures in %s\n", line.c_str(), rows.size(), opt.out.c_str());
	return 0;
}

// b2analytic benchmarks: timing, machine description and table output shared by the benchmarks.
//
// Speed is always reported as a median of repeats and, where it is a claim, as a ratio against
// a baseline measured in the same process (machines here are shared and noisy).
#pragma once

#include "common/DemoCommon.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace b2a::bench
{

/// The machine and build a measurement came from, for every report.
struct MachineInfo
{
	std::string cpu;        ///< CPU model name (from /proc/cpuinfo), "unknown" if unreadable
	int cores = 0;          ///< hardware threads available to the process
	std::string buildFlags; ///< compiler, build type and flags of the benchmark build
};

/// The machine and build this process runs on.
MachineInfo GetMachineInfo();

/// The machine as a JSON object (cpu, cores, build_flags).
demo::Json MachineJson(const MachineInfo& machine);

/// Median of the values (the mean of the two middle ones for an even count); 0 when empty.
double Median(std::vector<double> values);

/// Keep a value alive so that the optimiser cannot drop the work that produced it.
template <class T>
inline void KeepAlive(const T& value)
{
	asm volatile("" : : "g"(&value) : "memory");
}

/// CPU time of the calling thread in nanoseconds. On a shared machine the wall clock also counts
/// the time the thread waited for a core; the thread's CPU time does not, so single-threaded
/// measurements taken while other work runs stay comparable.
double ThreadCpuNanoseconds();

/// Nanoseconds per query: runs `pass()` (which performs `queriesPerPass` queries) `repeats`
/// times after one warm-up pass and returns the median thread CPU time per query.
template <class Pass>
double MedianNanosecondsPerQuery(Pass&& pass, int queriesPerPass, int repeats)
{
	pass(); // warm-up: caches, branch predictors, lazily built surface samples
	std::vector<double> times;
	times.reserve(repeats);
	for (int r = 0; r < repeats; ++r)
	{
		const double start = ThreadCpuNanoseconds();
		pass();
		times.push_back((ThreadCpuNanoseconds() - start) / queriesPerPass);
	}
	return Median(std::move(times));
}

/// A method's time and its ratio to a baseline timed in the same repeats.
struct PairedTiming
{
	double ns = 0.0;         ///< median time per query of the method
	double baselineNs = 0.0; ///< median time per query of the baseline
	double ratio = 0.0;      ///< median over the repeats of method time / baseline time
};

/// Times `pass` against `baseline` (each performing `queriesPerPass` queries) in alternation:
/// every repeat runs both, one right after the other, in an order that swaps from repeat to
/// repeat, and the ratio is the median of the repeats' own ratios. A machine whose speed drifts
/// (another job starting, the clock stepping down) slows both passes of a repeat alike, so the
/// ratio keeps what the medians of separately timed blocks lose. `clock` returns nanoseconds
/// (ThreadCpuNanoseconds; a test passes its own).
template <class Pass, class Baseline, class Clock>
PairedTiming MedianPairedPerQuery(Pass&& pass, Baseline&& baseline, int queriesPerPass, int repeats, Clock&& clock)
{
	pass(); // warm-up, as in MedianNanosecondsPerQuery
	baseline();
	std::vector<double> times, baseTimes, ratios;
	for (int r = 0; r < repeats; ++r)
	{
		double t[2] = {0.0, 0.0}; // method, baseline
		for (int k = 0; k < 2; ++k)
		{
			const bool method = (k == 0) == (r % 2 == 0);
			const double start = clock();
			method ? pass() : baseline();
			t[method ? 0 : 1] = (clock() - start) / queriesPerPass;
		}
		times.push_back(t[0]);
		baseTimes.push_back(t[1]);
		ratios.push_back(t[1] > 0.0 ? t[0] / t[1] : 0.0);
	}
	return {Median(std::move(times)), Median(std::move(baseTimes)), Median(std::move(ratios))};
}

/// A method's time per query on its poses and its ratio to a baseline on the same poses: the two
/// timed in alternation (MedianPairedPerQuery), so that the ratio does not take the machine's
/// drift between rows; the baseline itself gets its own median time and ratio 1.
template <class Pass, class Baseline>
PairedTiming TimeAgainstBaseline(Pass&& pass, Baseline&& baseline, bool isBaseline, int queriesPerPass, int repeats)
{
	if (isBaseline)
		return {MedianNanosecondsPerQuery(pass, queriesPerPass, repeats), 0.0, 1.0};
	PairedTiming t = MedianPairedPerQuery(pass, baseline, queriesPerPass, repeats, ThreadCpuNanoseconds);
	t.baselineNs = 0.0;
	return t;
}

/// Keeps the items (pair families: anything with a `name`) whose names are in `names`, in the
/// items' order; all of them where `names` is empty (the option --families not given).
template <class Item>
void SelectFamilies(std::vector<Item>& items, const std::vector<std::string>& names)
{
	if (names.empty())
		return;
	std::vector<Item> chosen;
	for (Item& item : items)
		if (std::find(names.begin(), names.end(), item.name) != names.end())
			chosen.push_back(std::move(item));
	items = std::move(chosen);
}

/// A generator of a pair family's own, seeded by the run's seed and the family's name (FNV-1a,
/// stable across compilers), so that a family's poses do not depend on which others run.
std::mt19937_64 FamilyRng(std::uint64_t seed, const std::string& name);

/// A table written both as CSV (machine-readable) and as Markdown (for a reader).
struct Table
{
	std::vector<std::string> columns;           ///< column names
	std::vector<std::vector<std::string>> rows; ///< cells, one vector per row

	/// CSV text with a header line; cells holding a comma or quote are quoted.
	std::string Csv() const;
	/// Markdown table text.
	std::string Markdown() const;
};

/// A number as text with `digits` significant digits ("nan"/"inf" spelled out, never empty).
std::string FormatNumber(double value, int digits = 4);

} // namespace b2a::bench

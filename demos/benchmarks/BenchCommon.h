// b2analytic benchmarks: timing, machine description and table output shared by the benchmarks.
//
// Speed is always reported as a median of repeats and, where it is a claim, as a ratio against
// a baseline measured in the same process (machines here are shared and noisy).
#pragma once

#include "common/DemoCommon.h"

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

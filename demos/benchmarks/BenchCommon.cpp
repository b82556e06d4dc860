// b2analytic benchmarks: shared timing and output code.
#include "BenchCommon.h"
#include "common/Plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>
#include <time.h>

#ifndef B2A_BUILD_FLAGS
#define B2A_BUILD_FLAGS "unknown"
#endif

namespace b2a::bench
{

std::mt19937_64 FamilyRng(std::uint64_t seed, const std::string& name)
{
	std::uint64_t hash = 1469598103934665603ull; // FNV-1a: stable across compilers (std::hash is not)
	for (const unsigned char ch : name)
		hash = (hash ^ ch) * 1099511628211ull;
	std::seed_seq seq{std::uint32_t(seed), std::uint32_t(seed >> 32), std::uint32_t(hash), std::uint32_t(hash >> 32)};
	return std::mt19937_64(seq);
}

MachineInfo GetMachineInfo()
{
	MachineInfo machine;
	machine.cpu = "unknown";
	std::ifstream cpuinfo("/proc/cpuinfo");
	std::string line;
	while (std::getline(cpuinfo, line))
	{
		if (line.rfind("model name", 0) == 0)
		{
			const auto colon = line.find(':');
			if (colon != std::string::npos)
			{
				machine.cpu = line.substr(line.find_first_not_of(" \t", colon + 1));
			}
			break;
		}
	}
	machine.cores = int(std::thread::hardware_concurrency());
	machine.buildFlags = B2A_BUILD_FLAGS;
	return machine;
}

demo::Json MachineJson(const MachineInfo& machine)
{
	demo::Json json;
	json["cpu"] = machine.cpu;
	json["cores"] = machine.cores;
	json["build_flags"] = machine.buildFlags;
	return json;
}

double ThreadCpuNanoseconds()
{
	timespec t{};
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return 1e9 * double(t.tv_sec) + double(t.tv_nsec);
}

double Median(std::vector<double> values)
{
	if (values.empty())
	{
		return 0.0;
	}
	const size_t mid = values.size() / 2;
	std::nth_element(values.begin(), values.begin() + mid, values.end());
	if (values.size() % 2 == 1)
	{
		return values[mid];
	}
	const double upper = values[mid];
	const double lower = *std::max_element(values.begin(), values.begin() + mid);
	return 0.5 * (lower + upper);
}

std::string Table::Csv() const
{
	auto cell = [](const std::string& text) {
		if (text.find_first_of(",\"\n") == std::string::npos)
		{
			return text;
		}
		std::string quoted = "\"";
		for (char c : text)
		{
			quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
		}
		return quoted + "\"";
	};
	std::ostringstream out;
	for (size_t i = 0; i < columns.size(); ++i)
	{
		out << (i ? "," : "") << cell(columns[i]);
	}
	out << "\n";
	for (const auto& row : rows)
	{
		for (size_t i = 0; i < row.size(); ++i)
		{
			out << (i ? "," : "") << cell(row[i]);
		}
		out << "\n";
	}
	return out.str();
}

std::string Table::Markdown() const
{
	std::ostringstream out;
	out << "|";
	for (const auto& c : columns)
	{
		out << " " << c << " |";
	}
	out << "\n|";
	for (size_t i = 0; i < columns.size(); ++i)
	{
		out << " --- |";
	}
	out << "\n";
	for (const auto& row : rows)
	{
		out << "|";
		for (const auto& c : row)
		{
			out << " " << c << " |";
		}
		out << "\n";
	}
	return out.str();
}

std::string FormatNumber(double value, int digits)
{
	if (std::isnan(value))
	{
		return "nan";
	}
	if (std::isinf(value))
	{
		return value > 0 ? "inf" : "-inf";
	}
	char text[64];
	std::snprintf(text, sizeof text, "%.*g", digits, value);
	return text;
}

} // namespace b2a::bench

// b2analytic demos: shared command line, files and progress.
#include "DemoCommon.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace b2a::demo
{

DemoOptions ParseDemoOptions(int argc, char** argv, const char* name, const char* help, const std::vector<std::string>& extra)
{
	DemoOptions o;
	o.name = name;
	o.out = std::string("out/") + name;
	for (int i = 1; i < argc; ++i)
	{
		const std::string arg = argv[i];
		auto value = [&](const char* what) {
			if (i + 1 >= argc)
			{
				std::fprintf(stderr, "%s: option '%s' needs %s (see --help)\n", name, arg.c_str(), what);
				std::exit(2);
			}
			return std::string(argv[++i]);
		};
		if (arg == "--help" || arg == "-h")
		{
			std::fputs(help, stdout);
			std::fputs("\nCommon options:\n"
			           "  --out DIR   output folder (default out/<demo>); created if missing\n"
			           "  --seed N    random seed (default 1)\n"
			           "  --quick     reduced run for CI, under a minute\n"
			           "  --help      this text\n",
			           stdout);
			std::exit(0);
		}
		else if (arg == "--out")
			o.out = value("a folder");
		else if (arg == "--seed")
		{
			const std::string v = value("a number");
			char* end = nullptr;
			const unsigned long long s = std::strtoull(v.c_str(), &end, 10);
			if (v.empty() || *end != '\0' || v[0] == '-')
			{
				std::fprintf(stderr, "%s: option '--seed' needs a non-negative integer, got '%s'\n", name, v.c_str());
				std::exit(2);
			}
			o.seed = s;
		}
		else if (arg == "--quick")
			o.quick = true;
		else if (std::find(extra.begin(), extra.end(), arg) != extra.end())
			o.extra[arg] = value("a value");
		else
		{
			std::fprintf(stderr, "%s: unknown argument '%s' (see --help)\n", name, arg.c_str());
			std::exit(2);
		}
	}
	std::error_code ec;
	std::filesystem::create_directories(o.out, ec);
	if (ec || !std::filesystem::is_directory(o.out))
	{
		std::fprintf(stderr, "%s: cannot create output folder '%s': %s\n", name, o.out.c_str(), ec.message().c_str());
		std::exit(1);
	}
	return o;
}

namespace
{
[[noreturn]] void BadValue(const DemoOptions& o, const std::string& option, const std::string& value, double lo, double hi)
{
	std::fprintf(stderr, "%s: option '%s' needs a number from %g to %g, got '%s'\n", o.name.c_str(), option.c_str(), lo, hi,
	             value.c_str());
	std::exit(2);
}

double ParseNumber(const DemoOptions& o, const std::string& option, const std::string& text, double lo, double hi)
{
	char* end = nullptr;
	const double v = std::strtod(text.c_str(), &end);
	if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
		BadValue(o, option, text, lo, hi);
	return v;
}
} // namespace

double DemoOptions::Number(const std::string& option, double fallback, double lo, double hi) const
{
	const auto it = extra.find(option);
	return it == extra.end() ? fallback : ParseNumber(*this, option, it->second, lo, hi);
}

std::vector<double> DemoOptions::Numbers(const std::string& option, const std::vector<double>& fallback, double lo, double hi) const
{
	const auto it = extra.find(option);
	if (it == extra.end())
		return fallback;
	std::vector<double> out;
	size_t start = 0;
	const std::string& text = it->second;
	while (start <= text.size())
	{
		const size_t comma = std::min(text.find(',', start), text.size());
		out.push_back(ParseNumber(*this, option, text.substr(start, comma - start), lo, hi));
		start = comma + 1;
	}
	return out;
}

void WriteText(const std::string& path, const std::string& text)
{
	std::ofstream f(path);
	f << text;
	f.close();
	if (!f)
	{
		std::fprintf(stderr, "cannot write '%s'\n", path.c_str());
		std::exit(1);
	}
}

void WriteJson(const std::string& path, const Json& value)
{
	WriteText(path, value.dump(2) + "\n");
}

double Progress::Elapsed() const
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

void Progress::Report(double fraction, const std::string& note)
{
	const double t = Elapsed();
	if (fraction < 1.0 && t - m_last < 0.5)
		return;
	m_last = t;
	std::fprintf(stderr, "[%s] %5.1f%%  %6.1f s  %s\n", m_name, 100.0 * fraction, t, note.c_str());
}

} // namespace b2a::demo

// b2analytic demos: shared command line, files and progress.
#include "DemoCommon.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace b2a::demo
{

DemoOptions ParseDemoOptions(int argc, char** argv, const char* name, const char* help)
{
	DemoOptions o;
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

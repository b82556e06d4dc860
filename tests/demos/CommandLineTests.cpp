// b2analytic tests: the demos' command line (demos/common/CommandLine.h): what its validators
// accept, reject and pass on to CLI11, the defaults of a quick run, and the help text.
#include <doctest/doctest.h>

#include "common/CommandLine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

using b2a::demo::CommandLine;
using b2a::demo::DemoOptions;

namespace
{
// A validator's verdict on `text`: "" when accepted (and `text` rewritten), else the message.
std::string Validate(const CLI::Validator& v, std::string& text)
{
	return v(text);
}

// Parse `args` (after the program name) with a fresh folder under demo_out for --out.
DemoOptions ParseArgs(CommandLine& cli, std::vector<std::string> args)
{
	const std::string out = "demo_out/command_line";
	std::filesystem::remove_all(out);
	args.insert(args.begin(), {"b2a_test", "--out", out});
	std::vector<char*> argv;
	for (std::string& a : args)
		argv.push_back(a.data());
	return cli.Parse(int(argv.size()), argv.data());
}
} // namespace

TEST_CASE("WholeNumber: whole values in range as strtod reads them, rewritten in decimal digits, the rest named")
{
	const CLI::Validator v = b2a::demo::WholeNumber(1, 20000);
	for (const auto& [given, rewritten] : std::vector<std::pair<std::string, std::string>>{
		     {"40", "40"}, {"012", "12"}, {"40.0", "40"}, {"1e3", "1000"}, {"+7", "7"}, {"20000", "20000"}, {"0x10", "16"}})
	{
		CAPTURE(given);
		std::string text = given;
		CHECK(Validate(v, text) == "");
		CHECK(text == rewritten); // "012" is twelve, as it always was (CLI11 alone would read octal 10)
	}
	for (const std::string bad : {"many", "", "1.5", "0", "20001", "-3", "nan", "inf", "1e400", "12abc"})
	{
		CAPTURE(bad);
		std::string text = bad;
		CHECK(Validate(v, text) == "needs a whole number from 1 to 20000, got '" + bad + "'");
	}
	// Up to 1e10 (the long run's steps), exactly.
	std::string big = "1e10";
	CHECK(Validate(b2a::demo::WholeNumber(1, 1e10), big) == "");
	CHECK(big == "10000000000");
}

TEST_CASE("RealNumber: the double strtod reads, bit for bit, through CLI11's own conversion")
{
	// CLI11 2.1 converts through long double; a decimal rounded twice can land one ulp off
	// strtod (about one in 8000 random decimals: the five after the demos' own values are such,
	// found by comparing strtod with (double) strtold). The validator hands CLI11 an exact
	// hexadecimal literal instead: every value below must come out as strtod's double.
	std::mt19937_64 rng(7);
	std::vector<std::string> texts = {"0.11", "0.32", "0.3", "1e-3", "99.99999999999999", "0.1000000000000000055511151231257827",
	                                  "52.807321022", "94.15631031729", "44.46369542439", "93.393923422636", "19.728491"};
	for (int i = 0; i < 2000; ++i)
	{
		char text[40];
		std::snprintf(text, sizeof text, "%.*g", 1 + int(rng() % 19), std::ldexp(double(rng() >> 11), -53) * 100.0);
		texts.push_back(text);
	}
	int checked = 0;
	for (const std::string& given : texts)
	{
		CAPTURE(given);
		CLI::App app;
		double value = -1.0;
		app.add_option("--x", value)->transform(b2a::demo::RealNumber(0.0, 100.0));
		std::vector<std::string> args = {"--x", given};
		std::reverse(args.begin(), args.end()); // CLI11 takes the arguments last first
		REQUIRE_NOTHROW(app.parse(args));
		CHECK(value == std::strtod(given.c_str(), nullptr));
		++checked;
	}
	CHECK(checked == 2011);
	for (const std::string bad : {"nan", "inf", "-1", "100.5", "x", "", "1,5"})
	{
		CAPTURE(bad);
		std::string text = bad;
		CHECK(Validate(b2a::demo::RealNumber(0.0, 100.0), text) == "needs a number from 0 to 100, got '" + bad + "'");
	}
}

TEST_CASE("UnsignedInteger, OneOf and ListOf: seeds, names and comma-separated lists")
{
	std::string seed = "18446744073709551615";
	CHECK(Validate(b2a::demo::UnsignedInteger(), seed) == "");
	CHECK(seed == "18446744073709551615");
	seed = "007";
	CHECK(Validate(b2a::demo::UnsignedInteger(), seed) == "");
	CHECK(seed == "7");
	for (const std::string bad : {"18446744073709551616", "-1", "1.5", "", "1e3"})
	{
		CAPTURE(bad);
		std::string text = bad;
		CHECK(Validate(b2a::demo::UnsignedInteger(), text) == "needs a whole number from 0 to 18446744073709551615, got '" + bad + "'");
	}

	const CLI::Validator scenes = b2a::demo::OneOf({"packing", "hopper"});
	std::string name = "hopper";
	CHECK(Validate(scenes, name) == "");
	name = "Hopper";
	CHECK(Validate(scenes, name) == "needs one of packing, hopper, got 'Hopper'");

	const CLI::Validator list = b2a::demo::ListOf(b2a::demo::WholeNumber(10, 1e6));
	std::string counts = "1000,040,2e3";
	CHECK(Validate(list, counts) == "");
	CHECK(counts == "1000,40,2000");
	for (const auto& [bad, message] : std::vector<std::pair<std::string, std::string>>{
		     {"1000,,4000", "item 2 of '1000,,4000' needs a whole number from 10 to 1e+06, got ''"},
		     {"1000,", "item 2 of '1000,' needs a whole number from 10 to 1e+06, got ''"},
		     {"", "item 1 of '' needs a whole number from 10 to 1e+06, got ''"},
		     {"250,12.5", "item 2 of '250,12.5' needs a whole number from 10 to 1e+06, got '12.5'"}})
	{
		CAPTURE(bad);
		std::string text = bad;
		CHECK(Validate(list, text) == message);
	}
}

TEST_CASE("CommandLine: quick defaults, given values, the last of repeated options, lists and the help")
{
	int particles = 0;
	double duration = 0.0, width = 12.0;
	std::vector<double> outlets;
	auto make = [&](CommandLine& cli) {
		cli.Add("--particles", particles, 900, 160, "N", "number of particles (default 900, quick 160)",
		        b2a::demo::WholeNumber(1, 20000));
		cli.Add("--duration", duration, 0.6, 0.3, "T", "seconds at most (default 0.6, quick 0.3)", b2a::demo::RealNumber(0.01, 100));
		cli.Add("--width", width, "K", "outlet width (default 12)", b2a::demo::RealNumber(0.5, 39));
		cli.Add("--outlets", outlets, {6, 8, 10}, {4, 6}, "D,D,...", "outlet widths (default 6,8,10; quick 4,6)",
		        b2a::demo::RealNumber(1, 39));
	};
	{
		CommandLine cli("b2a_test", "b2a_test: a program.\n");
		make(cli);
		const DemoOptions o = ParseArgs(cli, {});
		CHECK(!o.quick);
		CHECK(o.seed == 1);
		CHECK(o.name == "b2a_test");
		CHECK(std::filesystem::is_directory(o.out));
		CHECK(particles == 900);
		CHECK(duration == 0.6);
		CHECK(width == 12.0);
		CHECK(outlets == std::vector<double>{6, 8, 10});

		// The help: the program's text, the usage line, every option with its value's name and
		// its description, the common options in a group of their own.
		const std::string help = cli.App().help();
		CHECK(help.rfind("b2a_test: a program.\n\nUsage: b2a_test [OPTIONS]\n\nOptions:\n", 0) == 0);
		for (const char* line : {"  --particles N         number of particles (default 900, quick 160)\n",
		                         "  --outlets D,D,...     outlet widths (default 6,8,10; quick 4,6)\n", "\nCommon options:\n",
		                         "  --out DIR             output folder", "  --seed N              random seed (default 1)\n",
		                         "  --quick               reduced run for CI, under a minute\n", "  -h,--help             this text"})
		{
			CAPTURE(line);
			CHECK(help.find(line) != std::string::npos);
		}
		CHECK(help.find("\n\n\n") == std::string::npos);
	}
	{
		CommandLine cli("b2a_test", "");
		make(cli);
		const DemoOptions o = ParseArgs(cli, {"--quick", "--seed", "42"});
		CHECK(o.quick);
		CHECK(o.seed == 42);
		CHECK(particles == 160);
		CHECK(duration == 0.3);
		CHECK(outlets == std::vector<double>{4, 6});
	}
	{
		CommandLine cli("b2a_test", "");
		make(cli);
		ParseArgs(cli, {"--particles", "5", "--quick", "--particles=7", "--outlets", "4,5.5", "--duration", "0.11", "--width", "2"});
		CHECK(particles == 7); // given values win over the quick defaults; the last one counts
		CHECK(duration == std::strtod("0.11", nullptr));
		CHECK(width == 2.0);
		CHECK(outlets == std::vector<double>{4, 5.5});
	}
}

#ifdef B2A_DEMO_HOPPER
#include <fstream>
#include <iterator>
#include <sys/wait.h>

namespace
{
// Run `exe args`; returns the exit status and what it wrote on stderr.
int RunForError(const std::string& exe, const std::string& args, std::string& err)
{
	const std::string errPath = "demo_out/command_line_stderr.txt";
	std::filesystem::create_directories("demo_out");
	const int status = std::system(("\"" + exe + "\" " + args + " > /dev/null 2> " + errPath).c_str());
	std::ifstream f(errPath);
	err.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
} // namespace

TEST_CASE("every demo and benchmark rejects a bad value with exit status 2 and a message naming the option and the value")
{
	struct Case
	{
		const char* exe;
		const char* args;
		const char* message; // the whole first line of stderr
	};
	std::vector<Case> cases = {
		{B2A_DEMO_HOPPER, "--particles many",
		 "b2a_demo_hopper: --particles: needs a whole number from 1 to 20000, got 'many' (see --help)"},
		{B2A_DEMO_HOPPER, "--threads 1.5", "b2a_demo_hopper: --threads: needs a whole number from 1 to 256, got '1.5' (see --help)"},
		{B2A_DEMO_HOPPER, "--snapshots 0,x",
		 "b2a_demo_hopper: --snapshots: item 2 of '0,x' needs a number from 0 to 100, got 'x' (see --help)"},
		{B2A_DEMO_HOPPER, "--bogus", "b2a_demo_hopper: The following argument was not expected: --bogus (see --help)"},
		{B2A_DEMO_PACKING, "--duration nan", "b2a_demo_packing: --duration: needs a number from 0.01 to 100, got 'nan' (see --help)"},
		{B2A_DEMO_PACKING, "--seed -1",
		 "b2a_demo_packing: --seed: needs a whole number from 0 to 18446744073709551615, got '-1' (see --help)"},
		{B2A_DEMO_BEVERLOO, "--outlets 4,6,40",
		 "b2a_demo_beverloo: --outlets: item 3 of '4,6,40' needs a number from 1 to 39, got '40' (see --help)"},
		{B2A_DEMO_LONGRUN, "--steps 0", "b2a_demo_longrun: --steps: needs a whole number from 1 to 1e+10, got '0' (see --help)"},
		{B2A_DEMO_LONGRUN, "--settle", "b2a_demo_longrun: --settle: 1 required T missing (see --help)"},
		{B2A_DEMO_CONTACTS, "--quick extra", "b2a_demo_contacts: The following argument was not expected: extra (see --help)"},
		{B2A_DEMO_COLLISION, "--seed x",
		 "b2a_demo_collision: --seed: needs a whole number from 0 to 18446744073709551615, got 'x' (see --help)"},
#ifdef B2A_BENCH_SCENES
		{B2A_BENCH_SCENES, "--scenes packing,bogus",
		 "b2a_bench_scenes: --scenes: item 2 of 'packing,bogus' needs one of packing, hopper, layer, mixed, got 'bogus' (see --help)"},
		{B2A_BENCH_SCENES, "--counts 12.5",
		 "b2a_bench_scenes: --counts: item 1 of '12.5' needs a whole number from 10 to 1e+06, got '12.5' (see --help)"},
#endif
#ifdef B2A_BENCH_PAIRS
		{B2A_BENCH_PAIRS, "--repeats 0", "b2a_bench_pairs: --repeats: needs a whole number from 1 to 1000, got '0' (see --help)"},
#endif
#ifdef B2A_STRESS
		{B2A_STRESS, "--pool 8", "b2a_stress: --pool: needs a whole number from 16 to 1e+06, got '8' (see --help)"},
#endif
	};
	for (const Case& c : cases)
	{
		CAPTURE(c.args);
		std::string err;
		CHECK(RunForError(c.exe, "--out demo_out/command_line_bad " + std::string(c.args), err) == 2);
		CHECK(err.substr(0, err.find('\n')) == c.message);
	}
}
#endif

// b2analytic tests: the plain scene in a program that links Box2D alone (no adapter).
#include "../PlainScene.h"

#include <CLI/CLI.hpp>

#include <cstdio>

int main(int argc, char** argv)
{
	int steps = 240;
	CLI::App app("b2a_plain_scene: the plain Box2D scene of the bit-identity test, stepped without the adapter;\n"
	             "prints every body's final position, angle and velocity in hexadecimal floats.\n",
	             "b2a_plain_scene");
	app.set_help_flag("-h,--help", "this text");
	app.add_option("STEPS", steps, "steps to run, 0 to 1000000 (default 240)")->type_name("")->check(CLI::Range(0, 1000000).description(""));
	try
	{
		app.parse(argc, argv);
	}
	catch (const CLI::CallForHelp&)
	{
		std::fputs(app.help().c_str(), stdout);
		return 0;
	}
	catch (const CLI::ParseError& e)
	{
		std::fprintf(stderr, "b2a_plain_scene: %s (see --help)\n", e.what());
		return 2;
	}
	std::fputs(b2a::test::RunPlainScene(steps).c_str(), stdout);
	return 0;
}

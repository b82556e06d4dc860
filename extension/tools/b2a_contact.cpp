// b2analytic: b2a_contact, contact detection from the command line (JSON Lines in and out).
#include "ContactTool.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
	std::string path = "-";
	CLI::App app(b2a::tool::ContactToolSummary(), "b2a_contact");
	app.add_option("FILE", path, "the requests, one JSON object a line (default -: standard input)")->type_name("");
	app.set_help_flag("-h,--help", "this text");
	app.footer(b2a::tool::ContactToolHelp());
	try
	{
		app.parse(argc, argv);
	}
	catch (const CLI::CallForHelp&)
	{
		std::string help = app.help();
		help.erase(help.find_last_not_of('\n') + 1); // no blank line at the end
		std::printf("%s\n", help.c_str());
		return 0;
	}
	catch (const CLI::ParseError& e)
	{
		std::fprintf(stderr, "b2a_contact: %s (see --help)\n", e.what());
		return 2;
	}
	std::ifstream file;
	std::istream* in = &std::cin;
	if (path != "-")
	{
		file.open(path);
		if (!file)
		{
			std::fprintf(stderr, "b2a_contact: cannot read '%s'\n", path.c_str());
			return 2;
		}
		in = &file;
	}
	bool allOk = true;
	std::string line;
	while (std::getline(*in, line))
	{
		if (line.find_first_not_of(" \t\r") == std::string::npos)
			continue;
		bool ok = false;
		const std::string answer = b2a::tool::AnswerContactRequest(line, ok);
		std::fwrite(answer.data(), 1, answer.size(), stdout);
		std::fputc('\n', stdout);
		allOk = allOk && ok;
	}
	if (in->bad())
	{
		std::fprintf(stderr, "b2a_contact: read error on '%s'\n", path == "-" ? "stdin" : path.c_str());
		return 2;
	}
	return allOk ? 0 : 1;
}

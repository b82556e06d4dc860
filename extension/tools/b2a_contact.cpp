// b2analytic: b2a_contact, contact detection from the command line (JSON Lines in and out).
#include "ContactTool.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
	// Arguments are few enough to read by hand: [--help | -h] [FILE | -].
	std::string path;
	for (int i = 1; i < argc; ++i)
	{
		const std::string arg = argv[i];
		if (arg == "--help" || arg == "-h")
		{
			std::fputs(b2a::tool::ContactToolHelp(), stdout);
			return 0;
		}
		if (arg.size() > 1 && arg[0] == '-')
		{
			std::fprintf(stderr, "b2a_contact: unknown option '%s' (see --help)\n", arg.c_str());
			return 2;
		}
		if (!path.empty())
		{
			std::fprintf(stderr, "b2a_contact: more than one input file ('%s', '%s'; see --help)\n", path.c_str(), arg.c_str());
			return 2;
		}
		path = arg;
	}
	std::ifstream file;
	std::istream* in = &std::cin;
	if (!path.empty() && path != "-")
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
		std::fprintf(stderr, "b2a_contact: read error on '%s'\n", path.empty() ? "stdin" : path.c_str());
		return 2;
	}
	return allOk ? 0 : 1;
}

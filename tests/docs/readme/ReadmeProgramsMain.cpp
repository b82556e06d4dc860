// b2a_readme_programs README SOURCE_DIR OUT_DIR: writes the README's C++ programs into OUT_DIR as
// a CMake project that finds the installed b2analytic package, as a user would build them. A
// complete block becomes readme_line<N>.cpp; a block marked as a fragment of a file in the tree
// must appear in that file, line by line, and the file is built instead. OUT_DIR/programs.txt
// lists the executables to run. Exits 1, naming the block, where a fragment's file is missing
// or does not hold it, or where the README has no C++ block at all.
#include "MarkdownBlocks.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace b2a::test;

int main(int argc, char** argv)
{
	if (argc != 4)
	{
		std::fprintf(stderr, "usage: b2a_readme_programs README SOURCE_DIR OUT_DIR\n");
		return 2;
	}
	const fs::path readme = argv[1], root = argv[2], out = argv[3];
	if (!fs::exists(readme))
	{
		std::fprintf(stderr, "b2a_readme_programs: no file '%s'\n", argv[1]);
		return 1;
	}
	fs::create_directories(out);
	std::string cmake = "# Generated from README.md by b2a_readme_programs.\ncmake_minimum_required(VERSION 3.20)\n"
	                    "project(b2analytic_readme LANGUAGES CXX)\nfind_package(b2analytic REQUIRED)\n";
	std::string programs;
	int failures = 0, count = 0;
	for (const CodeBlock& b : CodeBlocks(ReadText(readme)))
	{
		if (b.language != "cpp" && b.language != "c++")
			continue;
		++count;
		std::string name, source;
		if (b.fragmentOf.empty())
		{
			name = "readme_line" + std::to_string(b.line);
			source = name + ".cpp";
			std::ofstream(out / source) << b.text;
		}
		else
		{
			const fs::path file = root / b.fragmentOf;
			std::string missing;
			if (!fs::exists(file))
			{
				std::fprintf(stderr, "README line %d: the fragment's file '%s' is not in the tree\n", b.line, b.fragmentOf.c_str());
				++failures;
				continue;
			}
			if (!FragmentOf(b.text, ReadText(file), missing))
			{
				std::fprintf(stderr, "README line %d: '%s' is not in %s\n", b.line, missing.c_str(), b.fragmentOf.c_str());
				++failures;
				continue;
			}
			name = "example_" + file.stem().string();
			source = fs::absolute(file).generic_string();
		}
		cmake += "add_executable(" + name + " \"" + source + "\")\ntarget_link_libraries(" + name + " PRIVATE b2analytic::b2analytic)\n";
		programs += name + "\n";
	}
	if (count == 0)
	{
		std::fprintf(stderr, "b2a_readme_programs: no C++ block in '%s'\n", argv[1]);
		return 1;
	}
	std::ofstream(out / "CMakeLists.txt") << cmake;
	std::ofstream(out / "programs.txt") << programs;
	std::printf("b2a_readme_programs: %d C++ blocks, %d programs written to %s\n", count, count - failures, out.generic_string().c_str());
	return failures == 0 ? 0 : 1;
}

// b2analytic documentation tests: code blocks and fragment markers of Markdown pages, and the
// README's own blocks.
#include <doctest/doctest.h>

#include "MarkdownBlocks.h"

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace b2a::test;

TEST_CASE("CodeBlocks finds fenced blocks, their language and fragment markers")
{
	const std::string md = "Text\n"
	                       "```cpp\nint main() {}\n```\n"
	                       "<!-- fragment of demos/examples/x.cpp -->\n"
	                       "~~~~ cpp title\nf();\n\n```\ng();\n~~~~\n"
	                       "<!-- fragment of y.cpp -->\nmore text\n"
	                       "```sh\nls\n```\n";
	const std::vector<CodeBlock> b = CodeBlocks(md);
	REQUIRE(b.size() == 3);
	CHECK(b[0].line == 2);
	CHECK(b[0].language == "cpp");
	CHECK(b[0].text == "int main() {}\n");
	CHECK(b[0].fragmentOf.empty());
	CHECK(b[1].language == "cpp");
	CHECK(b[1].fragmentOf == "demos/examples/x.cpp");
	CHECK(b[1].text == "f();\n\n```\ng();\n"); // a shorter fence inside does not close it
	CHECK(b[2].language == "sh");
	CHECK(b[2].fragmentOf.empty()); // the marker was not right before this fence
}

TEST_CASE("FragmentOf wants every line in order, indentation aside")
{
	const std::string program = "int main()\n{\n\tint a = 1;\n\tint b = 2;\n\treturn a + b;\n}\n";
	std::string missing;
	CHECK(FragmentOf("int a = 1;\n\nint b = 2;\n", program, missing));
	CHECK_FALSE(FragmentOf("int b = 2;\nint a = 1;\n", program, missing));
	CHECK(missing == "int a = 1;");
	CHECK_FALSE(FragmentOf("int c = 3;\n", program, missing));
	CHECK(missing == "int c = 3;");
}

TEST_CASE("The README's C++ blocks are complete programs or marked fragments of files in the tree")
{
	const std::filesystem::path root = B2A_SOURCE_DIR;
	std::ifstream in(root / "README.md");
	std::ostringstream text;
	text << in.rdbuf();
	int programs = 0, fragments = 0;
	for (const CodeBlock& b : CodeBlocks(text.str()))
	{
		if (b.language != "cpp" && b.language != "c++")
			continue;
		INFO("README.md line " << b.line);
		if (b.fragmentOf.empty())
		{
			// Built and run by the install test; here only that it is a program at all.
			CHECK(b.text.find("int main(") != std::string::npos);
			++programs;
			continue;
		}
		std::ifstream file(root / b.fragmentOf);
		REQUIRE_MESSAGE(file.good(), b.fragmentOf);
		std::ostringstream program;
		program << file.rdbuf();
		std::string missing;
		CHECK_MESSAGE(FragmentOf(b.text, program.str(), missing), "not in " << b.fragmentOf << ": " << missing);
		++fragments;
	}
	CHECK(programs >= 1);
	CHECK(programs + fragments >= 2);
}

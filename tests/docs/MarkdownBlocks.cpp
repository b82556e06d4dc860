// b2analytic documentation tests: fenced code blocks of a Markdown page.
#include "MarkdownBlocks.h"

#include <fstream>
#include <sstream>

namespace b2a::test
{

namespace
{
std::string Trimmed(const std::string& s)
{
	const size_t b = s.find_first_not_of(" \t\r");
	if (b == std::string::npos)
		return "";
	return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// The fence ("```" or "~~~", possibly longer) that opens a block on this line, or empty.
std::string Fence(const std::string& line)
{
	const size_t i = line.find_first_not_of(' ');
	if (i == std::string::npos || i > 3 || (line[i] != '`' && line[i] != '~'))
		return "";
	const size_t end = line.find_first_not_of(line[i], i);
	const size_t n = (end == std::string::npos ? line.size() : end) - i;
	return n >= 3 ? std::string(n, line[i]) : "";
}
} // namespace

std::string ReadText(const std::filesystem::path& path)
{
	std::ifstream in(path, std::ios::binary);
	std::ostringstream s;
	s << in.rdbuf();
	return s.str();
}

std::vector<CodeBlock> CodeBlocks(const std::string& markdown)
{
	std::vector<CodeBlock> blocks;
	std::istringstream in(markdown);
	std::string line, fence, lastText;
	CodeBlock block;
	for (int number = 1; std::getline(in, line); ++number)
	{
		if (fence.empty())
		{
			fence = Fence(line);
			if (fence.empty())
			{
				if (!Trimmed(line).empty())
					lastText = Trimmed(line);
				continue;
			}
			block = CodeBlock();
			block.line = number;
			block.language = Trimmed(Trimmed(line).substr(fence.size()));
			block.language = block.language.substr(0, block.language.find(' '));
			const std::string marker = "<!-- fragment of ";
			if (lastText.compare(0, marker.size(), marker) == 0 && lastText.size() > marker.size() + 4 &&
			    lastText.compare(lastText.size() - 4, 4, " -->") == 0)
				block.fragmentOf = Trimmed(lastText.substr(marker.size(), lastText.size() - marker.size() - 4));
			lastText.clear();
		}
		else if (Trimmed(line).compare(0, fence.size(), fence) == 0 && Trimmed(line).find_first_not_of(fence[0]) == std::string::npos)
		{
			blocks.push_back(block);
			fence.clear();
		}
		else
			block.text += line + "\n";
	}
	return blocks;
}

bool FragmentOf(const std::string& fragment, const std::string& program, std::string& missing)
{
	std::istringstream f(fragment), p(program);
	std::string want, have;
	while (std::getline(f, want))
	{
		want = Trimmed(want);
		if (want.empty())
			continue;
		bool found = false;
		while (!found && std::getline(p, have))
			found = Trimmed(have) == want;
		if (!found)
		{
			missing = want;
			return false;
		}
	}
	return true;
}

} // namespace b2a::test

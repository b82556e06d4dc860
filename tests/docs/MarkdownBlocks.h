// b2analytic documentation tests: the fenced code blocks of a Markdown page, for building the
// README's programs as a user would.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace b2a::test
{

/// The whole text of a file (empty when it cannot be read).
std::string ReadText(const std::filesystem::path& path);

/// A fenced code block of a Markdown page.
struct CodeBlock
{
	int line = 0;           ///< 1-based line of the opening fence
	std::string language;   ///< the fence's info word ("cpp", "sh", or empty)
	std::string text;       ///< the block's lines, each ending in '\n'
	/// The file (relative to the repository) this block is a fragment of, from a line
	/// `<!-- fragment of PATH -->` right before the fence; empty for a complete program.
	std::string fragmentOf;
};

/// The fenced code blocks (``` or ~~~) of a Markdown page, in order.
std::vector<CodeBlock> CodeBlocks(const std::string& markdown);

/// Whether every non-blank line of `fragment` appears in `program` in the same order, each
/// compared without its leading and trailing blanks (the program may indent them). Where not,
/// `missing` gets the first line that was not found.
bool FragmentOf(const std::string& fragment, const std::string& program, std::string& missing);

} // namespace b2a::test

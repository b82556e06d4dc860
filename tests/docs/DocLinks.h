// b2analytic documentation tests: the links of the Markdown files, and the references to docs/
// pages from source files, must point at files (and sections) that are in the tree.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace b2a::test
{

/// A link target found in a Markdown text.
struct MarkdownLink
{
	int line = 0;       ///< 1-based line of the link
	std::string target; ///< the target as written, e.g. "docs/method.md#frames"
};

/// GitHub's anchor of a heading: lower case, letters, digits, '-' and '_' kept, spaces turned
/// into '-', everything else (punctuation, symbols, backticks) dropped.
std::string HeadingSlug(const std::string& heading);

/// The texts of a Markdown document's ATX headings ("## Frames" gives "Frames"), outside fenced
/// code blocks.
std::vector<std::string> Headings(const std::string& markdown);

/// The anchors a Markdown document defines: each heading's slug, repeated ones numbered "-1",
/// "-2", ... as GitHub numbers them.
std::vector<std::string> Anchors(const std::string& markdown);

/// Inline link and image targets `[text](target)` outside fenced code blocks and code spans,
/// without an optional title ("target \"title\"").
std::vector<MarkdownLink> Links(const std::string& markdown);

/// Problems with the relative links of one Markdown file under `root`: a target that does not
/// exist, that lies outside `root`, that is absolute, or whose #anchor names no heading of the
/// target page. External links (with a scheme, e.g. https:) are not checked. Empty: all resolve.
std::vector<std::string> BrokenLinks(const std::filesystem::path& root, const std::filesystem::path& file);

/// Problems with the mentions of docs/<page>.md in one source file: the page must exist under
/// `root`, and each quoted section title that follows it (docs/method.md, "Frames" or
/// docs/method.md ("Frames", "Grid method")) must be one of its headings.
std::vector<std::string> BrokenDocReferences(const std::filesystem::path& root, const std::filesystem::path& file);

/// Files under `root` whose names end with one of `extensions` (".md", ".h", ...), skipping
/// hidden folders, build folders (those holding a CMakeCache.txt) and "out".
std::vector<std::filesystem::path> TreeFiles(const std::filesystem::path& root, const std::vector<std::string>& extensions);

} // namespace b2a::test

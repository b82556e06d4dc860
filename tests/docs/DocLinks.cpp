// b2analytic documentation tests: Markdown links and docs/ references.
#include "DocLinks.h"
#include "MarkdownBlocks.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

namespace b2a::test
{

namespace fs = std::filesystem;

namespace
{
std::vector<std::string> Lines(const std::string& text)
{
	std::vector<std::string> lines;
	std::istringstream in(text);
	for (std::string line; std::getline(in, line);)
		lines.push_back(line);
	return lines;
}

bool IsFence(const std::string& line)
{
	const size_t i = line.find_first_not_of(' ');
	return i != std::string::npos && i < 4 && (line.compare(i, 3, "```") == 0 || line.compare(i, 3, "~~~") == 0);
}

// The line with its code spans (`...`) blanked, so that links shown as code are not links.
std::string WithoutCodeSpans(const std::string& line)
{
	std::string out = line;
	size_t open = out.find('`');
	while (open != std::string::npos)
	{
		size_t ticks = out.find_first_not_of('`', open);
		if (ticks == std::string::npos)
			break;
		const std::string fence(ticks - open, '`');
		const size_t close = out.find(fence, ticks);
		if (close == std::string::npos)
			break;
		std::fill(out.begin() + long(open), out.begin() + long(close + fence.size()), ' ');
		open = out.find('`', close + fence.size());
	}
	return out;
}

// The Unicode code point of the UTF-8 sequence at text[i], and its length (1 for bad bytes).
char32_t CodePoint(const std::string& text, size_t i, size_t& length)
{
	const unsigned char c = static_cast<unsigned char>(text[i]);
	length = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
	if (i + length > text.size() || c < 0xC0)
	{
		length = 1;
		return c;
	}
	char32_t cp = length == 2 ? c & 0x1F : length == 3 ? c & 0x0F : c & 0x07;
	for (size_t k = 1; k < length; ++k)
		cp = (cp << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
	return cp;
}

// GitHub keeps letters, marks, numbers, connector punctuation, spaces and hyphens. Beyond ASCII
// this keeps everything but the punctuation and symbol blocks that headings here use (dashes,
// quotes, arrows, mathematical operators, ×, ÷, the Latin-1 signs), and keeps the super- and
// subscript digits, which are numbers.
bool KeptInSlug(char32_t cp)
{
	if (cp >= 0x2070 && cp <= 0x209F)
		return true;
	if (cp >= 0x2000 && cp <= 0x2BFF)
		return false;
	if ((cp >= 0x00A0 && cp <= 0x00BF) || cp == 0x00D7 || cp == 0x00F7)
		return false;
	return true;
}

std::string Trim(const std::string& s)
{
	const size_t b = s.find_first_not_of(" \t");
	if (b == std::string::npos)
		return "";
	const size_t e = s.find_last_not_of(" \t");
	return s.substr(b, e - b + 1);
}

bool HasScheme(const std::string& target)
{
	const size_t colon = target.find(':');
	if (colon == std::string::npos || colon == 0)
		return false;
	for (size_t i = 0; i < colon; ++i)
		if (!std::isalnum(static_cast<unsigned char>(target[i])) && target[i] != '+' && target[i] != '-' && target[i] != '.')
			return false;
	return true;
}

// Whether the path, normalised and with its links resolved, lies inside `root`.
bool InsideRoot(const fs::path& root, const fs::path& path)
{
	const fs::path r = fs::weakly_canonical(root), p = fs::weakly_canonical(path);
	auto ri = r.begin(), pi = p.begin();
	for (; ri != r.end(); ++ri, ++pi)
		if (pi == p.end() || *ri != *pi)
			return false;
	return true;
}

std::string Where(const fs::path& root, const fs::path& file, int line)
{
	return fs::relative(file, root).generic_string() + ":" + std::to_string(line) + ": ";
}
} // namespace

std::string HeadingSlug(const std::string& heading)
{
	std::string slug;
	for (size_t i = 0; i < heading.size();)
	{
		size_t length = 1;
		const char32_t cp = CodePoint(heading, i, length);
		if (cp < 0x80)
		{
			const char c = char(cp);
			if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')
				slug += char(std::tolower(static_cast<unsigned char>(c)));
			else if (c == ' ')
				slug += '-';
		}
		else if (KeptInSlug(cp))
			slug += heading.substr(i, length);
		i += length;
	}
	return slug;
}

std::vector<std::string> Headings(const std::string& markdown)
{
	std::vector<std::string> headings;
	bool fenced = false;
	for (const std::string& line : Lines(markdown))
	{
		if (IsFence(line))
		{
			fenced = !fenced;
			continue;
		}
		if (fenced)
			continue;
		const size_t hashes = line.find_first_not_of('#');
		if (hashes == 0 || hashes > 6 || hashes == std::string::npos || line[hashes] != ' ')
			continue;
		std::string text = Trim(line.substr(hashes));
		while (!text.empty() && text.back() == '#') // closing hashes
			text = Trim(text.substr(0, text.size() - 1));
		headings.push_back(text);
	}
	return headings;
}

std::vector<std::string> Anchors(const std::string& markdown)
{
	std::vector<std::string> anchors;
	std::map<std::string, int> seen;
	for (const std::string& heading : Headings(markdown))
	{
		const std::string slug = HeadingSlug(heading);
		const int n = seen[slug]++;
		anchors.push_back(n == 0 ? slug : slug + "-" + std::to_string(n));
	}
	return anchors;
}

std::vector<MarkdownLink> Links(const std::string& markdown)
{
	std::vector<MarkdownLink> links;
	bool fenced = false;
	int number = 0;
	for (const std::string& raw : Lines(markdown))
	{
		++number;
		if (IsFence(raw))
		{
			fenced = !fenced;
			continue;
		}
		if (fenced)
			continue;
		const std::string line = WithoutCodeSpans(raw);
		for (size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2))
		{
			const size_t close = line.find(')', at + 2);
			if (close == std::string::npos)
				break;
			std::string target = Trim(line.substr(at + 2, close - at - 2));
			const size_t space = target.find(' ');
			if (space != std::string::npos) // a title follows
				target = target.substr(0, space);
			if (target.size() >= 2 && target.front() == '<' && target.back() == '>')
				target = target.substr(1, target.size() - 2);
			links.push_back({number, target});
		}
	}
	return links;
}

std::vector<std::string> BrokenLinks(const fs::path& root, const fs::path& file)
{
	std::vector<std::string> problems;
	const std::string text = ReadText(file);
	for (const MarkdownLink& link : Links(text))
	{
		const std::string where = Where(root, file, link.line);
		if (link.target.empty())
		{
			problems.push_back(where + "empty link target");
			continue;
		}
		if (HasScheme(link.target))
			continue;
		const size_t hash = link.target.find('#');
		const std::string path = link.target.substr(0, hash);
		const std::string anchor = hash == std::string::npos ? "" : link.target.substr(hash + 1);
		if (!path.empty() && path.front() == '/')
		{
			problems.push_back(where + "'" + link.target + "' is absolute; links in the tree are relative");
			continue;
		}
		const fs::path target = path.empty() ? file : (file.parent_path() / path).lexically_normal();
		if (!InsideRoot(root, target))
		{
			problems.push_back(where + "'" + link.target + "' points outside the repository");
			continue;
		}
		if (!fs::exists(target))
		{
			problems.push_back(where + "'" + link.target + "': no such file in the tree");
			continue;
		}
		if (anchor.empty())
			continue;
		if (target.extension() != ".md")
		{
			problems.push_back(where + "'" + link.target + "': an anchor into a file that is not Markdown");
			continue;
		}
		const std::vector<std::string> anchors = Anchors(ReadText(target));
		if (std::find(anchors.begin(), anchors.end(), anchor) == anchors.end())
			problems.push_back(where + "'" + link.target + "': no heading with the anchor '" + anchor + "'");
	}
	return problems;
}

std::vector<std::string> BrokenDocReferences(const fs::path& root, const fs::path& file)
{
	std::vector<std::string> problems;
	const std::vector<std::string> lines = Lines(ReadText(file));
	for (size_t n = 0; n < lines.size(); ++n)
	{
		const std::string& line = lines[n];
		for (size_t at = line.find("docs/"); at != std::string::npos; at = line.find("docs/", at + 5))
		{
			if (at > 0 && (std::isalnum(static_cast<unsigned char>(line[at - 1])) || line[at - 1] == '_'))
				continue; // "mydocs/": another folder
			size_t end = at + 5;
			while (end < line.size() &&
			       (std::isalnum(static_cast<unsigned char>(line[end])) || line[end] == '_' || line[end] == '-' || line[end] == '.'))
				++end;
			std::string page = line.substr(at, end - at);
			while (!page.empty() && page.back() == '.') // a sentence's full stop
				page.pop_back();
			if (page.size() < 4 || page.compare(page.size() - 3, 3, ".md") != 0)
				continue; // the folder itself, or a file other than a page
			const std::string where = Where(root, file, int(n + 1));
			const fs::path target = root / page;
			if (!fs::exists(target))
			{
				problems.push_back(where + "'" + page + "': no such page in the tree");
				continue;
			}
			// Section titles: docs/x.md, "Title" or docs/x.md ("Title", "Title").
			size_t i = at + page.size();
			while (i < line.size() && (line[i] == ',' || line[i] == ' ' || line[i] == '('))
				++i;
			const std::vector<std::string> headings = Headings(ReadText(target));
			while (i < line.size() && line[i] == '"')
			{
				const size_t close = line.find('"', i + 1);
				if (close == std::string::npos)
					break;
				const std::string title = line.substr(i + 1, close - i - 1);
				if (std::find(headings.begin(), headings.end(), title) == headings.end())
					problems.push_back(where + "'" + page + "' has no section \"" + title + "\"");
				i = close + 1;
				if (line.compare(i, 2, ", ") != 0 || i + 2 >= line.size() || line[i + 2] != '"')
					break;
				i += 2;
			}
		}
	}
	return problems;
}

std::vector<fs::path> TreeFiles(const fs::path& root, const std::vector<std::string>& extensions)
{
	std::vector<fs::path> files;
	for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it)
	{
		const fs::path& p = it->path();
		const std::string name = p.filename().string();
		if (it->is_directory())
		{
			if ((!name.empty() && name[0] == '.') || name == "out" || fs::exists(p / "CMakeCache.txt"))
				it.disable_recursion_pending();
			continue;
		}
		for (const std::string& e : extensions)
			if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0)
			{
				files.push_back(p);
				break;
			}
	}
	std::sort(files.begin(), files.end());
	return files;
}

} // namespace b2a::test

// b2analytic documentation tests: every relative link of the tree's Markdown files resolves
// (file and #anchor), and every docs/<page>.md that a source file names exists, with the
// sections it names. The checker is tested first on made-up pages with known answers.
#include <doctest/doctest.h>

#include "DocLinks.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using namespace b2a::test;

namespace
{
const fs::path kRoot = B2A_SOURCE_DIR;

void Write(const fs::path& path, const std::string& text)
{
	fs::create_directories(path.parent_path());
	std::ofstream(path) << text;
}

// A scratch tree of its own per test case (CTest runs the cases in parallel), removed at its end.
struct ScratchTree
{
	fs::path root;
	explicit ScratchTree(const std::string& name) : root(fs::temp_directory_path() / ("b2a_doc_links_" + name))
	{
		fs::remove_all(root);
		fs::create_directories(root);
	}
	~ScratchTree() { fs::remove_all(root); }
};
} // namespace

TEST_CASE("HeadingSlug gives GitHub's anchors")
{
	// GitHub: lower case; letters, digits, '-' and '_' kept; spaces to '-'; the rest dropped.
	CHECK(HeadingSlug("Frames") == "frames");
	CHECK(HeadingSlug("The paper's results") == "the-papers-results");
	CHECK(HeadingSlug("Box2D 2.4.1 facts that shape the adapter") == "box2d-241-facts-that-shape-the-adapter");
	CHECK(HeadingSlug("The min–max fallback") == "the-minmax-fallback");
	CHECK(HeadingSlug("`b2a_contact` reads JSON") == "b2a_contact-reads-json");
	CHECK(HeadingSlug("From a level to a contact") == "from-a-level-to-a-contact");
	CHECK(HeadingSlug("Level λ₀ and Q (g/s)") == "level-λ₀-and-q-gs");
}

TEST_CASE("Anchors number repeated headings, and skip code blocks")
{
	const std::string md = "# Notes\n\n## Runs\ntext\n## Runs\n```sh\n# not a heading\n```\n### Runs ###\n#nospace\n";
	const std::vector<std::string> a = Anchors(md);
	REQUIRE(a.size() == 4);
	CHECK(a[0] == "notes");
	CHECK(a[1] == "runs");
	CHECK(a[2] == "runs-1");
	CHECK(a[3] == "runs-2");
}

TEST_CASE("Links finds link and image targets outside code")
{
	const std::string md = "See [a](a.md) and ![pic](img/p.svg \"title\").\n"
	                       "`[not](code.md)` [b](b.md#part)\n"
	                       "```\n[fenced](f.md)\n```\n"
	                       "[web](https://example.org/x)\n";
	const std::vector<MarkdownLink> l = Links(md);
	REQUIRE(l.size() == 4);
	CHECK(l[0].target == "a.md");
	CHECK(l[0].line == 1);
	CHECK(l[1].target == "img/p.svg");
	CHECK(l[2].target == "b.md#part");
	CHECK(l[2].line == 2);
	CHECK(l[3].target == "https://example.org/x");
}

TEST_CASE("BrokenLinks reports each kind of broken link and accepts good ones")
{
	ScratchTree t("links");
	Write(t.root / "docs/page.md", "# Page\n## Part one\n");
	Write(t.root / "img/p.svg", "<svg/>");
	Write(t.root / "README.md", "[ok](docs/page.md) [ok](docs/page.md#part-one) ![ok](img/p.svg) [ok](#top) [ok](docs/)\n"
	                            "[web](https://example.org)\n"
	                            "# Top\n");
	CHECK(BrokenLinks(t.root, t.root / "README.md").empty());

	Write(t.root / "docs/bad.md", "[a](missing.md)\n"
	                              "[b](page.md#no-such-part)\n"
	                              "[c](../../outside.md)\n"
	                              "[d](/docs/page.md)\n"
	                              "[e](../img/p.svg#x)\n");
	const std::vector<std::string> p = BrokenLinks(t.root, t.root / "docs/bad.md");
	REQUIRE(p.size() == 5);
	CHECK(p[0].find("docs/bad.md:1: 'missing.md': no such file") == 0);
	CHECK(p[1].find("no heading with the anchor 'no-such-part'") != std::string::npos);
	CHECK(p[2].find("outside the repository") != std::string::npos);
	CHECK(p[3].find("is absolute") != std::string::npos);
	CHECK(p[4].find("not Markdown") != std::string::npos);
}

TEST_CASE("BrokenDocReferences checks the pages and sections source files name")
{
	ScratchTree t("references");
	Write(t.root / "docs/method.md", "# The method\n## Frames\n## Grid method\n");
	Write(t.root / "src/ok.h", "// see docs/method.md, \"Frames\"; docs/method.md (\"Frames\", \"Grid method\").\n"
	                           "// docs/method.md. And mydocs/x.md is another folder's, docs/ a folder.\n");
	CHECK(BrokenDocReferences(t.root, t.root / "src/ok.h").empty());
	Write(t.root / "src/bad.h", "// docs/gone.md\n// docs/method.md, \"Frame\"\n// docs/method.md (\"Frames\", \"Grid\")\n");
	const std::vector<std::string> p = BrokenDocReferences(t.root, t.root / "src/bad.h");
	REQUIRE(p.size() == 3);
	CHECK(p[0] == "src/bad.h:1: 'docs/gone.md': no such page in the tree");
	CHECK(p[1] == "src/bad.h:2: 'docs/method.md' has no section \"Frame\"");
	CHECK(p[2] == "src/bad.h:3: 'docs/method.md' has no section \"Grid\"");
}

TEST_CASE("Every relative link in the tree's Markdown files resolves")
{
	const std::vector<fs::path> files = TreeFiles(kRoot, {".md"});
	// The pages that must be there (so that the test cannot pass on an empty walk).
	for (const char* page : {"README.md", "docs/method.md", "docs/design.md", "docs/benchmarks.md"})
		CHECK_MESSAGE(std::find(files.begin(), files.end(), kRoot / page) != files.end(), page);
	for (const fs::path& file : files)
		for (const std::string& problem : BrokenLinks(kRoot, file))
			FAIL_CHECK(problem);
}

TEST_CASE("Every docs/ page and section named in a source file exists")
{
	const std::vector<fs::path> files =
		TreeFiles(kRoot, {".h", ".cpp", ".cmake", ".txt", ".sh", ".md", ".in", ".json"});
	CHECK(files.size() > 100);
	for (const fs::path& file : files)
	{
		if (file.parent_path() == kRoot / "tests/docs")
			continue; // this folder's made-up pages name missing ones on purpose
		for (const std::string& problem : BrokenDocReferences(kRoot, file))
			FAIL_CHECK(problem);
	}
}

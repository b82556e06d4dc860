// b2analytic tests: the b2a_contact tool, through its request handler and as a program.
#include "ContactTool.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

using nlohmann::json;
using b2a::tool::AnswerContactRequest;

namespace
{
json Ask(const std::string& line, bool expectOk = true)
{
	bool ok = false;
	const std::string answer = AnswerContactRequest(line, ok);
	INFO("request: " << line);
	INFO("answer: " << answer);
	CHECK(ok == expectOk);
	CHECK(answer.find('\n') == std::string::npos);
	return json::parse(answer);
}

// Run the built program with a shell command line; returns its exit status and fills `out`
// (and `err` with what it wrote on stderr, when given).
int RunTool(const std::string& args, const std::string& input, std::string& out, std::string* err = nullptr)
{
	// Scratch files in the system's temporary folder, named after this process.
	const std::string base = (std::filesystem::temp_directory_path() / ("b2a_tool_test_" + std::to_string(getpid()))).string();
	const std::string inPath = base + "_input.jsonl", outPath = base + "_output.jsonl", errPath = base + "_error.txt";
	{
		std::ofstream f(inPath);
		f << input;
	}
	const std::string cmd =
		std::string("\"") + B2A_CONTACT_EXE + "\" " + args + " < " + inPath + " > " + outPath + " 2> " + errPath;
	const int status = std::system(cmd.c_str());
	auto read = [](const std::string& path, std::string& text) {
		std::ifstream f(path);
		text.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
	};
	read(outPath, out);
	if (err)
		read(errPath, *err);
	// (Removed again: left behind, every test run added files to the temporary folder.)
	std::error_code ignored;
	for (const std::string& path : {inPath, outPath, errPath})
		std::filesystem::remove(path, ignored);
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int Lines(const std::string& s)
{
	int n = 0;
	for (char c : s)
		n += c == '\n';
	return n;
}
} // namespace

TEST_CASE("contact mode on two circles matches the closed form")
{
	// Radii 1 and 2, centres 4 apart along x: separation 1, common level (4/3)², point at x = 4/3.
	const json r = Ask(R"({"id": 7, "a": {"type": "circle", "r": 1}, "b": {"type": "circle", "r": 2, "x": 4}})");
	CHECK(r["id"] == 7);
	CHECK(r["status"] == "ok");
	CHECK(r["mode"] == "contact");
	CHECK(r["method"] == "closed_form");
	CHECK(r["scale"].get<double>() == doctest::Approx(16.0 / 9.0).epsilon(1e-14));
	CHECK(r["point"][0].get<double>() == doctest::Approx(4.0 / 3.0).epsilon(1e-14));
	CHECK(r["normal"][0].get<double>() == doctest::Approx(1.0));
	CHECK(r["separation"].get<double>() == doctest::Approx(1.0).epsilon(1e-14));
	CHECK(r["touching"] == false);
	CHECK(r["point_a"][0].get<double>() == doctest::Approx(1.0));
	CHECK(r["point_b"][0].get<double>() == doctest::Approx(2.0));
}

TEST_CASE("every mode and method round-trips on an ellipse pair")
{
	// Two ellipses x²/4 + y² ≤ 1, the second turned by 90° and placed on the x axis at 4:
	// A's tip (2, 0) meets B's side (4 − 1, 0) at level C with 2√C·... the common level of two
	// scaled copies along the axis: A reaches x = 2√C, B reaches x = 4 − √C, so 3√C = 4.
	const std::string pair = R"("a": {"type": "ellipse", "a": 2, "b": 1},
	                            "b": {"type": "ellipse", "a": 2, "b": 1, "x": 4, "angle": 1.5707963267948966})";
	const double C = 16.0 / 9.0;
	for (const char* method : {"auto", "newton", "grid"})
	{
		CAPTURE(method);
		const json r = Ask(std::string(R"({"id": "c", "mode": "common", "method": ")") + method + "\", " + pair + "}");
		CHECK(r["mode"] == "common");
		CHECK(r["scale"].get<double>() == doctest::Approx(C).epsilon(1e-12));
		CHECK(r["point"][0].get<double>() == doctest::Approx(2.0 * std::sqrt(C)).epsilon(1e-12));
		CHECK(std::fabs(r["point"][1].get<double>()) < 1e-12);
		CHECK(r["normal"][0].get<double>() == doctest::Approx(1.0).epsilon(1e-12));
		CHECK(r["touching"] == false);
		CHECK(r["separation"].get<double>() == doctest::Approx(1.0).epsilon(1e-12)); // 4 − 1 − 2
	}
	for (const char* method : {"auto", "newton", "grid"})
	{
		CAPTURE(method);
		// B held at its surface: A must reach x = 3, so 2√f = 3, f = 9/4, at B's point (3, 0).
		const json r = Ask(std::string(R"({"id": [1, 2], "mode": "scale_a", "method": ")") + method + "\", " + pair + "}");
		CHECK(r["id"] == json::array({1, 2}));
		CHECK(r["scale"].get<double>() == doctest::Approx(9.0 / 4.0).epsilon(1e-12));
		CHECK(r["point"][0].get<double>() == doctest::Approx(3.0).epsilon(1e-12));
		CHECK(r["point_b"][0].get<double>() == doctest::Approx(3.0).epsilon(1e-12));
	}
	for (const char* method : {"auto", "newton", "grid"})
	{
		CAPTURE(method);
		const json r = Ask(std::string(R"({"mode": "contact", "method": ")") + method + "\", " + pair + "}");
		CHECK(r["id"].is_null());
		CHECK(r["separation"].get<double>() == doctest::Approx(1.0).epsilon(1e-12));
		CHECK(r["point_a"][0].get<double>() == doctest::Approx(2.0).epsilon(1e-12));
		CHECK(r["point_b"][0].get<double>() == doctest::Approx(3.0).epsilon(1e-12));
		CHECK(r["normal"][0].get<double>() == doctest::Approx(1.0).epsilon(1e-12));
	}
}

TEST_CASE("hearts are answered by the grid method in scale_a and contact modes")
{
	// Two hearts of size α = 1 side by side, 3 apart: apart, so the smallest level of A on B's
	// surface exceeds A's own α, and the separation is positive.
	const std::string pair = R"("a": {"type": "heart", "alpha": 1}, "b": {"type": "heart", "alpha": 1, "x": 3})";
	const json s = Ask(R"({"mode": "scale_a", )" + pair + "}");
	CHECK(s["method"] == "grid");
	CHECK(s["scale"].get<double>() > 1.0);
	CHECK(s["touching"] == false);
	const json c = Ask(R"({"mode": "contact", )" + pair + "}");
	CHECK(c["separation"].get<double>() > 0.0);
	CHECK(c["normal"][0].get<double>() > 0.9);
	// Moved to 1.5 apart they overlap.
	const json o = Ask(R"({"a": {"type": "heart", "alpha": 1}, "b": {"type": "heart", "alpha": 1, "x": 1.5}})");
	CHECK(o["touching"] == true);
	CHECK(o["separation"].get<double>() < 0.0);
}

TEST_CASE("bad lines each get their own error and name the field")
{
	struct Case { const char* line; const char* mustContain; };
	const Case cases[] = {
		{R"({"id": 1, "a": )", "malformed JSON"},
		{R"({"id": 2, "a": {"type": "circle"}, "b": {"type": "circle", "r": 1}})", "field 'a.r' is missing"},
		{R"({"id": 3, "a": {"type": "triangle", "r": 1}, "b": {"type": "circle", "r": 1}})", "unknown shape type \"triangle\""},
		{R"({"id": 4, "a": {"type": "circle", "r": 1}, "b": {"type": "ellipse", "a": -2, "b": 1}})", "field 'a' must be finite and > 0, got -2"},
		{R"({"id": 5, "a": {"type": "circle", "r": 1}})", "field 'b' is missing"},
		{R"({"id": 6, "mode": "closest", "a": {"type": "circle", "r": 1}, "b": {"type": "circle", "r": 1}})", "field 'mode'"},
		{R"({"id": 7, "method": "gjk", "a": {"type": "circle", "r": 1}, "b": {"type": "circle", "r": 1}})", "field 'method'"},
		{R"({"id": 8, "a": {"type": "circle", "r": "big"}, "b": {"type": "circle", "r": 1}})", "field 'a.r' must be a number"},
		{R"({"id": 9, "a": {"type": "superellipse", "a": 1, "b": 1, "n": 0.5, "m": 2}, "b": {"type": "circle", "r": 1}})", "field 'n' must be finite and >= 1, got 0.5"},
		{R"({"id": 10, "a": {"type": "heart", "alpha": 0}, "b": {"type": "circle", "r": 1}})", "field 'alpha'"},
		{R"({"id": 11, "mode": "common", "a": {"type": "heart", "alpha": 1}, "b": {"type": "circle", "r": 1}})", "use mode 'scale_a'"},
		{R"({"id": 12, "a": {"type": "circle", "r": 1, "radius": 2}, "b": {"type": "circle", "r": 1}})", "field 'a.radius' is not a field of a circle"},
		{R"({"id": 13, "a": {"type": "circle", "r": 1e999}, "b": {"type": "circle", "r": 1}})", "malformed JSON: [json.exception.out_of_range.406] number overflow parsing '1e999'"},
		{R"([1, 2, 3])", "must be a JSON object"},
		{R"({"id": 15, "mode": "common", "method": "newton", "a": {"type": "superellipse", "a": 1, "b": 1, "n": 1.5, "m": 1.5}, "b": {"type": "circle", "r": 1, "x": 3}})", "solver failed (newton)"},
	};
	for (const Case& c : cases)
	{
		const json r = Ask(c.line, false);
		CAPTURE(c.line);
		CHECK(r["status"] == "error");
		const std::string message = r["error"].get<std::string>();
		CAPTURE(message);
		CHECK(message.find(c.mustContain) != std::string::npos);
	}
	// The id survives errors found after it was read.
	CHECK(Ask(R"({"id": "keep", "a": {"type": "circle"}, "b": {"type": "circle", "r": 1}})", false)["id"] == "keep");
}

TEST_CASE("the program answers every line in order and sets its exit status")
{
	std::string out;
	const std::string good = R"({"id": 1, "a": {"type": "circle", "r": 1}, "b": {"type": "circle", "r": 1, "x": 3}})";
	const std::string bad = R"({"id": 2, "a": {"type": "circle"}, "b": {"type": "circle", "r": 1}})";

	CHECK(RunTool("", good + "\n\n   \n" + good + "\n", out) == 0);
	CHECK(Lines(out) == 2); // blank lines are skipped

	CHECK(RunTool("-", good + "\n" + bad + "\n" + good + "\n", out) == 1);
	REQUIRE(Lines(out) == 3);
	const size_t first = out.find('\n'), second = out.find('\n', first + 1);
	CHECK(json::parse(out.substr(0, first))["status"] == "ok");
	CHECK(json::parse(out.substr(first + 1, second - first - 1))["status"] == "error");
	CHECK(json::parse(out.substr(second + 1))["id"] == 1);

	const std::string file = (std::filesystem::temp_directory_path() / ("b2a_tool_test_" + std::to_string(getpid()) + "_input.jsonl")).string();
	CHECK(RunTool("\"" + file + "\"", "", out) == 0); // a file argument (here: empty)
	CHECK(RunTool("/nonexistent/requests.jsonl", "", out) == 2);
	CHECK(RunTool("--frobnicate", "", out) == 2);
	CHECK(RunTool("a.jsonl b.jsonl", "", out) == 2);
	CHECK(RunTool("--help", "", out) == 0);
	CHECK(out.find("scale_a") != std::string::npos);
	CHECK(out.find("Exit status") != std::string::npos);
}

TEST_CASE("the program's command line: its help, and bad arguments named with exit status 2")
{
	std::string out, err;
	REQUIRE(RunTool("-h", "", out) == 0);
	// What the help has always said: the tool, how to call it, the request and answer formats,
	// the exit status and an example.
	for (const char* text : {"b2a_contact: contact detection between analytic particles", "Usage: b2a_contact [OPTIONS] [FILE]",
	                         "FILE", "default -: standard input", "-h,--help", "Each input line is one JSON object",
	                         "Exit status: 0 when every line was answered", "Example:"})
	{
		CAPTURE(text);
		CHECK(out.find(text) != std::string::npos);
	}
	CHECK(RunTool("--frobnicate", "", out, &err) == 2);
	CHECK(err == "b2a_contact: The following argument was not expected: --frobnicate (see --help)\n");
	CHECK(RunTool("a.jsonl b.jsonl", "", out, &err) == 2);
	CHECK(err == "b2a_contact: The following argument was not expected: b.jsonl (see --help)\n");
	CHECK(RunTool("/nonexistent/requests.jsonl", "", out, &err) == 2);
	CHECK(err == "b2a_contact: cannot read '/nonexistent/requests.jsonl'\n");
	CHECK(out.empty());
}

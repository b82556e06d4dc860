// b2analytic tests: b2a_viewer run as a person would, headless under Xvfb with Mesa's software
// OpenGL: each sample for 300 frames, its screenshot's pixels checked against where the report
// says the bodies are and where the panel is; and the settings kept from one run to the next.
#include <doctest/doctest.h>

#include "SampleRegistry.h"

#include <nlohmann/json.hpp>
#include <stb_image.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <sys/wait.h>

namespace
{
using Json = nlohmann::json;

const std::string kOut = "viewer_out";

// Run the viewer under xvfb-run; returns its exit status and fills the report.
int RunViewer(const std::string& name, const std::string& args, Json& report)
{
	REQUIRE_MESSAGE(std::string(B2A_XVFB_RUN) != "", "xvfb-run was not found when configuring: bash scripts/setup.sh installs it");
	std::filesystem::create_directories(kOut);
	const std::string base = kOut + "/" + name;
	std::filesystem::remove(base + ".json");
	std::filesystem::remove(base + ".png");
	// Under AddressSanitizer the viewer's leak check is off: at exit, with the OpenGL driver
	// unloaded, LeakSanitizer reports two 56-byte blocks the sanitizer runtimes allocated while
	// the driver was loaded and names no module it could suppress by. The address and undefined
	// behaviour checks stay on, and the in-process viewer tests check our code for leaks.
	// (Without the sanitizers the variable is ignored.)
	const char* asan = std::getenv("ASAN_OPTIONS");
	const std::string env = std::string("ASAN_OPTIONS='") + (asan ? asan : "") + ":detect_leaks=0' ";
	const std::string cmd = env + std::string(B2A_XVFB_RUN) + " -a -s \"-screen 0 1280x800x24\" \"" + B2A_VIEWER_EXE + "\" " + args +
	                        " --report " + base + ".json --screenshot " + base + ".png > " + base + ".stdout 2> " + base + ".stderr";
	INFO("command: " << cmd);
	const int status = std::system(cmd.c_str());
	std::ifstream in(base + ".json");
	if (in)
		in >> report;
	std::ifstream out(base + ".stdout");
	std::string line;
	std::getline(out, line);
	std::printf("%s\n", line.c_str()); // the viewer's summary with its frame times, into CTest's log
	return status;
}

struct Image
{
	int width = 0, height = 0;
	std::vector<unsigned char> rgb;
	const unsigned char* At(int x, int y) const { return &rgb[3 * (size_t(y) * size_t(width) + size_t(x))]; }
};

Image ReadPng(const std::string& path)
{
	Image im;
	int channels = 0;
	unsigned char* data = stbi_load(path.c_str(), &im.width, &im.height, &channels, 3);
	REQUIRE_MESSAGE(data, "cannot read " << path);
	im.rgb.assign(data, data + size_t(im.width) * size_t(im.height) * 3);
	stbi_image_free(data);
	return im;
}

int Difference(const unsigned char* p, const int q[3])
{
	return std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])});
}

// The checks every sample's run must pass.
void CheckRun(const std::string& sample, const std::string& extra = "", int minimumBodies = 1)
{
	Json r;
	const std::string name = sample + (extra.empty() ? "" : "_compare");
	const int status = RunViewer(name, "--sample " + sample + " --frames 300 --settings " + kOut + "/" + name + "_settings.json " + extra, r);
	CHECK(status == 0);
	REQUIRE(r.is_object());
	CHECK(r["sample"] == sample);
	CHECK(r["frames"] == 300);
	CHECK(r["non_finite"] == 0);
	CHECK(r["escaped"] == 0);
	CHECK(r["bodies"].get<int>() >= minimumBodies);

	const Image im = ReadPng(kOut + "/" + name + ".png");
	REQUIRE(im.width == r["window"][0].get<int>());
	REQUIRE(im.height == r["window"][1].get<int>());
	int bg[3];
	for (int c = 0; c < 3; ++c)
		bg[c] = int(std::lround(255.0 * r["background"][c].get<double>()));
	const double px = r["panel"][0], py = r["panel"][1], pw = r["panel"][2], ph = r["panel"][3];
	const auto inPanel = [&](double x, double y) { return x >= px - 2 && x <= px + pw + 2 && y >= py - 2 && y <= py + ph + 2; };

	// Particles drawn where the bodies are: each dynamic body's centre (inside its own fixture)
	// on the screen, away from the panel and the text lines at the top, is not background.
	int visible = 0, drawn = 0;
	for (const Json& p : r["body_screen_points"])
	{
		const double x = p[0], y = p[1];
		if (x < 2 || y < 110 || x > im.width - 3 || y > im.height - 3 || inPanel(x, y))
			continue;
		++visible;
		drawn += Difference(im.At(int(x), int(y)), bg) > 10;
	}
	CAPTURE(visible);
	CAPTURE(drawn);
	CHECK(visible > 0);
	CHECK(drawn >= 0.95 * visible);

	// Not everything is painted: much of the scene area left of the panel is background.
	int background = 0, total = 0;
	for (int y = 110; y < im.height; y += 4)
		for (int x = 0; x < int(px) - 4; x += 4)
		{
			++total;
			background += Difference(im.At(x, y), bg) <= 3;
		}
	CAPTURE(background);
	CAPTURE(total);
	CHECK(background > 0.25 * total);

	// The panel is there: Dear ImGui's window (its dark background, 0.06 grey at alpha 0.94 over
	// ours) covers the rectangle the report gives, with text on it.
	REQUIRE(pw > 100);
	int windowBg[3];
	for (int c = 0; c < 3; ++c)
		windowBg[c] = int(std::lround(0.94 * 0.06 * 255.0 + 0.06 * bg[c]));
	int panelBg = 0, bright = 0, samples = 0;
	for (int y = int(py) + 4; y < int(py + ph) - 4; y += 2)
		for (int x = int(px) + 4; x < int(px + pw) - 4; x += 2)
		{
			++samples;
			const unsigned char* p = im.At(x, y);
			panelBg += Difference(p, windowBg) <= 4;
			bright += p[0] + p[1] + p[2] > 3 * 150;
		}
	CAPTURE(panelBg);
	CAPTURE(bright);
	CAPTURE(samples);
	CHECK(panelBg > 0.2 * samples);
	CHECK(bright > 0.01 * samples);
}
} // namespace

// One case per sample, so that CTest runs them side by side; the last case checks the list.
TEST_CASE("headless: hopper-discharge") { CheckRun("hopper-discharge", "", 300); }
TEST_CASE("headless: packing") { CheckRun("packing", "", 300); }
TEST_CASE("headless: beverloo-channel") { CheckRun("beverloo-channel", "", 300); } // of 500, less those discharged
TEST_CASE("headless: contact-cases") { CheckRun("contact-cases", "", 2); }
TEST_CASE("headless: collision-cases") { CheckRun("collision-cases", "", 2); }
TEST_CASE("headless: superellipse-stack") { CheckRun("superellipse-stack", "", 90); }
TEST_CASE("headless: ellipses-on-a-slope") { CheckRun("ellipses-on-a-slope", "", 8); }
TEST_CASE("headless: mixed-with-box2d-shapes") { CheckRun("mixed-with-box2d-shapes", "", 64); }
TEST_CASE("headless: shape-editor") { CheckRun("shape-editor", "", 6); }
TEST_CASE("headless: figure-17-superellipsoids")
{
	CheckRun("figure-17-superellipsoids", "", 2);
	// After 300 frames (one step of 0.001 ms each) the pair has stopped at its first contact
	// (about 0.192 ms): both particles are shaded in their colours, blue (i) and orange (j), and
	// the contact point is marked in magenta over them, left of the panel and below the text.
	Json r;
	std::ifstream(kOut + "/figure-17-superellipsoids.json") >> r;
	CHECK(r["readings"]["touching"] == 1.0);
	const Image im = ReadPng(kOut + "/figure-17-superellipsoids.png");
	int blue = 0, orange = 0, magenta = 0;
	for (int y = 110; y < im.height; ++y)
		for (int x = 0; x < int(r["panel"][0].get<double>()) - 4; ++x)
		{
			const unsigned char* p = im.At(x, y);
			blue += p[2] > p[0] + 30 && p[2] > p[1] + 10;
			orange += p[0] > p[2] + 60 && p[0] > p[1] + 20 && p[1] > p[2];
			magenta += p[0] > 200 && p[1] < 100 && p[2] > 100;
		}
	CAPTURE(blue);
	CAPTURE(orange);
	CAPTURE(magenta);
	CHECK(blue > 2000);
	CHECK(orange > 100);
	CHECK(magenta >= 25);
}
TEST_CASE("headless: packing side by side with Box2D 8-gons") { CheckRun("packing", "--compare side-by-side", 600); }

TEST_CASE("headless: every registered sample has its headless case above")
{
	const std::set<std::string> tested = {"hopper-discharge",   "packing",         "beverloo-channel",        "contact-cases", "collision-cases",
	                                      "superellipse-stack", "ellipses-on-a-slope", "mixed-with-box2d-shapes", "shape-editor",
	                                      "figure-17-superellipsoids"};
	for (const b2a::viewer::SampleEntry& e : b2a::viewer::Samples())
		CHECK(tested.count(b2a::viewer::SampleKey(e)) == 1);
	CHECK(tested.size() == b2a::viewer::Samples().size());
}

TEST_CASE("headless: the settings are kept from one run to the next")
{
	const std::string settings = kOut + "/kept_settings.json";
	std::filesystem::remove(settings);
	Json r;
	CHECK(RunViewer("kept_first", "--sample packing --frames 2 --compare polygons --settings " + settings, r) == 0);
	CHECK(r["sample"] == "packing");
	// The second run names no sample: it starts where the first left off, 8-gons and all.
	CHECK(RunViewer("kept_second", "--frames 2 --settings " + settings, r) == 0);
	CHECK(r["sample"] == "packing");
	CHECK(r["compare"] == "polygons");
	// A settings file with a bad value is refused, naming it; the viewer does not start.
	std::ofstream(settings) << R"({"windowWidth": 5})";
	const std::string cmd = std::string("\"") + B2A_VIEWER_EXE + "\" --frames 2 --settings " + settings + " > " + kOut +
	                        "/bad_settings.stdout 2> " + kOut + "/bad_settings.stderr";
	CHECK(WEXITSTATUS(std::system(cmd.c_str())) == 2);
	std::ifstream err(kOut + "/bad_settings.stderr");
	const std::string message((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
	CHECK(message.find("windowWidth") != std::string::npos);
	CHECK(message.find("5") != std::string::npos);
}

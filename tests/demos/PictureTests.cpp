// b2analytic tests: the demos' pictures. Plots keep their legend off the data and their markers
// inside the frame; snapshots of a granular scene have one clock, a key, a scale bar and the
// closed gate. The SVG is read back with regular expressions.
#include <doctest/doctest.h>

#include "common/GranularScene.h"
#include "common/Plot.h"
#include "common/Svg.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::demo;

namespace
{
struct Rect
{
	double x0, y0, x1, y1;
};

// Every match of `pattern` with its numeric groups.
std::vector<std::vector<double>> Numbers(const std::string& svg, const std::string& pattern)
{
	std::vector<std::vector<double>> all;
	const std::regex re(pattern);
	for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator(); ++it)
	{
		std::vector<double> v;
		for (size_t g = 1; g < it->size(); ++g)
			v.push_back(std::stod((*it)[g].str()));
		all.push_back(v);
	}
	return all;
}

// The plot's frame (the rectangle with a #333 stroke) and its legend (the white one).
Rect Frame(const std::string& svg)
{
	const auto r = Numbers(svg, R"re(<rect x="([-\d.]+)" y="([-\d.]+)" width="([\d.]+)" height="([\d.]+)" fill="none" stroke="#333")re");
	REQUIRE(r.size() == 1);
	return {r[0][0], r[0][1], r[0][0] + r[0][2], r[0][1] + r[0][3]};
}

Rect Legend(const std::string& svg)
{
	const auto r = Numbers(svg, R"re(<rect x="([-\d.]+)" y="([-\d.]+)" width="([\d.]+)" height="([\d.]+)" fill="white" fill-opacity)re");
	REQUIRE(r.size() == 1);
	return {r[0][0], r[0][1], r[0][0] + r[0][2], r[0][1] + r[0][3]};
}

// Centres and radii of the circle markers.
std::vector<std::vector<double>> Circles(const std::string& svg)
{
	return Numbers(svg, R"re(<circle cx="([-\d.]+)" cy="([-\d.]+)" r="([\d.]+)")re");
}

Series Points(const std::string& name, std::vector<double> x, std::vector<double> y)
{
	Series s{name, palette::blue, std::move(x), std::move(y), true};
	return s;
}
} // namespace

TEST_CASE("LinePlot puts its legend in a corner free of data, and keeps markers inside the frame")
{
	// Data in the top-right, top-left and bottom-right corners: the legend goes bottom-left.
	const std::string svg = LinePlot({Points("a", {0.0, 10.0, 0.0, 10.0, 5.0}, {10.0, 10.0, 9.5, 0.0, 5.0})}, "t", "x (m)", "y (m)");
	const Rect frame = Frame(svg), legend = Legend(svg);
	CHECK(legend.x0 < 0.5 * (frame.x0 + frame.x1)); // left half
	CHECK(legend.y0 > 0.5 * (frame.y0 + frame.y1)); // bottom half
	const auto circles = Circles(svg);
	REQUIRE(circles.size() == 6); // five points and the legend's marker
	for (const auto& c : circles)
	{
		// Inside the frame, a marker's radius from its edge at least.
		CHECK(c[0] - c[2] >= frame.x0);
		CHECK(c[0] + c[2] <= frame.x1);
		CHECK(c[1] - c[2] >= frame.y0);
		CHECK(c[1] + c[2] <= frame.y1);
	}
	for (size_t i = 0; i + 1 < circles.size(); ++i) // the data markers (the legend's is last)
	{
		const auto& c = circles[i];
		CHECK_FALSE((c[0] + c[2] > legend.x0 && c[0] - c[2] < legend.x1 && c[1] + c[2] > legend.y0 && c[1] - c[2] < legend.y1));
	}
}

TEST_CASE("LinePlot puts the legend beside the frame where every corner has data, and draws lines through no legend")
{
	// A line through all four corners' regions and a point in the middle of each side.
	Series line{"line", palette::vermillion, {0.0, 10.0, 10.0, 0.0, 0.0}, {0.0, 0.0, 10.0, 10.0, 0.0}, false};
	const std::string svg = LinePlot({line, Points("points", {5.0}, {5.0})}, "t", "x (m)", "y (m)");
	const Rect frame = Frame(svg), legend = Legend(svg);
	CHECK(legend.x0 > frame.x1);
	const auto width = Numbers(svg, R"re(<svg xmlns="http://www.w3.org/2000/svg" width="([\d.]+)")re");
	REQUIRE(width.size() == 1);
	CHECK(legend.x1 <= width[0][0]); // the picture widened to hold it
	// The legend shows each series as it is drawn: a line for the line, a marker for the points.
	CHECK(Numbers(svg, R"re(<line x1="([-\d.]+)" y1="[-\d.]+" x2="[-\d.]+" y2="[-\d.]+" stroke="#D55E00")re").size() == 1);
	CHECK(Circles(svg).size() == 2);
}

TEST_CASE("LinePlot's log axes have ticks at powers of ten, written as such")
{
	const std::string svg = LinePlot({Points("e", {1.0, 2.0}, {1e-12, 1e-3})}, "t", "x (m)", "error (m)", true);
	CHECK(svg.find(">10⁻¹²<") != std::string::npos);
	CHECK(svg.find(">10⁻³<") != std::string::npos);
	// Over fewer than three decades a log x axis also gets 2 and 5 times them.
	const std::string x = LinePlot({Points("e", {0.001, 0.05}, {1.0, 2.0})}, "t", "time (s)", "y (m)", false, true);
	for (const char* label : {">0.002<", ">0.005<", ">0.01<", ">0.02<", ">0.05<"})
		CHECK_MESSAGE(x.find(label) != std::string::npos, label);
}

TEST_CASE("A granular scene's snapshot has one clock, a key, a scale bar, and the gate while it is closed")
{
	GranularConfig config;
	config.particles = 12;
	config.boxWidth = 20.0;
	config.outletWidth = 6.0;
	GranularScene scene(config);
	for (int i = 0; i < 50; ++i)
		scene.Step();
	const std::string path = "picture_test_snapshot.svg";
	auto read = [&] {
		std::ifstream f(path);
		return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
	};
	scene.WriteSnapshot(path, "scene", scene.Time(), "(the gate about to open)");
	std::string closed = read();
	CHECK(Numbers(closed, R"re(>t = ([\d.]+) s)re").size() == 1); // one clock
	CHECK(closed.find(">t = 0.000 s (the gate about to open)<") != std::string::npos);
	CHECK(closed.find("gate over the outlet (closed)") != std::string::npos);
	CHECK(closed.find("stroke=\"#D55E00\" stroke-width=\"3.0\"") != std::string::npos); // the gate, drawn
	CHECK(closed.find(">5 mm<") != std::string::npos); // scale bar: a quarter of the width, rounded down
	CHECK(closed.find(">at rest (below 5 mm/s)<") != std::string::npos);
	CHECK(closed.find(" discharged") == std::string::npos); // nothing can have left yet

	scene.OpenOutlet();
	scene.WriteSnapshot(path, "scene");
	const std::string open = read();
	CHECK(Numbers(open, R"re(>t = ([\d.]+) s)re").size() == 1);
	CHECK(open.find("gate over the outlet") == std::string::npos);
	CHECK(open.find("stroke=\"#D55E00\"") == std::string::npos);
	CHECK(open.find(", 0 discharged") != std::string::npos);
	std::filesystem::remove(path);
}

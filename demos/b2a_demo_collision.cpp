// b2analytic demo: collision processes (the paper's Figures 4 and 8): the exact first-contact
// time and point from the time-of-impact solver, next to what fixed time stepping finds.
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/PaperCases.h"
#include "common/Plot.h"
#include "common/Svg.h"

#include "b2analytic/b2analytic.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::demo;

namespace
{
const char* kHelp = R"(b2a_demo_collision: the collision processes of the paper's Figures 4, 8 and 10.

Two superellipses (n = 6, m = 8, a = 2, b = 4, as in the paper's Figure 1), two hearts
(alpha = 1), and a small ellipse meeting a large one (Figure 10) move and rotate with constant
velocities until they first touch. The time-of-impact
solver (conservative advancement, then a bracketed root of the separation) gives the first
contact time and point; fixed time stepping, as the paper does it (440 steps for its
superellipses), finds the first step at which the particles overlap, late by up to a step.
The paper's velocities (its Tables 1 and 2) are missing from its text: these are ours, of the
same kind; its results were first contact at t = 0.0197 s for the superellipses and
t = 0.0088 s for the hearts.

Writes to DIR: summary.json (per case: the exact time and point, and for each step size the
stepping result and its error), <case>.svg (trajectories: start in blue, outlines along the way
in green, the contact configuration in red, the contact point as a dot) and
stepping_error.svg (error of fixed stepping against the step size).
)";

using Case = CollisionCase;

Json Vec(Vec2 v)
{
	return Json::array({v.x, v.y});
}

// First step index k at which the particles touch with fixed step dt (time k·dt), or −1.
double FixedStepping(const Case& c, double dt, int& steps)
{
	steps = 0;
	for (int k = 0; k * dt <= c.tMax; ++k)
	{
		++steps;
		const ContactResult r = ComputeContact(*c.a, c.ma.At(k * dt), *c.b, c.mb.At(k * dt));
		if (r.Ok() && r.touching)
			return k * dt;
	}
	return -1.0;
}

void Draw(const Case& c, const TimeOfImpactResult& toi, const std::string& path)
{
	std::vector<std::vector<Vec2>> outlines;
	Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
	auto add = [&](const Shape& s, const Pose& p) {
		outlines.push_back(Outline(s, p));
		for (Vec2 q : outlines.back())
		{
			lo = Vec2(std::min(lo.x, q.x), std::min(lo.y, q.y));
			hi = Vec2(std::max(hi.x, q.x), std::max(hi.y, q.y));
		}
	};
	const double tEnd = toi.hit ? toi.time : c.tMax;
	const int frames = 6;
	for (int k = 0; k <= frames; ++k)
	{
		const double t = tEnd * k / frames;
		add(*c.a, c.ma.At(t));
		add(*c.b, c.mb.At(t));
	}
	const Style start{palette::blue, palette::blue, 1.5, "", 0.3}, along{"none", palette::green, 0.8, "4,3", 1.0};
	const Style contact{palette::vermillion, palette::vermillion, 1.8, "", 0.3}, centres{"none", "#777777", 1.0, "2,3", 1.0};
	const std::vector<KeyEntry> key = {{KeyEntry::Kind::area, start, "at t = 0"},
	                                   {KeyEntry::Kind::line, along, "every sixth of the way"},
	                                   {KeyEntry::Kind::area, contact, "at the first contact"},
	                                   {KeyEntry::Kind::line, centres, "paths of the centres"},
	                                   {KeyEntry::Kind::dot, {palette::black, "none", 1.0, "", 1.0}, "first contact point"}};
	// Around the outlines: a margin, a band on top for the text, one below for the key and the
	// scale bar.
	const double pixelWidth = 720.0, pad = 0.06 * std::max(hi.x - lo.x, hi.y - lo.y);
	const double perUnit = pixelWidth / (hi.x - lo.x + 2.0 * pad);
	const double top = 56.0 / perUnit, bottom = (SvgCanvas::KeySize(key).y + 16.0) / perUnit;
	SvgCanvas svg(lo - Vec2(pad, pad + bottom), hi + Vec2(pad, pad + top), pixelWidth);
	for (size_t i = 0; i < outlines.size(); ++i)
	{
		const size_t frame = i / 2;
		svg.Polygon(outlines[i], frame == 0 ? start : int(frame) == frames ? contact : along);
	}
	for (const Motion* m : {&c.ma, &c.mb})
		svg.Polyline({m->pose.p, m->At(tEnd).p}, centres);
	if (toi.hit)
		svg.Dot(toi.contact.point, 4.5, palette::black);
	char line[200];
	std::snprintf(line, sizeof(line), "first contact at t = %.9f s at (%.6f, %.6f)", toi.time, toi.contact.point.x, toi.contact.point.y);
	svg.Label(10, 22, c.name, 16);
	svg.Label(10, 42, toi.hit ? line : "no contact within the interval", 13);
	svg.Key(8.0, svg.Height() - SvgCanvas::KeySize(key).y - 8.0, key);
	const double bar = RoundLength(0.2 * (hi.x - lo.x));
	svg.ScaleBar(svg.Width() - svg.Pixels(bar) - 20.0, svg.Height() - 10.0, bar, LengthLabel(bar, "mm"));
	WriteText(path, svg.Finish());
}
} // namespace

int main(int argc, char** argv)
{
	const DemoOptions opt = CommandLine("b2a_demo_collision", kHelp).Parse(argc, argv);
	Progress progress("b2a_demo_collision");
	std::vector<Case> cases = PaperCollisionCases();
	// Step counts over each interval: the paper's 440 for its superellipses, and others.
	const std::vector<int> stepCounts = opt.quick ? std::vector<int>{55, 440, 3520} : std::vector<int>{55, 110, 220, 440, 880, 1760, 3520, 7040};

	Json list = Json::array();
	std::vector<Series> errorSeries;
	const Marker markers[] = {Marker::circle, Marker::square, Marker::triangle};
	for (size_t i = 0; i < cases.size(); ++i)
	{
		const Case& c = cases[i];
		const auto t0 = std::chrono::steady_clock::now();
		const TimeOfImpactResult toi = TimeOfImpact(*c.a, c.ma, *c.b, c.mb, c.tMax);
		const double toiMicros = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
		Json j;
		j["name"] = c.name;
		j["a"] = c.a->Describe();
		j["b"] = c.b->Describe();
		j["motion_a"] = {{"pose", {c.ma.pose.p.x, c.ma.pose.p.y, c.ma.pose.q.Angle()}},
		                 {"velocity", Vec(c.ma.velocity)},
		                 {"angular_velocity", c.ma.angularVelocity}};
		j["motion_b"] = {{"pose", {c.mb.pose.p.x, c.mb.pose.p.y, c.mb.pose.q.Angle()}},
		                 {"velocity", Vec(c.mb.velocity)},
		                 {"angular_velocity", c.mb.angularVelocity}};
		j["status"] = StatusName(toi.status);
		j["hit"] = toi.hit;
		j["time"] = toi.time;
		j["point"] = Vec(toi.contact.point);
		j["normal"] = Vec(toi.contact.normal);
		j["separation_at_time"] = toi.contact.separation;
		j["iterations"] = toi.iterations;
		j["solver_time_us"] = toiMicros;
		Json stepping = Json::array();
		Series s{c.name, palette::series[i % 3], {}, {}, true, markers[i % 3]};
		for (int n : stepCounts)
		{
			const double dt = c.tMax / n;
			int evaluated = 0;
			const auto s0 = std::chrono::steady_clock::now();
			const double ts = FixedStepping(c, dt, evaluated);
			const double micros = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - s0).count();
			Json r;
			r["steps_per_interval"] = n;
			r["dt"] = dt;
			r["first_touching_step_time"] = ts >= 0.0 ? Json(ts) : Json(nullptr);
			r["error"] = ts >= 0.0 ? Json(ts - toi.time) : Json(nullptr);
			r["contact_evaluations"] = evaluated;
			r["time_us"] = micros;
			stepping.push_back(r);
			if (ts >= 0.0 && ts > toi.time)
			{
				s.x.push_back(dt);
				s.y.push_back(ts - toi.time);
			}
		}
		j["fixed_stepping"] = stepping;
		j["note"] = "fixed stepping reports the first step at which the particles already overlap: late by up to one step";
		list.push_back(j);
		errorSeries.push_back(s);
		Draw(c, toi, opt.out + "/" + c.name + ".svg");
		progress.Report(double(i + 1) / cases.size(), c.name);
	}
	WriteText(opt.out + "/stepping_error.svg",
	          LinePlot(errorSeries, "Fixed stepping: how late it finds the first contact", "time step (s)",
	                   "delay of the first overlapping step (s)", true, true));
	Json summary;
	summary["demo"] = "b2a_demo_collision";
	summary["quick"] = opt.quick;
	summary["cases"] = list;
	summary["paper"] = {{"superellipses_time", 0.0197}, {"superellipses_point", {13.844, 6.3381}}, {"hearts_time", 0.0088},
	                    {"note", "the paper's velocities are missing from its text; ours are of the same kind"}};
	WriteJson(opt.out + "/summary.json", summary);
	std::printf("b2a_demo_collision: superellipses first touch at t = %.9f s, hearts at t = %.9f s (exact); fixed stepping with %d "
	            "steps finds them %.2g s and %.2g s late; pictures and summary.json in %s\n",
	            list[0]["time"].get<double>(), list[1]["time"].get<double>(), 440,
	            list[0]["fixed_stepping"][opt.quick ? 1 : 3]["error"].is_null() ? -1.0 : list[0]["fixed_stepping"][opt.quick ? 1 : 3]["error"].get<double>(),
	            list[1]["fixed_stepping"][opt.quick ? 1 : 3]["error"].is_null() ? -1.0 : list[1]["fixed_stepping"][opt.quick ? 1 : 3]["error"].get<double>(),
	            opt.out.c_str());
	bool allHit = true;
	for (const Json& c : list)
		allHit = allHit && c["hit"].get<bool>();
	return allHit ? 0 : 1;
}

// b2analytic demo: the paper's contact cases (its Figures 2, 3, 6, 7, 9 and 16), solved exactly,
// with pictures of the particles, their rescaled outlines and the contact points.
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/Svg.h"

#include "b2analytic/b2analytic.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

using namespace b2a;
using namespace b2a::demo;

namespace
{
const char* kHelp = R"(b2a_demo_contacts: the paper's contact-detection cases, solved exactly.

Each case places two particles, rescales them until they touch (the common level for
superellipses by Newton-Raphson, the one-sided grid method with refinement for hearts and
for the paper's ellipse examples) and draws the particles, the rescaled outlines (dashed),
the contact point and the normal. The paper's Tables 1 and 2 (poses of its superellipse and
heart examples) are missing from its text: those cases use our own poses of the same kind,
and say so. The 1000:1 ellipses are fully specified and compared with the paper's value.

Writes DIR/summary.json (per case: level, point, method, iterations, median time) and one
SVG picture per case.
)";

struct Case
{
	std::string name, description, mode;
	ShapePtr a, b;
	Pose pa, pb;
	bool ownPoses = true;                      // the paper's poses are missing: ours
	std::function<LevelResult()> solve;        // default: by mode, automatic method
	double paperLevel = 0.0;                   // 0: the paper gives none for our poses
	Vec2 paperPoint;

	Case(std::string name_, std::string description_, std::string mode_, ShapePtr a_, ShapePtr b_, Pose pa_, Pose pb_,
	     bool ownPoses_ = true)
		: name(std::move(name_)), description(std::move(description_)), mode(std::move(mode_)), a(std::move(a_)),
		  b(std::move(b_)), pa(pa_), pb(pb_), ownPoses(ownPoses_)
	{
	}
};

Json Vec(Vec2 v)
{
	return Json::array({v.x, v.y});
}

// Picture of a case: particles filled, rescaled outlines dashed, contact point and normal.
void Draw(const Case& c, const LevelResult& r, const std::string& path)
{
	const bool common = c.mode == "common";
	// Outlines: A at the level found (common: both at C; scale_a: A at its level, B as is).
	const double levelA = r.level * (common ? c.a->SurfaceLevel() : 1.0);
	const double levelB = common ? r.level * c.b->SurfaceLevel() : c.b->SurfaceLevel();
	std::vector<std::vector<Vec2>> shapes = {Outline(*c.a, c.pa), Outline(*c.b, c.pb), Outline(*c.a, c.pa, levelA),
	                                         Outline(*c.b, c.pb, levelB)};
	Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
	for (const auto& s : shapes)
		for (Vec2 p : s)
		{
			lo = Vec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
			hi = Vec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
		}
	const double pad = 0.08 * std::max(hi.x - lo.x, hi.y - lo.y);
	lo = lo - Vec2(pad, pad);
	hi = hi + Vec2(pad, 3.0 * pad);
	SvgCanvas svg(lo, hi, 640.0);
	svg.Polygon(shapes[0], {"#4e79a7", "#2b4a6f", 1.5, "", 0.45});
	svg.Polygon(shapes[1], {"#f28e2b", "#8c4d10", 1.5, "", 0.45});
	svg.Polygon(shapes[2], {"none", "#2b4a6f", 1.5, "6,4", 1.0});
	svg.Polygon(shapes[3], {"none", "#8c4d10", 1.5, "6,4", 1.0});
	svg.Dot(c.pa.p, 3.0, "#2b4a6f");
	svg.Dot(c.pb.p, 3.0, "#8c4d10");
	const double arrow = 0.12 * (hi.x - lo.x);
	svg.Arrow(r.point, r.point + arrow * r.normal, {"none", "#c0392b", 2.0, "", 1.0});
	if (c.paperLevel > 0.0)
		svg.Dot(c.paperPoint, 4.0, "#27ae60");
	svg.Dot(r.point, 4.0, "#c0392b");
	char line[256];
	std::snprintf(line, sizeof(line), "%s: level %.10g at (%.6f, %.6f), %s", c.mode.c_str(), r.level, r.point.x, r.point.y,
	              MethodName(r.method));
	svg.Label(10, 20, c.name, 16);
	svg.Label(10, 40, line, 13);
	if (c.paperLevel > 0.0)
	{
		std::snprintf(line, sizeof(line), "paper (green dot): %.6g at (%.4f, %.4f)", c.paperLevel, c.paperPoint.x, c.paperPoint.y);
		svg.Label(10, 58, line, 13, "#27ae60");
	}
	else if (c.ownPoses)
		svg.Label(10, 58, "poses: ours (the paper's table is missing)", 13, "#555");
	WriteText(path, svg.Finish());
}
} // namespace

int main(int argc, char** argv)
{
	const DemoOptions opt = CommandLine("b2a_demo_contacts", kHelp).Parse(argc, argv);
	Progress progress("b2a_demo_contacts");
	std::vector<Case> cases;

	// Superellipses of the paper's Figure 1 (n = 6, m = 8, a = 2, b = 4), poses ours.
	const ShapePtr se = MakeSuperellipse(2.0, 4.0, 6.0, 8.0);
	{
		Case c{"superellipse_separated", "separated superellipses enlarged to touch (paper Fig. 2a, 3a kind)", "common", se, se,
		       Pose({0.0, 0.0}, kPi / 4), Pose({13.0, 9.0}, -kPi / 6)};
		cases.push_back(c);
		Case d{"superellipse_overlapping", "overlapping superellipses reduced to touch (paper Fig. 2b, 3b kind)", "common", se, se,
		       Pose({0.0, 0.0}, kPi / 4), Pose({1.5, -5.5}, kPi / 3)};
		cases.push_back(d);
	}
	// Hearts (paper eq. 20 with α = 1), grid method; poses ours.
	const ShapePtr heart = MakeHeart(1.0);
	{
		Case c{"heart_separated", "heart i enlarged onto heart j's surface, grid method (paper Fig. 6a, 7a kind)", "scale_a", heart, heart,
		       Pose({3.0, 5.0}, 0.2), Pose({4.9, 6.8}, -0.5)};
		cases.push_back(c);
		Case d{"heart_overlapping", "heart i reduced onto heart k's surface, grid method (paper Fig. 6b, 7b kind)", "scale_a", heart, heart,
		       Pose({3.0, 5.0}, 0.2), Pose({3.7, 5.9}, 0.6)};
		cases.push_back(d);
		Case e{"heart_in_notch", "a small heart inside the notch of a big one: several local minima", "scale_a", MakeHeart(0.05), MakeHeart(1.0),
		       Pose({0.0, 1.1}, kPi), Pose({0.0, 0.0}, 0.0)};
		cases.push_back(e);
	}
	// Ellipses with the grid method (paper Fig. 9 kind), poses ours.
	const ShapePtr ell = MakeEllipse(4.0, 2.0);
	{
		Case c{"ellipse_grid_separated", "separated ellipses, grid method (paper Fig. 9a, 9c kind)", "scale_a", ell, ell,
		       Pose({0.0, 0.0}, 0.3), Pose({9.0, 4.0}, -0.4)};
		cases.push_back(c);
		Case d{"ellipse_grid_overlapping", "overlapping ellipses, grid method (paper Fig. 9b, 9d kind)", "scale_a", ell, ell,
		       Pose({0.0, 0.0}, 0.3), Pose({4.0, 1.5}, 1.2)};
		cases.push_back(d);
	}
	// The paper's 1000:1 ellipses (Fig. 16), fully specified: j rescaled onto i's surface.
	const ShapePtr needle = MakeEllipse(0.1, 100.0);
	const Pose pi({1.2, 3.4}, kPi / 5.6), pj({2.1, -19.5}, kPi / 4.5);
	{
		Case c{"ellipse_1000_grid", "1000:1 ellipses, j enlarged onto i's surface by the grid method (paper Fig. 16)", "scale_a", needle,
		       needle, pj, pi, false};
		c.paperLevel = 13.6177;
		c.paperPoint = Vec2(54.4032, -81.2724);
		cases.push_back(c);
		Case d{"ellipse_1000_newton_scale", "the same by Newton on B's surface (the paper reports singular Jacobians)", "scale_a",
		       needle, needle, pj, pi, false};
		d.paperLevel = 13.6177;
		d.paperPoint = Vec2(54.4032, -81.2724);
		d.solve = [=] { return SolveScaleA(*needle, pj, *needle, pi, MethodChoice::newton); };
		cases.push_back(d);
		Case e{"ellipse_1000_common", "1000:1 ellipses, both rescaled to the common level (automatic: Newton)", "common", needle, needle, pi,
		       pj, false};
		cases.push_back(e);
	}

	const int repeats = opt.quick ? 15 : 201;
	Json list = Json::array();
	int failures = 0;
	for (size_t k = 0; k < cases.size(); ++k)
	{
		Case& c = cases[k];
		if (!c.solve)
		{
			if (c.mode == "common")
				c.solve = [&c] { return SolveCommonLevel(*c.a, c.pa, *c.b, c.pb); };
			else
				c.solve = [&c] { return SolveScaleA(*c.a, c.pa, *c.b, c.pb); };
		}
		LevelResult r;
		std::vector<double> times;
		for (int i = 0; i < repeats; ++i)
		{
			const auto t0 = std::chrono::steady_clock::now();
			r = c.solve();
			times.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
		}
		std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
		failures += !r.Ok();
		Json j;
		j["name"] = c.name;
		j["description"] = c.description;
		j["mode"] = c.mode;
		j["method"] = MethodName(r.method);
		j["status"] = StatusName(r.status);
		if (!r.Ok())
			j["failure"] = r.failure;
		j["level"] = r.level;
		j["point"] = Vec(r.point);
		j["normal"] = Vec(r.normal);
		j["iterations"] = r.iterations;
		j["median_time_us"] = times[times.size() / 2];
		j["a"] = c.a->Describe();
		j["b"] = c.b->Describe();
		j["pose_a"] = Json::array({c.pa.p.x, c.pa.p.y, c.pa.q.Angle()});
		j["pose_b"] = Json::array({c.pb.p.x, c.pb.p.y, c.pb.q.Angle()});
		j["poses"] = c.ownPoses ? "ours: the paper's table of poses is missing" : "the paper's";
		if (c.paperLevel > 0.0)
		{
			j["paper_level"] = c.paperLevel;
			j["paper_point"] = Vec(c.paperPoint);
			j["note"] = "the paper's grid value is the smallest level over a finite set of surface samples: an upper bound "
			            "that the refinement between samples lowers to the exact minimum";
		}
		list.push_back(j);
		Draw(c, r, opt.out + "/" + c.name + ".svg");
		progress.Report(double(k + 1) / cases.size(), c.name);
	}
	Json summary;
	summary["demo"] = "b2a_demo_contacts";
	summary["quick"] = opt.quick;
	summary["cases"] = list;
	summary["failures"] = failures;
	WriteJson(opt.out + "/summary.json", summary);
	std::printf("b2a_demo_contacts: %zu cases, %d failed, 1000:1 ellipses level %.10g (paper %.6g); pictures and summary.json in %s\n",
	            cases.size(), failures, list[7]["level"].get<double>(), 13.6177, opt.out.c_str());
	return failures == 0 ? 0 : 1;
}

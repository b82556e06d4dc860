// b2analytic demo: the paper's contact cases (its Figures 2, 3, 6, 7, 9 and 16), solved exactly,
// with pictures of the particles, their rescaled outlines and the contact points.
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/PaperCases.h"
#include "common/Svg.h"

#include "b2analytic/b2analytic.h"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
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

using Case = ContactCase;

Json Vec(Vec2 v)
{
	return Json::array({v.x, v.y});
}

// The outline of a posed shape at a level where it crosses the square of half-size `half` about
// `centre` (world), sampled densely there: a first pass over the polar angles around the centre's
// finds the stretch that crosses the square, a second samples that stretch (with a margin) finely.
std::vector<Vec2> OutlineNear(const Shape& shape, const Pose& pose, double level, Vec2 centre, double half)
{
	const Vec2 x = ToBody(pose, centre);
	const double theta = std::atan2(x.y, x.x);
	const double spread = std::min(kPi, 3.0 * half / std::max(Length(x), 1e-300));
	auto near = [&](Vec2 p) { return std::fabs(p.x - centre.x) <= 2.0 * half && std::fabs(p.y - centre.y) <= 2.0 * half; };
	double lo = 1e300, hi = -1e300;
	const int coarse = 4000;
	for (int k = 0; k <= coarse; ++k)
	{
		const double t = theta - spread + 2.0 * spread * k / coarse;
		if (near(ToWorld(pose, shape.SurfacePoint(t, level))))
		{
			lo = std::min(lo, t);
			hi = std::max(hi, t);
		}
	}
	std::vector<Vec2> points;
	if (!(hi >= lo))
		return points;
	const double margin = std::max(0.5 * (hi - lo), 2.0 * spread / coarse);
	const int fine = 600;
	for (int k = 0; k <= fine; ++k)
		points.push_back(ToWorld(pose, shape.SurfacePoint(lo - margin + (hi - lo + 2.0 * margin) * k / fine, level)));
	return points;
}

// The picture's styles: A blue, B orange, each rescaled outline dashed in its particle's colour.
const Style kA{palette::blue, palette::blue, 1.5, "", 0.3}, kB{palette::orange, palette::vermillion, 1.5, "", 0.45};
const Style kRescaledA{"none", palette::blue, 1.5, "6,4", 1.0}, kRescaledB{"none", palette::vermillion, 1.5, "6,4", 1.0};
const Style kNormal{"none", palette::black, 2.0, "", 1.0}, kContact{palette::black, "none", 1.0, "", 1.0};
const Style kPaper{palette::green, "none", 1.0, "", 1.0};

// The top-left pixel corner of a `size` square in a corner of the band between pixel rows y0
// and y1 that the fewest outline points fall into: where a magnified view hides the least.
Vec2 InsetCorner(const SvgCanvas& svg, const std::vector<std::vector<Vec2>>& outlines, double size, double y0, double y1)
{
	const Vec2 corners[] = {{12.0, y1 - size - 4.0}, {svg.Width() - size - 12.0, y1 - size - 4.0}, {12.0, y0 + 4.0},
	                        {svg.Width() - size - 12.0, y0 + 4.0}};
	Vec2 best = corners[0];
	size_t fewest = ~size_t(0);
	for (Vec2 c : corners)
	{
		size_t inside = 0;
		for (const auto& outline : outlines)
			for (Vec2 p : outline)
			{
				const Vec2 q = svg.PixelOf(p);
				inside += q.x >= c.x - 8.0 && q.x <= c.x + size + 8.0 && q.y >= c.y - 8.0 && q.y <= c.y + size + 8.0;
			}
		if (inside < fewest)
		{
			fewest = inside;
			best = c;
		}
	}
	return best;
}

// A magnified view of the contact point and the paper's point (apart by far less than a pixel of
// the whole picture), with its own scale bar, at pixel (x, y) of `svg`.
void DrawInset(SvgCanvas& svg, const Case& c, const LevelResult& r, double levelA, double levelB, Vec2 at, double size)
{
	const double x = at.x, y = at.y;
	const Vec2 centre = 0.5 * (r.point + c.paperPoint);
	const double half = std::max(2.5 * Length(r.point - c.paperPoint), 1e-9 * Length(r.point));
	SvgCanvas inset(centre - Vec2(half, half), centre + Vec2(half, half), size);
	inset.Polyline(OutlineNear(*c.a, c.pa, levelA, centre, half), kRescaledA);
	inset.Polyline(OutlineNear(*c.b, c.pb, levelB, centre, half), {"none", palette::vermillion, 1.5, "", 1.0});
	inset.Dot(c.paperPoint, 5.0, palette::green);
	inset.Dot(r.point, 5.0, palette::black);
	const double bar = RoundLength(0.4 * half);
	inset.ScaleBar(10.0, size - 8.0, bar, LengthLabel(bar, "mm"));
	inset.Label(8.0, 16.0, "magnified around the contact", 12);
	svg.Embed(inset, x, y);
	// Where the view is: a ring around the point in the whole picture.
	const Vec2 ring = svg.PixelOf(r.point);
	svg.Label(ring.x + 10.0, ring.y + 18.0, "magnified", 11);
	svg.Circle(r.point, 8.0 / svg.Pixels(1.0), {"none", palette::black, 1.0, "", 1.0});
}

// Picture of a case: particles filled, rescaled outlines dashed, contact point and normal, a key
// and a scale bar; for the paper's 1000:1 case also the paper's point, in a magnified view.
void Draw(const Case& c, const LevelResult& r, const std::string& path)
{
	const bool common = c.mode == "common";
	const bool paper = c.paperLevel > 0.0;
	// Outlines: A at the level found (common: both at C; scale_a: A at its level, B as is).
	const double levelA = r.level * (common ? c.a->SurfaceLevel() : 1.0);
	const double levelB = common ? r.level * c.b->SurfaceLevel() : c.b->SurfaceLevel();
	std::vector<std::vector<Vec2>> shapes = {Outline(*c.a, c.pa), Outline(*c.b, c.pb), Outline(*c.a, c.pa, levelA),
	                                         Outline(*c.b, c.pb, levelB)};
	std::vector<KeyEntry> key = {{KeyEntry::Kind::area, kA, "particle A"}, {KeyEntry::Kind::area, kB, "particle B"}};
	if (common)
	{
		key.push_back({KeyEntry::Kind::line, kRescaledA, "A rescaled to the common level"});
		key.push_back({KeyEntry::Kind::line, kRescaledB, "B rescaled to the common level"});
	}
	else
		key.push_back({KeyEntry::Kind::line, kRescaledA, "A rescaled to touch B"});
	key.push_back({KeyEntry::Kind::dot, kContact, "contact point"});
	key.push_back({KeyEntry::Kind::arrow, kNormal, "normal, from A to B"});
	if (paper)
		key.push_back({KeyEntry::Kind::dot, kPaper, "the paper's point"});
	Vec2 lo(1e300, 1e300), hi(-1e300, -1e300);
	for (const auto& s : shapes)
		for (Vec2 p : s)
		{
			lo = Vec2(std::min(lo.x, p.x), std::min(lo.y, p.y));
			hi = Vec2(std::max(hi.x, p.x), std::max(hi.y, p.y));
		}
	// Around the outlines: a margin, a band on top for the text, one below for the key and the
	// scale bar.
	const double pixelWidth = 720.0, pad = 0.06 * std::max(hi.x - lo.x, hi.y - lo.y);
	const double perUnit = pixelWidth / (hi.x - lo.x + 2.0 * pad);
	const double top = 90.0 / perUnit, bottom = (SvgCanvas::KeySize(key).y + 16.0) / perUnit;
	SvgCanvas svg(lo - Vec2(pad, pad + bottom), hi + Vec2(pad, pad + top), pixelWidth);
	svg.Polygon(shapes[0], kA);
	svg.Polygon(shapes[1], kB);
	svg.Polygon(shapes[2], kRescaledA);
	svg.Polygon(shapes[3], kRescaledB);
	svg.Dot(c.pa.p, 3.0, palette::blue);
	svg.Dot(c.pb.p, 3.0, palette::vermillion);
	svg.Arrow(r.point, r.point + 0.12 * (hi.x - lo.x) * r.normal, kNormal);
	svg.Dot(r.point, 4.0, palette::black);
	char line[256];
	std::snprintf(line, sizeof(line), "%s: level %.10g at (%.6f, %.6f), %s", c.mode.c_str(), r.level, r.point.x, r.point.y,
	              MethodName(r.method));
	svg.Label(10, 22, c.name, 16);
	svg.Label(10, 41, c.description, 12, "#333333");
	svg.Label(10, 60, line, 13);
	if (paper)
	{
		std::snprintf(line, sizeof(line), "the paper: %.6g at (%.4f, %.4f)", c.paperLevel, c.paperPoint.x, c.paperPoint.y);
		svg.Label(10, 78, line, 13, palette::green);
		const double keyTop = svg.Height() - SvgCanvas::KeySize(key).y - 16.0;
		DrawInset(svg, c, r, levelA, levelB, InsetCorner(svg, shapes, 250.0, 90.0, keyTop), 250.0);
	}
	else if (c.ownPoses)
		svg.Label(10, 78, "poses: ours (the paper's table is missing)", 13, "#555555");
	const Vec2 keySize = SvgCanvas::KeySize(key);
	svg.Key(8.0, svg.Height() - keySize.y - 8.0, key);
	const double bar = RoundLength(0.2 * (hi.x - lo.x));
	svg.ScaleBar(svg.Width() - svg.Pixels(bar) - 20.0, svg.Height() - 10.0, bar, LengthLabel(bar, "mm"));
	WriteText(path, svg.Finish());
}
} // namespace

int main(int argc, char** argv)
{
	const DemoOptions opt = CommandLine("b2a_demo_contacts", kHelp).Parse(argc, argv);
	Progress progress("b2a_demo_contacts");
	std::vector<Case> cases = PaperContactCases();

	const int repeats = opt.quick ? 15 : 201;
	Json list = Json::array();
	int failures = 0;
	for (size_t k = 0; k < cases.size(); ++k)
	{
		const Case& c = cases[k];
		LevelResult r;
		std::vector<double> times;
		for (int i = 0; i < repeats; ++i)
		{
			const auto t0 = std::chrono::steady_clock::now();
			r = c.Solve();
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

// b2analytic demos: line and scatter plots as SVG.
#include "Plot.h"

#include "Svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace b2a::demo
{

namespace
{
// Pixels between the frame and the outermost data, so that markers and line ends stay inside.
constexpr double kInset = 10.0;

std::string Format(const char* format, double v)
{
	char b[64];
	std::snprintf(b, sizeof(b), format, v);
	return b;
}

// 10 with the exponent k as superscript digits ("10⁻¹⁶").
std::string PowerOfTen(int k)
{
	static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
	std::string s = "10";
	if (k < 0)
		s += "⁻";
	const std::string e = std::to_string(std::abs(k));
	for (char c : e)
		s += digits[c - '0'];
	return s;
}

// A tick value m·10^k (m = 1, 2 or 5) as a plain number where it is short ("0.002", "500"),
// else as "5×10⁻⁶" (or "10⁻⁵" for m = 1).
std::string LogTickLabel(double m, int k)
{
	if (k >= -3 && k <= 4)
		return Format("%g", m * std::pow(10.0, k));
	return m == 1.0 ? PowerOfTen(k) : Format("%g", m) + "×" + PowerOfTen(k);
}

struct Tick
{
	double at;         // position in axis units (log10 of the value on a log axis)
	std::string label; // its label
};

// About five round values spanning [lo, hi].
std::vector<Tick> LinearTicks(double lo, double hi)
{
	const double span = hi - lo;
	const double raw = span / 5.0;
	const double mag = std::pow(10.0, std::floor(std::log10(raw)));
	const double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2.0 * mag : raw / mag < 7.5 ? 5.0 * mag : 10.0 * mag;
	std::vector<Tick> t;
	for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step)
	{
		const double at = std::fabs(v) < 1e-12 * span ? 0.0 : v;
		t.push_back({at, Format("%g", at)});
	}
	return t;
}

// Powers of ten in [lo, hi] (log10 units), every `step`-th where there are more than ten; over
// three decades or less also 2 and 5 times them, labelled as plain numbers.
std::vector<Tick> LogTicks(double lo, double hi)
{
	std::vector<Tick> t;
	const double eps = 1e-9 * (hi - lo);
	if (hi - lo <= 3.0)
	{
		for (int k = int(std::floor(lo)); k <= int(std::ceil(hi)); ++k)
			for (double m : {1.0, 2.0, 5.0})
			{
				const double at = k + std::log10(m);
				if (at >= lo - eps && at <= hi + eps)
					t.push_back({at, LogTickLabel(m, k)});
			}
		if (t.size() >= 3)
			return t;
		// Less than a decade or so: round values of the numbers themselves, placed logarithmically.
		t.clear();
		for (const Tick& v : LinearTicks(std::pow(10.0, lo), std::pow(10.0, hi)))
			if (v.at > 0.0)
				t.push_back({std::log10(v.at), v.label});
		return t;
	}
	const int step = std::max(1, int(std::ceil((hi - lo) / 10.0)));
	for (int k = int(std::ceil(lo - eps)); k <= hi + eps; ++k)
		if (k % step == 0)
			t.push_back({double(k), PowerOfTen(k)});
	return t;
}

// One axis: the data range in axis units and the pixels it maps to.
struct Axis
{
	bool log = false;
	double lo = 0.0, hi = 1.0; // axis units
	double p0 = 0.0, p1 = 1.0; // pixels of lo and hi

	bool Usable(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
	double Units(double v) const { return log ? std::log10(v) : v; }
	double PixelOfUnits(double u) const { return p0 + (u - lo) / (hi - lo) * (p1 - p0); }
	double Pixel(double v) const { return PixelOfUnits(Units(v)); }
	std::vector<Tick> Ticks() const { return log ? LogTicks(lo, hi) : LinearTicks(lo, hi); }
};

// The range of the usable values of every series' x (or y), widened where it is empty or a
// point: on a linear axis by 4 % on each side, on a log y axis to whole decades.
void SetRange(Axis& axis, const std::vector<Series>& series, bool ofX, bool wholeDecades)
{
	double lo = std::numeric_limits<double>::infinity(), hi = -lo;
	for (const Series& s : series)
		for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
		{
			const double v = ofX ? s.x[i] : s.y[i], other = ofX ? s.y[i] : s.x[i];
			if (!axis.Usable(v) || !std::isfinite(other))
				continue;
			lo = std::min(lo, axis.Units(v));
			hi = std::max(hi, axis.Units(v));
		}
	if (!std::isfinite(lo))
	{
		lo = 0.0;
		hi = 1.0;
	}
	if (!(hi > lo))
	{
		const double half = axis.log ? 0.5 : std::max(0.5 * std::fabs(lo), 0.5);
		lo -= half;
		hi += half;
	}
	else if (axis.log && wholeDecades)
	{
		lo = std::floor(lo);
		hi = std::ceil(hi);
	}
	else if (!axis.log)
	{
		const double pad = 0.04 * (hi - lo);
		lo -= pad;
		hi += pad;
	}
	axis.lo = lo;
	axis.hi = hi;
}

struct Box
{
	double x0, y0, x1, y1;
};

// Whether the segment from (ax, ay) to (bx, by) meets the box (Liang–Barsky clipping).
bool SegmentMeetsBox(double ax, double ay, double bx, double by, const Box& r)
{
	double t0 = 0.0, t1 = 1.0;
	const double dx = bx - ax, dy = by - ay;
	const double p[4] = {-dx, dx, -dy, dy};
	const double q[4] = {ax - r.x0, r.x1 - ax, ay - r.y0, r.y1 - ay};
	for (int i = 0; i < 4; ++i)
	{
		if (p[i] == 0.0)
		{
			if (q[i] < 0.0)
				return false;
			continue;
		}
		const double t = q[i] / p[i];
		if (p[i] < 0.0)
			t0 = std::max(t0, t);
		else
			t1 = std::min(t1, t);
		if (t0 > t1)
			return false;
	}
	return true;
}

// Pixel points of a series between two unusable values (a line breaks there).
using Run = std::vector<std::pair<double, double>>;

// The pixel points of a series, in runs.
std::vector<Run> Runs(const Series& s, const Axis& ax, const Axis& ay)
{
	std::vector<Run> runs(1);
	for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
	{
		if (!ax.Usable(s.x[i]) || !ay.Usable(s.y[i]))
		{
			if (!runs.back().empty())
				runs.emplace_back();
			continue;
		}
		runs.back().emplace_back(ax.Pixel(s.x[i]), ay.Pixel(s.y[i]));
	}
	if (runs.back().empty())
		runs.pop_back();
	return runs;
}

// Whether no marker (of `radius`) and no line segment of the series comes within 4 pixels of
// the box.
bool NoDataIn(const Box& box, const std::vector<Series>& series, const std::vector<std::vector<Run>>& runs, double radius)
{
	const Box grown{box.x0 - 4, box.y0 - 4, box.x1 + 4, box.y1 + 4};
	for (size_t k = 0; k < series.size(); ++k)
		for (const auto& run : runs[k])
			for (size_t i = 0; i < run.size(); ++i)
			{
				const auto& [x, y] = run[i];
				if (series[k].points || run.size() == 1)
				{
					if (x >= grown.x0 - radius && x <= grown.x1 + radius && y >= grown.y0 - radius && y <= grown.y1 + radius)
						return false;
				}
				else if (i > 0 && SegmentMeetsBox(run[i - 1].first, run[i - 1].second, x, y, grown))
					return false;
			}
	return true;
}

// A marker of `shape` centred at (x, y), `r` pixels in radius.
std::string MarkerSvg(Marker shape, double x, double y, double r, const std::string& colour)
{
	char b[256];
	switch (shape)
	{
	case Marker::square:
		std::snprintf(b, sizeof(b), "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>\n", x - 0.85 * r, y - 0.85 * r,
		              1.7 * r, 1.7 * r, colour.c_str());
		break;
	case Marker::triangle:
		std::snprintf(b, sizeof(b), "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"%s\"/>\n", x, y - 1.15 * r, x + r, y + 0.75 * r,
		              x - r, y + 0.75 * r, colour.c_str());
		break;
	case Marker::diamond:
		std::snprintf(b, sizeof(b), "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"%s\"/>\n", x, y - 1.2 * r, x + r, y, x,
		              y + 1.2 * r, x - r, y, colour.c_str());
		break;
	case Marker::triangleDown:
		std::snprintf(b, sizeof(b), "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"%s\"/>\n", x, y + 1.15 * r, x + r, y - 0.75 * r,
		              x - r, y - 0.75 * r, colour.c_str());
		break;
	case Marker::circle:
	default:
		std::snprintf(b, sizeof(b), "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\"/>\n", x, y, r, colour.c_str());
		break;
	}
	return b;
}

std::string TextSvg(double x, double y, const std::string& text, const char* anchor, int size, const char* extra = "")
{
	char b[256];
	std::snprintf(b, sizeof(b), "<text x=\"%.1f\" y=\"%.1f\" font-family=\"sans-serif\" font-size=\"%d\" text-anchor=\"%s\"%s>", x, y, size,
	              anchor, extra);
	return b + Escape(text) + "</text>\n";
}

std::string LineSvg(double ax, double ay, double bx, double by, const char* colour, double width)
{
	char b[200];
	std::snprintf(b, sizeof(b), "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%.1f\"/>\n", ax, ay, bx, by,
	              colour, width);
	return b;
}
} // namespace

std::string LinePlot(const std::vector<Series>& series, const std::string& title, const std::string& xLabel,
                     const std::string& yLabel, bool logY, bool logX)
{
	const double markerRadius = 4.0;
	Axis ax, ay;
	ax.log = logX;
	ay.log = logY;
	SetRange(ax, series, true, false);
	SetRange(ay, series, false, true);

	// Frame: the left margin holds the widest y tick label and the y label.
	double tickWidth = 0.0;
	for (const Tick& t : ay.Ticks())
		tickWidth = std::max(tickWidth, TextWidth(t.label, 12));
	const double top = 44, bottom = 56, left = std::max(64.0, tickWidth + 42.0);
	double W = 720;
	const double H = 440, pw = W - left - 20, ph = H - top - bottom;
	ax.p0 = left + kInset;
	ax.p1 = left + pw - kInset;
	ay.p0 = top + ph - kInset;
	ay.p1 = top + kInset;

	// Legend: in the first corner of the frame that no data crosses, else beside the frame.
	double textWidth = 0.0;
	for (const Series& s : series)
		textWidth = std::max(textWidth, TextWidth(s.name, 12));
	const double rowHeight = 18, boxW = 46 + textWidth, boxH = 8 + rowHeight * series.size();
	std::vector<std::vector<Run>> runs;
	for (const Series& s : series)
		runs.push_back(Runs(s, ax, ay));
	auto free = [&](const Box& box) { return NoDataIn(box, series, runs, markerRadius); };
	const double gap = 8;
	const Box corners[] = {{left + pw - gap - boxW, top + gap, left + pw - gap, top + gap + boxH},
	                       {left + gap, top + gap, left + gap + boxW, top + gap + boxH},
	                       {left + pw - gap - boxW, top + ph - gap - boxH, left + pw - gap, top + ph - gap},
	                       {left + gap, top + ph - gap - boxH, left + gap + boxW, top + ph - gap}};
	Box legend{left + pw + 16, top, left + pw + 16 + boxW, top + boxH};
	bool inside = false;
	for (const Box& c : corners)
		if (free(c))
		{
			legend = c;
			inside = true;
			break;
		}
	if (!inside)
		W = legend.x1 + 12;

	std::string body;
	// Grid, ticks and frame.
	double lastLabelEnd = -1e300; // x ticks whose labels would touch the previous one are left out
	for (const Tick& t : ax.Ticks())
	{
		const double x = ax.PixelOfUnits(t.at), half = 0.5 * TextWidth(t.label, 12);
		if (x - half < lastLabelEnd + 8.0)
			continue;
		lastLabelEnd = x + half;
		body += LineSvg(x, top, x, top + ph, "#e8e8e8", 1.0);
		body += LineSvg(x, top + ph, x, top + ph + 5, "#333", 1.0);
		body += TextSvg(x, top + ph + 19, t.label, "middle", 12);
	}
	for (const Tick& t : ay.Ticks())
	{
		const double y = ay.PixelOfUnits(t.at);
		body += LineSvg(left, y, left + pw, y, "#e8e8e8", 1.0);
		body += LineSvg(left - 5, y, left, y, "#333", 1.0);
		body += TextSvg(left - 8, y + 4, t.label, "end", 12);
	}
	char buf[256];
	std::snprintf(buf, sizeof(buf), "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#333\" stroke-width=\"1\"/>\n", left,
	              top, pw, ph);
	body += buf;
	// Data: lines first, markers over them.
	for (int pass = 0; pass < 2; ++pass)
		for (size_t k = 0; k < series.size(); ++k)
		{
			const Series& s = series[k];
			for (const auto& run : runs[k])
			{
				if (pass == 1 && (s.points || run.size() == 1))
					for (const auto& [x, y] : run)
						body += MarkerSvg(s.marker, x, y, markerRadius, s.colour);
				if (pass == 0 && !s.points && run.size() > 1)
				{
					body += "<polyline fill=\"none\" stroke=\"" + s.colour + "\" stroke-width=\"2\" stroke-linejoin=\"round\" points=\"";
					for (const auto& [x, y] : run)
						body += Format("%.1f,", x) + Format("%.1f ", y);
					body += "\"/>\n";
				}
			}
		}
	// Legend: each entry drawn as its series is, a marker or a stretch of line.
	if (!series.empty())
	{
		std::snprintf(buf, sizeof(buf),
		              "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"#bbb\" stroke-width=\"1\"/>\n",
		              legend.x0, legend.y0, boxW, boxH);
		body += buf;
	}
	for (size_t k = 0; k < series.size(); ++k)
	{
		const double y = legend.y0 + 4 + rowHeight * (k + 0.5);
		if (series[k].points)
			body += MarkerSvg(series[k].marker, legend.x0 + 20, y, markerRadius, series[k].colour);
		else
			body += LineSvg(legend.x0 + 8, y, legend.x0 + 32, y, series[k].colour.c_str(), 2.0);
		body += TextSvg(legend.x0 + 40, y + 4, series[k].name, "start", 12);
	}
	body += TextSvg(left + pw / 2, 26, title, "middle", 15);
	body += TextSvg(left + pw / 2, H - 14, xLabel, "middle", 13);
	std::snprintf(buf, sizeof(buf), " transform=\"rotate(-90 18 %.1f)\"", top + ph / 2);
	body += TextSvg(18, top + ph / 2, yLabel, "middle", 13, buf);
	std::snprintf(buf, sizeof(buf), "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n", W, H, W, H);
	return std::string(buf) + "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body + "</svg>\n";
}

} // namespace b2a::demo

// b2analytic demos: line plots as SVG.
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
std::string Tick(double v)
{
	char b[32];
	std::snprintf(b, sizeof(b), "%g", v);
	return b;
}

// About five round tick values spanning [lo, hi].
std::vector<double> Ticks(double lo, double hi)
{
	const double span = hi - lo;
	if (!(span > 0.0))
		return {lo};
	const double raw = span / 5.0;
	const double mag = std::pow(10.0, std::floor(std::log10(raw)));
	const double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2.0 * mag : raw / mag < 7.5 ? 5.0 * mag : 10.0 * mag;
	std::vector<double> t;
	for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step)
		t.push_back(std::fabs(v) < 1e-12 * span ? 0.0 : v);
	return t;
}
} // namespace

std::string LinePlot(const std::vector<Series>& series, const std::string& title, const std::string& xLabel,
                     const std::string& yLabel, bool logY)
{
	double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
	auto Y = [&](double y) { return logY ? std::log10(y) : y; };
	for (const Series& s : series)
		for (size_t i = 0; i < s.x.size(); ++i)
		{
			if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || (logY && !(s.y[i] > 0.0)))
				continue;
			x0 = std::min(x0, s.x[i]);
			x1 = std::max(x1, s.x[i]);
			y0 = std::min(y0, Y(s.y[i]));
			y1 = std::max(y1, Y(s.y[i]));
		}
	if (!std::isfinite(x0))
	{
		x0 = 0.0;
		x1 = 1.0;
		y0 = 0.0;
		y1 = 1.0;
	}
	if (logY)
	{
		y0 = std::floor(y0);
		y1 = std::ceil(y1);
	}
	if (!(y1 > y0))
		y1 = y0 + 1.0;
	if (!(x1 > x0))
		x1 = x0 + 1.0;
	if (!logY)
	{
		const double pad = 0.05 * (y1 - y0);
		y0 -= pad;
		y1 += pad;
	}
	// Plot area in pixels.
	const double W = 720, H = 440, left = 80, right = 20, top = 40, bottom = 60;
	const double pw = W - left - right, ph = H - top - bottom;
	auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * pw; };
	auto py = [&](double y) { return top + (1.0 - (Y(y) - y0) / (y1 - y0)) * ph; };
	auto pyRaw = [&](double yy) { return top + (1.0 - (yy - y0) / (y1 - y0)) * ph; };
	std::string body;
	char buf[256];
	auto line = [&](double ax, double ay, double bx, double by, const char* colour, double width) {
		std::snprintf(buf, sizeof(buf), "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"%.1f\"/>\n", ax, ay, bx,
		              by, colour, width);
		body += buf;
	};
	auto text = [&](double x, double y, const std::string& t, const char* anchor, int size) {
		std::snprintf(buf, sizeof(buf), "<text x=\"%.1f\" y=\"%.1f\" font-family=\"sans-serif\" font-size=\"%d\" text-anchor=\"%s\">", x, y, size,
		              anchor);
		body += buf + Escape(t) + "</text>\n";
	};
	line(left, top, left, top + ph, "#333", 1.0);
	line(left, top + ph, left + pw, top + ph, "#333", 1.0);
	for (double t : Ticks(x0, x1))
	{
		line(px(t), top + ph, px(t), top + ph + 5, "#333", 1.0);
		line(px(t), top, px(t), top + ph, "#eee", 1.0);
		text(px(t), top + ph + 20, Tick(t), "middle", 12);
	}
	if (logY)
		for (double d = y0; d <= y1 + 1e-9; d += 1.0)
		{
			line(left - 5, pyRaw(d), left + pw, pyRaw(d), "#eee", 1.0);
			text(left - 8, pyRaw(d) + 4, "1e" + Tick(d), "end", 12);
		}
	else
		for (double t : Ticks(y0, y1))
		{
			line(left - 5, pyRaw(t), left + pw, pyRaw(t), "#eee", 1.0);
			text(left - 8, pyRaw(t) + 4, Tick(t), "end", 12);
		}
	for (const Series& s : series)
	{
		std::string pts;
		for (size_t i = 0; i < s.x.size(); ++i)
		{
			if (!std::isfinite(s.y[i]) || (logY && !(s.y[i] > 0.0)))
				continue;
			if (s.points)
			{
				std::snprintf(buf, sizeof(buf), "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" fill=\"%s\"/>\n", px(s.x[i]), py(s.y[i]),
				              s.colour.c_str());
				body += buf;
			}
			else
			{
				std::snprintf(buf, sizeof(buf), "%.1f,%.1f ", px(s.x[i]), py(s.y[i]));
				pts += buf;
			}
		}
		if (!pts.empty())
			body += "<polyline fill=\"none\" stroke=\"" + s.colour + "\" stroke-width=\"1.8\" points=\"" + pts + "\"/>\n";
	}
	for (size_t k = 0; k < series.size(); ++k)
	{
		const double ly = top + 16 + 18 * k;
		line(left + pw - 190, ly - 4, left + pw - 165, ly - 4, series[k].colour.c_str(), 3.0);
		text(left + pw - 158, ly, series[k].name, "start", 12);
	}
	text(W / 2, 24, title, "middle", 15);
	text(left + pw / 2, H - 15, xLabel, "middle", 13);
	std::snprintf(buf, sizeof(buf), "<text x=\"18\" y=\"%.1f\" font-family=\"sans-serif\" font-size=\"13\" text-anchor=\"middle\" transform=\"rotate(-90 18 %.1f)\">",
	              top + ph / 2, top + ph / 2);
	body += buf + Escape(yLabel) + "</text>\n";
	std::snprintf(buf, sizeof(buf), "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n", W, H, W, H);
	return std::string(buf) + "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body + "</svg>\n";
}

} // namespace b2a::demo

// b2analytic demos: SVG writer.
#include "Svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace b2a::demo
{

namespace
{
std::string Num(double v)
{
	char b[32];
	std::snprintf(b, sizeof(b), "%.1f", v); // a tenth of a pixel
	return b;
}
} // namespace

std::string Escape(const std::string& text)
{
	std::string out;
	for (char c : text)
	{
		switch (c)
		{
		case '<': out += "&lt;"; break;
		case '>': out += "&gt;"; break;
		case '&': out += "&amp;"; break;
		case '"': out += "&quot;"; break;
		default: out += c;
		}
	}
	return out;
}

SvgCanvas::SvgCanvas(Vec2 lower, Vec2 upper, double pixelWidth) : m_lower(lower)
{
	const double w = std::max(upper.x - lower.x, 1e-300), h = std::max(upper.y - lower.y, 1e-300);
	m_scale = pixelWidth / w;
	m_width = pixelWidth;
	m_height = h * m_scale;
	m_body += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

std::string SvgCanvas::Point(Vec2 p) const
{
	return Num((p.x - m_lower.x) * m_scale) + "," + Num(m_height - (p.y - m_lower.y) * m_scale);
}

std::string SvgCanvas::Attributes(const Style& s)
{
	std::string a = " fill=\"" + s.fill + "\" stroke=\"" + s.stroke + "\" stroke-width=\"" + Num(s.width) + "\"";
	if (!s.dash.empty())
		a += " stroke-dasharray=\"" + s.dash + "\"";
	if (s.opacity < 1.0)
		a += " fill-opacity=\"" + Num(s.opacity) + "\"";
	return a;
}

void SvgCanvas::Polygon(const std::vector<Vec2>& points, const Style& style)
{
	m_body += "<polygon points=\"";
	for (Vec2 p : points)
		m_body += Point(p) + " ";
	m_body += "\"" + Attributes(style) + " stroke-linejoin=\"round\"/>\n";
}

void SvgCanvas::Polyline(const std::vector<Vec2>& points, const Style& style)
{
	m_body += "<polyline points=\"";
	for (Vec2 p : points)
		m_body += Point(p) + " ";
	m_body += "\"" + Attributes(style) + " stroke-linejoin=\"round\"/>\n";
}

void SvgCanvas::Circle(Vec2 centre, double radius, const Style& style)
{
	const std::string c = Point(centre);
	const size_t comma = c.find(',');
	m_body += "<circle cx=\"" + c.substr(0, comma) + "\" cy=\"" + c.substr(comma + 1) + "\" r=\"" + Num(radius * m_scale) +
	          "\"" + Attributes(style) + "/>\n";
}

void SvgCanvas::Dot(Vec2 centre, double pixels, const std::string& colour)
{
	Style s;
	s.fill = colour;
	s.stroke = "none";
	Circle(centre, pixels / m_scale, s);
}

void SvgCanvas::Arrow(Vec2 a, Vec2 b, const Style& style)
{
	Polyline({a, b}, style);
	const Vec2 d = b - a;
	const double len = Length(d);
	if (!(len > 0.0))
		return;
	const Vec2 u = d / len, n = Perp(u);
	const double head = std::min(0.3 * len, 10.0 / m_scale);
	Style fill = style;
	fill.fill = style.stroke;
	fill.dash.clear();
	Polygon({b, b - head * u + 0.4 * head * n, b - head * u - 0.4 * head * n}, fill);
}

void SvgCanvas::Text(Vec2 at, const std::string& text, double size, const std::string& colour)
{
	const std::string c = Point(at);
	const size_t comma = c.find(',');
	m_body += "<text x=\"" + c.substr(0, comma) + "\" y=\"" + c.substr(comma + 1) + "\" font-family=\"sans-serif\" font-size=\"" +
	          Num(size) + "\" fill=\"" + colour + "\">" + Escape(text) + "</text>\n";
}

void SvgCanvas::Label(double x, double y, const std::string& text, double size, const std::string& colour)
{
	m_body += "<text x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" font-family=\"sans-serif\" font-size=\"" + Num(size) +
	          "\" fill=\"" + colour + "\">" + Escape(text) + "</text>\n";
}

double TextWidth(const std::string& text, double size)
{
	int chars = 0;
	for (unsigned char c : text)
		chars += (c & 0xC0) != 0x80; // code points, not bytes
	return 0.6 * size * chars;
}

double RoundLength(double most)
{
	if (!(most > 0.0) || !std::isfinite(most))
		return 1.0;
	const double power = std::pow(10.0, std::floor(std::log10(most)));
	const double lead = most / power;
	return (lead >= 5.0 ? 5.0 : lead >= 2.0 ? 2.0 : 1.0) * power;
}

std::string LengthLabel(double length, const std::string& unit)
{
	char b[64];
	std::snprintf(b, sizeof(b), "%g %s", length, unit.c_str());
	return b;
}

void SvgCanvas::ScaleBar(double x, double y, double length, const std::string& label)
{
	const double w = Pixels(length);
	char b[320];
	std::snprintf(b, sizeof(b),
	              "<path d=\"M%s,%s v6 h%s v-6\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n",
	              Num(x).c_str(), Num(y - 6.0).c_str(), Num(w).c_str());
	m_body += b;
	// The label centred over the bar, but inside the picture where the bar is short.
	const double half = 0.5 * TextWidth(label, 12.0) + 2.0;
	const double centre = std::min(std::max(x + 0.5 * w, half), m_width - half);
	m_body += "<text x=\"" + Num(centre) + "\" y=\"" + Num(y - 10.0) +
	          "\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\">" + Escape(label) + "</text>\n";
}

namespace
{
constexpr double kKeyRow = 18.0, kKeyFont = 12.0, kKeySample = 28.0;
} // namespace

Vec2 SvgCanvas::KeySize(const std::vector<KeyEntry>& entries)
{
	double text = 0.0;
	for (const KeyEntry& e : entries)
		text = std::max(text, TextWidth(e.text, kKeyFont));
	return {8.0 + kKeySample + 8.0 + text + 8.0, 6.0 + kKeyRow * entries.size()};
}

void SvgCanvas::Key(double x, double y, const std::vector<KeyEntry>& entries)
{
	const Vec2 size = KeySize(entries);
	m_body += "<rect x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" width=\"" + Num(size.x) + "\" height=\"" + Num(size.y) +
	          "\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"#bbbbbb\" stroke-width=\"1\"/>\n";
	for (size_t k = 0; k < entries.size(); ++k)
	{
		const KeyEntry& e = entries[k];
		const double cy = y + 3.0 + kKeyRow * (k + 0.5), x0 = x + 8.0, x1 = x0 + kKeySample;
		std::string sample;
		switch (e.kind)
		{
		case KeyEntry::Kind::area:
			sample = "<rect x=\"" + Num(x0 + 6.0) + "\" y=\"" + Num(cy - 6.0) + "\" width=\"16\" height=\"12\" rx=\"3\"" +
			         Attributes(e.style) + "/>\n";
			break;
		case KeyEntry::Kind::line:
			sample = "<line x1=\"" + Num(x0) + "\" y1=\"" + Num(cy) + "\" x2=\"" + Num(x1) + "\" y2=\"" + Num(cy) + "\"" +
			         Attributes(e.style) + "/>\n";
			break;
		case KeyEntry::Kind::dot:
			sample = "<circle cx=\"" + Num(0.5 * (x0 + x1)) + "\" cy=\"" + Num(cy) + "\" r=\"4\" fill=\"" + e.style.fill + "\"/>\n";
			break;
		case KeyEntry::Kind::arrow:
			sample = "<line x1=\"" + Num(x0) + "\" y1=\"" + Num(cy) + "\" x2=\"" + Num(x1 - 7.0) + "\" y2=\"" + Num(cy) +
			         "\" stroke=\"" + e.style.stroke + "\" stroke-width=\"" + Num(e.style.width) + "\"/>\n<polygon points=\"" +
			         Num(x1) + "," + Num(cy) + " " + Num(x1 - 8.0) + "," + Num(cy - 4.0) + " " + Num(x1 - 8.0) + "," + Num(cy + 4.0) +
			         "\" fill=\"" + e.style.stroke + "\"/>\n";
			break;
		}
		m_body += sample;
		m_body += "<text x=\"" + Num(x1 + 8.0) + "\" y=\"" + Num(cy + 4.0) + "\" font-family=\"sans-serif\" font-size=\"" +
		          Num(kKeyFont) + "\">" + Escape(e.text) + "</text>\n";
	}
}

void SvgCanvas::Embed(const SvgCanvas& inset, double x, double y)
{
	m_body += "<svg x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" width=\"" + Num(inset.m_width) + "\" height=\"" +
	          Num(inset.m_height) + "\" viewBox=\"0 0 " + Num(inset.m_width) + " " + Num(inset.m_height) + "\" overflow=\"hidden\">\n" +
	          inset.m_body + "</svg>\n";
	m_body += "<rect x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" width=\"" + Num(inset.m_width) + "\" height=\"" + Num(inset.m_height) +
	          "\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
}

std::string SvgCanvas::Finish() const
{
	return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + Num(m_width) + "\" height=\"" + Num(m_height) +
	       "\" viewBox=\"0 0 " + Num(m_width) + " " + Num(m_height) + "\">\n" + m_body + "</svg>\n";
}

std::vector<Vec2> Outline(const Shape& shape, const Pose& pose, double level, int count)
{
	const auto samples = shape.Samples(count);
	const double L = std::isnan(level) ? shape.SurfaceLevel() : level;
	std::vector<Vec2> out;
	out.reserve(samples->point.size());
	for (size_t i = 0; i < samples->point.size(); ++i)
	{
		const Vec2 p = L == shape.SurfaceLevel() ? samples->point[i] : shape.SurfacePoint(samples->angle[i], L);
		out.push_back(ToWorld(pose, p));
	}
	return out;
}

} // namespace b2a::demo

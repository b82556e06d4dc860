// b2analytic demos: SVG writer.
#include "Svg.h"

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

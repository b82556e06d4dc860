// b2analytic demos: a small SVG writer in world coordinates (y up).
#pragma once

#include "b2analytic/Math.h"
#include "b2analytic/Shape.h"

#include <string>
#include <vector>

namespace b2a::demo
{

/// Drawing style of one element.
struct Style
{
	std::string fill = "none";    ///< fill colour (SVG syntax)
	std::string stroke = "black"; ///< stroke colour
	double width = 1.0;           ///< stroke width in pixels
	std::string dash;             ///< stroke-dasharray in pixels, empty for solid
	double opacity = 1.0;         ///< fill opacity
};

/// An SVG picture of a world-space rectangle, drawn with y up.
class SvgCanvas
{
public:
	/// A canvas showing [lower, upper] at `pixelWidth` pixels wide (height from the aspect).
	SvgCanvas(Vec2 lower, Vec2 upper, double pixelWidth);
	/// Closed polygon.
	void Polygon(const std::vector<Vec2>& points, const Style& style);
	/// Open polyline.
	void Polyline(const std::vector<Vec2>& points, const Style& style);
	/// Circle of a world radius.
	void Circle(Vec2 centre, double radius, const Style& style);
	/// Dot of a pixel radius.
	void Dot(Vec2 centre, double pixels, const std::string& colour);
	/// Arrow from a to b.
	void Arrow(Vec2 a, Vec2 b, const Style& style);
	/// Text at a world point (pixel size).
	void Text(Vec2 at, const std::string& text, double size = 14.0, const std::string& colour = "black");
	/// Text at pixel coordinates from the top-left corner.
	void Label(double x, double y, const std::string& text, double size = 14.0, const std::string& colour = "black");
	/// The finished document.
	std::string Finish() const;
	/// Pixel length of a world length.
	double Pixels(double length) const { return length * m_scale; }

private:
	std::string Point(Vec2 p) const;
	static std::string Attributes(const Style& s);
	Vec2 m_lower;
	double m_scale, m_width, m_height;
	std::string m_body;
};

/// World outline of a posed shape at a level (its own surface when level is NaN), from the
/// shape's cached surface sample angles.
std::vector<Vec2> Outline(const Shape& shape, const Pose& pose, double level = 0.0 / 0.0, int count = 512);

/// XML-escape text.
std::string Escape(const std::string& text);

} // namespace b2a::demo

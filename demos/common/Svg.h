// b2analytic demos: a small SVG writer in world coordinates (y up).
#pragma once

#include "b2analytic/Math.h"
#include "b2analytic/Shape.h"

#include <string>
#include <vector>

namespace b2a::demo
{

/// The Okabe–Ito palette (Okabe and Ito, "Color Universal Design", 2002): eight colours that stay
/// distinct for readers with the common forms of colour blindness. The demos draw with these.
namespace palette
{
inline const char* const blue = "#0072B2";       ///< blue
inline const char* const vermillion = "#D55E00"; ///< vermillion (red-orange)
inline const char* const green = "#009E73";      ///< bluish green
inline const char* const orange = "#E69F00";     ///< orange
inline const char* const purple = "#CC79A7";     ///< reddish purple
inline const char* const skyBlue = "#56B4E9";    ///< sky blue
inline const char* const yellow = "#F0E442";     ///< yellow (faint on white: fills, not lines)
inline const char* const black = "#000000";      ///< black
/// The colours in the order a plot's series take them (yellow last).
inline const char* const series[] = {blue, vermillion, green, orange, purple, skyBlue, black, yellow};
} // namespace palette

/// Drawing style of one element.
struct Style
{
	std::string fill = "none";    ///< fill colour (SVG syntax)
	std::string stroke = "black"; ///< stroke colour
	double width = 1.0;           ///< stroke width in pixels
	std::string dash;             ///< stroke-dasharray in pixels, empty for solid
	double opacity = 1.0;         ///< fill opacity
};

/// An entry of a picture's key: a sample drawn in the entry's style, and its text.
struct KeyEntry
{
	/// How the sample is drawn.
	enum class Kind
	{
		area, ///< a filled square in the style (a particle)
		line, ///< a stretch of line in the style (a wall, an outline, a path)
		dot,  ///< a dot of the style's fill colour (a point)
		arrow ///< an arrow in the style's stroke (a normal)
	};
	Kind kind = Kind::area; ///< the sample's kind
	Style style;            ///< its style
	std::string text;       ///< what it stands for
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
	/// A scale bar of `length` world units with its left end at pixel (x, y), labelled above
	/// with `label` (the length and its unit, e.g. "10 mm").
	void ScaleBar(double x, double y, double length, const std::string& label);
	/// A key: the entries stacked in a white box whose top-left corner is at pixel (x, y).
	void Key(double x, double y, const std::vector<KeyEntry>& entries);
	/// The pixel size of Key's box for these entries (width, height).
	static Vec2 KeySize(const std::vector<KeyEntry>& entries);
	/// `inset` drawn at pixel (x, y), framed and clipped to its own rectangle: a magnified view.
	void Embed(const SvgCanvas& inset, double x, double y);
	/// The finished document.
	std::string Finish() const;
	/// Pixel length of a world length.
	double Pixels(double length) const { return length * m_scale; }
	/// Pixel position (from the top-left corner) of a world point.
	Vec2 PixelOf(Vec2 p) const { return {(p.x - m_lower.x) * m_scale, m_height - (p.y - m_lower.y) * m_scale}; }
	/// Width of the picture in pixels.
	double Width() const { return m_width; }
	/// Height of the picture in pixels.
	double Height() const { return m_height; }

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

/// The largest length 1, 2 or 5 times a power of ten that is at most `most`: a scale bar's.
double RoundLength(double most);

/// A length with its unit for a scale bar's label, e.g. "10 mm" or "0.005 mm".
std::string LengthLabel(double length, const std::string& unit);

/// Width in pixels of a text in sans-serif at `size` pixels: 0.6 em a character, the average of
/// DejaVu Sans (the font rsvg and browsers fall back to), enough to keep texts apart.
double TextWidth(const std::string& text, double size);

/// XML-escape text.
std::string Escape(const std::string& text);

} // namespace b2a::demo

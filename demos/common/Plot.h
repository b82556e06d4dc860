// b2analytic demos: line and scatter plots as SVG.
#pragma once

#include <string>
#include <vector>

namespace b2a::demo
{

/// Marker shapes for plotted points (a series of points gets one; its legend shows the same).
enum class Marker
{
	circle,
	square,
	triangle,
	diamond,
	triangleDown
};

/// One curve or set of points of a plot.
struct Series
{
	std::string name;      ///< legend text
	std::string colour;    ///< SVG colour (see the palette in Svg.h)
	std::vector<double> x; ///< abscissae
	std::vector<double> y; ///< ordinates
	bool points = false;   ///< markers instead of a line
	Marker marker = Marker::circle; ///< the markers' shape, where `points`
};

/// An SVG plot of several series with axes, ticks and a legend. The legend goes into a corner of
/// the plot area that no data crosses, or beside the plot where every corner has data; markers
/// and lines keep a margin from the frame, so nothing is cut at its edge. With logY (logX),
/// non-positive values are left out and that axis is logarithmic, with ticks at powers of ten
/// (and at 2 and 5 times them where the axis spans few decades). Axis labels should carry their
/// unit, e.g. "time (s)".
std::string LinePlot(const std::vector<Series>& series, const std::string& title, const std::string& xLabel,
                     const std::string& yLabel, bool logY = false, bool logX = false);

} // namespace b2a::demo

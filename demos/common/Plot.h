// b2analytic demos: line plots as SVG.
#pragma once

#include <string>
#include <vector>

namespace b2a::demo
{

/// One curve of a plot.
struct Series
{
	std::string name;      ///< legend text
	std::string colour;    ///< SVG colour
	std::vector<double> x; ///< abscissae
	std::vector<double> y; ///< ordinates
	bool points = false;   ///< markers instead of a line
};

/// An SVG line plot of several series with axes, ticks and a legend. With logY, non-positive
/// values are left out and the y axis runs over whole decades.
std::string LinePlot(const std::vector<Series>& series, const std::string& title, const std::string& xLabel,
                     const std::string& yLabel, bool logY = false);

} // namespace b2a::demo

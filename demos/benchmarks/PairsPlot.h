// b2analytic benchmarks: the pair benchmark's picture of time against error.
#pragma once

#include <string>
#include <vector>

namespace b2a::bench
{

/// One method's result on a family of pairs.
struct PairsPlotPoint
{
	std::string method;        ///< the method's name in pairs.csv ("newton_warm", "grid_256", ...)
	double nsPerQuery = 0.0;   ///< median time per query (ns)
	double pointError = 0.0;   ///< largest contact point error over the family's poses, in units of the size
};

/// The SVG plot of a family's methods: time per query against the largest point error, both on
/// log scales. Each kind of method has its colour (Newton, the automatic path, the paper's plain
/// grid, the refined grid, Box2D's polygons, GJK on polygons, Bullet's GJK/EPA on hulls) and each
/// variant of it its marker.
/// Exact answers (error below 1e-17) are plotted at 1e-17 so that they show.
std::string PairsPlot(const std::string& family, const std::vector<PairsPlotPoint>& points);

} // namespace b2a::bench

// b2analytic validation: the area fraction of a packing inside a window, and its free surface.
#pragma once

#include "common/GranularScene.h"

#include <vector>

namespace b2a::demo
{

/// The area fraction of a packing inside a rectangular window.
struct WindowFraction
{
	double sum = 0.0;     ///< Σ over particles of their area inside the window, over the window's area
	double covered = 0.0; ///< the window's covered fraction (overlaps counted once)
	double width = 0.0;   ///< the sampled window's width (whole grid cells)
	double height = 0.0;  ///< the sampled window's height
};

/// The area fraction inside `window`, from the centres of a grid of square cells of side `h`
/// tested against each particle's level function (a cell counts for a particle whose level at
/// its centre is at most the surface level). The window is cut to whole cells from its lower
/// corner. The error is of order h over the particles' size: a cell straddles the outline
/// where the outline crosses it, and those errors have both signs. A window with no whole cell
/// gives zeros.
WindowFraction MeasureWindow(const std::vector<ParticleState>& packing, Box window, double h);

/// The lowest point of a packing's free surface: the box (of `boxWidth`, centred on x = 0) cut
/// into columns at least `column` wide, the top of the highest particle in each, the least of
/// those tops (0 for an empty column).
double FreeSurface(const std::vector<ParticleState>& packing, double boxWidth, double column);

} // namespace b2a::demo

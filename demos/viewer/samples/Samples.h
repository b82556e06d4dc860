// b2a_viewer: the factories of the samples, one file per sample or per category.
#pragma once

#include "Sample.h"

#include <memory>

namespace b2a::viewer
{

// Granular scenes of the demos (demos/common/GranularScene), in millimetres.
std::unique_ptr<Sample> MakeHopperSample();   ///< packing, then discharge through the outlet
std::unique_ptr<Sample> MakePackingSample();  ///< random packing under gravity in a closed box
std::unique_ptr<Sample> MakeBeverlooSample(); ///< 2 × 0.66 mm ellipses through a channel's outlet

// The paper's pair cases.
std::unique_ptr<Sample> MakeContactCasesSample();   ///< the pair inspector on the paper's contact cases
std::unique_ptr<Sample> MakeCollisionCasesSample(); ///< moving pairs: exact first contact against stepping

// Scenes of stacking, rolling and mixing.
std::unique_ptr<Sample> MakeSuperellipseStackSample(); ///< a stack and a pyramid of blocky superellipses
std::unique_ptr<Sample> MakeEllipseSlopeSample();      ///< ellipses rocking on the flat and rolling down a slope
std::unique_ptr<Sample> MakeMixedSample();             ///< analytic particles with Box2D's boxes, circles, edges, chains
std::unique_ptr<Sample> MakeSandboxSample();           ///< the shape editor: spawn any shape into a box

// 3D (drawn by the mesh renderer through the orbiting camera).
std::unique_ptr<Sample> MakeFigure17Sample(); ///< the paper's Figure 17: two superellipsoids colliding

} // namespace b2a::viewer

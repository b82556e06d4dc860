// b2analytic demos: the paper's Figure 17 scene, two superellipsoids in free flight that collide
// (shared by b2a_demo_superellipsoids and the viewer's 3D sample).
#pragma once

#include "b2analytic/3d/SuperellipsoidShape.h"
#include "b2analytic/3d/TimeOfImpact3.h"

#include <memory>

namespace b2a::demo
{

/// The paper reports the first contact of the Figure 17 pair at about this time (ms).
constexpr double kFigure17PaperTime = 0.1924;

/// Two superellipsoids and their motions (lengths in mm, time in ms).
struct Figure17Scene
{
	std::shared_ptr<SuperellipsoidShape> a, b; ///< particle i and particle j
	Motion3 ma, mb;                            ///< their motions from t = 0
};

/// The paper's Figure 17: particle i is |x/4|^6 + |y/4|^6 + |z/4|^12 <= 1 and particle j
/// |x/2|^8 + |y/3|^8 + |z/2|^8 <= 1, centred at (-10, -15, -10) and (-20, -25, -20), turned by
/// the z-x-z Euler angles (pi/9, pi/8, pi/7) and (pi/6, pi/5, pi/4), moving with velocities
/// (-20, -10, -15) and (10, 20, 15) mm/ms and angular velocities (20, -30, 2) and (-10, 20, -2)
/// rad/ms about the world axes. The paper gives neither its Euler convention nor its units: these
/// are the ones that reproduce its contact time.
Figure17Scene MakeFigure17Scene();

/// A world box holding both particles over [0, tEnd], rounded out to multiples of `tick`.
Box3 Figure17SceneBox(const Figure17Scene& s, double tEnd, double tick);

} // namespace b2a::demo

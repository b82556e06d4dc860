// b2analytic demos: the paper's pair cases, shared by the demos and the viewer: its contact
// figures (two particles at fixed poses, rescaled until they touch) and its collision processes
// (two particles moving with constant velocities until they first touch).
#pragma once

#include "b2analytic/b2analytic.h"

#include <string>
#include <vector>

namespace b2a::demo
{

/// A contact case of the paper's Figures 2, 3, 6, 7, 9 and 16.
struct ContactCase
{
	std::string name;        ///< short name (file names, the viewer's list)
	std::string description; ///< what it shows and which figure it is of
	/// "common": both particles rescaled to their common level (SolveCommonLevel); "scale_a": A
	/// rescaled onto B's own surface (SolveScaleA).
	std::string mode;
	ShapePtr a, b;           ///< the shapes
	Pose pa, pb;             ///< their poses
	bool ownPoses = true;    ///< the paper's poses are missing from its text: these are ours
	MethodChoice method = MethodChoice::automatic; ///< the solver asked for
	double paperLevel = 0.0; ///< the paper's level (0: it gives none for these poses)
	Vec2 paperPoint;         ///< the paper's contact point, where it gives one

	/// Solve the case as its mode and method say.
	LevelResult Solve() const;
};

/// The contact cases, in the order of the paper's figures.
std::vector<ContactCase> PaperContactCases();

/// A collision process of the paper's Figures 4, 8 and 10.
struct CollisionCase
{
	std::string name; ///< short name
	ShapePtr a, b;    ///< the shapes
	Motion ma, mb;    ///< their motions
	double tMax;      ///< the interval searched for the first contact
};

/// The collision processes: superellipses, hearts, and a small ellipse meeting a large one.
std::vector<CollisionCase> PaperCollisionCases();

} // namespace b2a::demo

// b2a_viewer: the contacts of a world counted by the method that solves them, with the mean
// time per contact: each broad-phase pair of the world is solved again after the step, timed,
// with the public API (b2a::ComputeFixtureContact, ComputePolygonContact, Box2D's b2Collide*).
#pragma once

#include <box2d/b2_world.h>

#include <map>
#include <string>

namespace b2a::viewer
{

/// One method's tally.
struct MethodTally
{
	int contacts = 0;        ///< pairs it solved
	int touching = 0;        ///< of which touching
	double microseconds = 0; ///< total solve time

	/// Mean time per contact in microseconds (0 when none).
	double Mean() const { return contacts > 0 ? microseconds / contacts : 0.0; }
};

/// The tallies by method name: b2a::MethodName for analytic pairs ("newton", "ellipse_pair",
/// "closed_form", "min_max", "grid", "separating_axis", ...), "box2d_polygons",
/// "box2d_circles" and the like for Box2D's own pairs.
struct MethodStats
{
	std::map<std::string, MethodTally> methods; ///< by method
	int pairs = 0;                              ///< broad-phase pairs (Box2D contacts) counted
	int failed = 0;                             ///< analytic solves that failed

	/// All pairs' total time in microseconds.
	double TotalMicroseconds() const;
};

/// Solve every contact of the world again, timing each (a cold solve: no warm start, so Newton
/// takes a few more iterations than inside the step).
MethodStats CountMethods(b2World* world);

} // namespace b2a::viewer

// Example: capsules (a shape kind registered outside the library) among superellipses and
// circles in a Box2D container.
#pragma once

#include "CapsuleShape.h"

#include <box2d/box2d.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>

namespace example
{

/// The scene's settings (SI units: metres, kilograms, seconds).
struct CapsuleSceneConfig
{
	int particles = 60;       ///< capsules, superellipses and circles, in turn
	double dt = 1.0 / 120.0;  ///< time step (s)
	std::uint64_t seed = 1;   ///< random sizes, orientations and placement jitter
};

/// What the scene has done so far.
struct CapsuleSceneReport
{
	int steps = 0;                ///< steps taken
	double time = 0.0;            ///< simulated time (s)
	/// Touching contacts summed over the steps, by pair of kinds ("capsule-superellipse",
	/// "capsule-capsule", "capsule-box2d_circle", "capsule-wall", ...).
	std::map<std::string, long> contacts;
	long closedFormContacts = 0;  ///< contacts the capsule's own closed forms answered
	double maxPenetration = 0.0;  ///< deepest overlap of a touching manifold point, any step (m, ≥ 0)
	double lastPenetration = 0.0; ///< the same at the last step
	int nonFinite = 0;            ///< bodies whose position, angle or velocity is not finite
	int escaped = 0;              ///< bodies outside the container
	double kineticEnergy = 0.0;   ///< of the particles now (J)
};

/// A U-shaped container of chain links 6 m wide, a tilted static box across its middle (a
/// Box2D polygon), and particles dropped from a jittered lattice: capsules, superellipses
/// (n = m = 4) and circles, half of the circles analytic, half Box2D's own.
class CapsuleScene
{
public:
	/// Build the scene, the particles at rest.
	explicit CapsuleScene(const CapsuleSceneConfig& config);
	/// One Box2D step, then the step's contacts tallied.
	void Step();
	/// The tally and the bodies' state now.
	CapsuleSceneReport Report() const;
	/// An SVG picture of the scene now.
	std::string Svg(const std::string& title) const;
	/// The world (for tests).
	b2World& World() { return *m_world; }

private:
	static std::string KindOf(const b2Fixture* f);
	void Tally();

	CapsuleSceneConfig m_config;
	std::unique_ptr<b2World> m_world;
	CapsuleSceneReport m_report;
	long m_closedFormAtStart = 0;
};

} // namespace example

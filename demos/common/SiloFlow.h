// b2analytic demos: a silo whose discharge is recycled to the top, for steady-flow and jamming
// measurements (the validation programs), and the particle kinds they compare.
#pragma once

#include "GranularScene.h"

#include <box2d/box2d.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace b2a::demo
{

/// One of the particle kinds the flow validations compare, and its size d (the length outlets
/// are measured in).
struct ParticleKind
{
	std::string name;      ///< "ellipse", "disk" or "superellipse"
	GranularConfig config; ///< particles (shape, size, spread, friction); the container is the caller's
	double d = 0.0;        ///< the kind's size: major axis, diameter or width (mm)
	double area = 0.0;     ///< mean particle area (mm²), with the size spread
};

/// The paper's Beverloo ellipses (2 × 0.66 mm, ±5 %), disks of the same mean area (±5 %), or
/// the hopper's n = 4 superellipses (2 mm wide, aspect 1.6, ±10 %). Friction 0.5 on particles,
/// floor and walls. Returns false for another name.
bool MakeParticleKind(const std::string& name, ParticleKind& kind);

/// The number of particles of `kind` that fill a container `width` wide to `height` at a packing
/// fraction `fraction`.
int ParticlesForBed(const ParticleKind& kind, double width, double height, double fraction);

/// Settle `config`'s particles (outlet closed) until their kinetic energy is below `ratio` times
/// the energy the fall released (checked every 100 steps after `minTime`), at most `maxTime`
/// seconds. Returns the packing; `fraction` and `depth` receive its packing fraction and height.
std::vector<ParticleState> SettleBed(const GranularConfig& config, double minTime, double maxTime, double ratio, double& fraction,
                                     double& depth);

/// True when no other dynamic body's (fat) bounding box overlaps a square of half side `r` around
/// `c` (disabled bodies, which leave the broad phase, never count).
bool IsFree(b2World& world, const b2Body* self, b2Vec2 c, float r);

/// Put `body` at rest at a random place in the band [x0, x1] × [y0, y1] where no other dynamic
/// body's bounding box comes within its bounding radius (plus 0.2), keeping its angle; tries
/// `attempts` places (x, then y, drawn from `rng` for each). Returns false if none was free;
/// `retries` counts the places that were not.
bool PlaceInFreeSpot(b2World& world, b2Body* body, double x0, double x1, double y0, double y1, int attempts, std::mt19937_64& rng,
                     long& retries);

/// A silo open at the bottom whose discharged particles go back to the top: a particle whose
/// centre falls one size d below the floor is put at rest in a band above the bed, so the bed
/// keeps its height and the flow lasts as long as wanted.
class RecyclingSilo
{
public:
	/// The silo `config` describes (its outlet open), filled with `packing`; recycled particles
	/// are put in the band from `bandLow` to `bandHigh` (mm above the floor).
	RecyclingSilo(const GranularConfig& config, const std::vector<ParticleState>& packing, double bandLow, double bandHigh,
	              std::uint64_t seed);
	/// Advance one step; returns how many particles left through the outlet in it.
	int Step();
	/// Recycle every particle whose centre lies over the outlet (half width plus one size d) and
	/// less than `height` above the floor: it breaks an arch. Returns how many were moved.
	int ClearOutlet(double height);
	/// Simulated time (s).
	double Time() const { return m_scene.Time(); }
	/// Particles that left through the outlet so far.
	long Exits() const { return m_exits; }
	/// Particles that found no free place at once and wait below the floor for another try.
	int Waiting() const { return int(m_waiting.size()); }
	/// The scene (snapshots, energies).
	GranularScene& Scene() { return m_scene; }

private:
	bool Recycle(b2Body* body);
	GranularScene m_scene;
	double m_bandLow, m_bandHigh;
	std::mt19937_64 m_rng;
	long m_exits = 0;
	long m_retries = 0;
	std::vector<b2Body*> m_waiting; // left, but no free place found yet (parked far below)
};

} // namespace b2a::demo

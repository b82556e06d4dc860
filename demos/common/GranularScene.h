// b2analytic demos: a container of analytic particles packed under gravity, with an outlet.
#pragma once

#include "DemoCommon.h"

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/Box2DConversions.h"
#include "b2analytic/b2analytic.h"

#include <box2d/box2d.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace b2a::demo
{

/// A granular scene in millimetres (docs/design.md, "Units": 1 length unit = 1 mm, g = 9810 mm/s²,
/// small steps, raised restitution thresholds). Masses are in grams (density in g/mm²).
struct GranularConfig
{
	int particles = 600;           ///< number of particles
	double width = 2.0;            ///< mean particle width along its long axis (mm)
	double aspect = 1.6;           ///< long over short semi-axis
	double exponent = 4.0;         ///< superellipse exponent n = m (2: ellipses)
	double sizeSpread = 0.1;       ///< relative spread of sizes (uniform ±)
	double boxWidth = 80.0;        ///< inner width of the container (mm)
	double boxHeight = 200.0;      ///< height of its walls (mm)
	double outletWidth = 24.0;     ///< width of the centred outlet (mm), closed by a gate until opened
	double friction = 0.5;         ///< particle and floor friction
	double wallFriction = 0.0;     ///< side walls' friction (0: the floor alone carries the weight)
	double restitution = 0.1;      ///< particle restitution
	double density = 1e-3;         ///< g/mm²
	double gravity = 9810.0;       ///< mm/s²
	double dt = 2e-4;              ///< time step (s)
	int velocityIterations = 8;    ///< Box2D velocity iterations
	int positionIterations = 3;    ///< Box2D position iterations
	std::uint64_t seed = 1;        ///< random seed (sizes, orientations, placement jitter)
	/// 0: analytic particles. 3 to b2_maxPolygonVertices: each particle a plain Box2D polygon
	/// with this many vertices on the same shape's surface (MakeInscribedPolygon), the baseline the
	/// benchmarks compare against; sizes, orientations and placement are the same.
	int polygonVertices = 0;
	/// Threads that compute the analytic contacts before each step (b2a::PrepareContacts);
	/// 1: b2World::Step alone. Any count steps the scene bit-identically.
	int threads = 1;
	/// Mixed particles instead of one family (MixedParticle): superellipses of non-integer
	/// exponents, ellipses, circles and a few hearts, `width` and `aspect` as above.
	bool mixed = false;
};

/// One particle of the mixed scenes (GranularConfig::mixed) with semi-axes a ≥ b, from two
/// uniform draws in [0, 1): `kind` picks the family (2 % hearts about 2a wide, 30 % circles of
/// radius (a + b)/2, 30 % ellipses a × b, 38 % superellipses a × b), `exponent` the
/// superellipse's n = m in [2.5, 5.5).
ShapePtr MixedParticle(double a, double b, double kind, double exponent);

/// The Beverloo demo's particles (after the paper's section 4.3): ellipses of 2 × 0.66 mm, sizes
/// within ±5 %, friction 0.5 on particles, floor and walls; the container is the caller's.
GranularConfig BeverlooEllipses();

/// Energies of the particles (μJ for g, mm, s: 1 g·mm²/s² = 1e-9 J; reported as is).
struct Energies
{
	double translational = 0.0; ///< Σ ½ m v²
	double rotational = 0.0;    ///< Σ ½ I ω² (about the centre of mass)
	double potential = 0.0;     ///< Σ m g y of the centre of mass (y = 0 at the floor)
	/// Total mechanical energy.
	double Total() const { return translational + rotational + potential; }
};

/// A particle of a saved packing: its shape and pose.
struct ParticleState
{
	ShapePtr shape; ///< the shape
	Pose pose;      ///< where it lies
};

/// The scene: a static container (two walls, a floor in two parts around the outlet, a gate
/// over the outlet) and the particles, dropped from a loose lattice.
class GranularScene
{
public:
	/// Build the scene; particles start at rest on a jittered lattice above the floor.
	explicit GranularScene(const GranularConfig& config);
	/// Build the scene with the outlet open and the particles of a saved packing, at rest.
	GranularScene(const GranularConfig& config, const std::vector<ParticleState>& packing);
	/// The particles' shapes and poses, to start other scenes from.
	std::vector<ParticleState> SaveState() const;
	/// Mean particle mass.
	double MeanParticleMass() const;
	~GranularScene();

	/// Advance one step.
	void Step();
	/// Advance one step of `dt` with these iterations (the viewer's panel sets them).
	void Step(double dt, int velocityIterations, int positionIterations);
	/// Simulated time (s).
	double Time() const { return m_time; }
	/// Particle energies now.
	Energies ComputeEnergies() const;
	/// Vertical force on the floor and gate, averaged over the steps since the last call (from
	/// the normal impulses Box2D reports in PostSolve).
	double TakeBottomForce();
	/// Total weight of the particles still in the container.
	double Weight() const;
	/// Open the outlet: remove the gate.
	void OpenOutlet();
	/// Particles that have left through the outlet so far (they are removed once below it).
	int Discharged() const { return m_discharged; }
	/// Particles still in the container.
	int Remaining() const { return int(m_particles.size()); }
	/// Area fraction of the particles below 80 % of the pile's height (from the shapes' analytic
	/// areas, also for polygon particles).
	double PackingFraction() const;
	/// Height of the highest particle centre above the floor.
	double PileHeight() const;
	/// Kinetic energy of the particles within `radius` of the outlet's centre.
	double KineticEnergyNearOutlet(double radius) const;
	/// Particles whose centre lies over the outlet, within `height` above the floor.
	int ParticlesOverOutlet(double height) const;
	/// Write an SVG snapshot of the container and the particles, with a key and a scale bar. Its
	/// one clock reads the scene's time from `timeOrigin`, followed by `clockNote` (e.g. "after the
	/// outlet opened").
	void WriteSnapshot(const std::string& path, const std::string& title, double timeOrigin = 0.0,
	                   const std::string& clockNote = "") const;
	/// The configuration.
	const GranularConfig& Config() const { return m_config; }
	/// The start of a demo's summary: demo name, options, particles and container.
	Json SummaryHead(const std::string& demo, const DemoOptions& options) const;
	/// The world (for inspection).
	b2World& World() { return *m_world; }

private:
	struct FloorMeter;
	void BuildContainer(bool gate);
	void AddParticle(ShapePtr shape, const Pose& pose);
	Pose ParticlePose(size_t i) const;
	std::vector<Vec2> ParticleOutline(size_t i) const;
	GranularConfig m_config;
	std::unique_ptr<b2World> m_world;
	std::unique_ptr<FloorMeter> m_meter;
	b2Body* m_container = nullptr;
	b2Fixture* m_gate = nullptr;
	std::vector<b2Body*> m_particles;
	std::vector<ShapePtr> m_shapes; // each particle's shape, in the same order
	double m_time = 0.0;
	int m_discharged = 0;
	int m_meterSteps = 0;
};

} // namespace b2a::demo

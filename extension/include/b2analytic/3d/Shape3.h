// b2analytic: the analytic shape interface of the 3D geometry core.
#pragma once

#include "b2analytic/3d/Math3.h"
#include "b2analytic/Shape.h" // InvalidParameter, FormatNumber
#include "b2analytic/ShapeKind.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace b2a
{

/// Value, gradient and Hessian of a 3D level function at one body point.
struct LevelDerivatives3
{
	double value = 0.0; ///< the level λ(x)
	Vec3 gradient;      ///< ∇λ(x)
	Sym33 hessian;      ///< ∇²λ(x)
};

/// Volume, centroid and inertia of a particle at its own surface level, in its body frame
/// (multiply by the density for mass and inertia).
struct MassProperties3
{
	double volume = 0.0; ///< volume
	Vec3 centroid;       ///< centroid in body coordinates
	Sym33 secondMoment;  ///< ∫ r rᵀ dV about the centroid (r = x − centroid)
	Sym33 inertia;       ///< ∫ (|r|² I − r rᵀ) dV about the centroid: the inertia tensor per unit density
};

/// Points on a shape's own surface on a two-parameter grid, computed once per shape and sample
/// count and reused (they depend on the shape only, not on any pose). The parameters are the
/// latitude η and longitude ω of a direction; `ring` rows of `perRing` points each (ring r at
/// latitude eta[r], column k at longitude omega[k], both increasing; longitude is cyclic),
/// then the two poles (η = −π/2, then η = +π/2). Point (r, k) lies on the ray from the centre
/// through the shape's own direction (a·cos η cos ω, b·cos η sin ω, c·sin η) for its semi-axes
/// a, b, c, and the nodes are spread so that both arc length and turning of the surface along
/// the equator and the meridians are resolved.
struct SurfaceSamples3
{
	double level = 1.0;           ///< the level the samples lie on (the shape's surface level)
	int rings = 0;                ///< rows of constant latitude (poles excluded)
	int perRing = 0;              ///< points per row
	std::vector<double> eta;      ///< latitude of each ring, increasing in (−π/2, π/2)
	std::vector<double> omega;    ///< longitude of each column, increasing in [−π, π)
	std::vector<Vec3> point;      ///< body-frame positions: rings·perRing grid points, then the two poles
	double maxSpacing = 0.0;      ///< largest distance between neighbouring samples
	int requested = 0;            ///< the sample count asked for (Shape3::Samples' key)

	/// Number of samples.
	int Count() const { return int(point.size()); }
	/// Index of grid point (r, k), k taken cyclically.
	int Index(int r, int k) const { return r * perRing + ((k % perRing) + perRing) % perRing; }
	/// Index of the south (η = −π/2) and north pole.
	int SouthPole() const { return rings * perRing; }
	/// Index of the north pole.
	int NorthPole() const { return rings * perRing + 1; }
	/// The indices of sample i's neighbours on the grid (the eight around a grid point, with a
	/// pole standing for the missing row beyond the first and last ring; a pole's are its ring's
	/// points) into `out`; returns how many.
	int Neighbours(int i, std::vector<int>& out) const;
};

/// An analytic 3D particle shape described by a level function λ(x) in its body frame.
///
/// The particle is { x : λ(x) ≤ L₀ } with L₀ = SurfaceLevel(); { λ ≤ L } for another level L is
/// the particle rescaled to L. Every shape is star-shaped about its body origin at every level
/// (λ grows along every ray from it) and symmetric about it (λ(−x) = λ(x)), so its centroid is
/// the origin. Shapes are immutable after construction and may be shared between threads.
class Shape3
{
public:
	virtual ~Shape3();
	Shape3(const Shape3&) = delete;
	Shape3& operator=(const Shape3&) = delete;

	/// The kind, a registered kind of dimension 3, which selects the solvers: its row and column
	/// in the 3D dispatch table (BuiltinKinds3 for the superellipsoid family).
	ShapeKind Kind() const { return m_kind; }
	/// The kind's name ("sphere", "ellipsoid", "superellipsoid", "convex_superellipsoid", ...).
	const char* KindName() const { return b2a::KindName(m_kind); }
	/// A readable description with every parameter, e.g. "ellipsoid(a=2, b=1, c=1)".
	virtual std::string Describe() const = 0;

	/// The level of the particle's own surface.
	double SurfaceLevel() const { return m_surfaceLevel; }
	/// The level at which a body point lies.
	virtual double Level(Vec3 x) const = 0;
	/// Level, gradient and Hessian at a body point.
	virtual LevelDerivatives3 Derivatives(Vec3 x) const = 0;
	/// Gradient of the level at a body point.
	virtual Vec3 Gradient(Vec3 x) const { return Derivatives(x).gradient; }
	/// Distance from the body origin to the level-L set along the unit body direction u.
	virtual double RadiusAt(Vec3 u, double level) const = 0;
	/// The point on the ray from the centre through the body point x (x ≠ 0) at level L.
	virtual Vec3 PointOnRay(Vec3 x, double level) const;
	/// The far crossing of the own surface by the body line x + t·d: the largest t with the point
	/// on the surface; false when the line misses or only grazes the particle.
	virtual bool FarCrossing(Vec3 x, Vec3 d, double& t) const = 0;

	/// Support point in the body frame: the point of the particle farthest along d (d ≠ 0, need
	/// not be unit).
	virtual Vec3 Support(Vec3 d) const = 0;
	/// The support value h(d) = max over the particle of x·d (body frame).
	virtual double SupportValue(Vec3 d) const { return Dot(Support(d), d); }
	/// Tight world AABB at a pose: along each world axis e the extent is the support value along
	/// Rᵀe, so the box touches the particle on all six sides.
	Box3 ComputeAABB(const Pose3& pose) const;
	/// Largest distance from the body origin to the surface (an enclosing radius where the shape
	/// says so).
	double BoundingRadius() const { return m_boundingRadius; }
	/// Volume, centroid and inertia at the own surface level.
	const MassProperties3& Mass() const { return m_mass; }

	/// Every level set is convex.
	bool IsConvex() const { return m_convex; }
	/// The level is twice continuously differentiable away from the origin and its level sets are
	/// strictly convex: the Newton common-level solver applies.
	bool IsSmoothConvex() const { return m_smoothConvex; }
	/// An exponent q such that λ^(1/q) is convex and grows about quadratically: Newton works on
	/// λ^(1/q) for its conditioning (levels it reports are in λ's own units).
	double LevelPower() const { return m_levelPower; }

	/// Surface samples at the own level, about `count` of them (≥ 16), computed on first use and
	/// cached; the reference is valid as long as the shape.
	const SurfaceSamples3& Samples(int count = kDefaultSampleCount) const;
	/// The default number of surface samples of the grid method.
	static constexpr int kDefaultSampleCount = 256;

protected:
	/// The constant properties; derived constructors set the rest with Finalize. Throws
	/// InvalidParameter (field 'kind') unless `kind` is a registered kind of dimension 3.
	Shape3(ShapeKind kind, double surfaceLevel, bool convex, bool smoothConvex, double levelPower);
	/// Set the bounding radius and mass properties (closed forms of the derived class).
	void Finalize(double boundingRadius, const MassProperties3& mass);
	/// Build the samples for about `count` points (called once per count, under a lock).
	virtual SurfaceSamples3 BuildSamples(int count) const = 0;

private:
	ShapeKind m_kind;
	double m_surfaceLevel;
	bool m_convex;
	bool m_smoothConvex;
	double m_levelPower;
	double m_boundingRadius = 0.0;
	MassProperties3 m_mass;

	mutable std::mutex m_sampleMutex;
	mutable std::vector<std::pair<int, std::unique_ptr<const SurfaceSamples3>>> m_samples;
	mutable std::atomic<const SurfaceSamples3*> m_lastSamples{nullptr}; // one of m_samples' (never removed)
};

/// Shared, immutable handle to a 3D shape.
using Shape3Ptr = std::shared_ptr<const Shape3>;

} // namespace b2a

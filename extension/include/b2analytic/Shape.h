// b2analytic: the analytic shape interface of the geometry core.
#pragma once

#include "b2analytic/Math.h"
#include "b2analytic/ShapeKind.h"

#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace b2a
{

/// Thrown when a shape (or any other input) is made with an invalid parameter.
/// The message names the field and the value, e.g. "superellipse: field 'n' must be >= 1, got 0.5".
class InvalidParameter : public std::invalid_argument
{
public:
	/// Build the message "<what>: field '<field>' <rule>, got <value>".
	InvalidParameter(const std::string& what, const std::string& field, const std::string& rule, double value);
	/// Build a free-form message that names the field; `field` is what Field() returns.
	InvalidParameter(const std::string& message, const std::string& field);
	/// The offending field's name.
	const std::string& Field() const { return m_field; }

private:
	std::string m_field;
};

/// Value, gradient and Hessian of a level function at one body point.
struct LevelDerivatives
{
	double value = 0.0; ///< the level λ(x)
	Vec2 gradient;      ///< ∇λ(x)
	Sym22 hessian;      ///< ∇²λ(x)
};

/// Area, centroid and second moments of area of a particle at its own surface level,
/// in its body frame (multiply by density for mass and rotational inertia).
struct MassProperties
{
	double area = 0.0;          ///< area
	Vec2 centroid;              ///< centroid in body coordinates
	double polarMoment = 0.0;   ///< ∫|x − centroid|² dA (polar second moment about the centroid)
	double Ixx = 0.0;           ///< ∫(y − cy)² dA, about the centroid
	double Iyy = 0.0;           ///< ∫(x − cx)² dA, about the centroid
	double Ixy = 0.0;           ///< ∫(x − cx)(y − cy) dA, about the centroid
};

/// Points on a shape's own surface, computed once per shape and sample count and reused
/// (they depend on the shape only, not on any pose). Samples are ordered counter-clockwise by
/// polar angle and spread so that both arc length and turning of the tangent are resolved:
/// half of the budget follows arc length, half follows curvature (tips of long ellipses
/// and the heart's cusps get their share).
struct SurfaceSamples
{
	double level = 0.0;         ///< the level the samples lie on (the shape's surface level)
	std::vector<double> angle;  ///< polar angle of each sample in the body frame, increasing, in [-π, π)
	std::vector<Vec2> point;    ///< body-frame position of each sample
	double maxSpacing = 0.0;    ///< largest distance between consecutive samples
	double maxDeviation = 0.0;  ///< largest measured distance from the true curve to the sample polygon

	/// The measured distance of the true curve from each sample arc's chord: arc k, from sample k
	/// to sample k + 1 (cyclic), at three points between them (the largest is maxDeviation).
	std::vector<double> arcDeviation;

	/// Number of samples.
	int Count() const { return int(point.size()); }
	/// The angles of sample k's two neighbours, unwrapped so that lo < angle[k] < hi: the bracket
	/// in which a search refines what sample k found.
	void NeighbourAngles(int k, double& lo, double& hi) const
	{
		const int n = Count();
		lo = angle[(k + n - 1) % n];
		hi = angle[(k + 1) % n];
		if (lo > angle[k]) lo -= 2.0 * kPi;
		if (hi < angle[k]) hi += 2.0 * kPi;
	}
};

/// Bounds of a shape's level over discs and boxes: an optional capability (Shape::Bounds) with
/// which the contact layer's searches skip work, never changing an answer. The grid method rules
/// out runs of surface samples whose disc (or box) A's level stays above a level already found,
/// and ends Newton a step early where the level is smooth; line searches inside or toward a
/// non-convex particle step over stretches the bounds clear. Every default claims nothing (−∞,
/// +∞, false); a shape overrides what it can bound (the heart all of it, the superellipse the
/// lower bound and smoothness).
class LevelBounds
{
public:
	virtual ~LevelBounds() = default;

	/// A lower bound of the level over the disc |x − centre| ≤ radius (body frame); −∞ for none.
	virtual double LevelLowerBound(Vec2 centre, double radius) const
	{
		(void)centre;
		(void)radius;
		return -std::numeric_limits<double>::infinity();
	}
	/// LevelLowerBound of `count` discs (centres[i], radii[i]) into out[0 … count − 1], in one
	/// call: the grid method bounds its groups and runs of samples together. The default calls
	/// LevelLowerBound; the heart evaluates two discs at a time.
	virtual void LevelLowerBounds(const Vec2* centres, const double* radii, int count, double* out) const;
	/// A lower bound of the level over a box (body frame), tighter than LevelLowerBound's over
	/// the disc around it and costlier: the grid method's last look at a run of samples, over
	/// the run's box, that LevelLowerBound did not rule out over its disc, before it evaluates
	/// the run. −∞ for none (the heart's is Taylor's, about the box's centre).
	virtual double TightLevelLowerBound(const OrientedBox& box) const
	{
		(void)box;
		return -std::numeric_limits<double>::infinity();
	}
	/// Whether the level is smooth (three times differentiable) over the disc |x − centre| ≤
	/// radius (body frame): where the grid method's refinement may end a step early, Newton's
	/// convergence predicted from its steps. False claims nothing.
	virtual bool LevelSmoothOver(Vec2 centre, double radius) const
	{
		(void)centre;
		(void)radius;
		return false;
	}
	/// Bounds of the level's curvature over the disc |x − centre| ≤ radius (body frame): every
	/// eigenvalue of the level's Hessian lies in [lowest, highest] there, so that along a line
	/// through the disc the level's second derivative does too (times the direction's squared
	/// length). A line search inside or toward a non-convex particle brackets its crossing by
	/// the parabolas they give, where the level is convex over the stretch ahead. False where
	/// there are none (the default) or the level is not smooth over the disc.
	virtual bool CurvatureBounds(Vec2 centre, double radius, double& lowest, double& highest) const
	{
		(void)centre;
		(void)radius;
		lowest = -std::numeric_limits<double>::infinity();
		highest = std::numeric_limits<double>::infinity();
		return false;
	}
	/// An upper bound of the level over the disc |x − centre| ≤ radius (body frame), with which
	/// a line search inside a non-convex particle steps over stretches that cannot leave it.
	/// +∞ for none: the search marches in steps finer than the samples.
	virtual double LevelUpperBound(Vec2 centre, double radius) const
	{
		(void)centre;
		(void)radius;
		return std::numeric_limits<double>::infinity();
	}

protected:
	LevelBounds() = default;
	LevelBounds(const LevelBounds&) = default;
	LevelBounds& operator=(const LevelBounds&) = default;
};

/// The grid method's acceleration data for a shape's samples (contact/SampleRuns.h): opaque here.
struct SampleRuns;
/// The contact manifold's faces of a shape for one patch tolerance (contact/ContactManifold.cpp):
/// opaque here.
struct FaceTable;

/// An analytic particle shape described by a level function λ(x) in its body frame.
///
/// The particle is { x : λ(x) ≤ L₀ } where L₀ = SurfaceLevel(); the sets { λ ≤ L } for other
/// levels L are the particle "rescaled" to level L (paper section 2). Every shape here is
/// star-shaped with respect to its body origin at every level: along any ray from the origin
/// λ increases, so each ray crosses each level set once. Shapes are immutable after
/// construction and may be shared between particles and threads.
class Shape
{
public:
	virtual ~Shape();
	Shape(const Shape&) = delete;
	Shape& operator=(const Shape&) = delete;

	/// The kind, computed once from the shape's parameters: the dispatch tables' row and column
	/// for its pairs (ShapeKind.h).
	ShapeKind Kind() const { return m_kind; }
	/// A readable description with all parameters, e.g. "ellipse(a=2, b=1)".
	virtual std::string Describe() const = 0;

	/// The level of the particle's own surface (1 for the superellipse family, α for the heart).
	double SurfaceLevel() const { return m_surfaceLevel; }
	/// The level at which a body point lies: the smallest L with x in { λ ≤ L }.
	virtual double Level(Vec2 x) const = 0;
	/// Level at `count` body points x[0 … count − 1] into out[0 … count − 1]: what Level answers
	/// for each, in one call (the grid method scans its samples a run at a time). The default calls
	/// Level; a shape overrides it where a loop of its own is cheaper than a virtual call a point.
	virtual void Levels(const Vec2* x, int count, double* out) const;
	/// Level, gradient and Hessian at a body point. Where the level function is not
	/// differentiable (a superellipse axis with n < 2, the heart's axis of symmetry) the result
	/// is finite and documented by the shape.
	virtual LevelDerivatives Derivatives(Vec2 x) const = 0;
	/// Gradient of the level function at a body point.
	virtual Vec2 Gradient(Vec2 x) const { return Derivatives(x).gradient; }

	/// Distance from the body origin to the level-L set along the unit body direction u.
	virtual double RadiusAt(Vec2 u, double level) const;
	/// Body point on the level-L set at polar angle θ.
	Vec2 SurfacePoint(double theta, double level) const;
	/// Body point on the own surface at polar angle θ.
	Vec2 SurfacePoint(double theta) const { return SurfacePoint(theta, m_surfaceLevel); }

	/// Closed form, where the shape has one, of the far crossing of the own surface by the body
	/// line x + t·d: the largest t with the point on the surface. Returns false when the shape
	/// has no closed form or the line misses the surface; the contact code then searches.
	virtual bool FarCrossing(Vec2 x, Vec2 d, double& t) const
	{
		(void)x;
		(void)d;
		(void)t;
		return false;
	}

	/// FarCrossing for a point x near the own surface (within a small fraction of the particle's
	/// size: a contact manifold's face point), the same crossing to rounding: a shape overrides it
	/// where a search started at such a point is cheaper than FarCrossing's from anywhere (the
	/// superellipse's Halley steps on its own level). The default is FarCrossing.
	virtual bool FarCrossingNear(Vec2 x, Vec2 d, double& t) const { return FarCrossing(x, d, t); }

	/// True only where the shape proves, in closed form, that the body line x + t·d misses the
	/// particle (clear of rounding: a grazing line is not a miss). False where it meets it or the
	/// shape cannot tell. The contact code then takes the radial point without searching the line.
	virtual bool LineMisses(Vec2 x, Vec2 d) const
	{
		(void)x;
		(void)d;
		return false;
	}

	/// Support point in the body frame: the point of the particle farthest along d
	/// (for a non-convex shape, the support point of its convex hull). d need not be unit.
	virtual Vec2 Support(Vec2 d) const;
	/// The support value h(d) = max over the particle of x·d (body frame, d need not be unit):
	/// Support(d)·d, which shapes with a closed form for the value override (separating axes and
	/// AABBs need the value, not the point).
	virtual double SupportValue(Vec2 d) const { return Dot(Support(d), d); }
	/// The shape's bounds of its level (LevelBounds), an optional capability: null (the default)
	/// where it has none, and the contact layer's searches then bound nothing.
	virtual const LevelBounds* Bounds() const { return nullptr; }
	/// Bounds lower ≤ h(d) ≤ upper on the support value h(d) = max over the particle of x·d (body
	/// frame, d need not be unit), for tests that can often decide without h itself: a separating
	/// axis is rejected or confirmed by the bounds alone unless the gap lies between them. The
	/// default is exact (both from Support); shapes with cheap inner and outer bodies override it.
	virtual void SupportBounds(Vec2 d, double& lower, double& upper) const
	{
		lower = upper = SupportValue(d);
	}
	/// SupportBounds() costs well below Support() and its lower bound is close to h(d) (closed
	/// forms, as for the superellipse and the heart): the separating-axis contact with a polygon
	/// then bounds each candidate axis first and takes supports only for those that can win, with
	/// the answer unchanged to the bit as long as the lower bound holds clear of rounding. False
	/// by default (the default SupportBounds is Support itself, and bounding first would take
	/// each support twice).
	bool SupportBoundsCheap() const { return m_supportBoundsCheap; }
	/// Tight world AABB of the particle at a pose: it touches the particle on all four sides.
	/// (Box2D asks for it twice per moving body and step, so shapes with a cheaper form override it.)
	virtual Box ComputeAABB(const Pose& pose) const;
	/// Largest distance from the body origin to the surface.
	double BoundingRadius() const { return m_boundingRadius; }
	/// The level at the body origin, Level((0, 0)), computed once (Finalize): the grid method
	/// asks at every contact whether a particle's centre lies inside it.
	double CentreLevel() const { return m_centreLevel; }
	/// Area, centroid and second moments at the own surface level.
	const MassProperties& Mass() const { return m_mass; }

	/// Every level set is convex.
	bool IsConvex() const { return m_convex; }
	/// The level function is twice continuously differentiable away from the origin and its
	/// level sets are strictly convex: the Newton common-level solver applies.
	bool IsSmoothConvex() const { return m_smoothConvex; }
	/// An exponent q such that λ^(1/q) is convex and grows about quadratically (q = 1 when λ
	/// itself is). The Newton solver works on λ^(1/q) for better conditioning; levels it reports
	/// are in λ's own units.
	double LevelPower() const { return m_levelPower; }

	/// Derivatives() costs about as much as Level() (closed forms, as for the heart and the
	/// superellipse): searches along a line then take Newton steps instead of bracketing on
	/// values alone. False by default (a shape whose derivatives come from differences of its
	/// level, as a user shape's may, is better served by the bracketing).
	bool DerivativesCheap() const { return m_derivativesCheap; }

	/// Polar angles (in [-π, π)) where the surface has corners; quadrature and sampling split there.
	const std::vector<double>& CornerAngles() const { return m_corners; }
	/// The corners' rays as unit vectors (cos, sin of CornerAngles, in the same order).
	const std::vector<Vec2>& CornerDirections() const { return m_cornerDirections; }
	/// The corners themselves: where each ray meets the surface (body frame, same order).
	const std::vector<Vec2>& CornerPoints() const { return m_cornerPoints; }
	/// True when the polar angle θ (in [−π, π], as atan2 gives it) lies within tol of a corner.
	bool NearCorner(double theta, double tol) const
	{
		for (double c : m_corners)
		{
			// Both angles lie in [−π, π], so one turn at most separates them (no remainder call).
			double d = std::fabs(theta - c);
			if (d > kPi)
				d = 2.0 * kPi - d;
			if (d < tol)
				return true;
		}
		return false;
	}

	/// Surface samples at the own level (count ≥ 3), computed on first use and cached.
	std::shared_ptr<const SurfaceSamples> Samples(int count = kDefaultSampleCount) const;
	/// The same samples by reference, valid as long as the shape: for the hot paths (the
	/// one-sided Newton's start, line crossings of non-convex shapes), which then skip Samples()'s
	/// lock and the handle's reference count once the count's samples exist (the last count
	/// asked for is kept in an atomic pointer, so threads that share the shape do not queue on
	/// the lock).
	const SurfaceSamples& SamplesRef(int count = kDefaultSampleCount) const;
	/// The default number of surface samples for the grid method.
	static constexpr int kDefaultSampleCount = 256;
	/// A number no other shape object of this process has (nor had): keys results kept between
	/// calls (a thread's last grid levels, the dense sampling pass) to this shape alone.
	std::uint64_t Serial() const { return m_serial; }

protected:
	/// Set the constant properties; derived constructors call Finalize() once they are ready.
	/// Throws InvalidParameter (field 'kind') unless `kind` is a registered 2D kind whose solver
	/// class the flags bear out (smoothConvex needs `smoothConvex`, convex needs `convex`).
	Shape(ShapeKind kind, double surfaceLevel, bool convex, bool smoothConvex, double levelPower);
	/// Compute bounding radius and mass properties (virtual functions are usable by now).
	/// A derived class may pass closed-form values; a negative radius or a null mass means
	/// "compute numerically".
	void Finalize(double boundingRadius, const MassProperties* mass);
	/// Add a corner angle (before Finalize).
	void AddCorner(double theta);
	/// Declare DerivativesCheap() (in the derived constructor).
	void SetDerivativesCheap() { m_derivativesCheap = true; }
	/// Declare SupportBoundsCheap() (in the derived constructor, with a SupportBounds override).
	void SetSupportBoundsCheap() { m_supportBoundsCheap = true; }
	/// A length scale used to bracket radial roots before the bounding radius is known.
	virtual double LengthHint() const { return 1.0; }

private:
	ShapeKind m_kind;
	double m_surfaceLevel;
	bool m_convex;
	bool m_smoothConvex;
	double m_levelPower;
	bool m_derivativesCheap = false;
	bool m_supportBoundsCheap = false;
	double m_boundingRadius = 0.0;
	double m_centreLevel = 0.0;
	MassProperties m_mass;
	std::vector<double> m_corners;
	std::vector<Vec2> m_cornerDirections;
	std::vector<Vec2> m_cornerPoints;

	std::uint64_t m_serial; // unique per shape: keys the dense sampling pass reused between sample counts
	mutable std::mutex m_sampleMutex;
	mutable std::vector<std::pair<int, std::shared_ptr<const SurfaceSamples>>> m_samples;
	mutable std::atomic<const SurfaceSamples*> m_lastSamples{nullptr}; // one of m_samples' (never removed)
	// The grid method's run hierarchy per sample count, built and kept by the contact layer
	// (contact/SampleRuns.h) under m_sampleMutex, the last one asked for in an atomic pointer.
	friend struct SampleRunsCache;
	mutable std::vector<std::shared_ptr<const SampleRuns>> m_runs;
	mutable std::atomic<const SampleRuns*> m_lastRuns{nullptr};
	// The manifold's faces per patch tolerance, built and kept by the contact layer
	// (contact/ContactManifold.cpp) under m_sampleMutex, the last one asked for in an atomic pointer.
	friend struct FaceTableCache;
	mutable std::vector<std::shared_ptr<const FaceTable>> m_faceTables;
	mutable std::atomic<const FaceTable*> m_lastFaceTable{nullptr};
};

/// Shared, immutable handle to a shape.
using ShapePtr = std::shared_ptr<const Shape>;

/// Format a double for messages with full round-trip precision.
std::string FormatNumber(double value);

} // namespace b2a

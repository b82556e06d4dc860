// Example: a shape kind of one's own, outside the library. A capsule (a segment of half-length h
// along its body x-axis, thickened by a radius r) registers the kind "capsule", closed-form
// contacts and common levels against capsules and circles, and leaves every other pair to the
// library's solvers for its solver class (convex: the grid method).
#pragma once

#include "b2analytic/b2analytic.h"

#include <atomic>
#include <memory>

namespace example
{

/// A capsule: the points within r of the segment S = [−h, h] × {0} (body frame). Its level is
/// λ(x) = d(x, S)² / r², so the level-L set is S thickened by r√L: the particle rescaled to L
/// is again a capsule about the same segment (a circle when h = 0). λ is convex (a squared
/// distance to a convex set) and continuously differentiable; its Hessian jumps where the flat
/// sides meet the caps, and the level sets have flat sides: convex, not strictly, so of solver
/// class convex. The level is 0 all along the segment, so the grid method's one-sided scale of
/// a capsule is not unique where its segment lies inside the other particle (a deep overlap,
/// deeper than the capsule's radius); the closed forms below have no such limit.
class CapsuleShape final : public b2a::Shape
{
public:
	/// A capsule of half-length h ≥ 0 and radius r > 0, both finite; throws
	/// b2a::InvalidParameter naming 'h' or 'r' and the value otherwise.
	CapsuleShape(double h, double r);

	std::string Describe() const override;
	double Level(b2a::Vec2 x) const override;
	b2a::LevelDerivatives Derivatives(b2a::Vec2 x) const override;
	/// The ray's crossing of the level-L capsule in closed form: on a flat side or a cap.
	double RadiusAt(b2a::Vec2 u, double level) const override;
	/// The segment's end along d plus r·d/|d|.
	b2a::Vec2 Support(b2a::Vec2 d) const override;
	/// h|dx| + r|d|.
	double SupportValue(b2a::Vec2 d) const override;
	/// Each half-width: h|cos| or h|sin| of the axis, plus r.
	b2a::Box ComputeAABB(const b2a::Pose& pose) const override;

	/// The half-length h.
	double HalfLength() const { return m_h; }
	/// The radius r.
	double Radius() const { return m_r; }
	/// The segment's ends in world coordinates at a pose.
	void Segment(const b2a::Pose& pose, b2a::Vec2& p, b2a::Vec2& q) const;

	/// Area 4hr + πr², centroid at the centre, second moments of the rectangle and the two caps.
	static b2a::MassProperties ClosedFormMass(double h, double r);

private:
	double LengthHint() const override { return m_h + m_r; }
	double m_h, m_r;
};

/// Make a capsule.
std::shared_ptr<CapsuleShape> MakeCapsule(double h, double r);

/// The kind "capsule" (dimension 2, solver class convex), registered on first use with its
/// functions: the closed-form contact and common level of two capsules and of a capsule and a
/// circle. Every other pair (a capsule against a superellipse, a heart, an ellipse) keeps the
/// table's default for class convex, the grid method, and capsules against Box2D's polygons the
/// separating axis. Thread-safe.
b2a::ShapeKind CapsuleKind();

/// The contact of a capsule A and a capsule or a circle B (whose segment is a point) in closed
/// form: the segments' closest points q_A, q_B at distance d, the normal along them, the points
/// q_A + r_A n and q_B − r_B n, the separation d − r_A − r_B, the common level
/// (d / (r_A + r_B))² at the point dividing q_A q_B in the ratio of the radii. Where the segments
/// cross (d at rounding level: no normal), the grid method.
b2a::ContactResult CapsuleContact(const b2a::Shape& a, const b2a::Pose& pa, const b2a::Shape& b, const b2a::Pose& pb,
                                  const b2a::SolverOptions& options, b2a::WarmStart* warm);
/// The common level of a capsule A and a capsule or a circle B in closed form (see
/// CapsuleContact); the grid's fixed point where the segments cross.
b2a::LevelResult CapsuleLevel(const b2a::Shape& a, const b2a::Pose& pa, const b2a::Shape& b, const b2a::Pose& pb,
                              const b2a::SolverOptions& options, const b2a::WarmStart* warm, b2a::LevelSlide* slide);

/// How many contacts the closed forms above have answered in this process (for the scene's
/// summary and the tests).
extern std::atomic<long> g_closedFormContacts;

} // namespace example

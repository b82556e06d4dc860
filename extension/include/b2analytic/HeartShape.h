// b2analytic: the heart-shaped particle of paper eq. 20.
#pragma once

#include "b2analytic/Shape.h"

#include <cmath>
#include <vector>

namespace b2a
{

/// Heart particle (x² + y² − α)³ − x² y³ ≤ 0 (paper eq. 20); α > 0 sets its size and plays the
/// role of the level value. The level at which a body point lies is
/// α(x) = x² + y² − cbrt(x² y³) = r² − |x|^{2/3} y, and the particle is { α(x) ≤ α }.
/// The notch at (0, √α) and the tip at (0, −√α) are corners; along the axis x = 0 the level
/// function is not differentiable in x, and there the reported derivatives drop the singular
/// |x|^{2/3} terms (∂/∂x = 0, ∂²/∂x² = 2, ∂²/∂x∂y = 0). Not convex: contacts use the grid method.
class HeartShape final : public Shape, public LevelBounds
{
public:
	/// Heart of size α; throws InvalidParameter unless α is finite and > 0.
	explicit HeartShape(double alpha);

	std::string Describe() const override;
	double Level(Vec2 x) const override;
	/// Level at two points at a time (SSE2 on x86-64), each Level's bit for bit; one at a time
	/// elsewhere.
	void Levels(const Vec2* x, int count, double* out) const override;
	LevelDerivatives Derivatives(Vec2 x) const override;
	double RadiusAt(Vec2 u, double level) const override;
	/// The support point of the convex hull: the tip where d lies inside the tip's normal cone
	/// (bounded by the hull's tangents from the tip to the lobes), else Newton's method on the
	/// tangency (level α and gradient parallel to d) from the best surface sample; where that does
	/// not settle on a convex stretch between the sample's neighbours, Shape::Support.
	Vec2 Support(Vec2 d) const override;
	/// From the default surface samples: the sample farthest along d (BestSample) lies on the
	/// surface, and the curve keeps within the samples' measured deviation of their polygon (taken
	/// four times over, as the overlap parts take it); each widened by 1e-12 of the size, so that
	/// they bound the computed support value too. No Newton step.
	void SupportBounds(Vec2 d, double& lower, double& upper) const override;
	/// Every bound of LevelBounds, which the grid method and the line searches inside and toward
	/// the heart use.
	const LevelBounds* Bounds() const override { return this; }
	/// x² + y² − |x|^{2/3} y bounded term by term over the disc (one cube root).
	double LevelLowerBound(Vec2 centre, double radius) const override;
	/// LevelLowerBound of two discs at a time (SSE2 on x86-64), each LevelLowerBound's bit for bit.
	void LevelLowerBounds(const Vec2* centres, const double* radii, int count, double* out) const override;
	/// Taylor's bound about the box's centre, off the axis (|cx| at least twice the radius of
	/// the disc around the box); −∞ elsewhere.
	double TightLevelLowerBound(const OrientedBox& box) const override;
	/// Off the axis (|cx| ≥ ρ), where the level's |x|^{2/3} has its kink.
	bool LevelSmoothOver(Vec2 centre, double radius) const override { return std::fabs(centre.x) >= radius; }
	/// The Hessian's eigenvalues bounded over the disc, off the axis (|cx| ≥ 2ρ); false elsewhere.
	bool CurvatureBounds(Vec2 centre, double radius, double& lowest, double& highest) const override;
	/// See LevelBounds::LevelUpperBound.
	double LevelUpperBound(Vec2 centre, double radius) const override;

	/// The size parameter α.
	double Alpha() const { return m_alpha; }

private:
	double LengthHint() const override;
	// Newton's method for the tangency along d from the sample `start`, kept between the rays
	// through its neighbouring samples `before` and `after`; false where it does not settle on a
	// local maximum of d·x.
	bool TangencyNewton(Vec2 d, Vec2 start, Vec2 before, Vec2 after, Vec2& x) const;
	double m_alpha;
	// α^{1/6}, RadiusAt's start at the surface level (std::pow's own value: every surface point
	// of the grid's refinement and the manifolds' part search asked for it again).
	double m_alphaSixth;
	// The sample farthest along d: the vertex of the samples' convex hull whose normal cone
	// holds d (a binary search over the hull's edge normals), as a scan of the samples finds it.
	int BestSample(Vec2 d) const;
	// sin and cos of the angle from the vertical of the hull's tangent from the tip to a lobe.
	double m_tipSin = 1.0, m_tipCos = 0.0;
	// The convex hull of the default surface samples, counter-clockwise: its vertices' sample
	// indices, and the pseudo-angle (a monotone stand-in for the polar angle, 4 a turn) of each
	// edge's outward normal (edge k from vertex k to k + 1), increasing from the first over one turn.
	std::vector<int> m_hull;
	std::vector<double> m_hullNormal;
};

/// Heart of size α.
std::shared_ptr<HeartShape> MakeHeart(double alpha);

} // namespace b2a

// b2analytic: the heart-shaped particle of paper eq. 20.
#pragma once

#include "b2analytic/Shape.h"

#include <cmath>

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
	double m_alpha;
};

/// Heart of size α.
std::shared_ptr<HeartShape> MakeHeart(double alpha);

} // namespace b2a

// b2a_viewer: the base of the pair samples (two analytic particles, no gravity, a view box that
// fits them), and their drawing helpers: a shape's outline at any level, the box around
// outlines, an arrow.
#pragma once

#include "DrawBatch.h"
#include "Sample.h"

#include "b2analytic/Shape.h"

#include <box2d/b2_math.h>

#include <vector>

namespace b2a::viewer
{

/// The world outline of `shape` at `pose` on its level-`level` set (NaN: its own surface),
/// `count` points evenly in polar angle.
std::vector<b2Vec2> LevelOutline(const Shape& shape, const Pose& pose, double level = 0.0 / 0.0, int count = 96);

/// Grow the box [lo, hi] to hold the points.
void GrowBox(const std::vector<b2Vec2>& points, b2Vec2& lo, b2Vec2& hi);

/// A line with an arrow head at `to`.
void DrawArrow(DrawBatch& batch, b2Vec2 from, b2Vec2 to, const b2Color& color);

/// Two analytic particles in a world without gravity, replaced case by case.
class PairSample : public Sample
{
protected:
	PairSample();
	/// Destroy the pair and make particles of `shapes` at `poses` (density 1); the clock starts again.
	void ReplacePair(const ShapePtr shapes[2], const Pose poses[2], float friction = 0.6f, float restitution = 0.0f);
	/// The view box fits these outlines; the viewer is asked to show it.
	void FitView(const std::vector<std::vector<b2Vec2>>& outlines);
	/// The view box, bounds ten times its size around it, a body size a tenth of it.
	SampleDefaults PairDefaults() const;
	/// The world pose of particle i's shape.
	Pose PoseOf(int i) const;

	b2Body* m_bodies[2] = {nullptr, nullptr}; ///< the two particles

private:
	b2Vec2 m_viewLo{-10.0f, -10.0f}, m_viewHi{10.0f, 10.0f};
};

} // namespace b2a::viewer

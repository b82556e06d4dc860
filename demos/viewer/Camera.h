// b2a_viewer: the 2D camera (Box2D testbed's, with the view's size in world units, so that
// scenes in metres and in millimetres both fit).
#pragma once

#include <box2d/b2_math.h>

namespace b2a::viewer
{

/// An orthographic camera: `center` at the middle of the window, `halfHeight` world units from
/// there to the top edge. Screen coordinates are pixels from the top-left corner, y down.
struct Camera
{
	b2Vec2 center{0.0f, 0.0f}; ///< world point at the window's centre
	float halfHeight = 25.0f;  ///< half the visible height, world units
	int width = 1280;          ///< window width, pixels
	int height = 800;          ///< window height, pixels

	/// World units per pixel.
	float UnitsPerPixel() const { return 2.0f * halfHeight / float(height); }
	/// The world point under a screen point.
	b2Vec2 ScreenToWorld(b2Vec2 screen) const;
	/// The screen point of a world point.
	b2Vec2 WorldToScreen(b2Vec2 world) const;
	/// Column-major 4×4 orthographic projection of the view, for the shaders.
	void Projection(float m[16]) const;
	/// Zoom by `factor` (> 1: see more) about the world point under a screen point, which stays put.
	void ZoomAbout(b2Vec2 screen, float factor);
	/// Show the box [lo, hi] with a margin, keeping the aspect ratio, in the window less
	/// `rightPixels` on the right (where the panel is).
	void Fit(b2Vec2 lo, b2Vec2 hi, float rightPixels = 0.0f);
};

} // namespace b2a::viewer

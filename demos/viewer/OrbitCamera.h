// b2a_viewer: the 3D samples' camera: a perspective view orbiting a target point, z up (the
// paper's Figure 17 frame). Dragging turns it about the target, the wheel moves it nearer or
// farther, and it can turn by itself.
#pragma once

#include "b2analytic/3d/Math3.h"

#include <box2d/b2_math.h>

namespace b2a::viewer
{

/// A camera on a sphere around `target`: `azimuth` about the world z axis, `elevation` above the
/// x-y plane, `distance` from the target. Screen coordinates are pixels from the top-left corner,
/// y down, as the 2D camera's.
struct OrbitCamera
{
	Vec3 target;                  ///< the point looked at
	double azimuth = -0.9;        ///< radians about z, from the x axis
	double elevation = 0.45;      ///< radians above the x-y plane, within ±kMaxElevation
	double distance = 50.0;       ///< from the target, world units
	double fovY = 0.6;            ///< vertical field of view, radians
	double centreX = 0.0;         ///< the target's shift on the screen, in normalised units (-1 to 1), to sit left of the panel
	bool autoOrbit = true;        ///< turn by itself (the panel's toggle)
	double orbitPerFrame = 0.004; ///< azimuth added per frame while turning by itself (radians)
	int width = 1280;             ///< window width, pixels
	int height = 800;             ///< window height, pixels

	/// How far the elevation may go, short of straight up or down (where "up" is undefined).
	static constexpr double kMaxElevation = 1.45;

	/// The camera's position.
	Vec3 Eye() const;
	/// Unit vectors: into the screen, screen right, screen up.
	void Basis(Vec3& forward, Vec3& right, Vec3& up) const;
	/// Column-major 4×4 matrix from world to clip coordinates (perspective), for the shaders.
	void ViewProjection(float m[16]) const;
	/// The screen point of a world point, and its depth along the view direction (≤ 0: behind the camera).
	b2Vec2 WorldToScreen(Vec3 p, double* depth = nullptr) const;
	/// The direction the light comes from (unit, world): from the camera, a little above and left.
	Vec3 LightDirection() const;

	/// Turn by a drag of (dx, dy) pixels: right turns the scene right, down tilts it towards the viewer.
	void Orbit(double dx, double dy);
	/// Move nearer (factor < 1) or farther (> 1).
	void Zoom(double factor);
	/// One frame's turn when turning by itself.
	void Advance();
	/// Look at the box's centre from far enough that its bounding sphere fills the window less
	/// `rightPixels` on the right (where the panel is); the angles stay.
	void Fit(const Box3& box, float rightPixels = 0.0f);
};

} // namespace b2a::viewer

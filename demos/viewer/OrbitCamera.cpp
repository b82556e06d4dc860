// b2a_viewer: the orbiting perspective camera.
#include "OrbitCamera.h"

#include "b2analytic/Math.h" // kPi

#include <algorithm>
#include <cmath>

namespace b2a::viewer
{

Vec3 OrbitCamera::Eye() const
{
	const double c = std::cos(elevation);
	return target + distance * Vec3(c * std::cos(azimuth), c * std::sin(azimuth), std::sin(elevation));
}

void OrbitCamera::Basis(Vec3& forward, Vec3& right, Vec3& up) const
{
	forward = Normalize(target - Eye());
	// Elevation stays short of ±90°, so forward is never parallel to z.
	right = Normalize(Cross(forward, Vec3(0, 0, 1)));
	up = Cross(right, forward);
}

void OrbitCamera::ViewProjection(float m[16]) const
{
	Vec3 f, r, u;
	Basis(f, r, u);
	const Vec3 eye = Eye();
	// View: rows right, up, -forward (OpenGL's camera looks down −z), translated by −eye.
	const double view[3][4] = {{r.x, r.y, r.z, -Dot(r, eye)}, {u.x, u.y, u.z, -Dot(u, eye)}, {-f.x, -f.y, -f.z, Dot(f, eye)}};
	// Perspective (gluPerspective), the near and far planes around the scene at its distance,
	// then a shift of the image by centreX in normalised x.
	const double t = 1.0 / std::tan(0.5 * fovY), aspect = double(width) / double(std::max(height, 1));
	const double zn = 0.02 * distance, zf = 20.0 * distance;
	const double p[4][3] = {{t / aspect, 0.0, -centreX}, {0.0, t, 0.0}, {0.0, 0.0, (zf + zn) / (zn - zf)}, {0.0, 0.0, -1.0}};
	const double pw[4] = {0.0, 0.0, 2.0 * zf * zn / (zn - zf), 0.0};
	// m = P · V, with P's columns 0–2 acting on the view's rows and its column 3 (pw) on w = 1.
	for (int row = 0; row < 4; ++row)
		for (int col = 0; col < 4; ++col)
		{
			double v = col == 3 ? pw[row] : 0.0;
			for (int k = 0; k < 3; ++k)
				v += p[row][k] * view[k][col];
			m[4 * col + row] = float(v);
		}
}

b2Vec2 OrbitCamera::WorldToScreen(Vec3 p, double* depth) const
{
	Vec3 f, r, u;
	Basis(f, r, u);
	const Vec3 d = p - Eye();
	const double z = Dot(d, f);
	if (depth)
		*depth = z;
	const double t = 1.0 / std::tan(0.5 * fovY), aspect = double(width) / double(std::max(height, 1));
	const double zSafe = std::fabs(z) > 1e-12 ? z : 1e-12;
	const double nx = t / aspect * Dot(d, r) / zSafe + centreX, ny = t * Dot(d, u) / zSafe;
	return b2Vec2(float(0.5 * (nx + 1.0) * width), float(0.5 * (1.0 - ny) * height));
}

Vec3 OrbitCamera::LightDirection() const
{
	Vec3 f, r, u;
	Basis(f, r, u);
	return Normalize(-f + 0.5 * u - 0.35 * r);
}

void OrbitCamera::Orbit(double dx, double dy)
{
	const double radiansPerPixel = 0.008;
	azimuth -= radiansPerPixel * dx;
	elevation = std::clamp(elevation + radiansPerPixel * dy, -kMaxElevation, kMaxElevation);
}

void OrbitCamera::Zoom(double factor)
{
	distance = std::clamp(distance * factor, 1e-6, 1e12);
}

void OrbitCamera::Advance()
{
	if (autoOrbit)
		azimuth = std::remainder(azimuth + orbitPerFrame, 2.0 * kPi);
}

void OrbitCamera::Fit(const Box3& box, float rightPixels)
{
	target = 0.5 * (box.lower + box.upper);
	const double radius = 0.5 * Length(box.upper - box.lower);
	const double usable = std::max(0.25 * width, double(width) - rightPixels);
	// Half angles that the sphere must fit in: vertically, and horizontally over the usable width.
	const double halfY = 0.5 * fovY, halfX = std::atan(std::tan(halfY) * usable / double(std::max(height, 1)));
	distance = 1.02 * radius / std::sin(std::min(halfY, halfX));
	centreX = usable / double(width) - 1.0;
}

} // namespace b2a::viewer

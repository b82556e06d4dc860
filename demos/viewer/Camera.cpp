// b2a_viewer: the 2D camera.
#include "Camera.h"

#include <algorithm>

namespace b2a::viewer
{

b2Vec2 Camera::ScreenToWorld(b2Vec2 s) const
{
	const float k = UnitsPerPixel();
	return b2Vec2(center.x + (s.x - 0.5f * float(width)) * k, center.y - (s.y - 0.5f * float(height)) * k);
}

b2Vec2 Camera::WorldToScreen(b2Vec2 w) const
{
	const float k = UnitsPerPixel();
	return b2Vec2(0.5f * float(width) + (w.x - center.x) / k, 0.5f * float(height) - (w.y - center.y) / k);
}

void Camera::Projection(float m[16]) const
{
	const float hy = halfHeight, hx = halfHeight * float(width) / float(height);
	std::fill(m, m + 16, 0.0f);
	m[0] = 1.0f / hx;
	m[5] = 1.0f / hy;
	m[10] = -1.0f;
	m[12] = -center.x / hx;
	m[13] = -center.y / hy;
	m[15] = 1.0f;
}

void Camera::ZoomAbout(b2Vec2 screen, float factor)
{
	const b2Vec2 before = ScreenToWorld(screen);
	halfHeight *= factor;
	const b2Vec2 after = ScreenToWorld(screen);
	center += before - after;
}

void Camera::Fit(b2Vec2 lo, b2Vec2 hi, float rightPixels)
{
	const float margin = 1.08f;
	const float usable = std::max(0.25f * float(width), float(width) - rightPixels);
	halfHeight = margin * 0.5f * std::max(hi.y - lo.y, (hi.x - lo.x) * float(height) / usable);
	center = 0.5f * (lo + hi);
	center.x += 0.5f * (float(width) - usable) * UnitsPerPixel();
	// Where the box is narrower than the view is tall (a wide box, or side by side), it sits at
	// the bottom, leaving the room above for the text over the scene.
	center.y = lo.y - 0.5f * (margin - 1.0f) * (hi.y - lo.y) + halfHeight;
}

} // namespace b2a::viewer

// b2analytic: the Box2D polygon inscribed in an analytic shape (MakeInscribedPolygon).
#include "b2analytic/Box2DConversions.h"

#include <box2d/b2_settings.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

namespace b2a
{

namespace
{
// Whether b2PolygonShape::Set accepts the points without its assertions (live in Debian's
// build): it welds points closer than half the linear slop, wraps the rest in their convex hull
// (gift wrapping, collinear points dropped), needs three hull points and an area above
// FLT_EPSILON (b2ComputeCentroid). The same steps here, with a margin on the area.
bool PolygonAccepts(const b2Vec2* points, int count)
{
	b2Vec2 kept[b2_maxPolygonVertices];
	int n = 0;
	const float weld = 0.5f * b2_linearSlop;
	for (int i = 0; i < count; ++i)
	{
		bool unique = true;
		for (int j = 0; j < n && unique; ++j)
			unique = b2DistanceSquared(points[i], kept[j]) >= weld * weld;
		if (unique)
			kept[n++] = points[i];
	}
	if (n < 3)
		return false;
	// The hull's area is at least the largest triangle's of its points: a triangle well above
	// FLT_EPSILON proves it (and refuses only shapes a hair above Box2D's own limit).
	double largest = 0.0;
	for (int i = 0; i < n; ++i)
		for (int j = i + 1; j < n; ++j)
			for (int k = j + 1; k < n; ++k)
			{
				const Vec2 a = ToVec2(kept[i]), b = ToVec2(kept[j]), c = ToVec2(kept[k]);
				largest = std::max(largest, std::fabs(Cross(b - a, c - a)));
			}
	return 0.5 * largest > 4.0 * double(FLT_EPSILON);
}
} // namespace

b2PolygonShape MakeInscribedPolygon(const Shape& shape, int count)
{
	if (count < 3 || count > b2_maxPolygonVertices)
		throw InvalidParameter("MakeInscribedPolygon", "count", "must be in [3, " + std::to_string(b2_maxPolygonVertices) + "]",
		                       count);
	// Vertex k at the polar angle of (a cos t, b sin t), t = 2πk/N, on the extents a, b along the
	// body axes: an affine image of the regular N-gon, which an affine map takes from the circle
	// to the ellipse (hence largest area there).
	const double a = shape.Support(Vec2(1.0, 0.0)).x, b = shape.Support(Vec2(0.0, 1.0)).y;
	b2Vec2 points[b2_maxPolygonVertices];
	for (int k = 0; k < count; ++k)
	{
		const double t = 2.0 * kPi * k / count;
		points[k] = ToB2Vec2(shape.SurfacePoint(std::atan2(b * std::sin(t), a * std::cos(t))));
	}
	if (!PolygonAccepts(points, count))
		throw InvalidParameter("MakeInscribedPolygon", "shape",
		                       "is too small for a Box2D polygon (its vertices must be at least half of b2_linearSlop "
		                       "apart and span an area), bounding radius",
		                       shape.BoundingRadius());
	b2PolygonShape polygon;
	polygon.Set(points, count);
	return polygon;
}

} // namespace b2a

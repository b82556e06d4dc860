// b2a_viewer: Box2D's debug drawing collected into vertex lists.
#include "DrawBatch.h"

#include <cmath>

namespace b2a::viewer
{
namespace
{
constexpr int kCircleSegments = 24;

double Cross(b2Vec2 o, b2Vec2 a, b2Vec2 b)
{
	return double(a.x - o.x) * double(b.y - o.y) - double(a.y - o.y) * double(b.x - o.x);
}

// Area centroid of a simple polygon, or the vertex mean when its area vanishes.
b2Vec2 AreaCentroid(const b2Vec2* v, int n)
{
	double area = 0.0, cx = 0.0, cy = 0.0, mx = 0.0, my = 0.0;
	for (int i = 0; i < n; ++i)
	{
		const b2Vec2 p = v[i], q = v[(i + 1) % n];
		const double c = double(p.x) * q.y - double(q.x) * p.y;
		area += c;
		cx += (double(p.x) + q.x) * c;
		cy += (double(p.y) + q.y) * c;
		mx += p.x;
		my += p.y;
	}
	if (std::fabs(area) < 1e-30)
		return b2Vec2(float(mx / n), float(my / n));
	return b2Vec2(float(cx / (3.0 * area)), float(cy / (3.0 * area)));
}
} // namespace

void DrawBatch::Clear()
{
	m_triangles.clear();
	m_lines.clear();
	m_points.clear();
}

void DrawBatch::Add(std::vector<DrawVertex>& list, b2Vec2 p, const b2Color& c, float size)
{
	list.push_back({p.x + m_offset.x, p.y + m_offset.y, c.r, c.g, c.b, c.a, size});
}

void DrawBatch::DrawPolygon(const b2Vec2* v, int32 n, const b2Color& color)
{
	for (int32 i = 0; i < n; ++i)
	{
		Add(m_lines, v[i], color);
		Add(m_lines, v[(i + 1) % n], color);
	}
}

void DrawBatch::FillPolygon(const b2Vec2* v, int32 n, const b2Color& fill)
{
	if (n < 3)
		return;
	// Box2D's polygons are convex and the analytic outlines star-shaped about the particle's
	// centre (a heart's too), so a fan from the area centroid fills them when every one of its
	// triangles turns the same way; otherwise (a shape the centroid does not see whole) clip ears.
	const b2Vec2 c = AreaCentroid(v, n);
	bool fan = true;
	for (int32 i = 0; i < n && fan; ++i)
		fan = Cross(c, v[i], v[(i + 1) % n]) >= 0.0;
	if (fan)
	{
		for (int32 i = 0; i < n; ++i)
		{
			Add(m_triangles, c, fill);
			Add(m_triangles, v[i], fill);
			Add(m_triangles, v[(i + 1) % n], fill);
		}
		return;
	}
	// Ear clipping of a counter-clockwise simple polygon, O(n²) (hearts have 48 vertices).
	std::vector<int>& idx = m_scratch;
	idx.resize(size_t(n));
	for (int i = 0; i < n; ++i)
		idx[size_t(i)] = i;
	int guard = 2 * n * n; // a polygon that is not simple ends here rather than looping
	while (idx.size() > 3 && guard-- > 0)
	{
		const size_t m = idx.size();
		bool clipped = false;
		for (size_t k = 0; k < m && !clipped; ++k)
		{
			const b2Vec2 a = v[idx[(k + m - 1) % m]], b = v[idx[k]], d = v[idx[(k + 1) % m]];
			if (Cross(a, b, d) <= 0.0)
				continue; // reflex corner
			bool empty = true;
			for (size_t j = 0; j < m && empty; ++j)
			{
				const int q = idx[j];
				if (q == idx[(k + m - 1) % m] || q == idx[k] || q == idx[(k + 1) % m])
					continue;
				empty = !(Cross(a, b, v[q]) > 0.0 && Cross(b, d, v[q]) > 0.0 && Cross(d, a, v[q]) > 0.0);
			}
			if (!empty)
				continue;
			Add(m_triangles, a, fill);
			Add(m_triangles, b, fill);
			Add(m_triangles, d, fill);
			idx.erase(idx.begin() + std::ptrdiff_t(k));
			clipped = true;
		}
		if (!clipped)
			break;
	}
	if (idx.size() == 3)
		for (int q : idx)
			Add(m_triangles, v[q], fill);
}

void DrawBatch::DrawSolidPolygon(const b2Vec2* v, int32 n, const b2Color& color)
{
	FillPolygon(v, n, b2Color(0.5f * color.r, 0.5f * color.g, 0.5f * color.b, 0.5f));
	DrawPolygon(v, n, color);
}

void DrawBatch::DrawCircle(const b2Vec2& center, float radius, const b2Color& color)
{
	b2Vec2 v[kCircleSegments];
	for (int i = 0; i < kCircleSegments; ++i)
	{
		const float t = 2.0f * b2_pi * float(i) / float(kCircleSegments);
		v[i] = center + radius * b2Vec2(std::cos(t), std::sin(t));
	}
	DrawPolygon(v, kCircleSegments, color);
}

void DrawBatch::DrawSolidCircle(const b2Vec2& center, float radius, const b2Vec2& axis, const b2Color& color)
{
	b2Vec2 v[kCircleSegments];
	for (int i = 0; i < kCircleSegments; ++i)
	{
		const float t = 2.0f * b2_pi * float(i) / float(kCircleSegments);
		v[i] = center + radius * b2Vec2(std::cos(t), std::sin(t));
	}
	DrawSolidPolygon(v, kCircleSegments, color);
	DrawSegment(center, center + radius * axis, color);
}

void DrawBatch::DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color& color)
{
	Add(m_lines, p1, color);
	Add(m_lines, p2, color);
}

void DrawBatch::DrawTransform(const b2Transform& xf)
{
	DrawSegment(xf.p, xf.p + m_axisLength * xf.q.GetXAxis(), b2Color(1.0f, 0.0f, 0.0f));
	DrawSegment(xf.p, xf.p + m_axisLength * xf.q.GetYAxis(), b2Color(0.0f, 1.0f, 0.0f));
}

void DrawBatch::DrawPoint(const b2Vec2& p, float size, const b2Color& color)
{
	Add(m_points, p, color, size);
}

} // namespace b2a::viewer

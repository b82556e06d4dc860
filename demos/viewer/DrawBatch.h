// b2a_viewer: a b2Draw that collects what Box2D (and b2a::DrawWorld) draws into vertex lists,
// which the OpenGL renderer then uploads. It needs no OpenGL itself, so the tests can check
// what was drawn without a window.
#pragma once

#include <box2d/b2_draw.h>

#include <vector>

namespace b2a::viewer
{

/// One vertex: world position, colour, and (for points) the size in pixels.
struct DrawVertex
{
	float x, y;       ///< world position (after the batch's offset)
	float r, g, b, a; ///< colour
	float size;       ///< point size in pixels (points only)
};

/// Box2D's debug drawing collected into triangles, lines and points, in the testbed's colours
/// (filled shapes at half the outline's colour and alpha 0.5).
class DrawBatch : public b2Draw
{
public:
	/// Forget everything drawn so far (keeps the flags, the offset and the axis length).
	void Clear();
	/// Added to every point drawn from now on (side-by-side scenes draw their second copy shifted).
	void SetOffset(b2Vec2 offset) { m_offset = offset; }
	/// The current offset.
	b2Vec2 Offset() const { return m_offset; }
	/// Length of the axes DrawTransform draws (world units; the scene's size sets it).
	void SetAxisLength(float length) { m_axisLength = length; }
	/// Points on each analytic outline (b2a::DrawWorld's outlineVertices): the viewer sets it from
	/// the bodies' size on the screen, so that small particles cost few triangles.
	void SetOutlineVertices(int count) { m_outlineVertices = count; }
	/// Points on each analytic outline.
	int OutlineVertices() const { return m_outlineVertices; }

	/// b2Draw: a closed outline.
	void DrawPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color) override;
	/// b2Draw: a filled polygon with its outline (convex, or star-shaped about its centroid, or
	/// any simple polygon, which is cut into ears).
	void DrawSolidPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color) override;
	/// b2Draw: a circle's outline.
	void DrawCircle(const b2Vec2& center, float radius, const b2Color& color) override;
	/// b2Draw: a filled circle with a line along its axis.
	void DrawSolidCircle(const b2Vec2& center, float radius, const b2Vec2& axis, const b2Color& color) override;
	/// b2Draw: a segment.
	void DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color& color) override;
	/// b2Draw: a frame's axes, red along x and green along y.
	void DrawTransform(const b2Transform& xf) override;
	/// b2Draw: a point of `size` pixels.
	void DrawPoint(const b2Vec2& p, float size, const b2Color& color) override;

	/// A filled polygon without an outline (the pair inspector's rescaled shapes).
	void FillPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color);

	/// Triangles, three vertices each.
	const std::vector<DrawVertex>& Triangles() const { return m_triangles; }
	/// Line segments, two vertices each.
	const std::vector<DrawVertex>& Lines() const { return m_lines; }
	/// Points.
	const std::vector<DrawVertex>& Points() const { return m_points; }

private:
	void Add(std::vector<DrawVertex>& list, b2Vec2 p, const b2Color& c, float size = 0.0f);
	std::vector<DrawVertex> m_triangles, m_lines, m_points;
	std::vector<int> m_scratch;
	b2Vec2 m_offset{0.0f, 0.0f};
	float m_axisLength = 0.4f;
	int m_outlineVertices = 48;
};

} // namespace b2a::viewer

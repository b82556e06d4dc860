// b2a_viewer: what a 3D sample draws, collected into vertex lists for the mesh renderer: shaded
// triangles, lines inside the scene, and lines and points drawn over it. It needs no OpenGL, so
// the tests can check what was drawn without a window. (3D samples have no Box2D world, so their
// drawing does not go through b2Draw.)
#pragma once

#include "b2analytic/3d/Math3.h"

#include <vector>

namespace b2a::viewer
{

/// An RGBA colour, components 0 to 1.
struct Colour3
{
	float r = 1.0f, g = 1.0f, b = 1.0f, a = 1.0f; ///< components
};

/// One vertex: world position, unit normal (zero: not shaded), colour, point size in pixels.
struct MeshVertex
{
	float x, y, z;    ///< world position
	float nx, ny, nz; ///< unit normal for Lambert shading; zero for lines and points
	float r, g, b, a; ///< colour
	float size;       ///< point size in pixels (points only)
};

/// A 3D scene's drawing for one frame.
class MeshBatch
{
public:
	/// Forget everything drawn so far.
	void Clear();
	/// A shaded triangle with a normal at each corner.
	void AddTriangle(const Vec3 p[3], const Vec3 n[3], const Colour3& c);
	/// A line hidden where the scene is in front of it (axes, the box).
	void AddLine(Vec3 a, Vec3 b, const Colour3& c);
	/// A line drawn over the scene (the contact normal).
	void AddOverlayLine(Vec3 a, Vec3 b, const Colour3& c);
	/// A point drawn over the scene, `size` pixels across (the contact point).
	void AddPoint(Vec3 p, float size, const Colour3& c);

	/// The triangles, three vertices each.
	const std::vector<MeshVertex>& Triangles() const { return m_triangles; }
	/// The lines inside the scene, two vertices each.
	const std::vector<MeshVertex>& Lines() const { return m_lines; }
	/// The lines over the scene, two vertices each.
	const std::vector<MeshVertex>& OverlayLines() const { return m_overlayLines; }
	/// The points over the scene.
	const std::vector<MeshVertex>& Points() const { return m_points; }

private:
	std::vector<MeshVertex> m_triangles, m_lines, m_overlayLines, m_points;
};

} // namespace b2a::viewer

// b2a_viewer: the 3D samples' vertex lists.
#include "MeshBatch.h"

namespace b2a::viewer
{
namespace
{
MeshVertex Vertex(Vec3 p, Vec3 n, const Colour3& c, float size = 1.0f)
{
	return MeshVertex{float(p.x), float(p.y), float(p.z), float(n.x), float(n.y), float(n.z), c.r, c.g, c.b, c.a, size};
}
} // namespace

void MeshBatch::Clear()
{
	m_triangles.clear();
	m_lines.clear();
	m_overlayLines.clear();
	m_points.clear();
}

void MeshBatch::AddTriangle(const Vec3 p[3], const Vec3 n[3], const Colour3& c)
{
	for (int i = 0; i < 3; ++i)
		m_triangles.push_back(Vertex(p[i], n[i], c));
}

void MeshBatch::AddLine(Vec3 a, Vec3 b, const Colour3& c)
{
	m_lines.push_back(Vertex(a, Vec3(), c));
	m_lines.push_back(Vertex(b, Vec3(), c));
}

void MeshBatch::AddOverlayLine(Vec3 a, Vec3 b, const Colour3& c)
{
	m_overlayLines.push_back(Vertex(a, Vec3(), c));
	m_overlayLines.push_back(Vertex(b, Vec3(), c));
}

void MeshBatch::AddPoint(Vec3 p, float size, const Colour3& c)
{
	m_points.push_back(Vertex(p, Vec3(), c, size));
}

} // namespace b2a::viewer

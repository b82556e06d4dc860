// b2a_viewer: the 3D sample base and its mesh drawing.
#include "Sample3.h"

#include "common/Render3d.h"

#include <cmath>

namespace b2a::viewer
{

BodyMesh MakeBodyMesh(const Shape3& shape, int samples)
{
	const demo::Mesh3 m = demo::SurfaceMesh(shape, Pose3(), samples, "", "#000000");
	BodyMesh out;
	out.vertex = m.vertex;
	out.triangle = m.triangle;
	out.normal.reserve(m.vertex.size());
	for (const Vec3& v : m.vertex)
	{
		// The level's gradient; where it vanishes or is not finite (it does neither on a
		// superellipsoid's surface), the direction from the centre.
		const Vec3 g = shape.Gradient(v);
		const double length = Length(g);
		out.normal.push_back(std::isfinite(length) && length > 0.0 ? g / length : Normalize(v));
	}
	return out;
}

void DrawBodyMesh(MeshBatch& batch, const BodyMesh& mesh, const Pose3& pose, const Colour3& c)
{
	std::vector<Vec3> p(mesh.vertex.size()), n(mesh.normal.size());
	for (size_t i = 0; i < p.size(); ++i)
	{
		p[i] = ToWorld(pose, mesh.vertex[i]);
		n[i] = Rotate(pose.q, mesh.normal[i]);
	}
	for (const auto& t : mesh.triangle)
	{
		const Vec3 tp[3] = {p[size_t(t[0])], p[size_t(t[1])], p[size_t(t[2])]};
		const Vec3 tn[3] = {n[size_t(t[0])], n[size_t(t[1])], n[size_t(t[2])]};
		batch.AddTriangle(tp, tn, c);
	}
}

void DrawArrow3(MeshBatch& batch, Vec3 from, Vec3 to, const Colour3& c)
{
	batch.AddOverlayLine(from, to, c);
	const Vec3 d = to - from;
	const double length = Length(d);
	if (!(length > 0.0))
		return;
	// Two directions across the shaft: any vector not along it, crossed with it, and again.
	const Vec3 u = d / length, side = Normalize(Cross(u, std::fabs(u.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0))),
	           other = Cross(u, side);
	const Vec3 back = to - 0.25 * d;
	for (Vec3 s : {side, -1.0 * side, other, -1.0 * other})
		batch.AddOverlayLine(to, back + 0.1 * length * s, c);
}

void DrawBoxAndAxes(MeshBatch& batch, const Box3& box)
{
	const Colour3 edge{0.45f, 0.45f, 0.5f, 1.0f};
	auto corner = [&](int k) {
		return Vec3(k & 1 ? box.upper.x : box.lower.x, k & 2 ? box.upper.y : box.lower.y, k & 4 ? box.upper.z : box.lower.z);
	};
	for (int k = 0; k < 8; ++k)
		for (int axis = 0; axis < 3; ++axis)
			if (!(k & (1 << axis)) && k != 0) // the edges from the lower corner are the axes
				batch.AddLine(corner(k), corner(k | (1 << axis)), edge);
	const Colour3 axisColour[3] = {{0.9f, 0.3f, 0.3f, 1.0f}, {0.3f, 0.85f, 0.3f, 1.0f}, {0.35f, 0.5f, 1.0f, 1.0f}};
	for (int axis = 0; axis < 3; ++axis)
		batch.AddLine(corner(0), corner(1 << axis), axisColour[axis]);
}

Sample3::Sample3(double hertz) : m_hertz(hertz)
{
	MakeWorld(b2Vec2(0.0f, 0.0f));
}

SampleDefaults Sample3::Defaults() const
{
	SampleDefaults d;
	d.step.hertz = m_hertz;
	d.polygonTwin = false;
	return d;
}

void Sample3::Draw(DrawBatch&, const DrawSettings&) {}

bool Sample3::Keyboard(int)
{
	return false;
}

void Sample3::StepWorld(float dt, int, int)
{
	Advance(double(dt));
}

} // namespace b2a::viewer

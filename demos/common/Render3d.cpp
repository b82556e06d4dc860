// b2analytic demos: shaded 3D views as SVG and meshes as OBJ.
#include "Render3d.h"
#include "DemoCommon.h"
#include "Svg.h" // Escape

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace b2a::demo
{

namespace
{
std::string Num(double v)
{
	char b[32];
	std::snprintf(b, sizeof(b), "%.1f", v);
	return b;
}

// The colour #rrggbb scaled by `shade` (0..1) towards black, mixed with white by `tint`.
std::string Shaded(const std::string& hex, double shade, double tint = 0.0)
{
	unsigned r = 0, g = 0, b = 0;
	std::sscanf(hex.c_str(), "#%02x%02x%02x", &r, &g, &b);
	auto channel = [&](unsigned c) {
		const double v = std::clamp(c * shade + 255.0 * tint, 0.0, 255.0);
		return unsigned(v + 0.5);
	};
	char out[8];
	std::snprintf(out, sizeof(out), "#%02x%02x%02x", channel(r), channel(g), channel(b));
	return out;
}

// The camera: screen right, screen up, and the direction into the screen (depth).
struct Camera
{
	Vec3 right, up, forward;
	double scale = 1.0, cx = 0.0, cy = 0.0; // world length → pixels, pixel centre
	double ScreenX(Vec3 p) const { return cx + scale * Dot(p, right); }
	double ScreenY(Vec3 p) const { return cy - scale * Dot(p, up); }
	std::string Point(Vec3 p) const { return Num(ScreenX(p)) + "," + Num(ScreenY(p)); }
};

Camera MakeCamera(const View3& view, double x0, double y0, double width, double height)
{
	Camera c;
	const Vec3 towardCamera(std::cos(view.elevation) * std::cos(view.azimuth), std::cos(view.elevation) * std::sin(view.azimuth),
	                        std::sin(view.elevation));
	c.forward = -towardCamera;
	c.right = Normalize(Cross(c.forward, Vec3(0, 0, 1)));
	c.up = Cross(c.right, c.forward);
	// Fit the box's eight corners, with room for the axes' labels.
	double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
	for (int k = 0; k < 8; ++k)
	{
		const Vec3 p(k & 1 ? view.box.upper.x : view.box.lower.x, k & 2 ? view.box.upper.y : view.box.lower.y,
		             k & 4 ? view.box.upper.z : view.box.lower.z);
		const double s[2] = {Dot(p, c.right), Dot(p, c.up)};
		for (int i = 0; i < 2; ++i)
		{
			lo[i] = std::min(lo[i], s[i]);
			hi[i] = std::max(hi[i], s[i]);
		}
	}
	const double margin = 46.0, top = 30.0;
	c.scale = std::min((width - 2 * margin) / (hi[0] - lo[0]), (height - 2 * margin - top) / (hi[1] - lo[1]));
	c.cx = x0 + 0.5 * width - c.scale * 0.5 * (lo[0] + hi[0]);
	c.cy = y0 + top + 0.5 * (height - top) + c.scale * 0.5 * (lo[1] + hi[1]);
	return c;
}

// The box's edges that lie behind the scene (both adjacent faces facing away from the camera
// or one of them), drawn first, and three of them carrying ticks: the axes.
std::string Axes(const View3& view, const Camera& cam)
{
	std::string out;
	const Box3& b = view.box;
	auto corner = [&](int k) {
		return Vec3(k & 1 ? b.upper.x : b.lower.x, k & 2 ? b.upper.y : b.lower.y, k & 4 ? b.upper.z : b.lower.z);
	};
	// Back faces: those whose outward normal points away from the camera.
	auto faceBack = [&](int axis, bool upper) {
		Vec3 n;
		n[axis] = upper ? 1.0 : -1.0;
		return Dot(n, cam.forward) > 0.0;
	};
	for (int k = 0; k < 8; ++k)
		for (int axis = 0; axis < 3; ++axis)
		{
			if (k & (1 << axis))
				continue;
			const int other = k | (1 << axis);
			// The edge along `axis` through corner k: adjacent faces are the other two axes' sides.
			bool back = false;
			for (int j = 0; j < 3; ++j)
				if (j != axis)
					back = back || faceBack(j, (k >> j) & 1);
			if (!back)
				continue;
			out += "<line x1=\"" + Num(cam.ScreenX(corner(k))) + "\" y1=\"" + Num(cam.ScreenY(corner(k))) + "\" x2=\"" +
			       Num(cam.ScreenX(corner(other))) + "\" y2=\"" + Num(cam.ScreenY(corner(other))) +
			       "\" stroke=\"#b0b0b0\" stroke-width=\"0.8\"/>\n";
		}
	// Ticks and labels on the bottom edges nearest the viewer (x and y) and a vertical edge at
	// the left (z).
	const char* names[3] = {"X", "Y", "Z"};
	// Where two labelled axes meet, the corner's tick labels would overlap: each axis leaves
	// unlabelled a tick at an end that an earlier axis also starts or ends at.
	std::vector<Vec3> ends;
	for (int axis = 0; axis < 3; ++axis)
	{
		Vec3 from = b.lower;
		if (axis < 2)
		{
			const int other = 1 - axis;
			// The other horizontal coordinate at its side nearer the camera.
			from[other] = Dot(Vec3(other == 0 ? 1 : 0, other == 1 ? 1 : 0, 0), cam.forward) < 0.0 ? b.upper[other] : b.lower[other];
		}
		else
		{
			// The vertical edge farthest to the left on screen.
			double best = 1e300;
			for (int k = 0; k < 4; ++k)
			{
				const Vec3 p = corner(k);
				if (cam.ScreenX(p) < best)
				{
					best = cam.ScreenX(p);
					from = p;
				}
			}
		}
		Vec3 to = from;
		to[axis] = b.upper[axis];
		from[axis] = b.lower[axis];
		const size_t earlier = ends.size();
		ends.push_back(from);
		ends.push_back(to);
		out += "<line x1=\"" + Num(cam.ScreenX(from)) + "\" y1=\"" + Num(cam.ScreenY(from)) + "\" x2=\"" + Num(cam.ScreenX(to)) +
		       "\" y2=\"" + Num(cam.ScreenY(to)) + "\" stroke=\"#333333\" stroke-width=\"1.2\"/>\n";
		// Outward from the box's centre on screen, for the tick marks and labels.
		const Vec3 mid = 0.5 * (from + to), centre = 0.5 * (b.lower + b.upper);
		double ox = cam.ScreenX(mid) - cam.ScreenX(centre), oy = cam.ScreenY(mid) - cam.ScreenY(centre);
		const double ol = std::hypot(ox, oy) > 0 ? std::hypot(ox, oy) : 1.0;
		ox /= ol;
		oy /= ol;
		const double first = std::ceil(b.lower[axis] / view.tick - 1e-9) * view.tick;
		for (double v = first; v <= b.upper[axis] + 1e-9; v += view.tick)
		{
			Vec3 p = from;
			p[axis] = v;
			const double x = cam.ScreenX(p), y = cam.ScreenY(p);
			out += "<line x1=\"" + Num(x) + "\" y1=\"" + Num(y) + "\" x2=\"" + Num(x + 5 * ox) + "\" y2=\"" + Num(y + 5 * oy) +
			       "\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
			bool shared = false;
			for (size_t e = 0; e < earlier; ++e)
				shared = shared || Distance(ends[e], p) < 1e-9 * (1.0 + Length(p));
			if (shared)
				continue;
			char text[32];
			std::snprintf(text, sizeof(text), "%g", std::fabs(v) < 1e-9 ? 0.0 : v);
			out += "<text x=\"" + Num(x + 14 * ox) + "\" y=\"" + Num(y + 14 * oy + 3.5) +
			       "\" font-family=\"sans-serif\" font-size=\"10\" text-anchor=\"middle\" fill=\"#333333\">" + text + "</text>\n";
		}
		out += "<text x=\"" + Num(cam.ScreenX(mid) + 44 * ox) + "\" y=\"" + Num(cam.ScreenY(mid) + 44 * oy + 4) +
		       "\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\" fill=\"#000000\">" + names[axis] + " (" +
		       Escape(view.unit) + ")</text>\n";
	}
	return out;
}
} // namespace

Mesh3 SurfaceMesh(const Shape3& shape, const Pose3& pose, int samples, const std::string& name, const std::string& colour)
{
	const SurfaceSamples3& s = shape.Samples(samples);
	Mesh3 m;
	m.name = name;
	m.colour = colour;
	for (const Vec3& p : s.point)
		m.vertex.push_back(ToWorld(pose, p));
	auto add = [&](int i, int j, int k) {
		// Counter-clockwise seen from outside: the normal points away from the centre.
		const Vec3 n = Cross(m.vertex[j] - m.vertex[i], m.vertex[k] - m.vertex[i]);
		if (Dot(n, m.vertex[i] + m.vertex[j] + m.vertex[k] - 3.0 * pose.p) < 0.0)
			std::swap(j, k);
		m.triangle.push_back({i, j, k});
	};
	for (int r = 0; r + 1 < s.rings; ++r)
		for (int k = 0; k < s.perRing; ++k)
		{
			add(s.Index(r, k), s.Index(r, k + 1), s.Index(r + 1, k + 1));
			add(s.Index(r, k), s.Index(r + 1, k + 1), s.Index(r + 1, k));
		}
	for (int k = 0; k < s.perRing; ++k)
	{
		add(s.SouthPole(), s.Index(0, k), s.Index(0, k + 1));
		add(s.NorthPole(), s.Index(s.rings - 1, k), s.Index(s.rings - 1, k + 1));
	}
	return m;
}

void WriteObj(const std::string& path, const std::vector<Mesh3>& meshes, const std::string& comment)
{
	std::string text = "# " + comment + "\n";
	int base = 1;
	char line[128];
	for (const Mesh3& m : meshes)
	{
		text += "o " + m.name + "\n";
		for (const Vec3& v : m.vertex)
		{
			std::snprintf(line, sizeof(line), "v %.9g %.9g %.9g\n", v.x, v.y, v.z);
			text += line;
		}
		for (const auto& t : m.triangle)
		{
			std::snprintf(line, sizeof(line), "f %d %d %d\n", t[0] + base, t[1] + base, t[2] + base);
			text += line;
		}
		base += int(m.vertex.size());
	}
	WriteText(path, text);
}

std::string RenderPanel(const std::vector<Mesh3>& meshes, const View3& view, const std::vector<Marker3>& markers,
                        const std::string& title, double x0, double y0, double width, double height)
{
	const Camera cam = MakeCamera(view, x0, y0, width, height);
	std::string out = "<g>\n<rect x=\"" + Num(x0) + "\" y=\"" + Num(y0) + "\" width=\"" + Num(width) + "\" height=\"" + Num(height) +
	                  "\" fill=\"white\" stroke=\"#dddddd\"/>\n";
	out += "<text x=\"" + Num(x0 + 0.5 * width) + "\" y=\"" + Num(y0 + 20) +
	       "\" font-family=\"sans-serif\" font-size=\"14\" text-anchor=\"middle\">" + Escape(title) + "</text>\n";
	out += Axes(view, cam);
	// Every front-facing triangle, far to near; light from the camera's upper left.
	const Vec3 light = Normalize(-cam.forward + 0.6 * cam.up - 0.5 * cam.right);
	struct Face
	{
		double depth;
		const Mesh3* mesh;
		int index;
		double shade;
	};
	std::vector<Face> faces;
	for (const Mesh3& m : meshes)
		for (int i = 0; i < int(m.triangle.size()); ++i)
		{
			const auto& t = m.triangle[i];
			const Vec3 a = m.vertex[t[0]], b = m.vertex[t[1]], c = m.vertex[t[2]];
			const Vec3 n = Normalize(Cross(b - a, c - a));
			if (Dot(n, cam.forward) >= 0.0)
				continue; // facing away
			const double diffuse = std::max(0.0, Dot(n, light));
			faces.push_back({Dot(a + b + c, cam.forward), &m, i, 0.25 + 0.75 * diffuse});
		}
	std::sort(faces.begin(), faces.end(), [](const Face& p, const Face& q) { return p.depth > q.depth; });
	for (const Face& f : faces)
	{
		const auto& t = f.mesh->triangle[f.index];
		const std::string colour = Shaded(f.mesh->colour, f.shade, 0.08);
		out += "<polygon points=\"" + cam.Point(f.mesh->vertex[t[0]]) + " " + cam.Point(f.mesh->vertex[t[1]]) + " " +
		       cam.Point(f.mesh->vertex[t[2]]) + "\" fill=\"" + colour + "\" stroke=\"" + colour + "\" stroke-width=\"0.4\"/>\n";
	}
	for (const Marker3& m : markers)
	{
		const double x = cam.ScreenX(m.point), y = cam.ScreenY(m.point);
		if (LengthSquared(m.arrow) > 0.0)
		{
			const Vec3 tip = m.point + m.arrow;
			const double tx = cam.ScreenX(tip), ty = cam.ScreenY(tip);
			const double dx = tx - x, dy = ty - y, l = std::hypot(dx, dy);
			out += "<line x1=\"" + Num(x) + "\" y1=\"" + Num(y) + "\" x2=\"" + Num(tx) + "\" y2=\"" + Num(ty) + "\" stroke=\"" +
			       m.colour + "\" stroke-width=\"2.2\"/>\n";
			if (l > 1.0)
			{
				const double ux = dx / l, uy = dy / l;
				out += "<polygon points=\"" + Num(tx) + "," + Num(ty) + " " + Num(tx - 9 * ux + 4 * uy) + "," + Num(ty - 9 * uy - 4 * ux) +
				       " " + Num(tx - 9 * ux - 4 * uy) + "," + Num(ty - 9 * uy + 4 * ux) + "\" fill=\"" + m.colour + "\"/>\n";
			}
		}
		out += "<circle cx=\"" + Num(x) + "\" cy=\"" + Num(y) + "\" r=\"4.5\" fill=\"" + m.colour +
		       "\" stroke=\"white\" stroke-width=\"1.5\"/>\n";
		if (!m.label.empty())
			out += "<text x=\"" + Num(x + 8) + "\" y=\"" + Num(y - 8) + "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"" +
			       m.colour + "\">" + Escape(m.label) + "</text>\n";
	}
	return out + "</g>\n";
}

std::string SvgDocument(const std::string& body, double width, double height)
{
	return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + Num(width) + "\" height=\"" + Num(height) + "\" viewBox=\"0 0 " +
	       Num(width) + " " + Num(height) + "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body + "</svg>\n";
}

} // namespace b2a::demo

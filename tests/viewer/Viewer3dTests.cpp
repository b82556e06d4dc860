// b2analytic tests: the viewer's 3D side without a window: the orbiting camera's projection, the
// meshes of the superellipsoids, the Figure 17 sample stopping at the first contact, and the
// mouse and keys turning the camera.
#include <doctest/doctest.h>

#include "ViewerTestSupport.h"

#include "b2analytic/3d/SuperellipsoidShape.h"

#include <GLFW/glfw3.h>

#include <cmath>

using namespace b2a;
using namespace b2a::test;
using namespace b2a::viewer;

namespace
{
// The screen point of p through the camera's matrix (what the shader computes), for comparison
// with WorldToScreen's own geometry.
b2Vec2 ThroughMatrix(const OrbitCamera& c, Vec3 p)
{
	float m[16];
	c.ViewProjection(m);
	double clip[4];
	for (int row = 0; row < 4; ++row)
		clip[row] = m[row] * p.x + m[4 + row] * p.y + m[8 + row] * p.z + m[12 + row];
	return b2Vec2(float(0.5 * (clip[0] / clip[3] + 1.0) * c.width), float(0.5 * (1.0 - clip[1] / clip[3]) * c.height));
}

constexpr const char* kFigure17 = "figure-17-superellipsoids";
} // namespace

TEST_CASE("orbit camera: the shaders' matrix and WorldToScreen agree, and Fit shows the box left of the panel")
{
	OrbitCamera c;
	c.width = 1280;
	c.height = 800;
	const Box3 box{Vec3(-25, -30, -25), Vec3(-5, -10, -5)};
	c.Fit(box, Viewer::kPanelWidth + 20.0f);
	const double usable = 1280.0 - Viewer::kPanelWidth - 20.0;
	// The box's centre is at the middle of the part of the window left of the panel.
	const b2Vec2 centre = c.WorldToScreen(c.target);
	CHECK(centre.x == doctest::Approx(0.5 * usable).epsilon(1e-6));
	CHECK(centre.y == doctest::Approx(400.0).epsilon(1e-6));
	for (int k = 0; k < 8; ++k)
	{
		const Vec3 p(k & 1 ? box.upper.x : box.lower.x, k & 2 ? box.upper.y : box.lower.y, k & 4 ? box.upper.z : box.lower.z);
		double depth = 0.0;
		const b2Vec2 s = c.WorldToScreen(p, &depth);
		CAPTURE(k);
		CHECK(depth > 0.0);
		CHECK(s.x >= 0.0f);
		CHECK(s.x <= float(usable));
		CHECK(s.y >= 0.0f);
		CHECK(s.y <= 800.0f);
		const b2Vec2 m = ThroughMatrix(c, p);
		CHECK(m.x == doctest::Approx(s.x).epsilon(1e-4));
		CHECK(m.y == doctest::Approx(s.y).epsilon(1e-4));
	}
	// The camera's basis: right-handed, the world's z up on the screen.
	Vec3 f, r, u;
	c.Basis(f, r, u);
	CHECK(Dot(Cross(r, u), -f) == doctest::Approx(1.0));
	CHECK(c.WorldToScreen(c.target + Vec3(0, 0, 1)).y < centre.y);
	// Turning: a drag right lowers the azimuth; the elevation stops short of the poles.
	const double az = c.azimuth;
	c.Orbit(100.0, 0.0);
	CHECK(c.azimuth == doctest::Approx(az - 0.8));
	c.Orbit(0.0, 1e6);
	CHECK(c.elevation == OrbitCamera::kMaxElevation);
	c.Orbit(0.0, -1e6);
	CHECK(c.elevation == -OrbitCamera::kMaxElevation);
}

TEST_CASE("3D meshes: the superellipsoids' vertices lie on their surfaces, with the level's unit normal")
{
	const auto shape = MakeSuperellipsoid(4, 4, 4, 6, 6, 12);
	const BodyMesh mesh = MakeBodyMesh(*shape, 2000);
	REQUIRE(mesh.vertex.size() > 1000);
	REQUIRE(mesh.normal.size() == mesh.vertex.size());
	// A closed surface of triangles: 2V − 4 of them (Euler's formula for a sphere's topology).
	CHECK(mesh.triangle.size() == 2 * mesh.vertex.size() - 4);
	const double h = 1e-6;
	for (size_t i = 0; i < mesh.vertex.size(); i += 7)
	{
		const Vec3 v = mesh.vertex[i], n = mesh.normal[i];
		CAPTURE(i);
		CHECK(shape->Level(v) == doctest::Approx(shape->SurfaceLevel()).epsilon(1e-9));
		CHECK(Length(n) == doctest::Approx(1.0));
		// Independent reference: the level's gradient by central differences.
		const Vec3 g((shape->Level(v + Vec3(h, 0, 0)) - shape->Level(v - Vec3(h, 0, 0))) / (2 * h),
		             (shape->Level(v + Vec3(0, h, 0)) - shape->Level(v - Vec3(0, h, 0))) / (2 * h),
		             (shape->Level(v + Vec3(0, 0, h)) - shape->Level(v - Vec3(0, 0, h))) / (2 * h));
		CHECK(Dot(n, Normalize(g)) > 1.0 - 1e-6);
	}
}

TEST_CASE("3D sample: Figure 17 flies to the exact first contact, within 1e-3 ms of the paper's 0.1924 ms, and stops there")
{
	TestViewer t(kFigure17);
	REQUIRE(t.view->Current3());
	CHECK(t.World()->GetBodyCount() == 0); // no Box2D bodies: the sample moves its own
	t.Frames(100);
	auto r = t.view->Current().Readings();
	CHECK(r["time_ms"] == doctest::Approx(0.1).epsilon(1e-6)); // 1000 steps a ms, one a frame
	CHECK(r["touching"] == 0.0);
	CHECK(r["separation_mm"] > 0.01);
	CHECK(r["common_level"] > 1.0);
	CHECK(std::fabs(r["first_contact_ms"] - 0.1924) < 1e-3);
	t.Frames(150);
	r = t.view->Current().Readings();
	CHECK(r["time_ms"] == r["first_contact_ms"]);
	CHECK(r["touching"] == 1.0);
	CHECK(std::fabs(r["separation_mm"]) < 1e-6);
	CHECK(r["common_level"] == doctest::Approx(1.0).epsilon(1e-6));
	// Both meshes drawn, the contact point over them.
	t.view->DrawScene();
	CHECK(t.view->Batch3().Triangles().size() > 2 * 3 * 2000);
	CHECK(t.view->Batch3().Points().size() == 1);
	// The normal's arrow starts at the contact point.
	REQUIRE(t.view->Batch3().OverlayLines().size() == 10);
	const MeshVertex& start = t.view->Batch3().OverlayLines()[0];
	CHECK(start.x == t.view->Batch3().Points()[0].x);
	CHECK(start.z == t.view->Batch3().Points()[0].z);
	CHECK(t.view->Batch().Triangles().empty()); // nothing through b2Draw
	const WorldHealth h = t.view->Health();
	CHECK(h.bodies == 2);
	CHECK(h.nonFinite == 0);
	CHECK(h.escaped == 0);
	// R starts the flight again.
	t.Key(GLFW_KEY_R);
	CHECK(t.view->Current().Readings()["time_ms"] == 0.0);
}

TEST_CASE("3D sample: left drag and arrows turn the camera, the wheel and Z X move it, Home restores it, and it turns by itself")
{
	TestViewer t(kFigure17);
	const OrbitCamera home = t.view->Orbit();
	t.view->Orbit().autoOrbit = false;
	t.view->OnCursor(b2Vec2(300.0f, 300.0f));
	t.view->OnMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
	t.view->OnCursor(b2Vec2(350.0f, 320.0f));
	t.view->OnMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
	CHECK(t.view->Orbit().azimuth == doctest::Approx(home.azimuth - 50 * 0.008));
	CHECK(t.view->Orbit().elevation == doctest::Approx(home.elevation + 20 * 0.008));
	t.view->OnCursor(b2Vec2(400.0f, 400.0f)); // no button: nothing turns
	CHECK(t.view->Orbit().azimuth == doctest::Approx(home.azimuth - 50 * 0.008));
	t.Key(GLFW_KEY_LEFT);
	CHECK(t.view->Orbit().azimuth == doctest::Approx(home.azimuth - 25 * 0.008));
	t.view->OnScroll(1.0);
	CHECK(t.view->Orbit().distance == doctest::Approx(home.distance / 1.1));
	t.Key(GLFW_KEY_Z);
	CHECK(t.view->Orbit().distance == doctest::Approx(home.distance));
	t.Key(GLFW_KEY_SPACE); // no bombs in 3D
	CHECK(t.World()->GetBodyCount() == 0);
	t.Key(GLFW_KEY_HOME);
	CHECK(t.view->Orbit().azimuth == home.azimuth);
	CHECK(t.view->Orbit().distance == home.distance);
	// Turning by itself: a fixed angle a frame, whether or not the sample is paused.
	t.view->Orbit().autoOrbit = true;
	t.Key(GLFW_KEY_P);
	t.Frames(10);
	CHECK(t.view->Orbit().azimuth == doctest::Approx(home.azimuth + 10 * home.orbitPerFrame));
	CHECK(t.view->Current().StepCount() == 0);
}

// b2analytic tests: the viewer's parts without a window: settings kept between runs, the camera,
// the debug drawing through b2Draw and b2a::DrawWorld, the contacts counted by method, the switch
// to Box2D 8-gons, and the shape editor's refusals.
#include <doctest/doctest.h>

#include "ViewerTestSupport.h"
#include "samples/ShapeEditor.h"

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/b2analytic.h"

#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace b2a;
using namespace b2a::test;
using namespace b2a::viewer;

namespace
{
std::string TempFile(const std::string& name)
{
	const auto dir = std::filesystem::temp_directory_path() / "b2a_viewer_tests";
	std::filesystem::create_directories(dir);
	return (dir / name).string();
}

// Area of the triangles a batch holds (each counter-clockwise triangle positive).
double TriangleArea(const DrawBatch& batch)
{
	double area = 0.0;
	const auto& t = batch.Triangles();
	for (size_t i = 0; i + 2 < t.size(); i += 3)
		area += 0.5 * ((double(t[i + 1].x) - t[i].x) * (double(t[i + 2].y) - t[i].y) -
		               (double(t[i + 2].x) - t[i].x) * (double(t[i + 1].y) - t[i].y));
	return area;
}
} // namespace

TEST_CASE("settings: saved and read back field by field; a missing file leaves the defaults")
{
	const std::string path = TempFile("settings_roundtrip.json");
	std::filesystem::remove(path);
	Settings s;
	CHECK(LoadSettings(path, s) == ""); // missing: defaults
	CHECK(s.windowWidth == 1280);
	s.sample = "packing";
	s.windowWidth = 1000;
	s.showPanel = false;
	s.compare = CompareMode::sideBySide;
	s.draw.aabbs = true;
	s.draw.contactNormals = true;
	s.steps["packing"].hertz = 2500.0;
	s.steps["packing"].stepsPerFrame = 7;
	s.steps["packing"].warmStarting = false;
	REQUIRE(SaveSettings(path, s) == "");
	Settings r;
	REQUIRE(LoadSettings(path, r) == "");
	CHECK(r.sample == "packing");
	CHECK(r.windowWidth == 1000);
	CHECK_FALSE(r.showPanel);
	CHECK(r.compare == CompareMode::sideBySide);
	CHECK(r.draw.aabbs);
	CHECK(r.draw.contactNormals);
	CHECK_FALSE(r.draw.contactPoints);
	CHECK(r.steps.at("packing").hertz == 2500.0);
	CHECK(r.steps.at("packing").stepsPerFrame == 7);
	CHECK_FALSE(r.steps.at("packing").warmStarting);
}

TEST_CASE("settings: a bad file is refused with the field and the value named, and changes nothing")
{
	const std::string path = TempFile("settings_bad.json");
	const auto refused = [&](const std::string& text, const std::string& field, const std::string& value) {
		std::ofstream(path) << text;
		Settings s;
		s.windowWidth = 640;
		const std::string e = LoadSettings(path, s);
		CAPTURE(text);
		CAPTURE(e);
		CHECK(e.find(path) != std::string::npos);
		CHECK(e.find(field) != std::string::npos);
		CHECK(e.find(value) != std::string::npos);
		CHECK(s.windowWidth == 640);
		CHECK(s.steps.empty());
	};
	refused(R"({"windowWidth": 20})", "windowWidth", "20");
	refused(R"({"compare": 7})", "compare", "7");
	refused(R"({"steps": {"packing": {"hertz": -5}}})", "hertz", "-5");
	refused(R"({"steps": {"packing": {"velocityIterations": 0}}})", "velocityIterations", "0");
	refused(R"({"draw": {"aabbs": "yes"}})", "aabbs", "yes");
	refused(R"({"windowWidth": 800, "steps": 3})", "steps", "3");
	refused("{not json", "not valid JSON", "");
}

TEST_CASE("camera: screen and world points map back and forth; Fit holds the box left of the panel")
{
	Camera c;
	c.width = 1280;
	c.height = 800;
	c.Fit(b2Vec2(-40.0f, -8.0f), b2Vec2(40.0f, 60.0f), 350.0f);
	for (b2Vec2 w : {b2Vec2(-40.0f, -8.0f), b2Vec2(40.0f, 60.0f), b2Vec2(3.5f, 7.25f)})
	{
		const b2Vec2 s = c.WorldToScreen(w);
		CHECK(s.x >= 0.0f);
		CHECK(s.x <= 1280.0f - 350.0f);
		CHECK(s.y >= 0.0f);
		CHECK(s.y <= 800.0f);
		const b2Vec2 back = c.ScreenToWorld(s);
		CHECK(back.x == doctest::Approx(w.x).epsilon(1e-5));
		CHECK(back.y == doctest::Approx(w.y).epsilon(1e-5));
	}
	// Screen y grows downwards, world y upwards.
	CHECK(c.WorldToScreen(b2Vec2(0.0f, 1.0f)).y < c.WorldToScreen(b2Vec2(0.0f, 0.0f)).y);
	// The projection takes the view's corners to clip space's.
	float m[16];
	c.Projection(m);
	const b2Vec2 topRight = c.ScreenToWorld(b2Vec2(1280.0f, 0.0f));
	CHECK(m[0] * topRight.x + m[12] == doctest::Approx(1.0f).epsilon(1e-5));
	CHECK(m[5] * topRight.y + m[13] == doctest::Approx(1.0f).epsilon(1e-5));
}

TEST_CASE("drawing: DrawWorld through the viewer's b2Draw puts an ellipse's outline on the ellipse and fills its area")
{
	b2World world(b2Vec2(0.0f, 0.0f));
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	bd.position.Set(3.0f, -2.0f);
	bd.angle = 0.7f;
	b2Body* body = world.CreateBody(&bd);
	const ShapePtr ellipse = MakeEllipse(2.0, 0.5);
	CreateAnalyticFixture(body, ellipse, 1.0f);
	DrawBatch batch;
	batch.SetFlags(b2Draw::e_shapeBit);
	DrawWorld(&world, &batch, 96);
	REQUIRE(batch.Lines().size() >= 2 * 96);
	const Pose pose = GetAnalyticPose(body->GetFixtureList());
	for (const DrawVertex& v : batch.Lines())
	{
		// Back to the body frame: on x²/4 + y²/0.25 = 1 to float rounding.
		const Vec2 p = ToBody(pose, Vec2(v.x, v.y));
		CHECK(p.x * p.x / 4.0 + p.y * p.y / 0.25 == doctest::Approx(1.0).epsilon(2e-5));
	}
	// The fill is the inscribed polygon of the outline: its area within 0.5 % of πab.
	CHECK(TriangleArea(batch) == doctest::Approx(kPi * 2.0 * 0.5).epsilon(5e-3));
	// Offsets shift everything (the side-by-side copy).
	DrawBatch shifted;
	shifted.SetFlags(b2Draw::e_shapeBit);
	shifted.SetOffset(b2Vec2(100.0f, 0.0f));
	DrawWorld(&world, &shifted, 96);
	REQUIRE(shifted.Lines().size() == batch.Lines().size());
	CHECK(shifted.Lines()[5].x == doctest::Approx(batch.Lines()[5].x + 100.0f));
	CHECK(shifted.Lines()[5].y == batch.Lines()[5].y);
}

TEST_CASE("drawing: a heart, which is not convex, is filled over its own area")
{
	b2World world(b2Vec2(0.0f, 0.0f));
	b2BodyDef bd;
	b2Body* body = world.CreateBody(&bd);
	const ShapePtr heart = MakeHeart(1.0);
	CreateAnalyticFixture(body, heart, 1.0f);
	DrawBatch batch;
	batch.SetFlags(b2Draw::e_shapeBit);
	DrawWorld(&world, &batch, 256);
	// Against the shape's own area (quadrature in the library); the sampled outline cuts corners
	// by less than a percent.
	CHECK(TriangleArea(batch) == doctest::Approx(heart->Mass().area).epsilon(1e-2));
	// And every triangle lies inside the heart: its centroid's level is below the surface's.
	const auto& t = batch.Triangles();
	for (size_t i = 0; i + 2 < t.size(); i += 3)
	{
		const Vec2 c((double(t[i].x) + t[i + 1].x + t[i + 2].x) / 3.0, (double(t[i].y) + t[i + 1].y + t[i + 2].y) / 3.0);
		CHECK(heart->Level(c) <= heart->SurfaceLevel() + 1e-6);
	}
}

TEST_CASE("statistics: contacts counted by the method that solves them")
{
	b2World world(b2Vec2(0.0f, 0.0f));
	const auto add = [&](ShapePtr shape, b2Vec2 p) {
		b2BodyDef bd;
		bd.type = b2_dynamicBody;
		bd.position = p;
		CreateAnalyticFixture(world.CreateBody(&bd), std::move(shape), 1.0f);
	};
	add(MakeCircle(1.0), b2Vec2(0.0f, 0.0f));
	add(MakeCircle(1.0), b2Vec2(1.9f, 0.0f)); // circles overlapping by 0.1
	add(MakeEllipse(1.0, 0.5), b2Vec2(20.0f, 0.0f));
	add(MakeEllipse(1.0, 0.5), b2Vec2(21.9f, 0.0f)); // ellipses end to end, overlapping by 0.1
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	b2PolygonShape box;
	box.SetAsBox(0.5f, 0.5f);
	bd.position.Set(40.0f, 0.0f);
	world.CreateBody(&bd)->CreateFixture(&box, 1.0f);
	bd.position.Set(40.9f, 0.0f);
	world.CreateBody(&bd)->CreateFixture(&box, 1.0f);
	world.Step(1e-6f, 1, 1); // Box2D makes its contacts for the pairs whose boxes overlap
	const MethodStats s = CountMethods(&world);
	CHECK(s.pairs == 3);
	CHECK(s.failed == 0);
	REQUIRE(s.methods.count("closed_form"));
	REQUIRE(s.methods.count("ellipse_pair"));
	REQUIRE(s.methods.count("box2d_polygons"));
	for (const char* m : {"closed_form", "ellipse_pair", "box2d_polygons"})
	{
		CAPTURE(m);
		CHECK(s.methods.at(m).contacts == 1);
		CHECK(s.methods.at(m).touching == 1);
		CHECK(s.methods.at(m).Mean() > 0.0);
	}
	CHECK(s.TotalMicroseconds() > 0.0);
}

TEST_CASE("comparison: analytic particles switched in place to Box2D 8-gons and back keep bodies, shapes and motion")
{
	TestViewer t("mixed-with-box2d-shapes");
	t.Frames(20);
	std::vector<b2Body*> bodies = t.Dynamic();
	std::vector<const Shape*> shapes;
	std::vector<b2Vec2> velocities;
	int analytic = 0;
	for (b2Body* b : bodies)
	{
		shapes.push_back(GetAnalyticShape(b->GetFixtureList()));
		velocities.push_back(b->GetLinearVelocity());
		analytic += shapes.back() != nullptr;
	}
	REQUIRE(analytic > 20);
	t.view->SetCompare(CompareMode::polygons);
	CHECK(t.view->Current().IsPolygons());
	REQUIRE(t.Dynamic() == bodies);
	for (size_t i = 0; i < bodies.size(); ++i)
	{
		const b2Fixture* f = bodies[i]->GetFixtureList();
		CHECK(GetAnalyticShape(f) == nullptr);
		CHECK(bodies[i]->GetLinearVelocity() == velocities[i]);
		if (!shapes[i])
			continue;
		REQUIRE(f->GetType() == b2Shape::e_polygon);
		const b2PolygonShape* p = static_cast<const b2PolygonShape*>(f->GetShape());
		// Eight corners; a heart's hull drops the one in its notch.
		CHECK(p->m_count == (shapes[i]->IsConvex() ? 8 : 7));
		// Its corners lie on the analytic surface (MakeInscribedPolygon), in the shape's frame.
		for (int32 k = 0; k < p->m_count; ++k)
		{
			const Vec2 v(p->m_vertices[k].x, p->m_vertices[k].y);
			CHECK(shapes[i]->Level(v) == doctest::Approx(shapes[i]->SurfaceLevel()).epsilon(1e-4));
		}
	}
	t.Frames(10); // they step as polygons
	t.view->SetCompare(CompareMode::analytic);
	CHECK_FALSE(t.view->Current().IsPolygons());
	for (size_t i = 0; i < bodies.size(); ++i)
		CHECK(GetAnalyticShape(bodies[i]->GetFixtureList()) == shapes[i]);
}

TEST_CASE("comparison: side by side, a second copy in 8-gons steps with the first and takes the mouse on its side")
{
	TestViewer t("superellipse-stack");
	t.view->SetCompare(CompareMode::sideBySide);
	Sample* twin = t.view->Twin();
	REQUIRE(twin);
	CHECK(twin->IsPolygons());
	CHECK_FALSE(t.view->Current().IsPolygons());
	CHECK(twin->World()->GetBodyCount() == t.World()->GetBodyCount());
	t.Frames(5);
	CHECK(twin->StepCount() == 5);
	CHECK(t.view->Current().StepCount() == 5);
	// A click on the right copy's top slab grabs the twin's body, not the sample's.
	b2Body* top = nullptr;
	for (b2Body* b = twin->World()->GetBodyList(); b; b = b->GetNext())
		if (b->GetType() == b2_dynamicBody && b->GetPosition().x < 0.0f && (!top || b->GetPosition().y > top->GetPosition().y))
			top = b;
	REQUIRE(top);
	t.CursorAt(top->GetPosition() + t.view->TwinOffset());
	t.view->OnMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
	REQUIRE(twin->MouseJoint());
	CHECK(twin->MouseJoint()->GetBodyB() == top);
	CHECK(t.view->Current().MouseJoint() == nullptr);
	t.view->OnMouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
	CHECK(twin->MouseJoint() == nullptr);
	// Both are drawn, the twin shifted by the offset.
	t.view->DrawScene();
	const std::vector<b2Vec2> points = t.view->BodyScreenPoints();
	CHECK(points.size() == 2 * t.Dynamic().size());
	t.view->SetCompare(CompareMode::analytic);
	CHECK(t.view->Twin() == nullptr);
}

TEST_CASE("shape editor: the factories' refusals reach the panel with the field and the value")
{
	ShapeEditor e;
	CHECK(e.Make());
	REQUIRE(e.shape);
	e.n = 0.5f;
	CHECK_FALSE(e.Make());
	CHECK(e.shape == nullptr);
	CHECK(e.error.find("'n'") != std::string::npos);
	CHECK(e.error.find("0.5") != std::string::npos);
	e.n = 4.0f;
	e.kind = EditorKind::heart;
	e.alpha = -1.0f;
	CHECK_FALSE(e.Make());
	CHECK(e.error.find("alpha") != std::string::npos);
	e.alpha = 0.5f;
	CHECK(e.Make());
	CHECK(e.shape->Describe().find("heart") != std::string::npos);
}

TEST_CASE("samples: every registered sample steps 60 frames with nothing non-finite and nothing escaped")
{
	for (const SampleEntry& e : Samples())
	{
		CAPTURE(e.name);
		TestViewer t(SampleKey(e));
		CHECK(t.view->SampleIndex() == FindSample(SampleKey(e)));
		t.Frames(60);
		t.view->DrawScene();
		const WorldHealth h = t.view->Health();
		CHECK(h.bodies > 0);
		CHECK(h.nonFinite == 0);
		CHECK(h.escaped == 0);
		// 2D samples draw through b2Draw, 3D samples into the mesh batch.
		CHECK(t.view->Batch().Triangles().size() + t.view->Batch3().Triangles().size() > 0);
		CHECK_FALSE(t.view->BodyScreenPoints().empty());
	}
}

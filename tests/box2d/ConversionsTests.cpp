// b2analytic tests: conversions between Box2D's math and the library's, the inscribed Box2D
// polygon, and the fixture shorthands with friction and restitution.
#include "SceneSupport.h"
#include "GeometryReference.h"

#include "b2analytic/Box2DConversions.h"

#include <doctest/doctest.h>

#include <string>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("Box2D vectors, rotations and transforms convert both ways; rotations come out rigid")
{
	const b2Vec2 v(1.25f, -3.5e-7f);
	CHECK(ToVec2(v).x == 1.25);
	CHECK(ToVec2(v).y == double(-3.5e-7f));
	CHECK(ToB2Vec2(Vec2(0.1, -2.0)).x == 0.1f);
	Random rng(7);
	for (int i = 0; i < 1000; ++i)
	{
		const float angle = float(rng.Uniform(-40.0, 40.0));
		const b2Rot q(angle); // Box2D's float sine and cosine, off unit length by up to 1e-7
		const Rot r = ToRot(q);
		CHECK(std::fabs(r.c * r.c + r.s * r.s - 1.0) < 1e-15);
		// The same direction as Box2D's pair, and the angle to float rounding.
		CHECK(std::fabs(r.c * q.s - r.s * q.c) < 1e-15);
		CHECK(r.c * q.c + r.s * q.s > 0.0);
		CHECK(std::fabs(std::remainder(r.Angle() - double(angle), 2.0 * kPi)) < 2e-7);
		const b2Transform xf(b2Vec2(float(rng.Uniform(-50.0, 50.0)), 3.0f), q);
		const Pose pose = ToPose(xf);
		CHECK(pose.p.x == double(xf.p.x));
		CHECK(pose.p.y == 3.0);
		const b2Transform back = ToB2Transform(pose);
		CHECK(back.p.x == xf.p.x);
		CHECK(back.p.y == xf.p.y);
		CHECK(std::fabs(back.q.c - q.c) <= 1.2e-7f);
		CHECK(std::fabs(back.q.s - q.s) <= 1.2e-7f);
	}
	// A zero or non-finite pair gives the identity, not NaN.
	b2Rot zero;
	zero.c = zero.s = 0.0f;
	CHECK(ToRot(zero).c == 1.0);
	CHECK(ToRot(zero).s == 0.0);
}

TEST_CASE("MakeInscribedPolygon: Box2D's polygon on the surface, refused by name where Box2D would assert")
{
	// Every vertex lies on the shape's surface (reference levels in long double) to float
	// rounding, and the polygon has the count asked for (convex shapes) or its hull (the heart).
	struct Case
	{
		ShapePtr shape;
		std::function<long double(Vec2)> level;
		double own;
	};
	const Case cases[] = {
		{MakeCircle(0.4), [](Vec2 x) { return SuperellipseLevelRef(x, 0.4, 0.4, 2.0, 2.0); }, 1.0},
		{MakeEllipse(0.5, 0.3), [](Vec2 x) { return SuperellipseLevelRef(x, 0.5, 0.3, 2.0, 2.0); }, 1.0},
		{MakeSuperellipse(0.5, 0.3, 4.0, 4.0), [](Vec2 x) { return SuperellipseLevelRef(x, 0.5, 0.3, 4.0, 4.0); }, 1.0},
		{MakeHeart(0.2), [](Vec2 x) { return HeartLevelRef(x); }, 0.2},
	};
	for (const Case& c : cases)
		for (int count = 3; count <= b2_maxPolygonVertices; ++count)
		{
			CAPTURE(c.shape->Describe());
			CAPTURE(count);
			const b2PolygonShape polygon = MakeInscribedPolygon(*c.shape, count);
			if (c.shape->IsConvex())
				CHECK(polygon.m_count == count);
			CHECK(polygon.m_count >= 3);
			CHECK(polygon.m_radius == b2_polygonRadius);
			for (int k = 0; k < polygon.m_count; ++k)
				CHECK(double(std::fabs(c.level(ToVec2(polygon.m_vertices[k])) / c.own - 1.0)) < 1e-6);
		}
	// The 8-gon of an ellipse starts on its major axis, as an affine-regular polygon does.
	const b2PolygonShape octagon = MakeInscribedPolygon(*MakeEllipse(0.5, 0.3), 8);
	bool onAxis = false;
	for (int k = 0; k < octagon.m_count; ++k)
		onAxis = onAxis || (octagon.m_vertices[k].x == 0.5f && octagon.m_vertices[k].y == 0.0f);
	CHECK(onAxis);
	auto message = [](auto&& f) {
		try
		{
			f();
		}
		catch (const InvalidParameter& e)
		{
			return std::string(e.what());
		}
		return std::string();
	};
	const ShapePtr circle = MakeCircle(1.0);
	CHECK(message([&] { MakeInscribedPolygon(*circle, 2); }).find("'count'") != std::string::npos);
	CHECK(message([&] { MakeInscribedPolygon(*circle, 9); }).find("'count'") != std::string::npos);
	// Smaller than Box2D's weld distance: its polygon would assert.
	CHECK(message([&] { MakeInscribedPolygon(*MakeCircle(0.001), 8); }).find("'shape'") != std::string::npos);
	CHECK(message([&] { MakeInscribedPolygon(*MakeEllipse(1.0, 1e-8), 8); }).find("'shape'") != std::string::npos);
	CHECK(MakeInscribedPolygon(*MakeCircle(0.01), 8).m_count >= 3);
}

TEST_CASE("CreateAnalyticFixture with density, friction and restitution sets them and refuses bad ones by name")
{
	b2World world(b2Vec2(0.0f, -10.0f));
	b2BodyDef def;
	def.type = b2_dynamicBody;
	b2Body* body = world.CreateBody(&def);
	const ShapePtr shape = MakeSuperellipse(0.5, 0.3, 4.0, 4.0);
	const b2Fixture* f = CreateAnalyticFixture(body, shape, 2.0f, 0.3f, 0.4f);
	CHECK(f->GetDensity() == 2.0f);
	CHECK(f->GetFriction() == 0.3f);
	CHECK(f->GetRestitution() == 0.4f);
	CHECK(GetAnalyticShape(f) == shape.get());
	CHECK(body->GetMass() == doctest::Approx(2.0 * shape->Mass().area).epsilon(1e-6));
	CHECK(CreateAnalyticFixture(body, shape, 1.0f, 0.5f)->GetRestitution() == 0.0f);
	AnalyticFixtureDef analytic;
	analytic.shape = shape;
	analytic.local = Pose(Vec2(1.0, 0.0), 0.5);
	const b2Fixture* g = CreateAnalyticFixture(body, analytic, 1.0f, 0.7f, 0.1f);
	CHECK(g->GetFriction() == 0.7f);
	CHECK(g->GetRestitution() == 0.1f);
	CHECK(GetAnalyticPose(g).p.x == doctest::Approx(1.0));
	CHECK_THROWS_WITH_AS(CreateAnalyticFixture(body, shape, 1.0f, -0.5f), doctest::Contains("'friction'"), InvalidParameter);
	CHECK_THROWS_WITH_AS(CreateAnalyticFixture(body, analytic, 1.0f, 0.5f, NAN), doctest::Contains("'restitution'"), InvalidParameter);
	CHECK_THROWS_AS(CreateAnalyticFixture(nullptr, shape, 1.0f, 0.5f), MisuseError);
}

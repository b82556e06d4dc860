// The worked example of a shape kind registered outside the library (demos/examples): the
// capsule's geometry against the library's generic answers, its closed-form contacts and common
// levels against the grid method, the fallback of its other pairs by solver class, misuse of
// the registry, and its Box2D scene.
//
// References: the base class's generic radial root, support and AABB (Shape::RadiusAt,
// Shape::Support, Shape::ComputeAABB, called past the capsule's overrides), numerical polar
// quadrature of the closed-form radius for the mass, the grid method (an independent solver)
// for the closed-form contacts and levels, dense outlines for the capsule–superellipse distance,
// and the segment–polygon distance for the capsule against a box.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include "CapsuleScene.h"
#include "TestSupport.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;
using namespace example;

namespace
{
// The larger coordinate difference.
double MaxDiff(Vec2 a, Vec2 b) { return std::max(std::fabs(a.x - b.x), std::fabs(a.y - b.y)); }

// Distance from x to segment p–q.
double SegmentDistance(Vec2 x, Vec2 p, Vec2 q)
{
	const Vec2 e = q - p;
	const double ee = LengthSquared(e);
	const double t = ee > 0.0 ? std::clamp(Dot(x - p, e) / ee, 0.0, 1.0) : 0.0;
	return Distance(x, p + t * e);
}

// A random capsule pose pair, B's centre at `reach` times the sum of bounding radii from A's,
// the two axes at least 0.2 rad from parallel (parallel capsules touch along a segment: no
// unique point to compare).
struct Pair
{
	std::shared_ptr<CapsuleShape> a, b;
	Pose pa, pb;
};
Pair RandomPair(Random& rng, double reach)
{
	Pair p;
	p.a = MakeCapsule(rng.Uniform(0.0, 1.5), rng.Uniform(0.2, 0.8));
	p.b = MakeCapsule(rng.Uniform(0.0, 1.5), rng.Uniform(0.2, 0.8));
	p.pa = Pose(Vec2(rng.Uniform(-1.0, 1.0), rng.Uniform(-1.0, 1.0)), rng.Angle());
	double turn = 0.0;
	do
		turn = rng.Angle();
	while (std::fabs(std::remainder(turn, kPi)) < 0.2);
	const double dir = rng.Angle();
	p.pb = Pose(p.pa.p + reach * (p.a->BoundingRadius() + p.b->BoundingRadius()) * Vec2(std::cos(dir), std::sin(dir)),
	            p.pa.q.Angle() + turn);
	return p;
}

// The field an InvalidParameter named ("" where none was thrown).
template <class F>
std::string RefusedField(F&& f)
{
	try
	{
		f();
	}
	catch (const InvalidParameter& e)
	{
		return e.Field();
	}
	return "";
}
} // namespace

TEST_CASE("capsule: level, radius, support, AABB and mass against the library's generic answers")
{
	Random rng(4001);
	for (int k = 0; k < 20; ++k)
	{
		const double h = k == 0 ? 0.0 : rng.Uniform(0.0, 2.0), r = rng.Uniform(0.1, 1.0);
		const auto c = MakeCapsule(h, r);
		INFO(c->Describe());
		CHECK(c->Kind() == CapsuleKind());
		CHECK(c->BoundingRadius() == h + r);
		double worstRadius = 0.0, worstSupport = 0.0, worstGradient = 0.0;
		for (int i = 0; i < 64; ++i)
		{
			const Vec2 x(rng.Uniform(-3.0, 3.0), rng.Uniform(-2.0, 2.0));
			const double d = SegmentDistance(x, Vec2(-h, 0.0), Vec2(h, 0.0));
			CHECK(RelativeError(c->Level(x), d * d / (r * r), 1e-300) <= 1e-13);
			// The gradient against central differences of the level.
			const double step = 1e-6 * (h + r);
			const Vec2 g = c->Derivatives(x).gradient;
			const Vec2 fd((c->Level(x + Vec2(step, 0.0)) - c->Level(x - Vec2(step, 0.0))) / (2.0 * step),
			              (c->Level(x + Vec2(0.0, step)) - c->Level(x - Vec2(0.0, step))) / (2.0 * step));
			worstGradient = std::max(worstGradient, Length(g - fd) / std::max(Length(g), 1.0 / r));
			const double theta = rng.Angle(), level = rng.LogUniform(0.01, 4.0);
			const Vec2 u(std::cos(theta), std::sin(theta));
			worstRadius = std::max(worstRadius, RelativeError(c->RadiusAt(u, level), c->Shape::RadiusAt(u, level)));
			worstSupport = std::max(worstSupport, std::fabs(c->SupportValue(u) - c->Shape::SupportValue(u)) / (h + r));
		}
		CAPTURE(worstRadius);
		CAPTURE(worstSupport);
		CAPTURE(worstGradient);
		CHECK(worstRadius <= 1e-12);
		CHECK(worstSupport <= 1e-12);
		CHECK(worstGradient <= 1e-6);
		const Pose pose(Vec2(0.3, -0.7), rng.Angle());
		const Box box = c->ComputeAABB(pose), generic = c->Shape::ComputeAABB(pose);
		CHECK(MaxDiff(box.lower, generic.lower) <= 1e-7 * (h + r));
		CHECK(MaxDiff(box.upper, generic.upper) <= 1e-7 * (h + r));
		// Mass: polar quadrature of the closed-form radius, Simpson's rule on 20000 intervals
		// split at the caps' tangent points (where the radius is not smooth).
		double area = 0.0, ixx = 0.0, iyy = 0.0;
		const double tangent = std::atan2(r, h);
		const double breaks[] = {-kPi, -kPi + tangent, -tangent, tangent, kPi - tangent, kPi};
		for (int piece = 0; piece < 5; ++piece)
		{
			const int n = 4000;
			const double t0 = breaks[piece], dt = (breaks[piece + 1] - t0) / n;
			for (int j = 0; j <= n; ++j)
			{
				const double t = t0 + j * dt, w = (j == 0 || j == n ? 1.0 : j % 2 ? 4.0 : 2.0) * dt / 3.0;
				const double R = c->RadiusAt(Vec2(std::cos(t), std::sin(t)), 1.0);
				area += w * R * R / 2.0;
				iyy += w * std::pow(R, 4) * std::cos(t) * std::cos(t) / 4.0;
				ixx += w * std::pow(R, 4) * std::sin(t) * std::sin(t) / 4.0;
			}
		}
		const MassProperties& m = c->Mass();
		CHECK(RelativeError(m.area, area) <= 1e-9);
		CHECK(RelativeError(m.Ixx, ixx) <= 1e-9);
		CHECK(RelativeError(m.Iyy, iyy) <= 1e-9);
		CHECK(m.polarMoment == m.Ixx + m.Iyy);
	}
}

TEST_CASE("capsule: the closed-form contact and common level agree with the grid method, and swapping flips them")
{
	Random rng(4002);
	double worstSeparation = 0.0, worstPoint = 0.0, worstNormal = 0.0, worstLevel = 0.0;
	int closedForm = 0, compared = 0;
	for (int k = 0; k < 60; ++k)
	{
		// From overlapping (the segments apart) to well separated.
		const Pair p = RandomPair(rng, rng.Uniform(0.5, 1.6));
		const double size = 0.5 * (p.a->BoundingRadius() + p.b->BoundingRadius());
		const long before = g_closedFormContacts.load();
		const ContactResult exact = ComputeContact(*p.a, p.pa, *p.b, p.pb);
		REQUIRE(exact.Ok());
		if (exact.method != SolveMethod::closedForm)
			continue; // the segments cross: the closed form hands the pair to the grid
		++closedForm;
		CHECK(g_closedFormContacts.load() == before + 1);
		const LevelResult level = SolveCommonLevel(*p.a, p.pa, *p.b, p.pb);
		const LevelResult gridLevel = SolveCommonLevel(*p.a, p.pa, *p.b, p.pb, MethodChoice::grid);
		REQUIRE(level.Ok());
		REQUIRE(gridLevel.Ok());
		CHECK(level.method == SolveMethod::closedForm);
		CHECK(level.level == exact.level);
		worstLevel = std::max(worstLevel, RelativeError(gridLevel.level, level.level));
		// The cell is symmetric: (B, A) is solved as such, its answer the flip of (A, B)'s.
		const ContactResult swapped = ComputeContact(*p.b, p.pb, *p.a, p.pa);
		CHECK(std::fabs(swapped.separation - exact.separation) <= 1e-15 * size);
		CHECK(Length(swapped.normal + exact.normal) <= 1e-15);
		// The grid's one-sided scale is well posed only while neither segment enters the other
		// capsule: on its segment a capsule's level is 0, and a segment inside the other
		// particle makes every point of it a minimum.
		Vec2 a0, a1, b0, b1;
		p.a->Segment(p.pa, a0, a1);
		p.b->Segment(p.pb, b0, b1);
		const double cores = std::min({SegmentDistance(a0, b0, b1), SegmentDistance(a1, b0, b1), SegmentDistance(b0, a0, a1),
		                               SegmentDistance(b1, a0, a1)});
		if (!(cores > 1.05 * std::max(p.a->Radius(), p.b->Radius())))
			continue;
		++compared;
		const ContactResult grid = ComputeContact(*p.a, p.pa, *p.b, p.pb, MethodChoice::grid);
		REQUIRE(grid.Ok());
		CHECK(grid.touching == exact.touching);
		worstSeparation = std::max(worstSeparation, std::fabs(grid.separation - exact.separation) / size);
		worstPoint = std::max(worstPoint, std::max(Distance(grid.pointA, exact.pointA), Distance(grid.pointB, exact.pointB)) / size);
		worstNormal = std::max(worstNormal, Length(grid.normal - exact.normal));
	}
	CAPTURE(worstSeparation);
	CAPTURE(worstPoint);
	CAPTURE(worstNormal);
	CAPTURE(worstLevel);
	CHECK(closedForm >= 50);
	CHECK(compared >= 30);
	// (Measured: 7e-16, 6e-16, 4e-16 rad and 5e-15: both exact to rounding.)
	CHECK(worstSeparation <= 1e-12);
	CHECK(worstPoint <= 1e-12);
	CHECK(worstNormal <= 1e-12);
	CHECK(worstLevel <= 1e-12);
}

TEST_CASE("capsule: against a circle by the closed form, the circle first by the same function flipped")
{
	Random rng(4003);
	const auto capsule = MakeCapsule(0.9, 0.4);
	double worst = 0.0;
	for (int k = 0; k < 40; ++k)
	{
		const auto circle = MakeCircle(rng.Uniform(0.1, 1.0));
		const Pose pa(Vec2(0.0, 0.0), rng.Angle());
		const double dir = rng.Angle();
		const Pose pb(rng.Uniform(0.6, 1.5) * (1.3 + circle->BoundingRadius()) * Vec2(std::cos(dir), std::sin(dir)), 0.0);
		const ContactResult exact = ComputeContact(*capsule, pa, *circle, pb);
		REQUIRE(exact.Ok());
		REQUIRE(exact.method == SolveMethod::closedForm);
		// Independent: the distance from the circle's centre to the capsule's segment.
		Vec2 s0, s1;
		capsule->Segment(pa, s0, s1);
		const double want = SegmentDistance(pb.p, s0, s1) - 0.4 - circle->BoundingRadius();
		CHECK(std::fabs(exact.separation - want) <= 1e-14);
		const ContactResult grid = ComputeContact(*capsule, pa, *circle, pb, MethodChoice::grid);
		REQUIRE(grid.Ok());
		worst = std::max(worst, std::fabs(grid.separation - exact.separation));
		const ContactResult flipped = ComputeContact(*circle, pb, *capsule, pa);
		CHECK(flipped.method == SolveMethod::closedForm);
		CHECK(flipped.separation == exact.separation);
		CHECK(flipped.normal.x == -exact.normal.x);
		CHECK(flipped.pointA.y == exact.pointB.y);
	}
	CAPTURE(worst);
	CHECK(worst <= 1e-12);
}

TEST_CASE("capsule: pairs without a function of their own take the grid by the kind's solver class, exactly")
{
	const ShapeKind capsule = CapsuleKind();
	CHECK(KindSolverClass(capsule) == SolverClass::convex);
	CHECK(bool(GetContactFunction(capsule, BuiltinKinds::superellipse) == &GridContact));
	CHECK(bool(GetContactFunction(BuiltinKinds::ellipse, capsule) == &GridContact));
	CHECK(bool(GetContactFunction(capsule, capsule) == &CapsuleContact));
	CHECK(bool(GetPolygonContactFunction(capsule) == &SeparatingAxisContact));
	// Capsule against superellipse, within a thousandth of touching: the grid's separation
	// against the distance between dense outlines (spacing 3e-4 of the size: within 1e-8 of the
	// curves'), and 2e-3 further in, overlapping. (Only near contact do the two agree: a grid
	// contact's separation is measured along its normal, not the least distance.)
	Random rng(4004);
	const auto c = MakeCapsule(0.8, 0.3);
	const auto s = MakeSuperellipse(0.9, 0.5, 4.0, 4.0);
	auto outline = [&](const Shape& shape, const Pose& pose, int n) {
		std::vector<Vec2> points;
		for (int i = 0; i < n; ++i)
			points.push_back(ToWorld(pose, shape.SurfacePoint(2.0 * kPi * i / n)));
		return points;
	};
	// The least distance between two outlines, and its direction (from a to b): only the points
	// within `reach` of the other shape's bounding circle are compared.
	auto distance = [&](const std::vector<Vec2>& a, const Pose& pa, const std::vector<Vec2>& b, const Pose& pb, double reach,
	                    Vec2* way) {
		std::vector<Vec2> nearA, nearB;
		for (const Vec2 x : a)
			if (Distance(x, pb.p) <= s->BoundingRadius() + reach)
				nearA.push_back(x);
		for (const Vec2 y : b)
			if (Distance(y, pa.p) <= c->BoundingRadius() + reach)
				nearB.push_back(y);
		double best = 1e300;
		for (const Vec2 x : nearA)
			for (const Vec2 y : nearB)
				if (LengthSquared(y - x) < best)
				{
					best = LengthSquared(y - x);
					if (way)
						*way = Normalize(y - x);
				}
		return std::sqrt(best);
	};
	for (int k = 0; k < 4; ++k)
	{
		const Pose pa(Vec2(0.0, 0.0), rng.Angle());
		const Vec2 u(std::cos(1.3 * k), std::sin(1.3 * k));
		const double angle = rng.Angle();
		// Along u, B at the centre distance where the outlines are 1e-3 apart: secant steps on
		// coarse outlines, then on fine ones (20000 points) near the contact.
		const std::vector<Vec2> coarseA = outline(*c, pa, 2000), a = outline(*c, pa, 20000);
		auto gapAt = [&](double t, bool fine, Vec2* way) {
			const Pose pb(t * u, angle);
			return fine ? distance(a, pa, outline(*s, pb, 20000), pb, 0.05, way) - 1e-3
			            : distance(coarseA, pa, outline(*s, pb, 2000), pb, 10.0, way) - 1e-3;
		};
		double t = 2.5;
		for (int it = 0; it < 12; ++it)
		{
			const double gap = gapAt(t, it >= 6, nullptr);
			t -= gap;
			if (it >= 6 && std::fabs(gap) <= 1e-7)
				break;
		}
		Vec2 way;
		const double gap = gapAt(t, true, &way);
		const Pose near(t * u, angle);
		const ContactResult r = ComputeContact(*c, pa, *s, near);
		REQUIRE(r.Ok());
		CHECK(r.method == SolveMethod::grid);
		CHECK_FALSE(r.touching);
		CHECK(std::fabs(r.separation - (gap + 1e-3)) <= 1e-5);
		// 3e-3 further along the outlines' closest direction: overlapping by about 2e-3.
		const ContactResult in = ComputeContact(*c, pa, *s, Pose(near.p - 3e-3 * way, angle));
		CHECK(in.touching);
		CHECK(in.separation < -1e-3);
		CHECK(in.separation > -3e-3);
	}
	// Against a box, by the separating axis: the segment's distance to the box's edges minus r.
	const Vec2 box[4] = {Vec2(-1.0, -0.25), Vec2(1.0, -0.25), Vec2(1.0, 0.25), Vec2(-1.0, 0.25)};
	const Pose boxPose(Vec2(0.0, -1.0), 0.1);
	for (int k = 0; k < 6; ++k)
	{
		const Pose pa(Vec2(rng.Uniform(-1.0, 1.0), rng.Uniform(0.0, 0.4)), rng.Angle());
		const ContactResult r = ComputePolygonContact(*c, pa, box, 4, boxPose);
		REQUIRE(r.Ok());
		Vec2 s0, s1;
		c->Segment(pa, s0, s1);
		double want = 1e300;
		for (int j = 0; j < 4; ++j)
		{
			const Vec2 p = ToWorld(boxPose, box[j]), q = ToWorld(boxPose, box[(j + 1) % 4]);
			want = std::min({want, SegmentDistance(s0, p, q), SegmentDistance(s1, p, q), SegmentDistance(p, s0, s1),
			                 SegmentDistance(q, s0, s1)});
		}
		CHECK(std::fabs(r.separation - (want - 0.3)) <= 1e-9);
	}
}

TEST_CASE("capsule: misuse of the registry and the shape is refused, naming the field")
{
	(void)CapsuleKind(); // registered by now
	CHECK(RefusedField([] { RegisterShapeKind("capsule", 2, SolverClass::convex); }) == "name");
	CHECK(RefusedField([] { MakeCapsule(-0.1, 0.5); }) == "h");
	CHECK(RefusedField([] { MakeCapsule(std::nan(""), 0.5); }) == "h");
	CHECK(RefusedField([] { MakeCapsule(0.5, 0.0); }) == "r");
	CHECK(RefusedField([] { MakeCapsule(0.5, INFINITY); }) == "r");
	CHECK(RefusedField([] { RegisterContactFunction(CapsuleKind(), ShapeKind(), &CapsuleContact); }) == "b");
	CHECK(RefusedField([] { RegisterLevelFunction(CapsuleKind(), BuiltinKinds::circle, nullptr); }) == "function");
	// A user shape cannot claim the capsule's kind without being convex.
	UserShapeDef def;
	def.function = [](Vec2 x, double L) { return LengthSquared(x) - L; };
	def.kind = CapsuleKind();
	CHECK(RefusedField([&] { MakeUserShape(def); }) == "kind");
}

TEST_CASE("capsule scene: a short Box2D run stays finite and in its container, and every kind of capsule pair meets")
{
	CapsuleSceneConfig config;
	config.particles = 30;
	CapsuleScene scene(config);
	for (int k = 0; k < 180; ++k)
		scene.Step();
	const CapsuleSceneReport r = scene.Report();
	CHECK(r.nonFinite == 0);
	CHECK(r.escaped == 0);
	CHECK(std::isfinite(r.kineticEnergy));
	for (const char* pair : {"capsule-capsule", "capsule-superellipse", "capsule-circle", "box2d_circle-capsule", "capsule-wall"})
	{
		INFO(pair);
		CHECK(r.contacts.count(pair) == 1);
	}
	CHECK(r.closedFormContacts >= r.contacts.at("capsule-capsule"));
	// Resting contacts overlap by about Box2D's linear slop (0.005 m), as between its own shapes.
	CAPTURE(r.lastPenetration);
	CHECK(r.lastPenetration <= 0.02);
}

TEST_CASE("b2a_example_capsules: the quick run writes its summary and picture")
{
	const std::string out = "example_out/capsules";
	std::filesystem::remove_all(out);
	std::filesystem::create_directories("example_out");
	const std::string cmd = std::string("\"") + B2A_EXAMPLE_CAPSULES + "\" --quick --out " + out + " > " + out + ".stdout 2> " + out +
	                        ".stderr";
	INFO(cmd);
	REQUIRE(std::system(cmd.c_str()) == 0);
	std::ifstream f(out + "/summary.json");
	REQUIRE(f.good());
	const nlohmann::json s = nlohmann::json::parse(f);
	CHECK(s["non_finite_bodies"] == 0);
	CHECK(s["escaped_bodies"] == 0);
	CHECK(s["closed_form_contacts"].get<long>() > 0);
	CHECK(s["touching_contacts_by_kinds"]["capsule-superellipse"].get<long>() > 0);
	CHECK(std::filesystem::file_size(out + "/scene.svg") > 1000);
}

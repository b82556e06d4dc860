// b2analytic demo: analytic particles in a game's units (metres, g = 10 m/s^2, 60 Hz, 8 velocity
// and 3 position iterations, sleeping on) beside the same scenes of Box2D's own shapes: a
// pyramid of blocks, a ramp, and a bucket pile with ray casts through it.
#include "common/CommandLine.h"
#include "common/DemoCommon.h"
#include "common/GameBucket.h"
#include "common/Plot.h"
#include "common/Svg.h"

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/Box2DConversions.h"
#include "b2analytic/b2analytic.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace b2a;
using namespace b2a::demo;

namespace
{
const char* kHelp = R"(b2a_demo_game: analytic particles in a game's units beside Box2D's own shapes.

Box2D's testbed settings: metres, gravity -10 m/s^2, 60 steps a second, 8 velocity and 3
position iterations, sleeping on. Three scenes:
  pyramid  10 rows (55 bodies) of superellipses |2x|^8 + |2y|^8 <= 1 (1 m blocks, density 5,
           friction 0.2) on a ground edge, each row stacked on the one below (touching with
           Box2D's slop), beside the same pyramid of boxes whose rounded outline is 1 x 1 m
           (b2PolygonShape::SetAsBox(0.49, 0.49) plus Box2D's 1 cm skin): the top's height
           against time and when each falls asleep.
  ramp     a 30-degree ramp: a pyramid block that sticks (friction 0.6 > tan 30), one that slides
           (friction 0.4: a = g (sin - mu cos)) and a disc of radius 0.4 m that rolls (a = 2/3 g
           sin): measured accelerations against the textbook. (A block n = 4 tips over there:
           its face, flat to the slop, is 0.38 m wide, and its centre 0.29 m downhill of the
           middle of it.)
  bucket   particles dropped from a lattice into a chain-shaped bucket 16 m wide, beside the same
           pile of Box2D 8-gons inscribed in the same shapes (b2a::MakeInscribedPolygon): when
           each pile falls asleep (-1: not within --duration), for every family alone and
           mixed (--quick: the chosen family alone); then vertical rays cast down through the
           chosen family's analytic pile (b2World::RayCast), every hit checked to lie on the
           reported particle's surface with no particle entered before it.

Writes to DIR: summary.json, pyramid.svg (both pyramids at rest), pyramid_top.svg (top height
against time), ramp.svg, bucket.svg (the analytic pile with the rays), bucket_polygons.svg,
bucket_awake.svg (bodies awake against time).

)";

const b2Vec2 kGravity = kGameGravity;
const float kStep = kGameStep;

// Box2D's debug drawing into an SVG canvas: b2a::DrawWorld draws the analytic particles' true
// outlines through it, and Box2D's own shapes as Box2D draws them.
class SvgDraw final : public b2Draw
{
public:
	explicit SvgDraw(SvgCanvas& canvas) : m_canvas(canvas) { SetFlags(e_shapeBit); }
	void DrawPolygon(const b2Vec2* v, int32 n, const b2Color& c) override { m_canvas.Polygon(Points(v, n), Outline(c)); }
	void DrawSolidPolygon(const b2Vec2* v, int32 n, const b2Color& c) override { m_canvas.Polygon(Points(v, n), Fill(c)); }
	void DrawCircle(const b2Vec2& p, float r, const b2Color& c) override { m_canvas.Circle(ToVec2(p), r, Outline(c)); }
	void DrawSolidCircle(const b2Vec2& p, float r, const b2Vec2&, const b2Color& c) override
	{
		m_canvas.Circle(ToVec2(p), r, Fill(c));
	}
	void DrawSegment(const b2Vec2& a, const b2Vec2& b, const b2Color& c) override
	{
		Style s = Outline(c);
		s.width = 2.0;
		m_canvas.Polyline({ToVec2(a), ToVec2(b)}, s);
	}
	void DrawTransform(const b2Transform&) override {}
	void DrawPoint(const b2Vec2& p, float, const b2Color& c) override { m_canvas.Dot(ToVec2(p), 2.0, Colour(c)); }

private:
	static std::vector<Vec2> Points(const b2Vec2* v, int32 n)
	{
		std::vector<Vec2> out;
		for (int32 i = 0; i < n; ++i)
			out.push_back(ToVec2(v[i]));
		return out;
	}
	static std::string Colour(const b2Color& c)
	{
		char b[32];
		std::snprintf(b, sizeof(b), "rgb(%d,%d,%d)", int(255 * c.r), int(255 * c.g), int(255 * c.b));
		return b;
	}
	static Style Outline(const b2Color& c)
	{
		Style s;
		s.stroke = Colour(c);
		return s;
	}
	static Style Fill(const b2Color& c)
	{
		Style s;
		s.fill = Colour(c);
		s.opacity = 0.5;
		s.stroke = Colour(c);
		return s;
	}
	SvgCanvas& m_canvas;
};

// Draw a world (lower-left and upper-right corners in metres) with a title into `canvas`.
void DrawInto(SvgCanvas& canvas, b2World& world, const std::string& title)
{
	SvgDraw draw(canvas);
	DrawWorld(&world, &draw);
	canvas.Label(10.0, 20.0, title);
}

b2Body* GroundEdge(b2World& world, b2Vec2 a, b2Vec2 b, float friction)
{
	b2BodyDef def;
	b2Body* ground = world.CreateBody(&def);
	b2EdgeShape edge;
	edge.SetTwoSided(a, b);
	b2FixtureDef fd;
	fd.shape = &edge;
	fd.friction = friction;
	ground->CreateFixture(&fd);
	return ground;
}

b2Body* DynamicBody(b2World& world, Vec2 position, double angle)
{
	b2BodyDef def;
	def.type = b2_dynamicBody;
	def.position = ToB2Vec2(position);
	def.angle = float(angle);
	return world.CreateBody(&def);
}

// ---------------------------------------------------------------------------------------------
// Pyramid

struct Pyramid
{
	std::unique_ptr<b2World> world;
	std::vector<double> time, top; // the top block's height at every step
	double asleepAt = -1.0;        // when every body slept (-1: not within the run)
	int onePoint = 0, twoPoints = 0; // touching contacts by manifold points at the end
};

// Box2D's testbed pyramid (rows offset by half a block plus half a gap, 1.125 m apart), each row
// stacked on the one below: the boxes 1 m - slop apart; the superellipses, whose rounded
// shoulders meet at height 2 y(d/2) with y(x) = 0.5 (1 - |2x|^8)^(1/8) and d the offset, that
// less the slop. (At 1 m the superellipses' rows would start 1.2 mm apart and land on each other
// with 2.5 cm overlaps, as boxes stacked with such gaps do: Box2D 2.4 has no speculative contacts.)
Pyramid RunPyramid(bool analytic, double maxTime)
{
	Pyramid p;
	p.world = std::make_unique<b2World>(kGravity);
	GroundEdge(*p.world, b2Vec2(-20.0f, 0.0f), b2Vec2(20.0f, 0.0f), 0.2f);
	const ShapePtr block = MakeSuperellipse(0.5, 0.5, 8.0, 8.0);
	const double offset = 0.5625, shoulder = 0.5 * std::pow(1.0 - std::pow(offset, 8.0), 1.0 / 8.0);
	const double spacing = (analytic ? 2.0 * shoulder : 1.0) - b2_linearSlop;
	b2Body* top = nullptr;
	for (int row = 0; row < 10; ++row)
		for (int k = row; k < 10; ++k)
		{
			top = DynamicBody(*p.world, Vec2(-7.0 + offset * row + 1.125 * (k - row), 0.75 + spacing * row), 0.0);
			if (analytic)
				CreateAnalyticFixture(top, block, 5.0f, 0.2f);
			else
			{
				b2PolygonShape box;
				box.SetAsBox(0.5f - b2_polygonRadius, 0.5f - b2_polygonRadius);
				top->CreateFixture(&box, 5.0f)->SetFriction(0.2f);
			}
		}
	for (int step = 1; step * kStep <= maxTime + 1e-9; ++step)
	{
		p.world->Step(kStep, 8, 3);
		p.time.push_back(step * kStep);
		p.top.push_back(top->GetPosition().y);
		if (p.asleepAt < 0.0 && AllAsleep(*p.world))
			p.asleepAt = step * kStep;
	}
	for (b2Contact* c = p.world->GetContactList(); c; c = c->GetNext())
		if (c->IsTouching())
			(c->GetManifold()->pointCount == 2 ? p.twoPoints : p.onePoint) += 1;
	return p;
}

Json PyramidPart(const std::string& out, Progress& progress)
{
	const double maxTime = 5.0;
	progress.Report(0.0, "pyramid of superellipses");
	const Pyramid a = RunPyramid(true, maxTime);
	progress.Report(0.1, "pyramid of boxes");
	const Pyramid b = RunPyramid(false, maxTime);
	double worst = 0.0;
	for (size_t k = 0; k < a.top.size(); ++k)
		if (a.time[k] > 1.0)
			worst = std::max(worst, std::fabs(a.top[k] - b.top[k]));
	SvgCanvas canvas(Vec2(-8.5, -0.5), Vec2(4.5, 10.5), 900.0);
	DrawInto(canvas, *a.world, "pyramid at rest: superellipses n = 8 (grey: asleep)");
	WriteText(out + "/pyramid.svg", canvas.Finish());
	SvgCanvas boxes(Vec2(-8.5, -0.5), Vec2(4.5, 10.5), 900.0);
	DrawInto(boxes, *b.world, "pyramid at rest: boxes of 1 x 1 m outline");
	WriteText(out + "/pyramid_boxes.svg", boxes.Finish());
	WriteText(out + "/pyramid_top.svg", LinePlot({{"superellipses n = 8", "#4e79a7", a.time, a.top, false},
	                                              {"boxes", "#e15759", b.time, b.top, false}},
	                                             "Height of the pyramid's top block", "time (s)", "height (m)"));
	Json j;
	j["rows"] = 10;
	j["bodies"] = 55;
	j["asleep_at_s"] = {{"superellipses", a.asleepAt}, {"boxes", b.asleepAt}};
	j["asleep_ratio"] = a.asleepAt > 0.0 && b.asleepAt > 0.0 ? a.asleepAt / b.asleepAt : -1.0;
	j["top_m"] = {{"superellipses", a.top.back()}, {"boxes", b.top.back()}};
	j["top_largest_difference_after_1s_m"] = worst;
	j["contacts"] = {{"one_point", a.onePoint}, {"two_points", a.twoPoints}};
	return j;
}

// ---------------------------------------------------------------------------------------------
// Ramp

// One body on a 30-degree ramp of its own (ramps stacked 4 m apart): its acceleration along the
// slope, from a least-squares parabola through its positions over 1 s after 0.1 s of settling.
struct RampBody
{
	std::string name;
	ShapePtr shape;
	float friction;
	double expected; // the textbook acceleration down the slope (m/s^2)
	b2Body* body = nullptr;
	std::vector<double> t, s;
	RampBody(std::string n, ShapePtr sh, float mu, double a) : name(std::move(n)), shape(std::move(sh)), friction(mu), expected(a) {}
};

Json RampPart(const std::string& out, Progress& progress)
{
	progress.Report(0.2, "ramp");
	const double theta = kPi / 6.0, g = 10.0;
	const Vec2 down(std::cos(theta), -std::sin(theta)), normal(std::sin(theta), std::cos(theta));
	std::vector<RampBody> bodies = {
		{"block sticks (friction 0.6)", MakeSuperellipse(0.5, 0.5, 8.0, 8.0), 0.6f, 0.0},
		{"block slides (friction 0.4)", MakeSuperellipse(0.5, 0.5, 8.0, 8.0), 0.4f, g * (std::sin(theta) - 0.4 * std::cos(theta))},
		{"disc rolls (friction 0.6)", MakeCircle(0.4), 0.6f, 2.0 / 3.0 * g * std::sin(theta)}};
	b2World world(kGravity);
	for (size_t i = 0; i < bodies.size(); ++i)
	{
		RampBody& r = bodies[i];
		const Vec2 origin(0.0, -4.0 * double(i));
		// Box2D mixes friction as the root of the product: the ramp has the body's.
		GroundEdge(world, ToB2Vec2(origin - 6.0 * down), ToB2Vec2(origin + 6.0 * down), r.friction);
		const double lift = r.shape->Support(Vec2(0.0, -1.0)).y; // (negative: the half-height below the centre)
		r.body = DynamicBody(world, origin - 4.0 * down + (b2_polygonRadius - b2_linearSlop - lift) * normal, -theta);
		CreateAnalyticFixture(r.body, r.shape, 1.0f, r.friction);
	}
	SvgCanvas canvas(Vec2(-6.0, -13.5), Vec2(6.0, 3.5), 700.0);
	std::vector<std::vector<Vec2>> trails(bodies.size());
	for (int step = 1; step <= 66; ++step)
	{
		world.Step(kStep, 8, 3);
		for (size_t i = 0; i < bodies.size(); ++i)
		{
			const Vec2 p = ToVec2(bodies[i].body->GetPosition());
			if (step > 6)
			{
				bodies[i].t.push_back(step * kStep);
				bodies[i].s.push_back(Dot(p, down));
			}
			if (step % 6 == 0)
				trails[i].push_back(p);
		}
	}
	Json list = Json::array();
	for (size_t i = 0; i < bodies.size(); ++i)
	{
		// s(t) = s0 + v t + a t^2 / 2: the normal equations of the least-squares fit.
		double m[3][4] = {};
		for (size_t k = 0; k < bodies[i].t.size(); ++k)
		{
			const double row[3] = {1.0, bodies[i].t[k], 0.5 * bodies[i].t[k] * bodies[i].t[k]};
			for (int r = 0; r < 3; ++r)
			{
				for (int c = 0; c < 3; ++c)
					m[r][c] += row[r] * row[c];
				m[r][3] += row[r] * bodies[i].s[k];
			}
		}
		for (int p = 0; p < 3; ++p) // Gauss-Jordan (the matrix is well conditioned over 1 s)
			for (int r = 0; r < 3; ++r)
				if (r != p)
				{
					const double f = m[r][p] / m[p][p];
					for (int c = 0; c < 4; ++c)
						m[r][c] -= f * m[p][c];
				}
		const double a = m[2][3] / m[2][2];
		list.push_back({{"body", bodies[i].name}, {"acceleration_m_s2", a}, {"textbook_m_s2", bodies[i].expected}});
		Style trail;
		trail.stroke = "#e15759";
		trail.dash = "4,3";
		canvas.Polyline(trails[i], trail);
	}
	DrawInto(canvas, world, "30-degree ramps after 1.1 s: stick, slide, roll (dashed: the path)");
	WriteText(out + "/ramp.svg", canvas.Finish());
	Json j;
	j["angle_deg"] = 30;
	j["bodies"] = list;
	return j;
}

// ---------------------------------------------------------------------------------------------
// Bucket

struct Bucket
{
	std::unique_ptr<b2World> world;
	std::vector<double> time, awake; // bodies awake, every 0.1 s
	double asleepAt = -1.0;
};

// The bucket of MakeGameBucket (16 m wide), run until every body sleeps or maxTime.
Bucket RunBucket(const std::vector<ShapePtr>& families, int particles, bool polygons, std::uint64_t seed, double maxTime,
                 Progress& progress, double progressFrom, double progressTo)
{
	Bucket bucket;
	bucket.world = MakeGameBucket(families, particles, polygons, seed);
	for (int step = 1; step * kStep <= maxTime + 1e-9; ++step)
	{
		bucket.world->Step(kStep, 8, 3);
		if (step % 6 == 0)
		{
			bucket.time.push_back(step * kStep);
			bucket.awake.push_back(AwakeBodies(*bucket.world));
			progress.Report(progressFrom + (progressTo - progressFrom) * step * kStep / maxTime,
			                std::string(polygons ? "8-gon" : "analytic") + " bucket: " + std::to_string(int(bucket.awake.back())) +
			                    " bodies awake");
		}
		if (AllAsleep(*bucket.world))
		{
			bucket.asleepAt = step * kStep;
			break;
		}
	}
	bucket.time.push_back(bucket.asleepAt > 0.0 ? bucket.asleepAt : maxTime);
	bucket.awake.push_back(AwakeBodies(*bucket.world));
	return bucket;
}

// Vertical rays down through the pile from 45 m: each nearest hit b2World::RayCast reports must
// lie on that particle's surface (within 1e-5 m of it by its level's gradient: the float hit
// point's rounding over 45 m is 3e-6 m), and the ray above it in no particle (600 points tested against every fixture the
// world's AABB query finds there). Drawn into `canvas` from the height `drawnFrom` down.
Json CastRays(b2World& world, SvgCanvas& canvas, int rays, float drawnFrom)
{
	struct Nearest : b2RayCastCallback
	{
		b2Fixture* fixture = nullptr;
		b2Vec2 point;
		float ReportFixture(b2Fixture* f, const b2Vec2& p, const b2Vec2&, float fraction) override
		{
			fixture = f;
			point = p;
			return fraction;
		}
	};
	struct Inside : b2QueryCallback
	{
		b2Vec2 point;
		bool found = false;
		bool ReportFixture(b2Fixture* f) override
		{
			found = found || f->TestPoint(point);
			return !found;
		}
	};
	int hits = 0, offSurface = 0, throughParticle = 0;
	Json byFamily = Json::object();
	Style line;
	line.stroke = "#e15759";
	line.width = 0.8;
	for (int k = 0; k < rays; ++k)
	{
		const float x = -7.95f + 15.9f * float(k) / float(rays - 1);
		const b2Vec2 from(x, 45.0f), to(x, 0.0f);
		Nearest nearest;
		world.RayCast(&nearest, from, to);
		const b2Vec2 end = nearest.fixture ? nearest.point : to;
		canvas.Polyline({Vec2(x, drawnFrom), ToVec2(end)}, line);
		if (!nearest.fixture || !GetAnalyticShape(nearest.fixture))
			continue;
		++hits;
		const Shape& shape = *GetAnalyticShape(nearest.fixture);
		const Vec2 body = ToBody(GetAnalyticPose(nearest.fixture), ToVec2(nearest.point));
		offSurface += std::fabs(shape.Level(body) - shape.SurfaceLevel()) > 1e-5 * Length(shape.Gradient(body));
		byFamily[KindName(shape.Kind())] = byFamily.value(KindName(shape.Kind()), 0) + 1;
		for (int i = 0; i < 600; ++i)
		{
			Inside inside;
			inside.point = from + (float(i) / 600.0f * 0.999f) * (end - from);
			b2AABB box;
			box.lowerBound = box.upperBound = inside.point;
			world.QueryAABB(&inside, box);
			if (inside.found)
			{
				++throughParticle;
				break;
			}
		}
	}
	return {{"rays", rays}, {"hits", hits}, {"hits_by_family", byFamily}, {"hit_points_off_the_surface", offSurface},
	        {"rays_through_a_particle_before_the_hit", throughParticle}};
}

// The bucket's options.
struct BucketOptions
{
	std::string family = "mixed";
	int particles = 0;
	double maxTime = 0.0;
};

Json BucketPart(const DemoOptions& opt, const BucketOptions& bucketOptions, Progress& progress)
{
	const std::string& family = bucketOptions.family;
	const int particles = bucketOptions.particles;
	const double maxTime = bucketOptions.maxTime;
	const std::vector<ShapePtr> families = GameFamilies(family);
	// Every family alone and mixed, each beside its 8-gons (--quick: the chosen family alone),
	// progress shared out evenly among them.
	const std::vector<std::string> names = opt.quick ? std::vector<std::string>{family} : GameFamilyNames();
	auto share = [&](double k) { return 0.25 + 0.75 * k / double(names.size()); };
	const Bucket a = RunBucket(families, particles, false, opt.seed, maxTime, progress, share(0.0), share(0.5));
	const Bucket p = RunBucket(families, particles, true, opt.seed, maxTime, progress, share(0.5), share(1.0));
	// The pictures reach 2 m above the higher pile's top.
	double top = 1.0;
	for (const Bucket* b : {&a, &p})
		for (b2Body* body = b->world->GetBodyList(); body; body = body->GetNext())
			if (body->GetType() == b2_dynamicBody)
				top = std::max(top, double(body->GetFixtureList()->GetAABB(0).upperBound.y));
	const Vec2 lower(-9.0, -1.0), upper(9.0, std::min(top + 2.0, 41.0));
	SvgCanvas canvas(lower, upper, 600.0);
	const Json rays = CastRays(*a.world, canvas, opt.quick ? 60 : 200, float(upper.y));
	DrawInto(canvas, *a.world, "bucket: analytic particles (grey: asleep) and ray casts");
	WriteText(opt.out + "/bucket.svg", canvas.Finish());
	SvgCanvas polygons(lower, upper, 600.0);
	DrawInto(polygons, *p.world, "bucket: Box2D 8-gons inscribed in the same shapes");
	WriteText(opt.out + "/bucket_polygons.svg", polygons.Finish());
	WriteText(opt.out + "/bucket_awake.svg", LinePlot({{"analytic", "#4e79a7", a.time, a.awake, false},
	                                                  {"8-gons", "#e15759", p.time, p.awake, false}},
	                                                 "Bodies awake in the bucket", "time (s)", "bodies awake"));
	Json j;
	j["family"] = family;
	j["particles"] = particles;
	j["duration_s"] = maxTime;
	j["asleep_at_s"] = {{"analytic", a.asleepAt}, {"polygons8", p.asleepAt}};
	j["asleep_ratio"] = a.asleepAt > 0.0 && p.asleepAt > 0.0 ? a.asleepAt / p.asleepAt : -1.0;
	j["awake_at_end"] = {{"analytic", a.awake.back()}, {"polygons8", p.awake.back()}};
	j["ray_casts"] = rays;
	// The other families (the chosen family's runs are those above).
	Json byFamily = Json::object();
	double done = 1.0;
	for (const std::string& name : names)
	{
		double analytic = a.asleepAt, octagons = p.asleepAt;
		if (name != family)
		{
			const std::vector<ShapePtr> shapes = GameFamilies(name);
			analytic = RunBucket(shapes, particles, false, opt.seed, maxTime, progress, share(done), share(done + 0.5)).asleepAt;
			octagons = RunBucket(shapes, particles, true, opt.seed, maxTime, progress, share(done + 0.5), share(done + 1.0)).asleepAt;
			done += 1.0;
		}
		byFamily[name] = {{"analytic_s", analytic},
		                  {"polygons8_s", octagons},
		                  {"ratio", analytic > 0.0 && octagons > 0.0 ? analytic / octagons : -1.0}};
	}
	j["asleep_by_family"] = byFamily;
	return j;
}
} // namespace

int main(int argc, char** argv)
{
	BucketOptions bucket;
	CommandLine cli("b2a_demo_game", kHelp);
	cli.Add("--particles", bucket.particles, 300, 80, "N", "particles in the bucket (default 300, quick 80)", WholeNumber(1, 2000));
	cli.Add("--family", bucket.family, "F",
	        "mixed (default), ellipse (0.5 x 0.3 m), superellipse (n = 4, 0.5 x 0.3 m), heart (alpha 0.2) or circle (r 0.4 m)",
	        OneOf({"mixed", "ellipse", "superellipse", "heart", "circle"}));
	cli.Add("--duration", bucket.maxTime, 60.0, 20.0, "T", "seconds the bucket runs at most (default 60, quick 20)",
	        RealNumber(1.0, 600.0));
	const DemoOptions opt = cli.Parse(argc, argv);
	const auto wallStart = std::chrono::steady_clock::now();
	Progress progress("b2a_demo_game");
	Json summary;
	summary["demo"] = "b2a_demo_game";
	summary["seed"] = opt.seed;
	summary["quick"] = opt.quick;
	summary["settings"] = "metres, gravity -10 m/s^2, 60 Hz, 8 velocity and 3 position iterations, sleeping on";
	summary["pyramid"] = PyramidPart(opt.out, progress);
	summary["ramp"] = RampPart(opt.out, progress);
	summary["bucket"] = BucketPart(opt, bucket, progress);
	summary["run_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
	WriteJson(opt.out + "/summary.json", summary);
	const Json& pyr = summary["pyramid"];
	const Json& bucketSummary = summary["bucket"];
	const Json& ramp = summary["ramp"]["bodies"];
	std::printf("b2a_demo_game: pyramid asleep at %.2f s (boxes %.2f s), top within %.3f m of the boxes' after 1 s; ramp: slides at "
	            "%.3f m/s^2 (textbook %.3f), rolls at %.3f (%.3f); bucket of %d (%s): asleep at %.2f s (8-gons %.2f s), %d of %d "
	            "rays hit, %d off the surface; pictures and summary.json in %s\n",
	            pyr["asleep_at_s"]["superellipses"].get<double>(), pyr["asleep_at_s"]["boxes"].get<double>(),
	            pyr["top_largest_difference_after_1s_m"].get<double>(), ramp[1]["acceleration_m_s2"].get<double>(),
	            ramp[1]["textbook_m_s2"].get<double>(), ramp[2]["acceleration_m_s2"].get<double>(),
	            ramp[2]["textbook_m_s2"].get<double>(), bucketSummary["particles"].get<int>(), bucketSummary["family"].get<std::string>().c_str(),
	            bucketSummary["asleep_at_s"]["analytic"].get<double>(), bucketSummary["asleep_at_s"]["polygons8"].get<double>(),
	            bucketSummary["ray_casts"]["hits"].get<int>(), bucketSummary["ray_casts"]["rays"].get<int>(),
	            bucketSummary["ray_casts"]["hit_points_off_the_surface"].get<int>(), opt.out.c_str());
	return 0;
}

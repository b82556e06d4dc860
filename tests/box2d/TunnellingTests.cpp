// b2analytic tests: in the hopper scene's units (mm, step 2e-4 s, 2 mm particles), particles
// thrown at thin walls and at each other as fast as an 800 mm fall makes them never pass through
// where Box2D promises it, and the limit of that promise is computed.
//
// The numbers: an 800 mm fall gives v = sqrt(2 · 9810 mm/s² · 800 mm) = 3962 mm/s. In one step of
// 2e-4 s a particle moves 0.79 mm: less than the n = 4 superellipse's smallest width (1.25 mm for
// 2 mm × 1.25 mm), more than a 2 mm 3:1 ellipse's (0.67 mm). What Box2D promises:
//  - Against static bodies (edges, chain links, boxes) continuous collision is always on: the
//    time of impact stops a dynamic body at the wall at any speed below Box2D's limit of
//    b2_maxTranslation = 2 length units per step (10000 mm/s here). The adapter's inscribed proxy
//    reaches the wall no earlier than the true shape, so the true shapes touch when it stops.
//  - Between dynamic bodies Box2D runs continuous collision only when one is a bullet; then the
//    proxies stop at touching, and the true shapes overlap by at most the two proxies' gaps
//    (how far each true surface reaches beyond its inscribed proxy).
//  - Without a bullet, two particles are only seen at the step ends, and Box2D promises nothing:
//    the first overlap can be as deep as the relative step v_rel · dt. Each particle contains
//    the disk of its inscribed radius ρ about its centre; a first overlap deeper than a good part
//    of ρ_A + ρ_B gets a contact normal oblique to the approach (the normal of a deep overlap
//    follows the shapes, not the motion), the velocity solver removes only the approach along
//    it, and the particles slide through each other. Measured (one particle at rest, the other
//    thrown at it, 100 random orientations and offsets per pair and speed): no pair passed
//    through at v_rel · dt ≤ 0.75 (ρ_A + ρ_B); passes begin at 0.77 (a 3:1 ellipse into a heart
//    at 3962 mm/s) to 0.9 (two 3:1 ellipses at 3000 mm/s). The rule asserted here, with margin:
//    non-bullets do not pass through each other for v_rel · dt ≤ (ρ_A + ρ_B) / 2. For the hopper
//    scene's particles (ρ = 0.625 mm) that is v_rel ≤ 3125 mm/s, above the 1981 mm/s of a fall
//    from the top of its 200 mm walls; for 3:1 ellipses (ρ = 0.333 mm) 1667 mm/s. An 800 mm fall
//    (3962 mm/s) is beyond the rule for most pairs: mark such particles as bullets.
#include "ReliabilitySupport.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
// The hopper scene's settings (demos/common/GranularScene.h).
constexpr float kDt = 2e-4f;
constexpr int kVelocityIterations = 8, kPositionIterations = 3;
constexpr double kFallSpeed = 3962.0;   // mm/s, sqrt(2 · 9810 · 800)
constexpr double kHopperSpeed = 1981.0; // mm/s, sqrt(2 · 9810 · 200): a fall from the hopper's wall top

struct Kind
{
	const char* name;
	ShapePtr shape;
};

// Four particle kinds about 2 mm wide.
std::vector<Kind> Kinds()
{
	return {{"superellipse n=4 2 x 1.25 mm", MakeSuperellipse(1.0, 0.625, 4.0, 4.0)},
	        {"ellipse 3:1 2 x 0.67 mm", MakeEllipse(1.0, 1.0 / 3.0)},
	        {"heart 2.06 mm wide", MakeHeart(0.8)},
	        {"circle 2 mm", MakeCircle(1.0)}};
}

// How far the true surface reaches beyond the fixture's proxy: the rounded polygon (core plus
// skin) that Box2D's time of impact works on. Box2D stops the proxy at the wall, so the true
// shape can be inside the wall by at most this much when it stops (before the contact pushes it
// out). 720 surface samples; distances to the core polygon in the body frame.
double ProxyGap(const b2Fixture* f)
{
	const b2PolygonShape* proxy = static_cast<const b2PolygonShape*>(f->GetShape());
	double gap = 0.0;
	for (Vec2 p : GetAnalyticShape(f)->Samples(720)->point)
	{
		// Distance to the convex core polygon: the largest face distance when outside every
		// face's corner region is not exact at corners, so take the distance to each edge.
		double inside = true, d = 1e30;
		for (int i = 0; i < proxy->m_count; ++i)
		{
			const Vec2 v1(proxy->m_vertices[i].x, proxy->m_vertices[i].y);
			const b2Vec2 w = proxy->m_vertices[(i + 1) % proxy->m_count];
			const Vec2 v2(w.x, w.y), e = v2 - v1;
			const double t = std::clamp(Dot(p - v1, e) / Dot(e, e), 0.0, 1.0);
			d = std::min(d, Length(p - (v1 + t * e)));
			inside = inside && Cross(e, p - v1) >= 0.0;
		}
		if (!inside)
			gap = std::max(gap, d - proxy->m_radius);
	}
	return gap;
}

// A particle as in the hopper scene (density g/mm², friction, restitution 0.1 with the raised
// millimetre threshold).
b2Body* Throw(b2World& world, const ShapePtr& shape, Vec2 at, double angle, Vec2 velocity, float spin, bool bullet)
{
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	bd.position.Set(float(at.x), float(at.y));
	bd.angle = float(angle);
	bd.bullet = bullet;
	bd.linearVelocity.Set(float(velocity.x), float(velocity.y));
	bd.angularVelocity = spin;
	b2Body* body = world.CreateBody(&bd);
	b2FixtureDef fd;
	fd.density = 1e-3f;
	fd.friction = 0.5f;
	fd.restitution = 0.1f;
	fd.restitutionThreshold = 1000.0f;
	AnalyticFixtureDef ad;
	ad.shape = shape;
	CreateAnalyticFixture(body, fd, ad);
	return body;
}

} // namespace

TEST_CASE("particles thrown at thin static walls as fast as an 800 mm fall, and twice that, stay on their side")
{
	// Walls along y = 0, the particles coming from above at 90°, 60° and 25° to the wall, spinning.
	enum Wall
	{
		edge,
		chain,
		thinBox,
		wallCount
	};
	const char* names[] = {"edge", "chain link", "0.1 mm box"};
	const std::vector<Kind> kinds = Kinds();
	Random rng(21);
	int thrown = 0;
	double deepest = 0.0; // deepest dig of a particle's lowest point below the wall's top
	for (int wall = 0; wall < wallCount; ++wall)
		for (const Kind& kind : kinds)
			for (double speed : {kFallSpeed, 2.0 * kFallSpeed})
				for (double incidence : {90.0, 60.0, 25.0})
				{
					CAPTURE(std::string(names[wall]));
					CAPTURE(std::string(kind.name));
					CAPTURE(speed);
					CAPTURE(incidence);
					b2World world(b2Vec2(0.0f, 0.0f));
					b2BodyDef gd;
					b2Body* ground = world.CreateBody(&gd);
					float top = 0.0f;
					b2FixtureDef wf;
					wf.friction = 0.5f;
					wf.restitutionThreshold = 1000.0f; // Box2D mixes thresholds by their minimum
					if (wall == edge)
					{
						b2EdgeShape e;
						e.SetTwoSided(b2Vec2(-200.0f, 0.0f), b2Vec2(200.0f, 0.0f));
						wf.shape = &e;
						ground->CreateFixture(&wf);
						top = e.m_radius;
					}
					else if (wall == chain)
					{
						// Right to left: the front (right of the direction) faces up, at the particle.
						const b2Vec2 points[4] = {b2Vec2(200.0f, -50.0f), b2Vec2(200.0f, 0.0f), b2Vec2(-200.0f, 0.0f), b2Vec2(-200.0f, -50.0f)};
						b2ChainShape c;
						c.CreateChain(points, 4, b2Vec2(200.0f, -100.0f), b2Vec2(-200.0f, -100.0f));
						wf.shape = &c;
						ground->CreateFixture(&wf);
						top = c.m_radius;
					}
					else
					{
						b2PolygonShape slab;
						slab.SetAsBox(200.0f, 0.05f, b2Vec2(0.0f, -0.05f), 0.0f);
						wf.shape = &slab;
						ground->CreateFixture(&wf);
						top = slab.m_radius;
					}
					// Start 3 mm plus a random fraction of a step above the wall, so the last step
					// before the wall ends anywhere in front of it.
					const double a = incidence * kPi / 180.0;
					const Vec2 velocity(speed * std::cos(a) * (rng.Uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0), -speed * std::sin(a));
					const double start = 3.0 + kind.shape->BoundingRadius() + rng.Uniform(0.0, 1.0) * speed * kDt;
					b2Body* p = Throw(world, kind.shape, Vec2(0.0, start), rng.Angle(), velocity, float(rng.Uniform(-300.0, 300.0)), false);
					double lowestEver = 1e30;
					for (int i = 0; i < 150; ++i)
					{
						world.Step(kDt, kVelocityIterations, kPositionIterations);
						const double lowest = WorldSupport(*kind.shape, PoseOf(p), Vec2(0.0, -1.0)).y;
						lowestEver = std::min(lowestEver, lowest);
						CHECK(p->GetWorldCenter().y > 0.0f); // the centre never crosses
					}
					// It hit: 30 ms later it moves away from the wall or rests on it (restitution
					// 0.1), the whole particle on its side.
					CHECK(p->GetLinearVelocity().y > -1.0f);
					CHECK(WorldSupport(*kind.shape, PoseOf(p), Vec2(0.0, -1.0)).y > top - 3.0 * b2_linearSlop - 1e-4);
					// At no step end did it dig deeper than its proxy's gap (plus Box2D's slop).
					const double gap = ProxyGap(p->GetFixtureList());
					CHECK(lowestEver > top - gap - 3.0 * b2_linearSlop);
					deepest = std::min(deepest, lowestEver - top);
					++thrown;
				}
	CHECK(thrown == wallCount * 4 * 2 * 3);
	MESSAGE("thrown at walls: " << thrown << ", deepest dig below a wall's top " << deepest << " mm");
}

TEST_CASE("fast particles thrown at each other: bullets never pass through; non-bullets within the computed safe speed")
{
	// Head-on along x, random orientations and small sideways offsets. Passing through: the
	// centres change sides along x while their sideways distance is less than ρ_A + ρ_B (in
	// continuous motion their inscribed disks, and so the particles, would have overlapped).
	const std::vector<Kind> kinds = Kinds();
	Random rng(34);
	int collisions = 0, nonBulletCases = 0;
	double deepestBullet = 0.0, deepestPlain = 0.0;
	for (size_t i = 0; i < kinds.size(); ++i)
		for (size_t j = i; j < kinds.size(); ++j)
		{
			const Shape& sa = *kinds[i].shape;
			const Shape& sb = *kinds[j].shape;
			const double rho = InscribedRadius(sa) + InscribedRadius(sb);
			const double safe = 0.5 * rho / kDt; // relative speed, mm/s
			// Speeds of A and B: into one at rest at the hopper's and the 800 mm fall speed, and
			// both at the fall speed.
			for (const auto& speeds :
			     {std::make_pair(kHopperSpeed, 0.0), std::make_pair(kFallSpeed, 0.0), std::make_pair(kFallSpeed, kFallSpeed)})
				for (int bullets = 0; bullets <= 2; ++bullets) // 0: none, 1: A, 2: both
					for (int trial = 0; trial < 3; ++trial)
					{
						const double relative = speeds.first + speeds.second;
						if (bullets == 0 && relative >= safe)
							continue; // Box2D promises nothing there
						CAPTURE(std::string(kinds[i].name));
						CAPTURE(std::string(kinds[j].name));
						CAPTURE(relative);
						CAPTURE(bullets);
						CAPTURE(trial);
						b2World world(b2Vec2(0.0f, 0.0f));
						const double gap = 4.0 + rng.Uniform(0.0, 1.0) * relative * kDt;
						const double offset = rng.Uniform(-0.3, 0.3);
						const double reach = sa.BoundingRadius() + sb.BoundingRadius();
						b2Body* a = Throw(world, kinds[i].shape, Vec2(-0.5 * (reach + gap), 0.0), rng.Angle(), Vec2(speeds.first, 0.0),
						                  0.0f, bullets >= 1);
						b2Body* b = Throw(world, kinds[j].shape, Vec2(0.5 * (reach + gap), offset), rng.Angle(),
						                  Vec2(-speeds.second, 0.0), 0.0f, bullets == 2);
						const double gaps = ProxyGap(a->GetFixtureList()) + ProxyGap(b->GetFixtureList());
						double deepest = 0.0;
						Vec2 r0 = PoseOf(b).p - PoseOf(a).p;
						for (int k = 0; k < 100; ++k)
						{
							world.Step(kDt, kVelocityIterations, kPositionIterations);
							const ContactResult c = ComputeFixtureContact(a->GetFixtureList(), b->GetFixtureList());
							REQUIRE(c.Ok());
							deepest = std::min(deepest, c.separation);
							const Vec2 r1 = PoseOf(b).p - PoseOf(a).p;
							if (r1.x <= 0.0 && r0.x > 0.0)
							{
								const double t = r0.x / (r0.x - r1.x);
								CHECK(std::fabs(r0.y + t * (r1.y - r0.y)) >= rho); // passed beside, not through
							}
							r0 = r1;
						}
						// They met: the approach was stopped (restitution 0.1: they part slowly, roll
						// or glance off).
						CHECK(a->GetLinearVelocity().x - b->GetLinearVelocity().x < 0.5 * relative);
						if (bullets > 0)
						{
							// Continuous collision stops the proxies at touching.
							CHECK(deepest > -gaps - 3.0 * b2_linearSlop);
							deepestBullet = std::min(deepestBullet, deepest);
						}
						else
						{
							// The first overlap is at most one relative step deep.
							CHECK(deepest > -relative * kDt - 3.0 * b2_linearSlop);
							deepestPlain = std::min(deepestPlain, deepest);
							++nonBulletCases;
						}
						++collisions;
					}
		}
	// The safe speeds quoted in the header comment: ρ (0.625, 0.333 mm) / dt for equal pairs.
	CHECK(InscribedRadius(*kinds[0].shape) / kDt == doctest::Approx(3125.0).epsilon(1e-3));
	CHECK(InscribedRadius(*kinds[1].shape) / kDt == doctest::Approx(5000.0 / 3.0).epsilon(1e-3));
	CHECK(nonBulletCases > 0);
	MESSAGE("particle-particle collisions: " << collisions << " (" << nonBulletCases << " without bullets), deepest overlap with bullets "
	                                         << deepestBullet << " mm, without " << deepestPlain << " mm");
}

TEST_CASE("every proxy lies inside its true shape, concave ones included, so no time of impact is dropped")
{
	// Box2D drops a time of impact whose contact is not touching when the bodies get there
	// (b2World::SolveTOI). The adapter's contact follows the true shapes, so the rounded proxy
	// (core polygon plus skin) must lie inside the true shape. Regression: a heart's proxy was
	// the hull of its surface points, bridging the notch, without a skin (the cusp's gradient
	// made the inset fail); a bullet superellipse meeting the heart there passed through it.
	const ShapePtr shapes[] = {MakeSuperellipse(1.0, 0.625, 4.0, 4.0), MakeEllipse(1.0, 1.0 / 3.0), MakeHeart(0.8), MakeHeart(0.2),
	                           MakeCircle(1.0), MakeEllipse(0.5, 0.05), MakeSuperellipse(1.0, 1.0, 1.0, 1.0),
	                           MakeSuperellipse(2.0, 4.0, 6.0, 8.0)};
	b2World world(b2Vec2(0.0f, 0.0f));
	b2BodyDef bd;
	b2Body* body = world.CreateBody(&bd);
	for (const ShapePtr& shape : shapes)
	{
		CAPTURE(shape->Describe());
		const b2Fixture* f = CreateAnalyticFixture(body, shape, 1.0f);
		const b2PolygonShape* proxy = static_cast<const b2PolygonShape*>(f->GetShape());
		REQUIRE(proxy->m_count >= 3);
		CHECK(proxy->m_radius == doctest::Approx(b2_polygonRadius)); // a skin, for Box2D's time of impact
		const double r = proxy->m_radius * (1.0 - 1e-5);
		int outside = 0, arcOutside = 0;
		for (int i = 0; i < proxy->m_count; ++i)
		{
			const b2Vec2 a = proxy->m_vertices[i], b = proxy->m_vertices[(i + 1) % proxy->m_count];
			const b2Vec2 n = proxy->m_normals[i], next = proxy->m_normals[(i + 1) % proxy->m_count];
			for (int k = 0; k <= 32; ++k) // along the edge, moved out by the skin
			{
				const b2Vec2 x = a + (k / 32.0f) * (b - a) + float(r) * n;
				outside += shape->Level(Vec2(x.x, x.y)) > shape->SurfaceLevel();
			}
			for (int k = 1; k < 8; ++k) // around the corner
			{
				b2Vec2 d = (1.0f - k / 8.0f) * n + (k / 8.0f) * next;
				d.Normalize();
				const b2Vec2 x = b + float(r) * d;
				outside += shape->Level(Vec2(x.x, x.y)) > shape->SurfaceLevel();
			}
			// Between those corner points the arc bulges past their chords by at most 0.02 skins
			// (convex shapes get no other test): 64 arc points, less that bulge, are inside.
			const double turn = std::atan2(double(b2Cross(n, next)), double(b2Dot(n, next)));
			for (int k = 1; k < 64; ++k)
			{
				const Rot q(turn * k / 64.0);
				const Vec2 d = Rotate(q, Vec2(n.x, n.y));
				const Vec2 x = Vec2(b.x, b.y) + 0.98 * r * d;
				arcOutside += shape->Level(x) > shape->SurfaceLevel();
			}
		}
		CHECK(outside == 0);
		CHECK(arcOutside == 0);
	}

	// The case found: a bullet superellipse thrown at a heart at 3962 mm/s each.
	b2World scene(b2Vec2(0.0f, 0.0f));
	b2Body* a = Throw(scene, MakeSuperellipse(1.0, 0.625, 4.0, 4.0), Vec2(-3.18764, 0.0), -0.903, Vec2(kFallSpeed, 0.0), 0.0f, true);
	b2Body* b = Throw(scene, MakeHeart(0.8), Vec2(3.18764, 0.16885), -0.732, Vec2(-kFallSpeed, 0.0), 0.0f, false);
	double deepest = 0.0;
	for (int k = 0; k < 20; ++k)
	{
		scene.Step(kDt, kVelocityIterations, kPositionIterations);
		deepest = std::min(deepest, ComputeFixtureContact(a->GetFixtureList(), b->GetFixtureList()).separation);
	}
	CHECK(a->GetPosition().x < b->GetPosition().x);
	CHECK(deepest > -ProxyGap(a->GetFixtureList()) - ProxyGap(b->GetFixtureList()) - 3.0 * b2_linearSlop);
}

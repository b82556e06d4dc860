// b2analytic tests: particles created overlapping deeply (up to half their size) separate
// without being flung, against each other, against Box2D circles and against thin walls.
//
// What Box2D promises, and so what is asserted (Box2D 2.4, b2_island.cpp, b2_contact_solver.cpp):
//  - Overlap is removed by the position solver alone. It moves positions, never velocities: per
//    iteration and manifold point it applies the impulse P = −C / K along the normal with
//    C = clamp(β (s + slop), −b2_maxLinearCorrection, 0) (β = b2_baumgarte = 0.2, s the
//    separation) and K ≥ 1/m of either body, so a body's centre moves by |P| / m ≤ |C| ≤
//    b2_maxLinearCorrection = 0.2 per point and iteration. Over one step (positionIterations = 3)
//    the push-out of a body's centre is at most 3 · 0.2 · (manifold points touching it): as a
//    speed, 0.6 · points / dt = 36 per point and second at 60 Hz, whatever the overlap.
//  - The velocity solver only removes approach velocity (no Baumgarte bias in 2.4; restitution
//    needs an approach faster than the threshold): particles created at rest in zero gravity keep
//    zero velocity while they separate. Under gravity contacts take energy away (restitution 0),
//    so no particle is faster than a free fall over the heights the pile ever spans.
//  - The position solver ends a step once every separation is ≥ −3 slop, and drives each towards
//    −slop: separated particles end with the exact separation ≥ −3 slop (within float rounding).
// A wrong contact normal in deep overlap (pointing the wrong way, or flipping between steps)
// breaks the last promise (they stay overlapped or pass through each other) and, under
// gravity, the speed bound (a pile "explodes").
#include "ReliabilitySupport.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
constexpr float kDt = 1.0f / 60.0f;
constexpr int kVelocityIterations = 8, kPositionIterations = 3;
constexpr double kFloatTolerance = 2e-4; // float positions of bodies a few units from the origin

// Manifold points of the touching contacts of a body.
int ManifoldPoints(b2Body* b)
{
	int n = 0;
	for (b2ContactEdge* e = b->GetContactList(); e; e = e->next)
		if (e->contact->IsTouching())
			n += e->contact->GetManifold()->pointCount;
	return n;
}

// Steps a world and records, for every dynamic body and step, the push-out (the centre's motion
// not explained by its velocity: Δc − dt·v) against the bound above, the largest speed, and
// anything not finite.
struct Watch
{
	double maxSpeed = 0.0;
	double maxPushout = 0.0;       // largest push-out of a centre in one step
	double maxPushoutRatio = 0.0;  // largest push-out over its bound
	double lowest = 1e30, highest = -1e30; // range of centre heights seen
	int nonFinite = 0;

	void Run(b2World& world, int steps)
	{
		std::vector<std::pair<b2Body*, b2Vec2>> before;
		for (int i = 0; i < steps; ++i)
		{
			before.clear();
			for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
				if (b->GetType() == b2_dynamicBody)
					before.emplace_back(b, b->GetWorldCenter());
			world.Step(kDt, kVelocityIterations, kPositionIterations);
			for (auto& [b, c0] : before)
			{
				if (!Finite(b))
				{
					++nonFinite;
					continue;
				}
				const b2Vec2 v = b->GetLinearVelocity();
				const double pushout = (b->GetWorldCenter() - c0 - kDt * v).Length();
				const double bound = kPositionIterations * b2_maxLinearCorrection * std::max(1, ManifoldPoints(b));
				maxPushout = std::max(maxPushout, pushout);
				maxPushoutRatio = std::max(maxPushoutRatio, pushout / bound);
				maxSpeed = std::max(maxSpeed, double(v.Length()));
				lowest = std::min(lowest, double(b->GetWorldCenter().y));
				highest = std::max(highest, double(b->GetWorldCenter().y));
			}
		}
	}
};

struct Particle
{
	const char* name;
	ShapePtr shape; // null: a Box2D b2CircleShape of radius 0.4
};

std::vector<Particle> Particles()
{
	return {{"superellipse n=4", MakeSuperellipse(0.5, 0.3, 4.0, 4.0)},
	        {"ellipse 3:1", MakeEllipse(0.6, 0.2)},
	        {"circle", MakeCircle(0.4)},
	        {"heart", MakeHeart(0.2)},
	        {"Box2D circle", nullptr}};
}

const ShapePtr& BoxCircle()
{
	static const ShapePtr circle = MakeCircle(0.4); // the same geometry, for measuring
	return circle;
}

b2Body* Make(b2World& world, const Particle& p, Vec2 at, double angle)
{
	if (p.shape)
		return MakeParticle(world, p.shape, float(at.x), float(at.y), float(angle));
	b2BodyDef bd;
	bd.type = b2_dynamicBody;
	bd.position.Set(float(at.x), float(at.y));
	bd.angle = float(angle);
	b2Body* b = world.CreateBody(&bd);
	b2CircleShape c;
	c.m_radius = 0.4f;
	b2FixtureDef fd;
	fd.shape = &c;
	fd.density = 1.0f;
	fd.friction = 0.6f;
	b->CreateFixture(&fd);
	return b;
}

// The exact separation of two particles at their bodies' poses.
double Separation(const Particle& pa, const b2Body* a, const Particle& pb, const b2Body* b)
{
	const Shape& sa = pa.shape ? *pa.shape : *BoxCircle();
	const Shape& sb = pb.shape ? *pb.shape : *BoxCircle();
	return ComputeContact(sa, PoseOf(a), sb, PoseOf(b)).separation;
}
} // namespace

TEST_CASE("pairs created overlapping by up to half their size separate at rest, within Box2D's push-out bound")
{
	const std::vector<Particle> particles = Particles();
	Random rng(8);
	int pairs = 0;
	double worstSeparation = 0.0, worstPushout = 0.0;
	for (size_t i = 0; i < particles.size(); ++i)
		for (size_t j = i; j < particles.size(); ++j)
		{
			if (!particles[i].shape && !particles[j].shape)
				continue; // two Box2D circles: nothing of ours
			for (double fraction : {0.1, 0.3, 0.5})
				for (int trial = 0; trial < 3; ++trial)
				{
					const Particle &pa = particles[i], &pb = particles[j];
					CAPTURE(pa.name);
					CAPTURE(pb.name);
					CAPTURE(fraction);
					CAPTURE(trial);
					// B's centre along a random direction u from A's, so that along the line of
					// centres their chords overlap by `fraction` of their summed radii: at 0.5 two
					// equal circles have each centre on the other's surface.
					const double angleA = rng.Angle(), angleB = rng.Angle(), direction = rng.Angle();
					const Vec2 u(std::cos(direction), std::sin(direction));
					const Shape& sa = pa.shape ? *pa.shape : *BoxCircle();
					const Shape& sb = pb.shape ? *pb.shape : *BoxCircle();
					const Vec2 ca(0.3, -0.2);
					const Vec2 cb = ca + (1.0 - fraction) * (Radial(sa, angleA, u) + Radial(sb, angleB, -1.0 * u)) * u;

					b2World world(b2Vec2(0.0f, 0.0f));
					b2Body* a = Make(world, pa, ca, angleA);
					b2Body* b = Make(world, pb, cb, angleB);
					CHECK(Separation(pa, a, pb, b) < 0.0); // the chords overlap, so the particles do
					const b2Vec2 centre0 = a->GetMass() * a->GetWorldCenter() + b->GetMass() * b->GetWorldCenter();

					Watch watch;
					watch.Run(world, 60);
					REQUIRE(watch.nonFinite == 0);
					// Pushed apart by position correction only: no velocity at all, each step's
					// push-out within the bound, equal and opposite impulses (the mass centre stays).
					CHECK(watch.maxSpeed < 1e-6);
					CHECK(watch.maxPushoutRatio <= 1.0 + 1e-5);
					const b2Vec2 centre1 = a->GetMass() * a->GetWorldCenter() + b->GetMass() * b->GetWorldCenter();
					CHECK((centre1 - centre0).Length() / (a->GetMass() + b->GetMass()) < 1e-4);
					// Separated to Box2D's tolerance, on the sides they started on (not through).
					const double s1 = Separation(pa, a, pb, b);
					CHECK(s1 >= -3.0 * b2_linearSlop - kFloatTolerance);
					CHECK(Dot(Vec2(b->GetPosition().x - a->GetPosition().x, b->GetPosition().y - a->GetPosition().y), cb - ca) > 0.0);
					worstSeparation = std::min(worstSeparation, s1);
					worstPushout = std::max(worstPushout, watch.maxPushout);
					++pairs;
				}
		}
	CHECK(pairs == 14 * 9);
	MESSAGE("deep-overlap pairs: " << pairs << ", worst final separation " << worstSeparation << ", largest push-out in a step "
	                               << worstPushout << " (bound per manifold point " << kPositionIterations * b2_maxLinearCorrection << ")");
}

TEST_CASE("particles created half inside thin static walls are pushed out on their own side")
{
	// Walls along y = 0: a two-sided edge, a link of a chain loop (one-sided, its front up), a
	// 0.04 thick Box2D box, and a static analytic superellipse 0.04 thick. Each particle's lowest
	// point lies `fraction` of its height below the wall's top, its centroid no lower than the
	// top. Box2D pushes a polygon out along the axis of least overlap, and for one-sided chains
	// only a polygon whose centroid is in front; the adapter does the same for the true shapes.
	// So a particle less than half inside comes out on its own side. (Exactly half is a tie:
	// either side is right.)
	enum Wall
	{
		edge,
		chain,
		box,
		analytic,
		wallCount
	};
	const char* names[] = {"edge", "chain", "thin box", "analytic slab"};
	const std::vector<Particle> particles = Particles();
	Random rng(11);
	int cases = 0;
	for (int wall = 0; wall < wallCount; ++wall)
		for (const Particle& p : particles)
			for (double fraction : {0.25, 0.45})
				for (int trial = 0; trial < 2; ++trial)
				{
					CAPTURE(std::string(names[wall]));
					CAPTURE(std::string(p.name));
					CAPTURE(fraction);
					b2World world(b2Vec2(0.0f, 0.0f));
					b2BodyDef gd;
					b2Body* ground = world.CreateBody(&gd);
					double top = 0.0; // the wall's top surface, skins included
					if (wall == edge)
					{
						b2EdgeShape e;
						e.SetTwoSided(b2Vec2(-10.0f, 0.0f), b2Vec2(10.0f, 0.0f));
						ground->CreateFixture(&e, 0.0f);
						top = e.m_radius;
					}
					else if (wall == chain)
					{
						// Counter-clockwise loop: the outside is the front. Its top edge is y = 0.
						const b2Vec2 loop[4] = {b2Vec2(-10.0f, -2.0f), b2Vec2(10.0f, -2.0f), b2Vec2(10.0f, 0.0f), b2Vec2(-10.0f, 0.0f)};
						b2ChainShape c;
						c.CreateLoop(loop, 4);
						ground->CreateFixture(&c, 0.0f);
						top = c.m_radius;
					}
					else if (wall == box)
					{
						b2PolygonShape slab;
						slab.SetAsBox(10.0f, 0.02f, b2Vec2(0.0f, -0.02f), 0.0f);
						ground->CreateFixture(&slab, 0.0f);
						top = slab.m_radius;
					}
					else
					{
						gd.position.Set(0.0f, -0.02f);
						ground->SetTransform(gd.position, 0.0f);
						CreateAnalyticFixture(ground, MakeSuperellipse(10.0, 0.02, 8.0, 8.0), 0.0f);
					}
					const double angle = rng.Angle();
					const Shape& s = p.shape ? *p.shape : *BoxCircle();
					// Extents below and above the centroid, with the centroid at the origin.
					const Vec2 centroid = Rotate(Rot(angle), s.Mass().centroid);
					const Pose centred(-1.0 * centroid, angle);
					const double down = -WorldSupport(s, centred, Vec2(0.0, -1.0)).y;
					const double up = WorldSupport(s, centred, Vec2(0.0, 1.0)).y;
					const double depth = std::min(fraction * (up + down), down);
					const Vec2 at = Vec2(rng.Uniform(-1.0, 1.0), top + down - depth) - centroid;
					b2Body* body = Make(world, p, at, angle);

					Watch watch;
					watch.Run(world, 60);
					REQUIRE(watch.nonFinite == 0);
					CHECK(watch.maxSpeed < 1e-6);
					CHECK(watch.maxPushoutRatio <= 1.0 + 1e-5);
					// Out on its own side: its lowest point within Box2D's tolerance of the top.
					const double lowest = WorldSupport(s, PoseOf(body), Vec2(0.0, -1.0)).y;
					CHECK(body->GetWorldCenter().y > 0.0f);
					CHECK(lowest >= top - 3.0 * b2_linearSlop - kFloatTolerance);
					++cases;
				}
	CHECK(cases == wallCount * 5 * 4);
}

TEST_CASE("a pile created with deep overlaps in a box settles under gravity without flinging anything")
{
	// Twenty particles of all kinds dropped into a 6 wide box from a cluster whose pitch (0.55)
	// is about half their size: each overlaps its neighbours by up to half its size. (In a box
	// narrower than a settled layer's width, overlaps stay: Box2D's soft position correction
	// cannot push particles apart against walls and the weight above them.)
	const std::vector<Particle> particles = Particles();
	Random rng(3);
	const float g = 10.0f;
	b2World world(b2Vec2(0.0f, -g));
	b2BodyDef gd;
	b2Body* ground = world.CreateBody(&gd);
	// A one-sided chain: its front (the right of its direction) faces into the box.
	const b2Vec2 container[4] = {b2Vec2(3.0f, 6.0f), b2Vec2(3.0f, 0.0f), b2Vec2(-3.0f, 0.0f), b2Vec2(-3.0f, 6.0f)};
	b2ChainShape walls;
	walls.CreateChain(container, 4, container[0], container[3]);
	ground->CreateFixture(&walls, 0.0f);
	std::vector<std::pair<const Particle*, b2Body*>> bodies;
	for (int i = 0; i < 20; ++i)
	{
		const Particle& p = particles[i % particles.size()];
		const Vec2 at(-1.1 + 0.55 * (i % 5) + rng.Uniform(-0.05, 0.05), 0.5 + 0.55 * (i / 5) + rng.Uniform(-0.05, 0.05));
		bodies.emplace_back(&p, Make(world, p, at, rng.Angle()));
	}
	double deepest = 0.0;
	for (size_t i = 0; i < bodies.size(); ++i)
		for (size_t j = i + 1; j < bodies.size(); ++j)
			deepest = std::min(deepest, Separation(*bodies[i].first, bodies[i].second, *bodies[j].first, bodies[j].second));
	CHECK(deepest < -0.25); // deep overlaps to start with

	// Eight seconds: the pile itself settles within five, but a circle may still be rolling down
	// its slope then, which is no fling (the speed bound below is over the whole run).
	Watch watch;
	watch.Run(world, 480);
	REQUIRE(watch.nonFinite == 0);
	// Speed: contacts (restitution 0, friction) only take energy; the push-out adds potential
	// energy by lifting, which the heights seen include. So nothing is faster than a free fall
	// over the range of centre heights seen (25 % margin for the solver's iterative impulses).
	const double freeFall = std::sqrt(2.0 * g * (watch.highest - watch.lowest));
	CHECK(watch.maxSpeed <= 1.25 * freeFall);
	CHECK(watch.maxPushoutRatio <= 1.0 + 1e-5);
	// Everything stayed in the box and separated; after 8 s the pile is at rest.
	double worst = 0.0;
	for (size_t i = 0; i < bodies.size(); ++i)
	{
		const b2Vec2 p = bodies[i].second->GetPosition();
		CHECK(std::fabs(p.x) < 3.0f);
		CHECK(p.y > 0.0f);
		CHECK(p.y < 6.0f);
		CHECK(bodies[i].second->GetLinearVelocity().Length() < 0.1f);
		for (size_t j = i + 1; j < bodies.size(); ++j)
			worst = std::min(worst, Separation(*bodies[i].first, bodies[i].second, *bodies[j].first, bodies[j].second));
	}
	CHECK(worst >= -3.0 * b2_linearSlop - kFloatTolerance);
	MESSAGE("deep-overlap pile: deepest start " << deepest << ", max speed " << watch.maxSpeed << " (free fall over the heights seen "
	                                            << freeFall << "), largest push-out " << watch.maxPushout << ", final worst separation "
	                                            << worst);
}

TEST_CASE("a one-sided chain decides the side by the particle's centroid, as Box2D does for its polygons")
{
	// Regression: the adapter used the shape's origin. A heart's origin lies below its centroid
	// (by 0.184 for α = 0.2), so a heart whose centroid was in front of a chain but whose origin
	// was behind it got no contact and stayed stuck inside the chain.
	const auto heart = MakeHeart(0.2);
	const double centroidY = heart->Mass().centroid.y;
	REQUIRE(centroidY > 0.15);
	for (const double originY : {-0.05, -0.02})
	{
		CAPTURE(originY);
		b2World world(b2Vec2(0.0f, 0.0f));
		b2BodyDef gd;
		b2Body* ground = world.CreateBody(&gd);
		const b2Vec2 loop[4] = {b2Vec2(-10.0f, -2.0f), b2Vec2(10.0f, -2.0f), b2Vec2(10.0f, 0.0f), b2Vec2(-10.0f, 0.0f)};
		b2ChainShape chain;
		chain.CreateLoop(loop, 4);
		ground->CreateFixture(&chain, 0.0f);
		b2Body* body = MakeParticle(world, heart, 0.2f, float(originY)); // upright: centroid at originY + 0.184 > 0
		const double lowest0 = WorldSupport(*heart, PoseOf(body), Vec2(0.0, -1.0)).y;
		REQUIRE(lowest0 < -0.45); // deep, but less than half of the heart's height (1.07)
		for (int i = 0; i < 60; ++i)
			world.Step(kDt, kVelocityIterations, kPositionIterations);
		CHECK(WorldSupport(*heart, PoseOf(body), Vec2(0.0, -1.0)).y >= chain.m_radius - 3.0 * b2_linearSlop - kFloatTolerance);
	}
	// With the centroid behind the chain there is no contact at all (Box2D's rule): the heart,
	// moving down, passes through undisturbed.
	b2World world(b2Vec2(0.0f, 0.0f));
	b2BodyDef gd;
	b2Body* ground = world.CreateBody(&gd);
	b2EdgeShape link;
	link.SetOneSided(b2Vec2(20.0f, 0.0f), b2Vec2(10.0f, 0.0f), b2Vec2(-10.0f, 0.0f), b2Vec2(-20.0f, 0.0f)); // front: up
	ground->CreateFixture(&link, 0.0f);
	b2Body* body = MakeParticle(world, heart, 0.2f, float(-centroidY - 0.02));
	body->SetLinearVelocity(b2Vec2(0.0f, -1.0f));
	for (int i = 0; i < 30; ++i)
		world.Step(kDt, kVelocityIterations, kPositionIterations);
	CHECK(body->GetLinearVelocity().y == doctest::Approx(-1.0f));
	CHECK(body->GetPosition().y == doctest::Approx(-centroidY - 0.02 - 0.5).epsilon(1e-4));
}

// b2analytic tests: piles that sleep. A pile poured into a chain bucket in Box2D's testbed
// settings falls asleep as soon as the same pile of Box2D 8-gons inscribed in the same shapes
// (b2a::MakeInscribedPolygon), and a settled pile of hearts keeps its contacts' points and
// normals from step to step.
#include "BucketScene.h"
#include "SceneSupport.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("a small bucket pile of each family alone and mixed falls asleep within 1.5 times its 8-gons' time")
{
	for (const char* family : {"ellipse", "circle", "superellipse", "heart", "mixed"})
	{
		CAPTURE(family);
		// 20 particles in a bucket 3 m wide, 15 s at most, the medians of seeds 1-5.
		const MedianAsleepTimes m = MedianAsleep(family, 20, 1.5f, 15.0);
		const double analytic = m.analyticMedian, polygons = m.polygonsMedian;
		CAPTURE(analytic);
		CAPTURE(polygons);
		CHECK(polygons < 15.0);
		CHECK(analytic <= 1.5 * polygons);
	}
}

TEST_CASE("a settled pile of hearts keeps its contacts' points and normals from step to step")
{
	// 40 hearts in a bucket 4 m wide, from 3 to 4 s (settled, not all asleep): Box2D's world
	// manifold of every touching contact at each step against the step before. A point that keeps
	// its id stays on its lobe or part (it moves less than 15 cm: a lobe's point hopping to the
	// other lobe under the same id moved 0.62 m; a part's point may slide along a long overlap by
	// a few cm when its deepest sample moves to another local minimum of the run, the separations
	// and the normal unchanged), and normals turn by less than 0.01 rad a step
	// on average (a single point hopping between two parts of two hearts' overlap turned them by
	// 0.18 rad a step).
	b2World world(b2Vec2(0.0f, -10.0f));
	b2BodyDef groundDef;
	b2Body* ground = world.CreateBody(&groundDef);
	const b2Vec2 v[4] = {b2Vec2(2.0f, 40.0f), b2Vec2(2.0f, 0.0f), b2Vec2(-2.0f, 0.0f), b2Vec2(-2.0f, 40.0f)};
	b2ChainShape chain;
	chain.CreateChain(v, 4, v[0], v[3]);
	ground->CreateFixture(&chain, 0.0f)->SetFriction(0.6f);
	const ShapePtr heart = MakeHeart(0.2);
	const double cell = 2.0 * heart->BoundingRadius() + 0.05;
	const int perRow = int((4.0 - cell) / cell) + 1;
	for (int i = 0; i < 40; ++i)
		MakeParticle(world, heart, float(-0.5 * (perRow - 1) * cell + (i % perRow) * cell),
		             float(heart->BoundingRadius() + 0.05 + (i / perRow) * cell), float(0.7 * i), 1.0f, 0.6f);
	struct Seen
	{
		int count = 0;
		uint32 id[2] = {0, 0};
		b2Vec2 normal, point[2];
	};
	std::map<b2Contact*, Seen> last;
	double turn = 0.0, largestJump = 0.0;
	int compared = 0, wallContacts = 0;
	for (int step = 1; step <= 240; ++step)
	{
		world.Step(1.0f / 60.0f, 8, 3);
		if (step < 180)
			continue;
		std::map<b2Contact*, Seen> now;
		for (b2Contact* c = world.GetContactList(); c; c = c->GetNext())
		{
			if (!c->IsTouching())
				continue;
			b2WorldManifold wm;
			c->GetWorldManifold(&wm);
			Seen s;
			s.count = c->GetManifold()->pointCount;
			s.normal = wm.normal;
			for (int k = 0; k < s.count; ++k)
			{
				s.id[k] = c->GetManifold()->points[k].id.key;
				s.point[k] = wm.points[k];
			}
			now[c] = s;
			wallContacts += c->GetFixtureA()->GetBody() == ground || c->GetFixtureB()->GetBody() == ground;
			const auto before = last.find(c);
			if (before == last.end())
				continue;
			const Seen& o = before->second;
			++compared;
			turn += std::acos(std::clamp(double(b2Dot(o.normal, s.normal)), -1.0, 1.0));
			for (int k = 0; k < s.count; ++k)
				for (int j = 0; j < o.count; ++j)
					if (o.id[j] == s.id[k])
						largestJump = std::max(largestJump, double((o.point[j] - s.point[k]).Length()));
		}
		last.swap(now);
	}
	REQUIRE(compared > 1000);
	CHECK(wallContacts > 0);
	CHECK(largestJump < 0.15);
	CHECK(turn / compared < 0.01);
}

#include "GameBucket.h"

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/Box2DConversions.h"
#include "b2analytic/b2analytic.h"

#include <algorithm>
#include <random>

namespace b2a::demo
{
std::vector<ShapePtr> GameFamilies(const std::string& family)
{
	const ShapePtr ellipse = MakeEllipse(0.5, 0.3), block = MakeSuperellipse(0.5, 0.3, 4.0, 4.0), heart = MakeHeart(0.2),
	               circle = MakeCircle(0.4);
	if (family == "ellipse")
		return {ellipse};
	if (family == "superellipse")
		return {block};
	if (family == "heart")
		return {heart};
	if (family == "circle")
		return {circle};
	return {ellipse, block, heart, circle};
}

const std::vector<std::string>& GameFamilyNames()
{
	static const std::vector<std::string> names = {"ellipse", "superellipse", "heart", "circle", "mixed"};
	return names;
}

std::unique_ptr<b2World> MakeGameBucket(const std::vector<ShapePtr>& families, int particles, bool polygons, std::uint64_t seed,
                                        double width)
{
	auto world = std::make_unique<b2World>(kGameGravity);
	b2BodyDef def;
	b2Body* ground = world->CreateBody(&def);
	// Walls 40 m tall at 16 m wide, and as much taller as the bucket is wider: 3000 hearts' hull
	// 8-gons heap above 40 m in a bucket 50 m wide.
	const float half = float(0.5 * width), height = float(40.0 * std::max(1.0, width / 16.0));
	const b2Vec2 v[4] = {b2Vec2(half, height), b2Vec2(half, 0.0f), b2Vec2(-half, 0.0f), b2Vec2(-half, height)};
	b2ChainShape chain;
	chain.CreateChain(v, 4, v[0], v[3]);
	ground->CreateFixture(&chain, 0.0f)->SetFriction(0.6f);
	double reach = 0.0;
	for (const ShapePtr& s : families)
		reach = std::max(reach, s->BoundingRadius());
	const double cell = 2.0 * reach + 0.05;
	const int perRow = int((width - cell) / cell) + 1;
	std::mt19937_64 rng(seed);
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	for (int i = 0; i < particles; ++i)
	{
		const ShapePtr& shape = families[size_t(i) % families.size()];
		const Vec2 at(-0.5 * (perRow - 1) * cell + (i % perRow) * cell + 0.02 * (unit(rng) - 0.5), reach + 0.05 + (i / perRow) * cell);
		b2BodyDef bodyDef;
		bodyDef.type = b2_dynamicBody;
		bodyDef.position = ToB2Vec2(at);
		bodyDef.angle = float(2.0 * kPi * unit(rng));
		b2Body* body = world->CreateBody(&bodyDef);
		if (polygons)
		{
			const b2PolygonShape polygon = MakeInscribedPolygon(*shape, 8);
			body->CreateFixture(&polygon, 1.0f)->SetFriction(0.6f);
		}
		else
			CreateAnalyticFixture(body, shape, 1.0f, 0.6f);
	}
	return world;
}

bool AllAsleep(b2World& world)
{
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
		if (b->GetType() == b2_dynamicBody && b->IsAwake())
			return false;
	return true;
}

int AwakeBodies(b2World& world)
{
	int n = 0;
	for (b2Body* b = world.GetBodyList(); b; b = b->GetNext())
		n += b->GetType() == b2_dynamicBody && b->IsAwake();
	return n;
}

} // namespace b2a::demo

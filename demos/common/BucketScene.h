// b2analytic demos: the bucket pile of b2a_demo_game (and of the tests' sleeping piles): one
// shape per family, particles dropped from a lattice into a chain bucket.
#pragma once

#include "b2analytic/AnalyticFixture.h"
#include "b2analytic/Box2DConversions.h"
#include "b2analytic/b2analytic.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace b2a::demo
{

/// The bucket's families: ellipse 0.5 x 0.3 m, superellipse n = 4 of the same semi-axes, heart
/// α = 0.2, circle r = 0.4 m, or all four in turn (any other name: "mixed").
inline std::vector<ShapePtr> BucketFamilies(const std::string& family)
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

/// A chain bucket 2·halfWidth wide and 40 m tall (its links face inwards, friction 0.6) in
/// `world`, and `particles` of the families in turn on a lattice of cells two bounding radii and
/// 5 cm wide above its floor, at random angles from `seed` (density 1, friction 0.6): analytic
/// particles, or the Box2D 8-gons inscribed in the same shapes (MakeInscribedPolygon).
inline void FillBucket(b2World& world, const std::vector<ShapePtr>& families, int particles, float halfWidth, bool polygons,
                       std::uint64_t seed)
{
	b2BodyDef groundDef;
	b2Body* ground = world.CreateBody(&groundDef);
	const b2Vec2 v[4] = {b2Vec2(halfWidth, 40.0f), b2Vec2(halfWidth, 0.0f), b2Vec2(-halfWidth, 0.0f), b2Vec2(-halfWidth, 40.0f)};
	b2ChainShape chain;
	chain.CreateChain(v, 4, v[0], v[3]);
	ground->CreateFixture(&chain, 0.0f)->SetFriction(0.6f);
	double reach = 0.0;
	for (const ShapePtr& s : families)
		reach = std::max(reach, s->BoundingRadius());
	const double cell = 2.0 * reach + 0.05;
	const int perRow = int((2.0 * halfWidth - cell) / cell) + 1;
	std::mt19937_64 rng(seed);
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	for (int i = 0; i < particles; ++i)
	{
		const ShapePtr& shape = families[size_t(i) % families.size()];
		const Vec2 at(-0.5 * (perRow - 1) * cell + (i % perRow) * cell + 0.02 * (unit(rng) - 0.5), reach + 0.05 + (i / perRow) * cell);
		b2BodyDef def;
		def.type = b2_dynamicBody;
		def.position = ToB2Vec2(at);
		def.angle = float(2.0 * kPi * unit(rng));
		b2Body* body = world.CreateBody(&def);
		if (polygons)
		{
			const b2PolygonShape polygon = MakeInscribedPolygon(*shape, 8);
			body->CreateFixture(&polygon, 1.0f)->SetFriction(0.6f);
		}
		else
			CreateAnalyticFixture(body, shape, 1.0f, 0.6f);
	}
}

} // namespace b2a::demo

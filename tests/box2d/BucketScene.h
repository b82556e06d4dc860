// b2analytic tests: the bucket pile of b2a_demo_game (common/BucketScene.h) in Box2D's testbed
// settings (metres, g = 10 m/s², 60 Hz, 8 velocity and 3 position iterations, sleeping on), of
// analytic particles or of their Box2D 8-gons, and when it falls asleep.
#pragma once

#include "common/BucketScene.h"

namespace b2a::test
{

using demo::BucketFamilies;

/// When every body of a bucket pile (demo::FillBucket: `particles` of the families, a bucket
/// 2·halfWidth wide, analytic or 8-gons, `seed`) slept (s), or −1 if not within maxTime.
inline double BucketAsleepAt(const std::vector<ShapePtr>& families, int particles, float halfWidth, bool polygons,
                             std::uint64_t seed, double maxTime)
{
	b2World world(b2Vec2(0.0f, -10.0f));
	demo::FillBucket(world, families, particles, halfWidth, polygons, seed);
	for (int step = 1; step <= int(maxTime * 60.0 + 0.5); ++step)
	{
		world.Step(1.0f / 60.0f, 8, 3);
		bool asleep = true;
		for (b2Body* b = world.GetBodyList(); b && asleep; b = b->GetNext())
			asleep = b->GetType() != b2_dynamicBody || !b->IsAwake();
		if (asleep)
			return step / 60.0;
	}
	return -1.0;
}

} // namespace b2a::test

// b2analytic tests: the bucket pile of b2a_demo_game (demos/common/GameBucket.h) in Box2D's
// testbed settings (metres, g = 10 m/s², 60 Hz, 8 velocity and 3 position iterations, sleeping
// on), of analytic particles or of their Box2D 8-gons, and when it falls asleep.
#pragma once

#include "common/GameBucket.h"

namespace b2a::test
{

/// The bucket's families by name (demo::GameFamilies).
inline std::vector<ShapePtr> BucketFamilies(const std::string& family)
{
	return demo::GameFamilies(family);
}

/// When every body of a bucket pile (demo::MakeGameBucket: `particles` of the families, a bucket
/// 2·halfWidth wide, analytic or 8-gons, `seed`) slept (s), or −1 if not within maxTime.
inline double BucketAsleepAt(const std::vector<ShapePtr>& families, int particles, float halfWidth, bool polygons,
                             std::uint64_t seed, double maxTime)
{
	const std::unique_ptr<b2World> world = demo::MakeGameBucket(families, particles, polygons, seed, 2.0 * halfWidth);
	for (int step = 1; step <= int(maxTime / demo::kGameStep + 0.5); ++step)
	{
		world->Step(demo::kGameStep, demo::kGameVelocityIterations, demo::kGamePositionIterations);
		if (demo::AllAsleep(*world))
			return step * double(demo::kGameStep);
	}
	return -1.0;
}

} // namespace b2a::test

// b2analytic tests: the bucket pile of b2a_demo_game (demos/common/GameBucket.h) in Box2D's
// testbed settings (metres, g = 10 m/s², 60 Hz, 8 velocity and 3 position iterations, sleeping
// on), of analytic particles or of their Box2D 8-gons, and when it falls asleep.
#pragma once

#include "common/GameBucket.h"

#include <algorithm>
#include <vector>

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

/// When the piles of seeds 1-5 slept (s; a pile awake after maxTime counts as maxTime), and
/// the medians: a pile sleeps when its last mover stops, which differs from seed to seed by up
/// to five times or more, so the median of five is what a test can hold a family to.
struct MedianAsleepTimes
{
	std::vector<double> analytic, polygons; ///< per seed, 1 to 5
	double analyticMedian = 0.0, polygonsMedian = 0.0;
};

/// BucketAsleepAt for seeds 1-5, analytic and as 8-gons, and the medians.
inline MedianAsleepTimes MedianAsleep(const std::string& family, int particles, float halfWidth, double maxTime)
{
	MedianAsleepTimes m;
	for (std::uint64_t seed = 1; seed <= 5; ++seed)
		for (bool poly : {false, true})
		{
			const double t = BucketAsleepAt(BucketFamilies(family), particles, halfWidth, poly, seed, maxTime);
			(poly ? m.polygons : m.analytic).push_back(t > 0.0 ? t : maxTime);
		}
	auto median = [](std::vector<double> v) {
		std::sort(v.begin(), v.end());
		return v[2];
	};
	m.analyticMedian = median(m.analytic);
	m.polygonsMedian = median(m.polygons);
	return m;
}

} // namespace b2a::test

// b2a validation tests (label validation): the bucket pile of b2a_demo_game at full size, 300
// particles in a chain bucket 16 m wide in Box2D's testbed settings, falls asleep within 1.5 times
// the time of the same pile of Box2D 8-gons inscribed in the same shapes, in the median of seeds
// 1-5: ellipses and circles. The mixed pile does not yet (a known failure here), nor the
// superellipse n = 4 and heart piles (docs/benchmarks.md, "Sleeping piles"). A pile sleeps when
// its last mover stops, and a smooth particle rocking on a flat face loses no energy, so one
// seed's time can be many times the median's: the median is what the test holds a family to.
#include "box2d/BucketScene.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
// Seeds 1-5 of a 300-particle pile of `family`, analytic and as 8-gons: the median times at
// which each fell asleep (a pile awake after 60 s counts as 60 s).
void MedianAsleep300(const std::string& family, double& analytic, double& polygons)
{
	std::vector<double> a, p;
	for (std::uint64_t seed = 1; seed <= 5; ++seed)
	{
		const double ta = BucketAsleepAt(BucketFamilies(family), 300, 8.0f, false, seed, 60.0);
		const double tp = BucketAsleepAt(BucketFamilies(family), 300, 8.0f, true, seed, 60.0);
		MESSAGE(family << " seed " << seed << ": analytic " << ta << " s, 8-gons " << tp << " s");
		a.push_back(ta > 0.0 ? ta : 60.0);
		p.push_back(tp > 0.0 ? tp : 60.0);
	}
	std::sort(a.begin(), a.end());
	std::sort(p.begin(), p.end());
	analytic = a[2];
	polygons = p[2];
}
} // namespace

TEST_CASE("300 ellipses or circles in a bucket fall asleep within 1.5 times the same pile of 8-gons, median of five seeds")
{
	for (const std::string family : {"ellipse", "circle"})
	{
		CAPTURE(family);
		double analytic = 0.0, polygons = 0.0;
		MedianAsleep300(family, analytic, polygons);
		CAPTURE(analytic);
		CAPTURE(polygons);
		CHECK(polygons < 60.0);
		CHECK(analytic <= 1.5 * polygons);
	}
}

// Known failure: the mixed pile's median is 16.0 s against its 8-gons' 9.2 s (1.74 times), one
// seed of five never asleep within 60 s; its last movers rock and roll on curved faces.
TEST_CASE("300 mixed particles in a bucket fall asleep within 1.5 times the same pile of 8-gons (known failure)" *
          doctest::should_fail())
{
	double analytic = 0.0, polygons = 0.0;
	MedianAsleep300("mixed", analytic, polygons);
	CAPTURE(analytic);
	CAPTURE(polygons);
	CHECK(polygons < 60.0);
	CHECK(analytic <= 1.5 * polygons);
}

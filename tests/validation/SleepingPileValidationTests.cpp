// b2a validation tests (label validation): the bucket pile of b2a_demo_game at full size, 300
// particles in a chain bucket 16 m wide in Box2D's testbed settings, falls asleep within 1.5 times
// the time of the same pile of Box2D 8-gons inscribed in the same shapes. Ellipses, circles and
// the mixed pile; the superellipse n = 4 and heart piles do not yet (docs/benchmarks.md,
// "Sleeping piles").
#include "box2d/BucketScene.h"

#include <doctest/doctest.h>

using namespace b2a;
using namespace b2a::test;

TEST_CASE("300 particles in a bucket fall asleep within 1.5 times the same pile of 8-gons")
{
	for (const char* family : {"ellipse", "circle", "mixed"})
	{
		CAPTURE(family);
		const double analytic = BucketAsleepAt(BucketFamilies(family), 300, 8.0f, false, 1, 60.0);
		const double polygons = BucketAsleepAt(BucketFamilies(family), 300, 8.0f, true, 1, 60.0);
		CAPTURE(analytic);
		CAPTURE(polygons);
		REQUIRE(polygons > 0.0);
		CHECK(analytic > 0.0);
		CHECK(analytic <= 1.5 * polygons);
	}
}

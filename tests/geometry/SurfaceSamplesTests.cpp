// Shape::Samples: points on the own surface, ordered by angle, spread by arc length and turning,
// cached per count.
#include <doctest/doctest.h>

#include "GeometryReference.h"
#include "TestSupport.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
const int kCounts[] = {3, 8, 13, 64, 256, 1024};

// Perimeter of the own surface from a dense polygon (relative error ~1e-10 at 100000 vertices).
double Perimeter(const Shape& s)
{
	const auto p = SurfacePolygon(s, 100000);
	double sum = 0.0;
	for (size_t i = 0; i < p.size(); ++i)
		sum += Distance(p[i], p[(i + 1) % p.size()]);
	return sum;
}

double SegmentDistance(Vec2 p, Vec2 a, Vec2 b)
{
	const Vec2 ab = b - a;
	const double t = std::clamp(Dot(p - a, ab) / LengthSquared(ab), 0.0, 1.0);
	return Distance(p, a + t * ab);
}
} // namespace

TEST_CASE("surface samples: every sample lies on the surface level set")
{
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		for (int count : kCounts)
		{
			CAPTURE(count);
			const auto smp = s.Samples(count);
			REQUIRE(smp->Count() == count);
			REQUIRE(smp->angle.size() == smp->point.size());
			CHECK(smp->level == s.SurfaceLevel());
			for (int k = 0; k < count; ++k)
			{
				const Vec2 p = smp->point[k];
				// 1e-12 relative, as for SurfacePoint (see LevelSetTests), with the library's
				// level and with the independent long-double one.
				CHECK(RelativeError(s.Level(p), s.SurfaceLevel()) < 1e-12);
				CHECK(RelativeError(double(c.levelRef(p)), s.SurfaceLevel()) < 1e-12);
				// The stored point is SurfacePoint(angle) (to an ulp: a user shape's radial root
				// solve may take another bracket once its bounding radius is known).
				CHECK(Distance(p, s.SurfacePoint(smp->angle[k])) <= 1e-15 * s.BoundingRadius());
			}
		}
	}
}

TEST_CASE("surface samples: ordered by polar angle, strictly increasing from -pi up to pi")
{
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		for (int count : kCounts)
		{
			CAPTURE(count);
			const auto smp = c.shape->Samples(count);
			for (int k = 0; k < smp->Count(); ++k)
			{
				CHECK(smp->angle[k] >= -kPi);
				CHECK(smp->angle[k] < kPi);
				if (k > 0) CHECK(smp->angle[k] > smp->angle[k - 1]);
				// The stored angle is the point's own polar angle (atan2 is in (−π, π]).
				const Vec2 p = smp->point[k];
				const double a = std::atan2(p.y, p.x);
				CHECK(std::fabs(std::remainder(a - smp->angle[k], 2.0 * kPi)) < 1e-14);
			}
		}
	}
}

TEST_CASE("surface samples: maxSpacing is the largest gap, and arc length is resolved")
{
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		const double perimeter = Perimeter(*c.shape);
		for (int count : kCounts)
		{
			CAPTURE(count);
			const auto smp = c.shape->Samples(count);
			double gap = 0.0;
			for (int k = 0; k < count; ++k)
				gap = std::max(gap, Distance(smp->point[k], smp->point[(k + 1) % count])); // wraps around
			CHECK(smp->maxSpacing == doctest::Approx(gap).epsilon(1e-15));
			// Half of the sampling budget follows arc length, so no chord is longer than about
			// 2 × perimeter / count (observed up to 2.03 for the 1000:1 ellipse, where the
			// equidistribution works on a discrete dense polygon). Without it, angle-uniform
			// samples would leave chords of ~100 on the 1000:1 ellipse.
			CHECK(smp->maxSpacing <= 2.2 * perimeter / count);
		}
	}
}

TEST_CASE("surface samples: maxDeviation is the distance from the curve to the sample polygon")
{
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		for (int count : kCounts)
		{
			CAPTURE(count);
			const auto smp = s.Samples(count);
			// Our own measurement: 15 interior points of every arc between consecutive samples.
			double dev = 0.0;
			for (int k = 0; k < count; ++k)
			{
				const int j = (k + 1) % count;
				double t0 = smp->angle[k], t1 = smp->angle[j];
				if (t1 <= t0) t1 += 2.0 * kPi;
				for (int q = 1; q < 16; ++q)
					dev = std::max(dev, SegmentDistance(s.SurfacePoint(t0 + (t1 - t0) * q / 16.0), smp->point[k], smp->point[j]));
			}
			// The library measures a subset of these points (quarters of each arc): never more,
			// and (observed) within 12% for 8 or 13 samples, 1% from 64 on.
			CHECK(smp->maxDeviation <= dev * (1.0 + 1e-12));
			CHECK(dev <= (count < 64 ? 1.2 : 1.02) * smp->maxDeviation);
		}
	}
}

TEST_CASE("surface samples: the 1000:1 ellipse's tips are resolved by turning, not just arc length")
{
	// Half the budget follows the turning of the tangent: a tip with curvature radius a²/b = 1e-4
	// must receive samples so that the polygon's turning per sample stays near 2 × 2π / count.
	// (Arc length alone would put ~1 sample around each tip and turn by ~π there.)
	const auto s = MakeEllipse(0.1, 100.0);
	for (int count : {64, 256, 1024})
	{
		CAPTURE(count);
		const auto smp = s->Samples(count);
		double maxTurn = 0.0;
		for (int k = 0; k < count; ++k)
		{
			const Vec2 in = smp->point[k] - smp->point[(k + count - 1) % count];
			const Vec2 out = smp->point[(k + 1) % count] - smp->point[k];
			maxTurn = std::max(maxTurn, std::fabs(std::atan2(Cross(in, out), Dot(in, out))));
		}
		CHECK(maxTurn <= 3.0 * 2.0 * kPi / count); // observed ≤ 2.25 × 2π / count
	}
}

TEST_CASE("surface samples: the heart's cusps are samples themselves")
{
	for (const char* name : {"heart alpha=1", "user heart alpha=1.3 (analytic G derivatives)"})
	{
		CAPTURE(name);
		const Shape& s = *FindShapeCase(name).shape;
		for (int count : kCounts)
		{
			CAPTURE(count);
			const auto smp = s.Samples(count);
			for (double corner : {-0.5 * kPi, 0.5 * kPi})
			{
				CAPTURE(corner);
				CHECK(std::find(smp->angle.begin(), smp->angle.end(), corner) != smp->angle.end());
			}
		}
	}
}

TEST_CASE("surface samples: computed once per count and shared, also across threads")
{
	const auto heart = MakeHeart(1.7);
	const auto a = heart->Samples(300);
	const auto b = heart->Samples(301);
	CHECK(heart->Samples(300).get() == a.get());
	CHECK(heart->Samples(301).get() == b.get());
	CHECK(a.get() != b.get());
	CHECK(b->Count() == 301);
	// The default count is kDefaultSampleCount.
	CHECK(heart->Samples().get() == heart->Samples(Shape::kDefaultSampleCount).get());
	CHECK(heart->Samples()->Count() == Shape::kDefaultSampleCount);

	// Concurrent first requests for a new count get one shared result.
	const auto ellipse = MakeEllipse(0.1, 100.0);
	std::vector<const SurfaceSamples*> seen(4, nullptr);
	std::vector<std::thread> threads;
	for (int t = 0; t < 4; ++t)
		threads.emplace_back([&, t] { seen[t] = ellipse->Samples(777).get(); });
	for (auto& th : threads) th.join();
	for (int t = 1; t < 4; ++t)
		CHECK(seen[t] == seen[0]);
	CHECK(ellipse->Samples(777).get() == seen[0]);
}

TEST_CASE("surface samples: SamplesRef is Samples' object, whichever count was asked for last and on any thread")
{
	const auto heart = MakeHeart(0.9);
	// Alternating counts: the kept pointer changes hands, the answer is always the count's own.
	for (int round = 0; round < 3; ++round)
		for (const int count : {300, Shape::kDefaultSampleCount, 64})
		{
			const SurfaceSamples& ref = heart->SamplesRef(count);
			CHECK(&ref == heart->Samples(count).get());
			CHECK(ref.Count() == count);
		}
	CHECK(&heart->SamplesRef() == heart->Samples().get());
	// Threads asking for different counts at once each get their own count's samples.
	const auto ellipse = MakeEllipse(0.4, 3.0);
	std::vector<int> wrong(4, 0);
	std::vector<std::thread> threads;
	for (int t = 0; t < 4; ++t)
		threads.emplace_back([&, t] {
			const int count = 100 + 50 * (t % 2);
			for (int k = 0; k < 200; ++k)
				wrong[t] += ellipse->SamplesRef(count).Count() != count;
		});
	for (auto& th : threads) th.join();
	for (int t = 0; t < 4; ++t)
		CHECK(wrong[t] == 0);
	CHECK(&ellipse->SamplesRef(150) == ellipse->Samples(150).get());
}

TEST_CASE("surface samples: the same whatever other shapes and counts were sampled before on the thread")
{
	// The dense pass is reused between counts of one shape (a fixture asks for two in a row). The
	// samples of a count must not depend on that: each shape is sampled fresh, then its twin (same
	// parameters) after interleaving other shapes and counts, and the two must be identical.
	auto make = [](int which) -> ShapePtr {
		switch (which)
		{
		case 0: return MakeEllipse(2.0, 0.66);
		case 1: return MakeSuperellipse(1.0, 0.6, 4.0, 4.0);
		case 2: return MakeHeart(1.0);
		default: return MakeSuperellipse(1.0, 0.5, 1.0, 2.0); // corners
		}
	};
	for (int which = 0; which < 4; ++which)
	{
		CAPTURE(which);
		const ShapePtr fresh = make(which);
		const auto seven = fresh->Samples(7);
		const ShapePtr twin = make(which);
		const ShapePtr other = make((which + 1) % 4);
		const auto twinDefault = twin->Samples(); // fills the thread's dense pass with the twin's
		(void)other->Samples(33);                 // ... then another shape's
		const auto twinSeven = twin->Samples(7);  // so this one computes its dense pass again
		const auto freshDefault = fresh->Samples();
		REQUIRE(twinSeven->Count() == seven->Count());
		for (int k = 0; k < seven->Count(); ++k)
		{
			CHECK(twinSeven->angle[k] == seven->angle[k]);
			CHECK(twinSeven->point[k].x == seven->point[k].x);
			CHECK(twinSeven->point[k].y == seven->point[k].y);
		}
		REQUIRE(twinDefault->Count() == freshDefault->Count());
		for (int k = 0; k < freshDefault->Count(); ++k)
			CHECK(twinDefault->angle[k] == freshDefault->angle[k]);
		CHECK(twinDefault->maxDeviation == freshDefault->maxDeviation);
	}
}

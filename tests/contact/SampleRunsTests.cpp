// The grid method's hierarchy over a shape's surface samples (contact/SampleRuns.h): discs and
// boxes that hold the curve between the samples, made once per shape and sample count.
#include <doctest/doctest.h>

#include "GeometryReference.h"

#include "contact/SampleRuns.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

using namespace b2a;
using namespace b2a::test;

namespace
{
const int kCounts[] = {3, 8, 13, 64, 256, 1024};
} // namespace

TEST_CASE("sample runs: each run's disc and box enclose its stretch of the curve, the box thin")
{
	// The grid method skips a run when A's level is provably high over its disc, or over its box
	// (its last look), so both must hold every point of the curve between the run's first and
	// last sample, not only the samples. Aligned with the run's chord, the box is much thinner
	// than the disc is wide: that is what it is for.
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		const Shape& s = *c.shape;
		for (int count : kCounts)
		{
			CAPTURE(count);
			const SampleRuns& runs = SampleRunsOf(s, count);
			const SurfaceSamples* smp = runs.samples;
			const int L = SampleRuns::kRunLength;
			REQUIRE(int(runs.runCentre.size()) == (count + L - 1) / L);
			REQUIRE(runs.runRadius.size() == runs.runCentre.size());
			REQUIRE(runs.runBox.size() == runs.runCentre.size());
			double slack = 1e300; // the tightest margin seen: the discs are not needlessly large
			double widthOverRadius = 0.0; // mean of the box's half-width over the disc's radius
			for (size_t g = 0; g < runs.runCentre.size(); ++g)
			{
				CAPTURE(g);
				const OrientedBox& box = runs.runBox[g];
				CHECK(std::fabs(Length(box.axis) - 1.0) <= 1e-15);
				const Vec2 across(-box.axis.y, box.axis.x);
				const int first = int(g) * L, last = std::min(first + L, count);
				double t0 = smp->angle[first], t1 = smp->angle[last % count];
				if (t1 <= t0) t1 += 2.0 * kPi;
				double reach = 0.0, along = 0.0, off = 0.0;
				for (int q = 0; q <= 64 * (last - first); ++q)
				{
					const Vec2 x = s.SurfacePoint(t0 + (t1 - t0) * q / (64.0 * (last - first)));
					reach = std::max(reach, Distance(x, runs.runCentre[g]));
					along = std::max(along, std::fabs(Dot(x - box.centre, box.axis)));
					off = std::max(off, std::fabs(Dot(x - box.centre, across)));
				}
				CHECK(reach <= runs.runRadius[g]);
				CHECK(along <= box.halfLength);
				CHECK(off <= box.halfWidth);
				slack = std::min(slack, runs.runRadius[g] / reach);
				widthOverRadius += box.halfWidth / runs.runRadius[g] / double(runs.runBox.size());
			}
			if (count >= 64)
				CHECK(slack < 1.5);
			// (Measured at 256 samples: 0.002 to 0.041, the hearts' 0.040 and 0.041.)
			if (count >= 256)
				CHECK(widthOverRadius < 0.1);
		}
	}
}

TEST_CASE("sample runs: each group's disc encloses its runs' discs")
{
	// The grid method skips a whole group of runs when A's level is provably high over the
	// group's disc, so that disc must hold each of its runs' discs (and so their curve).
	for (const ShapeCase& c : AllShapeKinds())
	{
		CAPTURE(c.name);
		for (int count : kCounts)
		{
			CAPTURE(count);
			const SampleRuns& hierarchy = SampleRunsOf(*c.shape, count);
			const int runs = int(hierarchy.runCentre.size()), G = SampleRuns::kGroupRuns;
			REQUIRE(int(hierarchy.groupCentre.size()) == (runs + G - 1) / G);
			REQUIRE(hierarchy.groupRadius.size() == hierarchy.groupCentre.size());
			double widest = 0.0; // the group discs are no larger than their runs need
			for (size_t group = 0; group < hierarchy.groupCentre.size(); ++group)
			{
				double reach = 0.0;
				for (int g = int(group) * G; g < std::min(int(group + 1) * G, runs); ++g)
				{
					const double r = Distance(hierarchy.groupCentre[group], hierarchy.runCentre[size_t(g)]) + hierarchy.runRadius[size_t(g)];
					CHECK(r <= hierarchy.groupRadius[group] * (1.0 + 1e-15));
					reach = std::max(reach, r);
				}
				widest = std::max(widest, hierarchy.groupRadius[group] / reach);
			}
			CHECK(widest <= 1.0 + 1e-15);
		}
	}
}

TEST_CASE("sample runs: made once per shape and count, over the shape's own samples, on any thread")
{
	const auto heart = MakeHeart(1.1);
	for (int count : {64, 256, 300})
	{
		const SampleRuns& runs = SampleRunsOf(*heart, count);
		CHECK(runs.count == count);
		CHECK(runs.samples == heart->Samples(count).get());
		CHECK(&SampleRunsOf(*heart, count) == &runs);
	}
	CHECK(&SampleRunsOf(*heart, 64) == &SampleRunsOf(*heart, 64));
	// Threads asking for alternating counts all get the one object of each count.
	const auto ellipse = MakeEllipse(2.0, 0.7);
	const SampleRuns* first[2] = {&SampleRunsOf(*ellipse, 128), &SampleRunsOf(*ellipse, 150)};
	std::vector<std::thread> threads;
	int wrong[4] = {0, 0, 0, 0};
	for (int t = 0; t < 4; ++t)
		threads.emplace_back([&, t] {
			for (int i = 0; i < 2000; ++i)
			{
				const int which = (i + t) % 2;
				wrong[t] += &SampleRunsOf(*ellipse, which ? 150 : 128) != first[which];
			}
		});
	for (std::thread& th : threads)
		th.join();
	for (int t = 0; t < 4; ++t)
		CHECK(wrong[t] == 0);
}

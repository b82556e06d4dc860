// b2analytic tests: the benchmarks' paired timing (BenchCommon.h) on a programmed clock: the
// ratio is the median of each repeat's own ratio, so drift of the machine's speed between
// repeats cancels where medians of separately timed passes do not.
#include <doctest/doctest.h>

#ifdef B2A_BENCH_PAIRS // the benchmarks are optional (B2A_BUILD_BENCHMARKS)

#include "BenchCommon.h"

#include <vector>

using namespace b2a::bench;

namespace
{
// A clock that a pass advances by its cost times the machine's slowness at that moment.
struct ProgrammedClock
{
	double now = 0.0;
	double operator()() const { return now; }
};
} // namespace

TEST_CASE("MedianPairedPerQuery: the ratio of each repeat's passes, whatever the drift")
{
	ProgrammedClock clock;
	// The machine slows down by 2.5× during the run, then speeds up again; a method costs 3 and
	// the baseline 1 units per pass at speed 1.
	const std::vector<double> slowness = {1.0, 1.0, 1.3, 2.5, 2.5, 2.5, 2.5, 1.2, 1.0, 1.0, 1.0};
	int call = 0; // passes run so far (two warm-ups, then two per repeat)
	auto slow = [&] { return slowness[size_t(std::min<int>(call / 2, int(slowness.size()) - 1))]; };
	std::vector<char> order;
	auto method = [&] { clock.now += 3.0 * slow(); ++call; order.push_back('m'); };
	auto baseline = [&] { clock.now += 1.0 * slow(); ++call; order.push_back('b'); };
	const PairedTiming t = MedianPairedPerQuery(method, baseline, 1, 9, [&] { return clock(); });
	CHECK(t.ratio == doctest::Approx(3.0).epsilon(1e-12));
	// The medians on their own: both passes of a repeat run at its slowness, so each median
	// takes the middle one of the nine repeats' (1.0, 1.3, 2.5 ×4, 1.2, 1.0, 1.0), 1.3.
	CHECK(t.ns == doctest::Approx(3.0 * 1.3).epsilon(1e-12));
	CHECK(t.baselineNs == doctest::Approx(1.0 * 1.3).epsilon(1e-12));
	// Warm-up of both, then the order swaps every repeat: m b, b m, m b, ...
	REQUIRE(order.size() == 2 + 2 * 9);
	CHECK(order[0] == 'm');
	CHECK(order[1] == 'b');
	CHECK(order[2] == 'm');
	CHECK(order[3] == 'b');
	CHECK(order[4] == 'b');
	CHECK(order[5] == 'm');
	CHECK(order[6] == 'm');
}

TEST_CASE("MedianPairedPerQuery: separately timed blocks would report the drift as a ratio")
{
	// The reference the paired ratio improves on: the method timed while the machine is slow and
	// the baseline after it has recovered give a median ratio off by the slowness (2.5 here),
	// which the paired timing of the test above does not.
	ProgrammedClock clock;
	double slowness = 2.5;
	auto method = [&] { clock.now += 3.0 * slowness; };
	auto baseline = [&] { clock.now += 1.0 * slowness; };
	const PairedTiming slowRun = MedianPairedPerQuery(method, baseline, 1, 5, [&] { return clock(); });
	slowness = 1.0;
	const PairedTiming fastRun = MedianPairedPerQuery(method, baseline, 1, 5, [&] { return clock(); });
	CHECK(slowRun.ns / fastRun.baselineNs == doctest::Approx(7.5));
	CHECK(slowRun.ratio == doctest::Approx(3.0));
	CHECK(fastRun.ratio == doctest::Approx(3.0));
	// Per-query division, and a baseline that took no time gives ratio 0, not a division by 0.
	const PairedTiming perQuery = MedianPairedPerQuery(method, [] {}, 4, 3, [&] { return clock(); });
	CHECK(perQuery.ns == doctest::Approx(0.75));
	CHECK(perQuery.ratio == 0.0);
}

#endif

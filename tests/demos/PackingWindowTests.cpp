// b2analytic tests: the packing validation's window measurement against lattices and lenses
// whose area fractions are known in closed form.
#include "validation/PackingWindow.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace b2a;
using namespace b2a::demo;

TEST_CASE("MeasureWindow: a window of whole periods of touching disks holds the hexagonal fraction π/(2√3)")
{
	// Unit disks on the triangular lattice of spacing 2: periods 2 across and 2√3 up, so a
	// window of 20 by 12 periods, anywhere, holds exactly the lattice's fraction.
	const double r = 1.0, dy = std::sqrt(3.0) * r;
	const ShapePtr disk = MakeCircle(r);
	std::vector<ParticleState> packing;
	for (int j = -2; j < 30; ++j)
		for (int i = -2; i < 25; ++i)
			packing.push_back({disk, Pose(Vec2(2.0 * r * i + (j % 2 ? r : 0.0), dy * j), 0.0)});
	const Box window{Vec2(3.3, 4.1), Vec2(3.3 + 40.0 * r, 4.1 + 24.0 * dy)};
	const WindowFraction w = MeasureWindow(packing, window, r / 40.0);
	CHECK(w.sum == doctest::Approx(kPi / (2.0 * std::sqrt(3.0))).epsilon(5e-4));
	CHECK(w.covered == doctest::Approx(w.sum).epsilon(1e-12)); // touching, not overlapping
	CHECK(w.width == doctest::Approx(40.0).epsilon(1e-3));
}

TEST_CASE("MeasureWindow: overlaps count twice in the sum and once in the covered fraction, and a tilted ellipse has area πab")
{
	// Two unit disks 1.2 apart: their lens has area 2r² acos(d/2r) − (d/2)√(4r² − d²).
	const double r = 1.0, d = 1.2;
	const ShapePtr disk = MakeCircle(r);
	const Box window{Vec2(-5.0, -5.0), Vec2(5.0, 5.0)};
	const WindowFraction w =
		MeasureWindow({{disk, Pose(Vec2(-0.5 * d, 0.3), 0.0)}, {disk, Pose(Vec2(0.5 * d, 0.3), 0.0)}}, window, 0.01);
	const double lens = 2.0 * r * r * std::acos(d / (2.0 * r)) - 0.5 * d * std::sqrt(4.0 * r * r - d * d);
	CHECK(w.sum * 100.0 == doctest::Approx(2.0 * kPi * r * r).epsilon(1e-3));
	CHECK(w.covered * 100.0 == doctest::Approx(2.0 * kPi * r * r - lens).epsilon(1e-3));
	const WindowFraction e = MeasureWindow({{MakeEllipse(2.0, 0.7), Pose(Vec2(0.4, -0.2), 0.5)}}, window, 0.01);
	CHECK(e.sum * 100.0 == doctest::Approx(kPi * 2.0 * 0.7).epsilon(1e-3));
	// Half of a disk on the window's edge counts half.
	const WindowFraction half = MeasureWindow({{disk, Pose(Vec2(5.0, 0.0), 0.0)}}, window, 0.01);
	CHECK(half.sum * 100.0 == doctest::Approx(0.5 * kPi).epsilon(2e-3));
	// No whole cell: zeros.
	CHECK(MeasureWindow({{disk, Pose(Vec2(0.0, 0.0), 0.0)}}, Box{Vec2(0.0, 0.0), Vec2(0.005, 1.0)}, 0.01).sum == 0.0);
}

TEST_CASE("FreeSurface: the lowest of the columns' highest tops")
{
	const ShapePtr disk = MakeCircle(1.0);
	// Box 12 wide in three columns of 4: tops 5, 3 and 7 (centre heights plus the radius).
	const std::vector<ParticleState> packing = {{disk, Pose(Vec2(-4.0, 1.0), 0.0)}, {disk, Pose(Vec2(-4.5, 4.0), 0.0)},
	                                            {disk, Pose(Vec2(0.0, 2.0), 0.0)},  {disk, Pose(Vec2(4.0, 6.0), 0.0)},
	                                            {disk, Pose(Vec2(5.0, 1.0), 0.0)}};
	CHECK(FreeSurface(packing, 12.0, 4.0) == doctest::Approx(3.0));
	CHECK(FreeSurface(packing, 12.0, 12.0) == doctest::Approx(7.0)); // one column: the highest top
}

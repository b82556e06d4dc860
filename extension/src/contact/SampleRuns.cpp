// b2analytic: the grid method's hierarchy over a shape's surface samples, and its cache.
#include "contact/SampleRuns.h"

#include <algorithm>
#include <mutex>

namespace b2a
{

SampleRuns BuildSampleRuns(const SurfaceSamples& s)
{
	SampleRuns out;
	out.samples = &s;
	const int n = s.Count();
	// Run discs: the centre of the run's sample box, the radius to its farthest sample plus
	// twice the deviation of the curve from the sample polygon.
	for (int first = 0; first < n; first += SampleRuns::kRunLength)
	{
		const int last = std::min(first + SampleRuns::kRunLength, n); // sample index, mod n
		Vec2 lower = s.point[first], upper = lower;
		for (int k = first + 1; k <= last; ++k)
		{
			const Vec2 p = s.point[k % n];
			lower = Vec2(std::min(lower.x, p.x), std::min(lower.y, p.y));
			upper = Vec2(std::max(upper.x, p.x), std::max(upper.y, p.y));
		}
		const Vec2 centre = 0.5 * (lower + upper);
		double radius = 0.0;
		for (int k = first; k <= last; ++k)
			radius = std::max(radius, Distance(centre, s.point[k % n]));
		out.runCentre.push_back(centre);
		out.runRadius.push_back(radius + 2.0 * s.maxDeviation);
		// The box along the chord: the samples' extents along it and across it, widened on
		// every side by twice the largest deviation measured on the run's own arcs (the curve
		// keeps within it of the sample polygon, which the samples' box holds whatever its
		// orientation; the shape's largest, the discs' margin, is the heart's cusp's, and
		// taken for every run it made the heart's boxes four times as wide).
		// (Plus the points' rounding: a straight run measures no deviation.)
		double runDeviation = 0.0, farthest = 0.0;
		for (int k = first; k < last; ++k)
		{
			runDeviation = std::max(runDeviation, s.arcDeviation[size_t(k)]);
			farthest = std::max(farthest, Length(s.point[k]));
		}
		runDeviation += 1e-14 * farthest;
		const Vec2 start = s.point[first], chord = s.point[last % n] - start;
		const Vec2 axis = LengthSquared(chord) > 0.0 ? Normalize(chord) : Vec2(1.0, 0.0), across(-axis.y, axis.x);
		double alongLow = 0.0, alongHigh = 0.0, acrossLow = 0.0, acrossHigh = 0.0;
		for (int k = first + 1; k <= last; ++k)
		{
			const Vec2 d = s.point[k % n] - start;
			alongLow = std::min(alongLow, Dot(d, axis));
			alongHigh = std::max(alongHigh, Dot(d, axis));
			acrossLow = std::min(acrossLow, Dot(d, across));
			acrossHigh = std::max(acrossHigh, Dot(d, across));
		}
		OrientedBox box;
		box.axis = axis;
		box.centre = start + (0.5 * (alongLow + alongHigh)) * axis + (0.5 * (acrossLow + acrossHigh)) * across;
		box.halfLength = 0.5 * (alongHigh - alongLow) + 2.0 * runDeviation;
		box.halfWidth = 0.5 * (acrossHigh - acrossLow) + 2.0 * runDeviation;
		out.runBox.push_back(box);
	}
	// Group discs: the centre of the box of the group's run discs, the radius reaching the
	// farthest edge of any of them.
	const int runs = int(out.runCentre.size());
	for (int first = 0; first < runs; first += SampleRuns::kGroupRuns)
	{
		const int last = std::min(first + SampleRuns::kGroupRuns, runs);
		Vec2 lower = out.runCentre[first], upper = lower;
		for (int g = first; g < last; ++g)
		{
			const Vec2 c = out.runCentre[g];
			const double r = out.runRadius[g];
			lower = Vec2(std::min(lower.x, c.x - r), std::min(lower.y, c.y - r));
			upper = Vec2(std::max(upper.x, c.x + r), std::max(upper.y, c.y + r));
		}
		const Vec2 centre = 0.5 * (lower + upper);
		double radius = 0.0;
		for (int g = first; g < last; ++g)
			radius = std::max(radius, Distance(centre, out.runCentre[g]) + out.runRadius[g]);
		out.groupCentre.push_back(centre);
		out.groupRadius.push_back(radius);
	}
	return out;
}

// The shape's cache of run hierarchies (its private members, this struct its friend).
struct SampleRunsCache
{
	static const SampleRuns& Get(const Shape& shape, int count)
	{
		// Entries are never removed, so a pointer to one stays valid with the shape.
		const SampleRuns* last = shape.m_lastRuns.load(std::memory_order_acquire);
		if (last && last->count == count)
			return *last;
		const SurfaceSamples& samples = shape.SamplesRef(count); // (takes the lock itself)
		std::lock_guard<std::mutex> lock(shape.m_sampleMutex);
		const SampleRuns* found = nullptr;
		for (const auto& entry : shape.m_runs)
			if (entry->count == count)
				found = entry.get();
		if (!found)
		{
			auto made = std::make_shared<SampleRuns>(BuildSampleRuns(samples));
			made->count = count;
			found = made.get();
			shape.m_runs.push_back(std::move(made));
		}
		shape.m_lastRuns.store(found, std::memory_order_release);
		return *found;
	}
};

const SampleRuns& SampleRunsOf(const Shape& shape, int count)
{
	return SampleRunsCache::Get(shape, count);
}

} // namespace b2a

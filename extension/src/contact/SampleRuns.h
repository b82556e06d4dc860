// b2analytic: the grid method's hierarchy over a shape's surface samples (internal).
#pragma once

#include "b2analytic/Shape.h"

#include <vector>

namespace b2a
{

/// Discs and boxes over runs of a shape's surface samples, and discs over groups of runs: what
/// the grid method bounds A's level over before it evaluates the samples (branch and bound).
/// Made once per shape and sample count, on the first grid solve that asks (SampleRunsOf).
struct SampleRuns
{
	/// Arcs per run.
	static constexpr int kRunLength = 8;
	/// Runs per group.
	static constexpr int kGroupRuns = 4;

	int count = 0;                          ///< the sample count asked for (Shape::Samples' argument)
	const SurfaceSamples* samples = nullptr; ///< those samples (the shape's, valid as long as it)
	/// Discs enclosing runs of the curve: run g spans the arcs from sample g·kRunLength to sample
	/// (g+1)·kRunLength (cyclic; the last run may be shorter). The radius covers the samples and
	/// the measured deviation of the curve between them, twice over. The grid method skips a run
	/// where a lower bound of A's level over its disc exceeds a level it has already found.
	std::vector<Vec2> runCentre;
	std::vector<double> runRadius; ///< radius of each run's disc
	/// Boxes enclosing the runs, each aligned with its run's chord (first sample to last) and
	/// holding the samples and, by the discs' rule, twice the curve's measured deviation from
	/// them: a run's arc bends little over its length, so the box is thin where the disc is
	/// round, and a bound over it need not cover the disc's far sides.
	std::vector<OrientedBox> runBox;
	/// Discs enclosing groups of runs: group G holds runs G·kGroupRuns … (G+1)·kGroupRuns − 1
	/// (the last group may hold fewer) and its disc encloses theirs. The grid method bounds the
	/// groups first and a run's own disc only where its group's bound does not rule it out.
	std::vector<Vec2> groupCentre;
	std::vector<double> groupRadius; ///< radius of each group's disc
};

/// The run hierarchy over `samples`.
SampleRuns BuildSampleRuns(const SurfaceSamples& samples);

/// The shape's samples of `count` (Shape::Samples) with their run hierarchy, made on first use
/// and kept with the shape. Once made, the last count asked for is one atomic load away (no
/// lock, no reference count: threads that share the shape do not queue on it).
const SampleRuns& SampleRunsOf(const Shape& shape, int count);

} // namespace b2a

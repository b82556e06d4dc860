// b2analytic: the grid method's one-sided solve, handing back what the contact needs again (internal).
#pragma once

#include "b2analytic/CommonLevel.h"

#include <cstdint>

namespace b2a
{

/// SolveGridScale, writing A's body-frame gradient at the answer's point into *bodyGradientA
/// (when the solve succeeds): the solve computes it for the normal, and the grid's contact
/// needs it again for its normal, its crossing and its one-side test.
LevelResult SolveGridScale(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, const SolverOptions& options,
                           double levelB, Vec2* bodyGradientA);

/// The levels of A at B's surface samples that this thread's last grid solve evaluated, and the
/// lower bounds it took over the discs of B's SampleRuns.
struct GridLevels
{
	const double* value = nullptr;         ///< A's level at sample k where stamp[k] == generation
	const std::uint32_t* stamp = nullptr;  ///< per sample
	std::uint32_t generation = 0;          ///< the solve's stamp
	/// A's lower bound over each group's disc of B's SampleRuns (LevelBounds::LevelLowerBounds),
	/// where the solve bounded every group; else null.
	const double* groupBound = nullptr;
	/// A's lower bound over run r's disc, at least its group's, where runStamp[r] == generation.
	const double* runBound = nullptr;
	const std::uint32_t* runStamp = nullptr; ///< per run
	/// Per run of B's SampleRuns: nonzero where the solve evaluated the run whole (every level of
	/// its samples, both ends included, stamped).
	const char* scanned = nullptr;
	/// A's TightLevelLowerBound over run r's box (B's SampleRuns' runBox, in A's frame), where
	/// boxStamp[r] == generation.
	const double* boxBound = nullptr;
	const std::uint32_t* boxStamp = nullptr; ///< per run
};

/// Where this thread's last grid solve (SolveGridScale, succeeded) rescaled A onto B's own
/// surface through `samples` (B's, SampleRunsOf's) with the relative pose bInA (B's body to
/// A's, Relative(pa, pb), bit for bit): the levels it evaluated, each A's Level at
/// ToWorld(bInA, samples.point[k]), and its bounds, into *out, and true. False elsewhere. Valid until the
/// thread's next grid solve.
bool LastGridLevels(const Shape& a, const Shape& b, const Pose& bInA, const SurfaceSamples& samples, GridLevels* out);

} // namespace b2a

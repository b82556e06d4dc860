// b2a_bench_scenes --game: the bucket scene of b2a_demo_game in a game's units, each family of
// particles alone and the four mixed, analytic against the same scene of Box2D 8-gons.
#pragma once

#include "common/DemoCommon.h"

#include <string>
#include <vector>

namespace b2a::bench
{
/// What the game scenes run.
struct GameSceneOptions
{
	std::vector<int> counts;           ///< particles per scene (the bucket widens as sqrt(N/300))
	std::vector<std::string> families; ///< GameFamilyNames() to run
	int steps = 0;                     ///< steps of each run (60 a second), all timed
	int repeats = 0;                   ///< runs of each variant, alternated; medians reported
	std::string only;                  ///< "analytic" or "polygon8": run that variant alone (for profiles)
};

/// The help text of the game scenes, for b2a_bench_scenes --help.
extern const char* kGameScenesHelp;

/// Runs the game scenes, writes DIR/game.csv, DIR/game.md and DIR/game.json, prints a one-line
/// summary; returns 0, or 1 when a particle was lost or became non-finite.
int RunGameScenes(const demo::DemoOptions& opt, const GameSceneOptions& options, demo::Progress& progress);

} // namespace b2a::bench

#pragma once
// The options of a movement covering (--agent-reach and its companions),
// shared by `decompose` and `audit`, and the seeds file they read.

#include "hullcover/covering/movement_covering.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace hullcover::app {

/// The command line's view of MovementOptions.
struct MovementCliOptions {
  std::string reach; ///< "", "walk" or "fly"; "" = no movement covering
  std::optional<double> slop, height, climb;
  double max_slope = kDefaultMaxSlopeDegrees;
  std::string up = "+y";
  std::string seeds_path;
};

/// Most seeds a --reachable-from file may hold.
inline constexpr int kMostSeeds = 1 << 20;

/// Adds --agent-reach, --agent-slop, --agent-height, --agent-climb,
/// --max-slope, --up and --reachable-from to `cmd`.
void add_movement_options(CLI::App& cmd, MovementCliOptions& o);

/// The first movement option given without --agent-reach (which it would
/// not change), or empty.
std::string option_without_reach(const MovementCliOptions& o);

/// MovementOptions for agents of `radius`, with the seeds read from the
/// file; nothing (after a message on stderr) when the file is unreadable or
/// malformed.
std::optional<MovementOptions> movement_options_from(const MovementCliOptions& o, double radius);

} // namespace hullcover::app

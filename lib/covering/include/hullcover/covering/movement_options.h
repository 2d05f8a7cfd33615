#pragma once
/// \file movement_options.h
/// How to make a movement covering (MovementOptions, with the defaults and
/// limits every option takes) and what one counted (MovementStatistics).
/// Kept apart from movement_covering.h so the decomposer's parts, which
/// read both, do not depend on the result they feed.

#include "hullcover/geometry/status.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace hullcover {

/// Where an agent can be.
enum class AgentReach {
  /// Standing on walkable faces (slope at most max_slope_degrees from up),
  /// stepping up at most `climb`, and dropping straight down off ledges.
  walk,
  /// Anywhere at clearance >= r connected to a seed through such points: a
  /// superset of walking.
  fly,
};

/// The slop E defaults to the agent's radius over this: 0.02 m for a
/// 0.3 m agent, the penetration slop of Jolt Physics.
inline constexpr double kDefaultSlopPerRadius = 1.0 / 15.0;
/// The agent height H defaults to this many radii (1.8 m at 0.3 m).
inline constexpr double kDefaultHeightInRadii = 6.0;
/// The climb defaults to this many radii (0.4 m at 0.3 m, Recast's demo).
inline constexpr double kDefaultClimbInRadii = 4.0 / 3.0;
/// Walkable faces rise at most this many degrees (Recast's default).
inline constexpr double kDefaultMaxSlopeDegrees = 45.0;
/// The reach grid's cells are this many radii wide: small enough that no
/// cell next to a surface of any thickness holds a centre the agent could
/// occupy on the far side (docs/definitions-and-proofs.md), large enough to
/// stay small.
inline constexpr double kReachCellInRadii = 0.7;
/// The reach grid spans at most this many cells over the scene's box,
/// counted in whole blocks of 16^3 (about 10 bytes a block while it is
/// built: at most about 170 MB, and 8 more a block on the grid's outside
/// when a flyer starts beyond it). A scene that needs more at its radius is
/// refused with a message (a larger radius, or a part of the scene, fits).
inline constexpr long long kMostReachCells = 1LL << 36;
/// ... and holds at most this many one by one, a byte each while it is
/// built (1 GiB): the blocks near surfaces, where some cells may hold an
/// agent and some not (open air, solid ground and the space between a
/// world's maps cost nothing more).
inline constexpr long long kMostReachCellsHeld = 1LL << 30;

/// How to make a movement covering. Lengths in scene units.
struct MovementOptions {
  double radius = 0.0; ///< r > 0
  double slop = -1.0;  ///< E, 0 <= E < r; below 0: kDefaultSlopPerRadius x r
  AgentReach reach = AgentReach::walk;
  double height = -1.0;                               ///< walk: H >= 2 r; below 0: kDefaultHeightInRadii x r
  double climb = -1.0;                                ///< walk: >= 0; below 0: kDefaultClimbInRadii x r
  double max_slope_degrees = kDefaultMaxSlopeDegrees; ///< walk: in [0, 90)
  /// Up: one of the six axis directions (a unit vector with one non-zero
  /// entry).
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  /// Where agents start (spawn points): every agent centre reachable from
  /// one of them. Empty: every walkable region (fly: the space connected
  /// to one; a scene without walkable faces, all space at clearance >= r).
  std::vector<Eigen::Vector3d> seeds;
  int max_hull_vertices = 255; ///< >= 8
  int threads = 0;             ///< 0: every core; the covering does not depend on it
  /// The touchable faces are split into regions of at most this many
  /// (before an exact hull's faces join the region of its first), merged
  /// each on its own, at once on the threads, then across each cut between
  /// them, once both its sides are merged (>= 1).
  int faces_per_region = 512;
  /// Called now and then with the fraction of work done (0..1); may be empty.
  std::function<void(double)> progress;
};

/// What a movement covering counted (beside CoveringStatistics).
struct MovementStatistics {
  double radius = 0.0, slop = 0.0, height = 0.0, climb = 0.0; ///< as used
  AgentReach reach = AgentReach::walk;
  long long grid_cells = 0;      ///< cells of the reach grid
  long long reachable_cells = 0; ///< of which an agent centre may occupy
  double cell = 0.0;             ///< the grid's cell side, scene units
  int seeds = 0;                 ///< seeds used (given ones, or one per walkable face)
  int touchable_faces = 0;       ///< faces an agent may touch: the faces covered
  long long candidates = 0;      ///< hulls proven: the exact covering's hulls tried as groups, and merges tried
  long long merges = 0;          ///< merges made
  long long undecided = 0;       ///< hulls refused because their proof ran out of budget
  double seconds_reach = 0.0;    ///< the reach grid and touchable faces
  double seconds_exact = 0.0;    ///< the exact covering the merging starts from
  double seconds_merging = 0.0;
};

/// The agent MovementOptions describe, with every default filled in and
/// the up axis split out: what the decomposer and the movement audit both
/// work from.
struct AgentShape {
  double radius = 0.0;
  double slop = 0.0;
  double height = 0.0;
  double climb = 0.0;
  double min_up_cosine = 0.0; ///< a walkable face's normal . up is at least this
  int up_axis = 1;            ///< 0, 1 or 2
  double up_sign = 1.0;       ///< +1 or -1
  AgentReach reach = AgentReach::walk;
};

/// The agent of `options`, or `invalid_argument` naming the option out of
/// range (radius > 0; 2 `tol` <= slop < radius, `tol` the scene's largest
/// tolerance; height >= 2 radius; climb >= 0; slope in [0, 90); up an axis
/// direction).
Result<AgentShape> resolve_agent_shape(const MovementOptions& options, double tol);

} // namespace hullcover

#pragma once
/// \file character_controller.h
/// A kinematic character controller on hullcover's runtime: capsules that
/// walk at random and fall, moved by sweeps (time of impact, then sliding
/// along the contact plane) as a game server moves its players. Built only
/// on hullcover::bvh's public API (hull_world.h).
///
/// Conventions: lengths in scene units, times in seconds, speeds in scene
/// units per second. A character's position is its capsule's centre; the
/// capsule's axis points along `up`.

#include "hullcover/bvh/hull_world.h"
#include "hullcover/geometry/status.h"

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

namespace example_server {

/// How characters are shaped and move. Every length in scene units.
struct ControllerSettings {
  /// Capsule radius, > 2 x skin (the inside check shrinks it by the skin).
  double radius = 0.4;
  /// Half the capsule's axis segment (between its end spheres' centres), >= 0.
  double half_height = 0.5;
  /// Gap kept between a character and every hull after a move, > 0: the
  /// slack that keeps rounding from ever placing a capsule inside a hull.
  double skin = 0.02;
  /// Unit vector against gravity; the capsule's axis.
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  /// Walking speed along the ground, scene units per second, >= 0.
  double walk_speed = 3.0;
  /// Acceleration of falling, scene units per second squared, >= 0.
  double gravity = 9.81;
  /// Fastest fall, scene units per second, >= 0.
  double terminal_fall_speed = 20.0;
  /// One simulation step, seconds, > 0.
  double time_step = 1.0 / 60.0;
  /// A character whose position along `up` drops below this (scene units)
  /// has fallen out of the level and is put back at its start.
  double respawn_below = -1e30;
};

/// Queries one thread ran, by kind, and what the controller did with them.
struct QueryCounts {
  std::int64_t sweeps = 0;     ///< HullWorld::sweep calls
  std::int64_t contacts = 0;   ///< HullWorld::contacts calls (penetration checks)
  std::int64_t overlaps = 0;   ///< HullWorld::overlap calls (the final inside check)
  std::int64_t sweep_hits = 0; ///< sweeps that met a hull (each followed by a slide)
  std::int64_t recoveries = 0; ///< contacts that found a capsule inside a hull and pushed it out
  std::int64_t respawns = 0;   ///< characters that fell out of the level and were put back
  std::int64_t steps = 0;      ///< character steps taken

  /// Every query, of every kind.
  std::int64_t queries() const { return sweeps + contacts + overlaps; }
  void add(const QueryCounts& other);
};

/// One character: its own state and its own random stream, so a thread that
/// owns it needs no lock and a run is repeatable from its seed.
struct Character {
  int id = 0;                                         ///< index in the whole run
  Eigen::Vector3d start = Eigen::Vector3d::Zero();    ///< free start position (capsule centre)
  Eigen::Vector3d position = Eigen::Vector3d::Zero(); ///< current capsule centre
  double heading = 0.0;                               ///< walking direction, radians in the ground plane
  double fall_speed = 0.0;                            ///< current speed down, >= 0
  double path_length = 0.0;                           ///< scene units moved in all, respawns not counted
  std::mt19937_64 random;                             ///< this character's random walk
};

/// Moves characters through a world shared read-only between threads.
class CharacterController {
public:
  /// `world` must outlive the controller.
  CharacterController(const hullcover::bvh::HullWorld& world, const ControllerSettings& settings);

  /// One time step of `character`: turn a little at random, fall under
  /// gravity, sweep the capsule along the motion, stop a skin short of the
  /// first hull hit and slide the rest along that hull's surface (a few
  /// times at most), then check for penetration with a contacts query.
  /// Fails only when a query does (its Status).
  [[nodiscard]] hullcover::Status step(Character& character, QueryCounts& counts) const;

  /// The hulls a capsule shrunk by the skin overlaps at the character's
  /// position: empty unless the controller let it end inside a hull.
  [[nodiscard]] hullcover::Status hulls_inside(const Character& character, std::vector<int>& hulls,
                                               QueryCounts& counts) const;

  /// Whether a capsule (grown by the skin) centred at `position` is clear of
  /// every hull: where a character may start.
  [[nodiscard]] hullcover::Status is_free(const Eigen::Vector3d& position, bool& free) const;

  const ControllerSettings& settings() const { return settings_; }

private:
  const hullcover::bvh::HullWorld& world_;
  ControllerSettings settings_;
  Eigen::Isometry3d upright_;           // the capsule's rotation: local z to `up`
  Eigen::Vector3d ground_x_, ground_y_; // unit, spanning the ground plane

  Eigen::Isometry3d pose_at(const Eigen::Vector3d& position) const;
  /// Sweeps and slides `character` by `motion`; sets `grounded` when a hull
  /// it met faces up enough to stand on.
  hullcover::Status move_and_slide(Character& character, Eigen::Vector3d motion, bool& grounded,
                                   QueryCounts& counts) const;
};

/// Up to `count` free start positions for characters, chosen from `seed`
/// alone: a point in the world's box, dropped by a ray onto the surface below
/// it (one that can be stood on), lifted so the capsule stands a skin above,
/// kept when is_free says so. Fails with `invalid_argument` when too few are
/// found after many tries (a capsule too large for the level).
hullcover::Status find_start_positions(const hullcover::bvh::HullWorld& world, const CharacterController& controller,
                                       int count, std::uint64_t seed, std::vector<Eigen::Vector3d>& positions);

/// The box holding every hull of the world (scene units).
hullcover::Aabb world_bounds(const hullcover::bvh::HullWorld& world);

} // namespace example_server

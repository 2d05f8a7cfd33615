#pragma once
/// \file reach_grid.h
/// The reach grid: a superset, cell by cell, of the centres an agent can
/// occupy (docs/definitions-and-proofs.md, "Movement coverings"). A cell is
/// kept when it may hold a reachable centre; a cell left out holds none.
/// Exact where it matters: hulls are never judged on cells alone, only
/// cleared by them (movement_validity.h decides the rest with distances).

#include "movement/scene_clearance.h"

#include "hullcover/covering/movement_options.h"

#include <cstdint>
#include <vector>

namespace hullcover::detail {

/// A grid of cubes over the scene's box grown by the radius and a cell.
class ReachGrid {
public:
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(); ///< lowest corner of cell (0, 0, 0)
  double cell = 0.0;                                ///< side of a cell, scene units
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();   ///< cells along x, y, z
  int seeds_used = 0;                               ///< seeds in cells an agent may occupy

  long long cell_count() const { return static_cast<long long>(dims.x()) * dims.y() * dims.z(); }
  long long index(int i, int j, int k) const { return (static_cast<long long>(k) * dims.y() + j) * dims.x() + i; }
  Eigen::Vector3d centre(int i, int j, int k) const {
    return origin + (Eigen::Vector3d(i, j, k).array() + 0.5).matrix() * cell;
  }
  /// Half the diagonal of a cell.
  double half_diagonal() const;
  bool reachable(long long index) const { return reachable_[index] != 0; }
  /// Whether the cell holding `p` may hold a reachable centre (true outside the grid).
  bool reachable_at(const Eigen::Vector3d& p) const;
  /// Whether some cell meeting `box` may hold a reachable centre (true when
  /// the box leaves the grid).
  bool any_reachable(const Aabb& box) const;
  long long reachable_count() const;

  /// Sets the cells that may hold a reachable centre (one byte each) and
  /// counts them per brick, for any_reachable.
  void set_reachable(std::vector<std::uint8_t> reachable);

  /// Cells per side of a brick (the coarse level any_reachable walks first).
  static constexpr int kBrick = 8;

private:
  std::vector<std::uint8_t> reachable_;
  std::vector<std::uint16_t> brick_counts_;
  Eigen::Vector3i bricks_ = Eigen::Vector3i::Zero();
};

/// The reach grid of `mesh` for `agent`, from `seeds` (each already checked
/// to have clearance >= r; empty: all clear space, flying). Fails with
/// `limit_exceeded` when the grid would exceed kMostReachCells, and, when
/// `seeds_given` (the user's spawn points), with `invalid_argument` for a
/// seed no agent of this reach occupies; default seeds there are passed
/// over (a walkable face under a low ceiling).
Result<ReachGrid> build_reach_grid(const Mesh& mesh, const SceneClearance& clearance, const AgentShape& agent,
                                   const std::vector<Eigen::Vector3d>& seeds, bool seeds_given, int threads);

/// Whether face `face` may be touched by an agent: some reachable cell lies
/// within r of it (the cell's centre within r plus half its diagonal).
bool face_may_be_touched(const ReachGrid& grid, const SceneClearance& clearance, const AgentShape& agent, int face);

/// The default seeds: over each walkable face, the points r (and 2 tol)
/// in front of its centroid and of the middles between the centroid and
/// its corners, where their clearance is at least r.
std::vector<Eigen::Vector3d> default_seeds(const SceneClearance& clearance, const AgentShape& agent, double tol);

/// Whether triangle `face` is walkable for `agent` (its normal within the
/// slope of up). Zero-area faces are not.
bool is_walkable(const Mesh& mesh, const AgentShape& agent, int face);

} // namespace hullcover::detail

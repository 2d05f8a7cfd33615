#pragma once
/// \file reach_cells.h
/// The reach grid's cells (reach_grid.h builds them): cubes over the scene,
/// each kept when it may hold a reachable agent centre, with the queries
/// the proofs ask of them.

#include "hullcover/geometry/aabb.h"

#include <Eigen/Core>

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
  bool reachable(long long index) const { return (reachable_[index >> 6] >> (index & 63)) & 1u; }
  /// Whether the cell holding `p` may hold a reachable centre (true outside the grid).
  bool reachable_at(const Eigen::Vector3d& p) const;
  /// Whether some cell meeting `box` may hold a reachable centre (true when
  /// the box leaves the grid).
  bool any_reachable(const Aabb& box) const;
  long long reachable_count() const;

  /// Sets the cells that may hold a reachable centre (one byte each, kept
  /// as one bit each: the proofs ask at scattered points, and a grid eight
  /// times smaller stays in cache) and counts them per brick, for
  /// any_reachable.
  void set_reachable(std::vector<std::uint8_t> reachable);

  /// Cells per side of a brick (the coarse level any_reachable walks first).
  static constexpr int kBrick = 8;

private:
  std::vector<std::uint64_t> reachable_; // bit (index & 63) of word index >> 6
  std::vector<std::uint16_t> brick_counts_;
  Eigen::Vector3i bricks_ = Eigen::Vector3i::Zero();
};

} // namespace hullcover::detail

#pragma once
/// \file reach_cells.h
/// The reach grid's cells (reach_grid.h builds them): cubes over the scene,
/// each kept when it may hold a reachable agent centre, with the queries
/// the proofs ask of them. The cells are held in blocks of kReachBlock a
/// side, and only a block with some cells kept and some not holds a bit per
/// cell: a level's open air, its solid ground and the empty space between
/// the maps of a world cost one number a block.

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/block_bytes.h"
#include "movement/oriented_box.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace hullcover::detail {

/// Cells per side of a block of the reach grid (a power of 2): the blocks
/// of its marks while it is built (block_bytes.h).
inline constexpr int kReachBlock = BlockBytes::kSide;
/// Cells in a block.
inline constexpr int kReachBlockCells = kReachBlock * kReachBlock * kReachBlock;

/// An oriented box whose bounding box meets at most this many cells is
/// tested against each kept one (ReachGrid::any_reachable).
inline constexpr int kMostCellsTestedOneByOne = 64;

/// What a block of the reach grid holds: none of its cells kept, all of
/// them, or (a number >= 0) the block's own bits at that slot.
inline constexpr std::int32_t kNoCellKept = -1;
inline constexpr std::int32_t kEveryCellKept = -2;

/// A grid of cubes over the scene's box grown by the radius and a cell.
class ReachGrid {
public:
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(); ///< lowest corner of cell (0, 0, 0)
  double cell = 0.0;                                ///< side of a cell, scene units
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();   ///< cells along x, y, z
  int seeds_used = 0;                               ///< seeds in cells an agent may occupy

  long long cell_count() const { return static_cast<long long>(dims.x()) * dims.y() * dims.z(); }
  Eigen::Vector3d centre(int i, int j, int k) const {
    return origin + (Eigen::Vector3d(i, j, k).array() + 0.5).matrix() * cell;
  }
  /// Half the diagonal of a cell.
  double half_diagonal() const;
  /// Whether cell (i, j, k) of the grid may hold a reachable centre.
  bool reachable(int i, int j, int k) const {
    const std::int32_t held = blocks_[block_of(i, j, k)];
    if (held < 0) return held == kEveryCellKept;
    const int at = bit_in_block(i, j, k);
    return (bits_[static_cast<size_t>(held) * kWordsPerBlock + (at >> 6)] >> (at & 63)) & 1u;
  }
  /// Whether the cell holding `p` may hold a reachable centre (true outside the grid).
  bool reachable_at(const Eigen::Vector3d& p) const;
  /// Whether some cell meeting `box` may hold a reachable centre (true when
  /// the box leaves the grid).
  bool any_reachable(const Aabb& box) const;
  /// The same for a box along any axes: its bounding box first, then, when
  /// that meets a cell that may and at most kMostCellsTestedOneByOne cells
  /// in all, each of those cells against the box itself (a slanted box's
  /// bounding box meets cells it does not).
  bool any_reachable(const OrientedBox& box) const;
  long long reachable_count() const { return reachable_count_; }
  /// Cells held one bit each (in blocks partly kept).
  long long cells_held() const { return static_cast<long long>(bits_.size()) * 64; }

  /// Blocks along x, y, z.
  Eigen::Vector3i block_dims() const { return (dims.array() + kReachBlock - 1) / kReachBlock; }
  /// Sizes the blocks for `dims`, no cell kept.
  void clear_blocks();
  /// Keeps every cell of block `block` (its index along x, y, z), or none
  /// (`kept`). Each block is set once, after clear_blocks.
  void set_block(const Eigen::Vector3i& block, bool kept);
  /// Keeps the cells of block `block` whose flag in `kept` (kReachBlockCells
  /// flags in the block's own order, x fastest) is not zero.
  void set_block_cells(const Eigen::Vector3i& block, const std::uint8_t* kept);

private:
  static constexpr int kWordsPerBlock = kReachBlockCells / 64;
  size_t block_of(int i, int j, int k) const {
    return (static_cast<size_t>(k / kReachBlock) * block_dims_.y() + j / kReachBlock) * block_dims_.x() +
           i / kReachBlock;
  }
  static int bit_in_block(int i, int j, int k) {
    return ((k % kReachBlock) * kReachBlock + j % kReachBlock) * kReachBlock + i % kReachBlock;
  }
  // One row of a block (kReachBlock cells along x) from bit `lo` to `hi`
  // (in the row) holds a kept cell.
  bool row_has_kept(std::int32_t held, int j, int k, int lo, int hi) const;

  std::vector<std::int32_t> blocks_; // per block: kNoCellKept, kEveryCellKept or its slot in bits_
  std::vector<std::uint64_t> bits_;  // kWordsPerBlock words per slot, bit bit_in_block(...)
  Eigen::Vector3i block_dims_ = Eigen::Vector3i::Zero();
  long long reachable_count_ = 0;
};

} // namespace hullcover::detail

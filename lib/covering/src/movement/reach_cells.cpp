#include "movement/reach_cells.h"

#include <algorithm>
#include <cmath>

namespace hullcover::detail {

double ReachGrid::half_diagonal() const { return 0.5 * cell * std::sqrt(3.0); }

void ReachGrid::clear_blocks() {
  block_dims_ = block_dims();
  blocks_.assign(static_cast<size_t>(block_dims_.x()) * block_dims_.y() * block_dims_.z(), kNoCellKept);
  bits_.clear();
  reachable_count_ = 0;
}

void ReachGrid::set_block(const Eigen::Vector3i& block, bool kept) {
  const Eigen::Vector3i lo = block * kReachBlock;
  const Eigen::Vector3i hi = (lo.array() + kReachBlock).min(dims.array());
  blocks_[block_of(lo.x(), lo.y(), lo.z())] = kept ? kEveryCellKept : kNoCellKept;
  if (kept) reachable_count_ += static_cast<long long>(hi.x() - lo.x()) * (hi.y() - lo.y()) * (hi.z() - lo.z());
}

void ReachGrid::set_block_cells(const Eigen::Vector3i& block, const std::uint8_t* kept) {
  const Eigen::Vector3i lo = block * kReachBlock;
  const Eigen::Vector3i hi = (lo.array() + kReachBlock).min(dims.array());
  const size_t b = block_of(lo.x(), lo.y(), lo.z());
  // Cells beyond the grid (in its last blocks) are never asked; only the
  // grid's own cells are counted.
  long long count = 0;
  const std::int32_t slot = static_cast<std::int32_t>(bits_.size() / kWordsPerBlock);
  bits_.resize(bits_.size() + kWordsPerBlock, 0);
  std::uint64_t* words = bits_.data() + static_cast<size_t>(slot) * kWordsPerBlock;
  for (int k = lo.z(); k < hi.z(); ++k)
    for (int j = lo.y(); j < hi.y(); ++j)
      for (int i = lo.x(); i < hi.x(); ++i) {
        const int at = bit_in_block(i, j, k);
        if (!kept[at]) continue;
        words[at >> 6] |= std::uint64_t{1} << (at & 63);
        ++count;
      }
  reachable_count_ += count;
  const long long cells = static_cast<long long>(hi.x() - lo.x()) * (hi.y() - lo.y()) * (hi.z() - lo.z());
  if (count == 0 || count == cells) {
    // None or all: one number for the block, as a uniform one.
    bits_.resize(bits_.size() - kWordsPerBlock);
    blocks_[b] = count == 0 ? kNoCellKept : kEveryCellKept;
    return;
  }
  blocks_[b] = slot;
}

bool ReachGrid::reachable_at(const Eigen::Vector3d& p) const {
  Eigen::Vector3i c;
  for (int a = 0; a < 3; ++a) {
    // In the grid the quotient is not negative, so truncating it is its
    // floor (std::floor is a library call on baseline x86-64, and the
    // proofs ask this at every point they try).
    const double q = (p[a] - origin[a]) / cell;
    if (!(q >= 0.0 && q < dims[a])) return true;
    c[a] = static_cast<int>(q);
  }
  return reachable(c.x(), c.y(), c.z());
}

bool ReachGrid::any_reachable(const OrientedBox& box) const {
  const Aabb bounds = box.bounds();
  if (!any_reachable(bounds)) return false;
  if (reachable_at(box.centre)) return true; // the cell of its centre meets it
  // Within the grid: any_reachable(bounds) said a box leaving it may reach.
  Eigen::Vector3i lo, hi;
  for (int a = 0; a < 3; ++a) {
    const double l = (bounds.min[a] - origin[a]) / cell, h = (bounds.max[a] - origin[a]) / cell;
    lo[a] = static_cast<int>(l);
    hi[a] = static_cast<int>(h);
  }
  // Counted in 64 bits: a large box's cells would overflow an int.
  const Eigen::Matrix<long long, 3, 1> span = (hi - lo).cast<long long>().array() + 1;
  if (span.prod() > kMostCellsTestedOneByOne) return true;
  for (int k = lo.z(); k <= hi.z(); ++k)
    for (int j = lo.y(); j <= hi.y(); ++j)
      for (int i = lo.x(); i <= hi.x(); ++i)
        if (reachable(i, j, k) && !box.apart_from_cube(centre(i, j, k), 0.5 * cell)) return true;
  return false;
}

bool ReachGrid::row_has_kept(std::int32_t held, int j, int k, int lo, int hi) const {
  // A row is kReachBlock bits inside one word (kReachBlock divides 64).
  const int first = ((k % kReachBlock) * kReachBlock + j % kReachBlock) * kReachBlock;
  const std::uint64_t word = bits_[static_cast<size_t>(held) * kWordsPerBlock + (first >> 6)] >> (first & 63);
  const std::uint64_t mask = ((std::uint64_t{1} << (hi - lo + 1)) - 1) << lo;
  return (word & mask) != 0;
}

bool ReachGrid::any_reachable(const Aabb& box) const {
  Eigen::Vector3i lo, hi;
  for (int a = 0; a < 3; ++a) {
    const double l = (box.min[a] - origin[a]) / cell, h = (box.max[a] - origin[a]) / cell;
    if (!(l >= 0.0 && h < dims[a])) return true; // leaves the grid (or NaN): may reach
    if (h < l) return false;                     // an empty box meets no cell
    lo[a] = static_cast<int>(l);                 // the floors, as in reachable_at
    hi[a] = static_cast<int>(h);
  }
  const Eigen::Vector3i blo = lo / kReachBlock, bhi = hi / kReachBlock;
  for (int bk = blo.z(); bk <= bhi.z(); ++bk)
    for (int bj = blo.y(); bj <= bhi.y(); ++bj)
      for (int bi = blo.x(); bi <= bhi.x(); ++bi) {
        const std::int32_t held = blocks_[(static_cast<size_t>(bk) * block_dims_.y() + bj) * block_dims_.x() + bi];
        if (held == kNoCellKept) continue;
        if (held == kEveryCellKept) return true;
        const Eigen::Vector3i clo = lo.cwiseMax(Eigen::Vector3i(bi, bj, bk) * kReachBlock);
        const Eigen::Vector3i chi =
            hi.cwiseMin((Eigen::Vector3i(bi, bj, bk).array() + 1).matrix() * kReachBlock - Eigen::Vector3i::Ones());
        for (int k = clo.z(); k <= chi.z(); ++k)
          for (int j = clo.y(); j <= chi.y(); ++j)
            if (row_has_kept(held, j, k, clo.x() % kReachBlock, chi.x() % kReachBlock)) return true;
      }
  return false;
}

} // namespace hullcover::detail

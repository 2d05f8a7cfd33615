#include "movement/reach_cells.h"

#include <cmath>

namespace hullcover::detail {

double ReachGrid::half_diagonal() const { return 0.5 * cell * std::sqrt(3.0); }

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
  return reachable(index(c.x(), c.y(), c.z()));
}

void ReachGrid::set_reachable(std::vector<std::uint8_t> reachable) {
  reachable_.assign((reachable.size() + 63) / 64, 0);
  for (size_t i = 0; i < reachable.size(); ++i)
    if (reachable[i]) reachable_[i >> 6] |= std::uint64_t{1} << (i & 63);
  bricks_ = (dims.array() + kBrick - 1) / kBrick;
  brick_counts_.assign(static_cast<size_t>(bricks_.x()) * bricks_.y() * bricks_.z(), 0);
  for (int k = 0; k < dims.z(); ++k)
    for (int j = 0; j < dims.y(); ++j)
      for (int i = 0; i < dims.x(); ++i)
        if (reachable[index(i, j, k)])
          ++brick_counts_[(static_cast<size_t>(k / kBrick) * bricks_.y() + j / kBrick) * bricks_.x() + i / kBrick];
}

long long ReachGrid::reachable_count() const {
  long long n = 0;
  for (std::uint16_t c : brick_counts_) n += c;
  return n;
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
  const Eigen::Vector3i blo = lo / kBrick, bhi = hi / kBrick;
  for (int bk = blo.z(); bk <= bhi.z(); ++bk)
    for (int bj = blo.y(); bj <= bhi.y(); ++bj)
      for (int bi = blo.x(); bi <= bhi.x(); ++bi) {
        if (brick_counts_[(static_cast<size_t>(bk) * bricks_.y() + bj) * bricks_.x() + bi] == 0) continue;
        const Eigen::Vector3i clo = lo.cwiseMax(Eigen::Vector3i(bi, bj, bk) * kBrick);
        const Eigen::Vector3i chi =
            hi.cwiseMin((Eigen::Vector3i(bi, bj, bk).array() + 1).matrix() * kBrick - Eigen::Vector3i::Ones());
        for (int k = clo.z(); k <= chi.z(); ++k)
          for (int j = clo.y(); j <= chi.y(); ++j)
            for (int i = clo.x(); i <= chi.x(); ++i)
              if (reachable(index(i, j, k))) return true;
      }
  return false;
}

} // namespace hullcover::detail

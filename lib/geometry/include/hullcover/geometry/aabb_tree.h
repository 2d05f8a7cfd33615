#pragma once
/// \file aabb_tree.h
/// A static bounding-volume tree over boxes, for "which mesh elements are
/// near this hull" queries during the validity checks (paper 4.3: "we rely
/// on space partitioning to speed up this process").

#include "hullcover/geometry/aabb.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace hullcover {

/// Built once over a fixed list of boxes; answers box-overlap queries with
/// the indices of the boxes in that list.
class AabbTree {
public:
  AabbTree() = default;
  /// Builds over `boxes` (index i is reported for boxes[i]); empty boxes
  /// are never reported. O(n log n).
  explicit AabbTree(const std::vector<Aabb>& boxes);

  /// Appends to `out` the index of every box overlapping `query` (closed
  /// boxes: touching counts), in no particular order; nothing for an empty
  /// query.
  void overlapping(const Aabb& query, std::vector<int>& out) const;

  /// Calls `meet(i)` for the boxes that, grown by `margin`, the segment
  /// from-to passes through, nearest first as far as the tree tells, and
  /// skips boxes it enters later than the nearest meeting so far plus
  /// `slack`. `meet` returns where item i is met as a fraction s of the
  /// segment (s in [0, 1]), or anything above 1 + slack for not met.
  void nearest_along_segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double margin, double slack,
                             const std::function<double(int)>& meet) const;

  bool empty() const { return nodes_.empty(); }

private:
  struct Node {
    Aabb box;
    int first = 0;   ///< leaf: first item in items_
    int count = 0;   ///< leaf: number of items; inner node: 0
    int left = -1;   ///< inner node: children
    int right = -1;
  };
  int build(int begin, int end, const std::vector<Aabb>& boxes, std::vector<Eigen::Vector3d>& centres);

  std::vector<Node> nodes_;
  std::vector<int> items_;
  std::vector<Aabb> item_boxes_;
};

} // namespace hullcover

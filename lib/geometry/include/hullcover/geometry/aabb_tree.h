#pragma once
/// \file aabb_tree.h
/// A static bounding-volume tree over boxes, for "which mesh elements are
/// near this hull" queries during the validity checks (paper 4.3: "we rely
/// on space partitioning to speed up this process").

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/mappable_array.h"

#include <Eigen/Core>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace hullcover {

namespace detail {
struct AabbTreeStorage;
}

/// Built once over a fixed list of boxes; answers box-overlap queries with
/// the indices of the boxes in that list.
class AabbTree {
public:
  /// An empty tree: every query on it meets nothing.
  AabbTree() = default;
  /// Builds over `boxes` (index i is reported for boxes[i]); empty boxes
  /// are never reported. O(n log n).
  explicit AabbTree(const std::vector<Aabb>& boxes);

  /// Appends to `out` the index of every box overlapping `query` (closed
  /// boxes: touching counts), in no particular order; nothing for an empty
  /// query.
  void overlapping(const Aabb& query, std::vector<int>& out) const;

  /// Calls `stop(i)` for the boxes overlapping `query`, as `overlapping`
  /// lists them and in that order, until one returns true; returns whether
  /// one did. For "is any of them ...?" questions: the walk ends at the
  /// first yes instead of listing every box first.
  template <class Stop>
  bool any_overlapping(const Aabb& query, Stop&& stop) const;

  /// any_overlapping, which also passes over every subtree whose box (an
  /// inner node's, rounded outward) `outside(box)` says holds no item
  /// `stop` could say yes to: for questions with a test on a region that is
  /// cheaper than the test on each item in it (region_outside_interior:
  /// no vertex in a box outside a hull's plane is inside the hull). `stop`
  /// is then called for a subsequence of any_overlapping's calls, and the
  /// answer is the same whenever `outside` keeps its promise.
  template <class Outside, class Stop>
  bool any_overlapping_pruned(const Aabb& query, Outside&& outside, Stop&& stop) const;

  /// Calls `meet(i)` for the boxes that, grown by `margin`, the segment
  /// from-to passes through, nearest first as far as the tree tells, and
  /// skips boxes it enters later than the nearest meeting so far plus
  /// `slack`. `meet` (any callable taking the item's index) returns where
  /// item i is met as a fraction s of the segment (s in [0, 1]), or
  /// anything above 1 + slack for not met. A template, so that the ray
  /// casts of the validity checks (millions per scene) call `meet` inline.
  template <class Meet>
  void nearest_along_segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double margin, double slack,
                             Meet&& meet) const;

  /// The smallest squared distance from `p` to an item, as `distance2(i)`
  /// (any callable taking the item's index and returning its squared
  /// distance from p, never below its box's) tells, or limit * limit when
  /// no item is nearer than `limit`. Only items whose boxes lie no farther
  /// than the nearest found so far are asked, nearest box first as far as
  /// the tree tells: the answer is the minimum over every item within
  /// `limit`, whatever the order.
  template <class Distance2>
  double nearest_to_point(const Eigen::Vector3d& p, double limit, Distance2&& distance2) const;

  /// True when the tree holds no (non-empty) box.
  bool empty() const { return items_.empty(); }

private:
  // Writes a tree's arrays to a prepared scene file and views them there
  // (lib/covering/src/cells/prepared_scene_file.cpp).
  friend struct detail::AabbTreeStorage;

  /// A box in floats, rounded outward from the doubles it stands for: an
  /// inner node then fits one 64-byte cache line with both of its
  /// children's boxes, and the walks (memory-bound on large scenes) read
  /// half as much. Being outward, it can only make an overlap walk open
  /// more nodes, never fewer; items are always tested on their exact boxes.
  /// (A segment walk may take nodes in another order than exact boxes
  /// would give, so callers must not depend on the order of equal hits.)
  struct FloatBox {
    float min[3];
    float max[3];
  };
  static FloatBox outward(const Aabb& box);
  /// A child of an inner node: an inner node's index in nodes_, or a leaf,
  /// `count` items from items_[index].
  /// Plain data (no initialisers), so that a walk's stack of them is not
  /// cleared on every call: each walk is short, and there are millions.
  struct ChildRef {
    int index; ///< inner: index in nodes_; leaf: first item in items_
    int count; ///< leaf: number of items (> 0); inner: 0
  };
  /// A child still to open on a segment walk, and where the segment enters
  /// its box.
  struct PendingChild {
    ChildRef ref;
    double entry;
  };
  /// An inner node: its two children and their boxes, read together, on a
  /// cache-line boundary so that one node is one memory read.
  struct alignas(64) Node {
    FloatBox box[2];
    ChildRef child[2];
  };
  static_assert(sizeof(Node) == 64 && alignof(Node) == 64, "an inner node fills one cache line");

  /// Whether the closed boxes meet; false for an empty query (its min is
  /// above its max).
  static bool overlaps(const FloatBox& box, const Aabb& query) {
    for (int axis = 0; axis < 3; ++axis)
      if (double(box.min[axis]) > query.max[axis] || double(box.max[axis]) < query.min[axis]) return false;
    return true;
  }
  /// Squared distance from `p` to `box` (an Aabb or a FloatBox); 0 inside.
  template <class Box>
  static double point_box_distance2(const Eigen::Vector3d& p, const Box& box) {
    double sum = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      const double below = double(box.min[axis]) - p[axis], above = p[axis] - double(box.max[axis]);
      const double gap = std::max({below, above, 0.0});
      sum += gap * gap;
    }
    return sum;
  }
  /// Slab test: where the segment from + s (to - from), s in [0, 1], enters
  /// `box` (an Aabb or a FloatBox) grown by `margin` (0 when it starts
  /// inside), or infinity when it misses it. `inverse` holds 1 / (to - from)
  /// per axis (infinite along an axis the segment does not move on).
  template <class Box>
  static double segment_box_entry(const Eigen::Vector3d& from, const Eigen::Vector3d& inverse, const Box& box,
                                  double margin);
  /// Deepest traversal stack: a walk holds at most the tree's depth + 1
  /// entries.
  static constexpr int kMaxDepth = 128;

  /// Below this depth nodes split where the surface-area cost is least;
  /// from it on, at the median, which halves the items: the depth then
  /// stays under kMaxSurfaceAreaDepth + log2(n) + 1 < kMaxDepth for any n
  /// an int counts.
  static constexpr int kMaxSurfaceAreaDepth = 64;
  static_assert(kMaxSurfaceAreaDepth + 32 < kMaxDepth, "a walk's stack holds the deepest tree");

  /// The arrays a build fills, moved into the tree when it is done.
  struct Building {
    std::vector<Node> nodes;
    std::vector<int> items;
  };
  /// Reorders items[begin, end) about the binned split plane of least
  /// surface-area cost and returns where the second part starts, or -1 when
  /// no plane parts them (every centre in one bin, or extents too large to
  /// bin).
  int surface_area_split(std::vector<int>& items, int begin, int end, const std::vector<Aabb>& boxes,
                         const std::vector<Eigen::Vector3d>& centres, const Aabb& centre_box);
  /// Builds the subtree over building.items[begin, end), `depth` levels
  /// below the root, into `building`; returns it and its box.
  ChildRef build(Building& building, int begin, int end, int depth, const std::vector<Aabb>& boxes,
                 const std::vector<Eigen::Vector3d>& centres, Aabb& box);

  MappableArray<Node> nodes_; ///< the inner nodes
  ChildRef root_{0, 0};       ///< the root: an inner node, or the only leaf
  FloatBox root_box_{};       ///< the root's box (a leaf's when the root is the only leaf)
  MappableArray<int> items_;
  MappableArray<Aabb> leaf_boxes_; ///< the box of items_[i] at i: read in the order the walks read them
};

template <class Box>
inline double AabbTree::segment_box_entry(const Eigen::Vector3d& from, const Eigen::Vector3d& inverse, const Box& box,
                                          double margin) {
  constexpr double kMiss = std::numeric_limits<double>::infinity();
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double low = double(box.min[axis]) - margin - from[axis];
    const double high = double(box.max[axis]) + margin - from[axis];
    if (std::isinf(inverse[axis])) {
      if (low > 0.0 || high < 0.0) return kMiss;
      continue;
    }
    double s0 = low * inverse[axis];
    double s1 = high * inverse[axis];
    if (s0 > s1) std::swap(s0, s1);
    enter = std::max(enter, s0);
    leave = std::min(leave, s1);
    if (enter > leave) return kMiss;
  }
  return enter;
}

template <class Stop>
bool AabbTree::any_overlapping(const Aabb& query, Stop&& stop) const {
  if (items_.empty() || query.empty() || !overlaps(root_box_, query)) return false;
  ChildRef stack[kMaxDepth];
  int top = 0;
  stack[top++] = root_;
  while (top > 0) {
    const ChildRef ref = stack[--top];
    if (ref.count > 0) {
      for (int i = ref.index; i < ref.index + ref.count; ++i)
        if (boxes_overlap(leaf_boxes_[i], query) && stop(items_[i])) return true;
      continue;
    }
    // Children in the order the walk has always taken them (right first),
    // so that callers see the same list.
    const Node& node = nodes_[ref.index];
    assert(top + 2 <= kMaxDepth);
    if (overlaps(node.box[0], query)) stack[top++] = node.child[0];
    if (overlaps(node.box[1], query)) stack[top++] = node.child[1];
  }
  return false;
}

template <class Outside, class Stop>
bool AabbTree::any_overlapping_pruned(const Aabb& query, Outside&& outside, Stop&& stop) const {
  if (items_.empty() || query.empty() || !overlaps(root_box_, query)) return false;
  const auto open = [&](const FloatBox& box) {
    return overlaps(box, query) && !outside(Aabb{Eigen::Vector3d(box.min[0], box.min[1], box.min[2]),
                                                 Eigen::Vector3d(box.max[0], box.max[1], box.max[2])});
  };
  if (!open(root_box_)) return false;
  ChildRef stack[kMaxDepth];
  int top = 0;
  stack[top++] = root_;
  while (top > 0) {
    const ChildRef ref = stack[--top];
    if (ref.count > 0) {
      for (int i = ref.index; i < ref.index + ref.count; ++i)
        if (boxes_overlap(leaf_boxes_[i], query) && stop(items_[i])) return true;
      continue;
    }
    const Node& node = nodes_[ref.index];
    assert(top + 2 <= kMaxDepth);
    if (open(node.box[0])) stack[top++] = node.child[0];
    if (open(node.box[1])) stack[top++] = node.child[1];
  }
  return false;
}

template <class Meet>
void AabbTree::nearest_along_segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double margin,
                                     double slack, Meet&& meet) const {
  if (items_.empty()) return;
  const Eigen::Vector3d delta = to - from;
  Eigen::Vector3d inverse;
  for (int axis = 0; axis < 3; ++axis)
    inverse[axis] = delta[axis] == 0.0 ? std::numeric_limits<double>::infinity() : 1.0 / delta[axis];
  // Each stack entry carries where the segment enters its box; the nearer
  // child goes on top, so boxes are mostly opened nearest first.
  PendingChild stack[kMaxDepth];
  int top = 0;
  const double root = segment_box_entry(from, inverse, root_box_, margin);
  if (std::isinf(root)) return;
  stack[top++] = {root_, root};
  double best = std::numeric_limits<double>::infinity();
  while (top > 0) {
    const PendingChild pending = stack[--top];
    const ChildRef ref = pending.ref;
    const double entry = pending.entry;
    if (entry > best + slack) continue;
    if (ref.count > 0) {
      for (int i = ref.index; i < ref.index + ref.count; ++i) {
        // A missed box's entry is infinite, and so is `best` until a first
        // meeting: test the miss on its own.
        const double item_entry = segment_box_entry(from, inverse, leaf_boxes_[i], margin);
        if (!std::isinf(item_entry) && item_entry <= best + slack) best = std::min(best, meet(items_[i]));
      }
      continue;
    }
    const Node& node = nodes_[ref.index];
    const double left = segment_box_entry(from, inverse, node.box[0], margin);
    const double right = segment_box_entry(from, inverse, node.box[1], margin);
    assert(top + 2 <= kMaxDepth);
    if (left <= right) {
      if (!std::isinf(right)) stack[top++] = {node.child[1], right};
      if (!std::isinf(left)) stack[top++] = {node.child[0], left};
    } else {
      if (!std::isinf(left)) stack[top++] = {node.child[0], left};
      stack[top++] = {node.child[1], right};
    }
  }
}

template <class Distance2>
double AabbTree::nearest_to_point(const Eigen::Vector3d& p, double limit, Distance2&& distance2) const {
  double best = limit * limit;
  if (items_.empty()) return best;
  // Each stack entry carries its box's squared distance from p; the nearer
  // child goes on top, so near items are met first and prune the rest.
  struct PendingNode {
    ChildRef ref;
    double distance2;
  };
  PendingNode stack[kMaxDepth];
  int top = 0;
  const double root = point_box_distance2(p, root_box_);
  if (root > best) return best;
  stack[top++] = {root_, root};
  while (top > 0) {
    const PendingNode pending = stack[--top];
    if (pending.distance2 > best) continue;
    const ChildRef ref = pending.ref;
    if (ref.count > 0) {
      for (int i = ref.index; i < ref.index + ref.count; ++i)
        if (point_box_distance2(p, leaf_boxes_[i]) <= best) best = std::min(best, distance2(items_[i]));
      continue;
    }
    const Node& node = nodes_[ref.index];
    const double left = point_box_distance2(p, node.box[0]);
    const double right = point_box_distance2(p, node.box[1]);
    assert(top + 2 <= kMaxDepth);
    if (left <= right) {
      if (right <= best) stack[top++] = {node.child[1], right};
      if (left <= best) stack[top++] = {node.child[0], left};
    } else {
      if (left <= best) stack[top++] = {node.child[0], left};
      if (right <= best) stack[top++] = {node.child[1], right};
    }
  }
  return best;
}

} // namespace hullcover

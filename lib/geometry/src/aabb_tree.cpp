#include "hullcover/geometry/aabb_tree.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace hullcover {
namespace {
constexpr int kLeafSize = 4;

// The greatest float at or below `value` (-infinity below the float range,
// the largest float above it: a double beyond the range has no float
// neighbour, and casting it is undefined).
float float_at_or_below(double value) {
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  constexpr double kLargest = std::numeric_limits<float>::max();
  if (value < -kLargest) return -kInfinity;
  if (value > kLargest) return std::numeric_limits<float>::max();
  const float nearest = static_cast<float>(value);
  return double(nearest) > value ? std::nextafter(nearest, -kInfinity) : nearest;
}
} // namespace

AabbTree::FloatBox AabbTree::outward(const Aabb& box) {
  FloatBox out{};
  for (int axis = 0; axis < 3; ++axis) {
    out.min[axis] = float_at_or_below(box.min[axis]);
    out.max[axis] = -float_at_or_below(-box.max[axis]);
  }
  return out;
}

AabbTree::AabbTree(const std::vector<Aabb>& boxes) {
  // Empty boxes overlap nothing: left out, they cannot stretch a node's box
  // to infinity (an empty box's min is +infinity) or give NaN centres.
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    if (!boxes[i].empty()) items_.push_back(i);
  if (items_.empty()) return;
  std::vector<Eigen::Vector3d> centres(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) centres[i] = 0.5 * (boxes[i].min + boxes[i].max);
  // Leaves hold 2 to kLeafSize items (median splits), so there are at most
  // n / 2 leaves and one inner node fewer.
  nodes_.reserve(items_.size() / 2 + 1);
  Aabb root_box;
  root_ = build(0, static_cast<int>(items_.size()), boxes, centres, root_box);
  root_box_ = outward(root_box);
  // A leaf's boxes side by side, in the order its items are listed.
  leaf_boxes_.reserve(items_.size());
  for (int item : items_) leaf_boxes_.push_back(boxes[item]);
}

AabbTree::ChildRef AabbTree::build(int begin, int end, const std::vector<Aabb>& boxes,
                                   const std::vector<Eigen::Vector3d>& centres, Aabb& box) {
  Aabb centre_box;
  for (int i = begin; i < end; ++i) {
    box.extend(boxes[items_[i]].min);
    box.extend(boxes[items_[i]].max);
    centre_box.extend(centres[items_[i]]);
  }
  if (end - begin <= kLeafSize) return ChildRef{begin, end - begin};
  // The parent before its children, the left child (when inner) right after
  // it: a walk going left reads the next cache line.
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::Index axis = 0;
  (centre_box.max - centre_box.min).maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end, [&](int a, int b) {
    return centres[a][axis] < centres[b][axis] || (centres[a][axis] == centres[b][axis] && a < b);
  });
  Aabb left_box, right_box;
  const ChildRef left = build(begin, middle, boxes, centres, left_box);
  const ChildRef right = build(middle, end, boxes, centres, right_box);
  Node& node = nodes_[index];
  node.box[0] = outward(left_box);
  node.box[1] = outward(right_box);
  node.child[0] = left;
  node.child[1] = right;
  return ChildRef{index, 0};
}

void AabbTree::overlapping(const Aabb& query, std::vector<int>& out) const {
  if (items_.empty() || query.empty() || !overlaps(root_box_, query)) return;
  ChildRef stack[kMaxDepth];
  int top = 0;
  stack[top++] = root_;
  while (top > 0) {
    const ChildRef ref = stack[--top];
    if (ref.count > 0) {
      for (int i = ref.index; i < ref.index + ref.count; ++i)
        if (boxes_overlap(leaf_boxes_[i], query)) out.push_back(items_[i]);
      continue;
    }
    // Children in the order the walk has always taken them (right first),
    // so that callers see the same list.
    const Node& node = nodes_[ref.index];
    assert(top + 2 <= kMaxDepth);
    if (overlaps(node.box[0], query)) stack[top++] = node.child[0];
    if (overlaps(node.box[1], query)) stack[top++] = node.child[1];
  }
}

} // namespace hullcover

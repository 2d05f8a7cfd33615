#include "hullcover/geometry/aabb_tree.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace hullcover {
namespace {
constexpr int kLeafSize = 4;
constexpr int kMaxDepth = 128;
// Slab test: where the segment from + s (to - from), s in [0, 1], enters
// `box` grown by `margin` (0 when it starts inside), or infinity when it
// misses it. `inverse` holds 1 / (to - from) per axis (infinite along an
// axis the segment does not move on).
double segment_box_entry(const Eigen::Vector3d& from, const Eigen::Vector3d& inverse, const Aabb& box, double margin) {
  constexpr double kMiss = std::numeric_limits<double>::infinity();
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double low = box.min[axis] - margin - from[axis];
    const double high = box.max[axis] + margin - from[axis];
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

Eigen::Vector3d inverse_of(const Eigen::Vector3d& delta) {
  Eigen::Vector3d inverse;
  for (int axis = 0; axis < 3; ++axis)
    inverse[axis] = delta[axis] == 0.0 ? std::numeric_limits<double>::infinity() : 1.0 / delta[axis];
  return inverse;
}

} // namespace

AabbTree::AabbTree(const std::vector<Aabb>& boxes) : item_boxes_(boxes) {
  // Empty boxes overlap nothing: left out, they cannot stretch a node's box
  // to infinity (an empty box's min is +infinity) or give NaN centres.
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    if (!boxes[i].empty()) items_.push_back(i);
  if (items_.empty()) return;
  std::vector<Eigen::Vector3d> centres(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) centres[i] = 0.5 * (boxes[i].min + boxes[i].max);
  nodes_.reserve(2 * items_.size() / kLeafSize + 2);
  build(0, static_cast<int>(items_.size()), boxes, centres);
}

int AabbTree::build(int begin, int end, const std::vector<Aabb>& boxes, std::vector<Eigen::Vector3d>& centres) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Aabb box, centre_box;
  for (int i = begin; i < end; ++i) {
    box.extend(boxes[items_[i]].min);
    box.extend(boxes[items_[i]].max);
    centre_box.extend(centres[items_[i]]);
  }
  nodes_[index].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  Eigen::Index axis = 0;
  (centre_box.max - centre_box.min).maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(items_.begin() + begin, items_.begin() + middle, items_.begin() + end, [&](int a, int b) {
    return centres[a][axis] < centres[b][axis] || (centres[a][axis] == centres[b][axis] && a < b);
  });
  const int left = build(begin, middle, boxes, centres);
  const int right = build(middle, end, boxes, centres);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

void AabbTree::overlapping(const Aabb& query, std::vector<int>& out) const {
  if (nodes_.empty() || query.empty()) return;
  // The tree is balanced (median splits), so its depth is about log2(n / 4):
  // a fixed stack of kMaxDepth entries holds any traversal.
  int stack[kMaxDepth];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int n = stack[--top];
    const Node& node = nodes_[n];
    if (!boxes_overlap(node.box, query)) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        if (boxes_overlap(item_boxes_[items_[i]], query)) out.push_back(items_[i]);
      continue;
    }
    assert(top + 2 <= kMaxDepth);
    stack[top++] = node.left;
    stack[top++] = node.right;
  }
}

void AabbTree::nearest_along_segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double margin,
                                     double slack, const std::function<double(int)>& meet) const {
  if (nodes_.empty()) return;
  const Eigen::Vector3d inverse = inverse_of(to - from);
  // Each stack entry carries where the segment enters its box; the nearer
  // child goes on top, so boxes are mostly opened nearest first.
  std::pair<int, double> stack[kMaxDepth];
  int top = 0;
  const double root = segment_box_entry(from, inverse, nodes_[0].box, margin);
  if (std::isinf(root)) return;
  stack[top++] = {0, root};
  double best = std::numeric_limits<double>::infinity();
  while (top > 0) {
    const auto [n, entry] = stack[--top];
    if (entry > best + slack) continue;
    const Node& node = nodes_[n];
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        // A missed box's entry is infinite, and so is `best` until a first
        // meeting: test the miss on its own.
        const double item_entry = segment_box_entry(from, inverse, item_boxes_[items_[i]], margin);
        if (!std::isinf(item_entry) && item_entry <= best + slack) best = std::min(best, meet(items_[i]));
      }
      continue;
    }
    const double left = segment_box_entry(from, inverse, nodes_[node.left].box, margin);
    const double right = segment_box_entry(from, inverse, nodes_[node.right].box, margin);
    assert(top + 2 <= kMaxDepth);
    if (left <= right) {
      if (!std::isinf(right)) stack[top++] = {node.right, right};
      if (!std::isinf(left)) stack[top++] = {node.left, left};
    } else {
      if (!std::isinf(left)) stack[top++] = {node.left, left};
      stack[top++] = {node.right, right};
    }
  }
}

} // namespace hullcover

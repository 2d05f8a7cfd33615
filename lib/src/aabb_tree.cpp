#include "hullcover/lib/aabb_tree.h"

#include <algorithm>
#include <cassert>
#include <numeric>

namespace hullcover {
namespace {
constexpr int kLeafSize = 4;
constexpr int kMaxDepth = 128;
// Slab test: does the segment from + s (to - from), s in [0, 1], meet `box`?
bool segment_meets_box(const Eigen::Vector3d& from, const Eigen::Vector3d& delta, const Aabb& box) {
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (delta[axis] == 0.0) {
      if (from[axis] < box.min[axis] || from[axis] > box.max[axis]) return false;
      continue;
    }
    double s0 = (box.min[axis] - from[axis]) / delta[axis];
    double s1 = (box.max[axis] - from[axis]) / delta[axis];
    if (s0 > s1) std::swap(s0, s1);
    enter = std::max(enter, s0);
    leave = std::min(leave, s1);
    if (enter > leave) return false;
  }
  return true;
}

} // namespace

AabbTree::AabbTree(const std::vector<Aabb>& boxes) : item_boxes_(boxes) {
  if (boxes.empty()) return;
  items_.resize(boxes.size());
  std::iota(items_.begin(), items_.end(), 0);
  std::vector<Eigen::Vector3d> centres(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) centres[i] = 0.5 * (boxes[i].min + boxes[i].max);
  nodes_.reserve(2 * boxes.size() / kLeafSize + 2);
  build(0, static_cast<int>(boxes.size()), boxes, centres);
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
  if (nodes_.empty()) return;
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

void AabbTree::along_segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double margin,
                             std::vector<int>& out) const {
  if (nodes_.empty()) return;
  const Eigen::Vector3d delta = to - from;
  int stack[kMaxDepth];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!segment_meets_box(from, delta, grown(node.box, margin))) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        if (segment_meets_box(from, delta, grown(item_boxes_[items_[i]], margin))) out.push_back(items_[i]);
      continue;
    }
    assert(top + 2 <= kMaxDepth);
    stack[top++] = node.left;
    stack[top++] = node.right;
  }
}

} // namespace hullcover

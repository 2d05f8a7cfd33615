#include "hullcover/geometry/aabb_tree.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace hullcover {
namespace {
constexpr int kLeafSize = 4;
} // namespace

AabbTree::AabbTree(const std::vector<Aabb>& boxes) {
  // Empty boxes overlap nothing: left out, they cannot stretch a node's box
  // to infinity (an empty box's min is +infinity) or give NaN centres.
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    if (!boxes[i].empty()) items_.push_back(i);
  if (items_.empty()) return;
  std::vector<Eigen::Vector3d> centres(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) centres[i] = 0.5 * (boxes[i].min + boxes[i].max);
  nodes_.reserve(2 * items_.size() / kLeafSize + 2);
  build(0, static_cast<int>(items_.size()), boxes, centres);
  // A leaf's boxes side by side, in the order its items are listed.
  leaf_boxes_.reserve(items_.size());
  for (int item : items_) leaf_boxes_.push_back(boxes[item]);
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
  int stack[kMaxDepth];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int n = stack[--top];
    const Node& node = nodes_[n];
    if (!boxes_overlap(node.box, query)) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        if (boxes_overlap(leaf_boxes_[i], query)) out.push_back(items_[i]);
      continue;
    }
    assert(top + 2 <= kMaxDepth);
    stack[top++] = node.left;
    stack[top++] = node.right;
  }
}

} // namespace hullcover

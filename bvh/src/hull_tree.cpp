#include "hull_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hullcover::bvh::detail {

struct HullTree::Item {
  Aabb box;
  Eigen::Vector3d centre;
  std::int32_t hull;
};

namespace {

// Bins per axis of the binned surface area heuristic: enough to place a
// split close to the best one, few enough that a build stays linear.
constexpr int kSplitBins = 32;
// Past this depth splits are at the median, so a tree over any boxes
// (nested ones can make every heuristic split lopsided) stays within
// this plus log2 of the hull count deep: bounded recursion and walk stacks.
constexpr size_t kHeuristicDepth = 40;

double half_area(const Aabb& box) {
  const Eigen::Vector3d e = (box.max - box.min).cwiseMax(0.0);
  return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
}

Aabb empty_box() {
  Aabb box;
  box.min.setConstant(std::numeric_limits<double>::infinity());
  box.max.setConstant(-std::numeric_limits<double>::infinity());
  return box;
}

void grow(Aabb& box, const Aabb& other) {
  box.min = box.min.cwiseMin(other.min);
  box.max = box.max.cwiseMax(other.max);
}

// The bin of a centre coordinate x among kSplitBins over [lo, lo + extent].
int bin_of(double x, double lo, double extent) {
  return std::min(kSplitBins - 1, static_cast<int>(kSplitBins * (x - lo) / extent));
}

// Splits items [begin, end) (at least two) in two and returns where the
// second part starts: the binned surface area heuristic's best plane of
// all three axes (a plane across the axis where the centres spread most
// is often not the cheapest: rays and spheres then open fewer nodes), or
// the middle when the centres coincide (both parts then non-empty all the
// same) or past the heuristic's depth.
template <typename Item>
size_t split(std::vector<Item>& items, size_t begin, size_t end, bool at_median) {
  Aabb centres = empty_box();
  for (size_t i = begin; i < end; ++i) {
    centres.min = centres.min.cwiseMin(items[i].centre);
    centres.max = centres.max.cwiseMax(items[i].centre);
  }
  int widest = 0;
  (centres.max - centres.min).maxCoeff(&widest);
  const size_t middle = begin + (end - begin) / 2;
  if (!((centres.max - centres.min)[widest] > 0.0)) {
    std::nth_element(items.begin() + begin, items.begin() + middle, items.begin() + end,
                     [](const Item& a, const Item& b) { return a.hull < b.hull; });
    return middle;
  }
  const auto at_middle = [&] {
    std::nth_element(items.begin() + begin, items.begin() + middle, items.begin() + end,
                     [widest](const Item& a, const Item& b) { return a.centre[widest] < b.centre[widest]; });
    return middle;
  };
  if (at_median) return at_middle();
  int best_axis = -1, best = -1;
  double best_cost = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = centres.min[axis], extent = centres.max[axis] - lo;
    if (!(extent > 0.0)) continue;
    Aabb bin_box[kSplitBins];
    size_t bin_count[kSplitBins] = {};
    for (Aabb& b : bin_box) b = empty_box();
    for (size_t i = begin; i < end; ++i) {
      const int b = bin_of(items[i].centre[axis], lo, extent);
      grow(bin_box[b], items[i].box);
      ++bin_count[b];
    }
    // Cost of each plane between bins: area times count on either side.
    double right_cost[kSplitBins] = {};
    Aabb right = empty_box();
    size_t right_count = 0;
    for (int b = kSplitBins - 1; b > 0; --b) {
      grow(right, bin_box[b]);
      right_count += bin_count[b];
      right_cost[b] = right_count ? half_area(right) * static_cast<double>(right_count) : 0.0;
    }
    Aabb left = empty_box();
    size_t left_count = 0;
    for (int b = 1; b < kSplitBins; ++b) {
      grow(left, bin_box[b - 1]);
      left_count += bin_count[b - 1];
      if (left_count == 0 || left_count == end - begin) continue;
      const double cost = half_area(left) * static_cast<double>(left_count) + right_cost[b];
      if (cost < best_cost) {
        best_cost = cost;
        best = b;
        best_axis = axis;
      }
    }
  }
  if (best < 0) return at_middle();
  const double lo = centres.min[best_axis], extent = centres.max[best_axis] - lo;
  const auto cut = std::partition(items.begin() + begin, items.begin() + end,
                                  [&](const Item& item) { return bin_of(item.centre[best_axis], lo, extent) < best; });
  return static_cast<size_t>(cut - items.begin());
}

} // namespace

namespace {
std::vector<Aabb> boxes_of(const std::vector<RuntimeHull>& hulls) {
  std::vector<Aabb> boxes;
  boxes.reserve(hulls.size());
  for (const RuntimeHull& hull : hulls) boxes.push_back(hull.box);
  return boxes;
}
} // namespace

HullTree::HullTree(const std::vector<RuntimeHull>& hulls) : HullTree(boxes_of(hulls)) {}

HullTree::HullTree(const std::vector<Aabb>& boxes) {
  if (boxes.empty()) throw std::invalid_argument("a hull tree needs at least one box");
  if (boxes.size() > static_cast<size_t>(std::numeric_limits<std::int32_t>::max() / 2))
    throw std::length_error("more hulls than a packed tree indexes");
  std::vector<Item> items(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i)
    items[i] = {boxes[i], 0.5 * (boxes[i].min + boxes[i].max), static_cast<std::int32_t>(i)};
  nodes_.reserve(boxes.size() / 2 + 1);
  build_node(items, 0, items.size(), 1);
  const WideNode& top = nodes_.front();
  bounds_ = empty_box();
  for (int i = 0; i < top.count; ++i)
    grow(bounds_, {Eigen::Vector3d(top.face[0][i], top.face[1][i], top.face[2][i]),
                   Eigen::Vector3d(top.face[3][i], top.face[4][i], top.face[5][i])});
}

std::int32_t HullTree::build_node(std::vector<Item>& items, size_t begin, size_t end, size_t depth) {
  height_ = std::max(height_, depth);
  // Up to four groups: the items split in two, and each part with more
  // than one item split again (a binary tree's two levels in one node).
  size_t cuts[5] = {begin, end, end, end, end};
  int groups = 1;
  const bool at_median = depth > kHeuristicDepth;
  if (end - begin > 1) {
    cuts[1] = split(items, begin, end, at_median);
    groups = 2;
    const size_t first = cuts[1] - begin, second = end - cuts[1];
    if (end - begin <= 4) {
      groups = static_cast<int>(end - begin); // one item per lane
      for (int g = 0; g <= groups; ++g) cuts[g] = begin + static_cast<size_t>(g);
    } else {
      size_t next[5] = {begin, 0, 0, 0, 0};
      int n = 1;
      if (first > 1) next[n++] = split(items, begin, cuts[1], at_median);
      next[n++] = cuts[1];
      if (second > 1) next[n++] = split(items, cuts[1], end, at_median);
      next[n] = end;
      groups = n;
      std::copy(next, next + n + 1, cuts);
    }
  }
  const std::int32_t at = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  nodes_[at].count = groups;
  for (int g = 0; g < groups; ++g) {
    Aabb box = empty_box();
    for (size_t i = cuts[g]; i < cuts[g + 1]; ++i) grow(box, items[i].box);
    const std::int32_t child =
        cuts[g + 1] - cuts[g] == 1 ? ~items[cuts[g]].hull : build_node(items, cuts[g], cuts[g + 1], depth + 1);
    WideNode& n = nodes_[at]; // after the recursion: nodes_ may have moved
    n.child[g] = child;
    n.face[0][g] = float_at_or_below(box.min[0]);
    n.face[1][g] = float_at_or_below(box.min[1]);
    n.face[2][g] = float_at_or_below(box.min[2]);
    n.face[3][g] = float_at_or_above(box.max[0]);
    n.face[4][g] = float_at_or_above(box.max[1]);
    n.face[5][g] = float_at_or_above(box.max[2]);
  }
  return at;
}

} // namespace hullcover::bvh::detail

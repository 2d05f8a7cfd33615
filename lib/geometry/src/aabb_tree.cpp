#include "hullcover/geometry/aabb_tree.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace hullcover {
namespace {
constexpr int kLeafSize = 4;
// Candidate split planes per axis: more finds slightly better splits, at a
// longer build.
constexpr int kSplitBins = 16;

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
  Building building;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    if (!boxes[i].empty()) building.items.push_back(i);
  if (building.items.empty()) return;
  std::vector<Eigen::Vector3d> centres(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) centres[i] = 0.5 * (boxes[i].min + boxes[i].max);
  // Median splits would give at most n / 2 leaves; a surface-area split may
  // leave one item alone, so this is a first guess, not a bound.
  building.nodes.reserve(building.items.size() / 2 + 1);
  Aabb root_box;
  root_ = build(building, 0, static_cast<int>(building.items.size()), 0, boxes, centres, root_box);
  root_box_ = outward(root_box);
  // A leaf's boxes side by side, in the order its items are listed.
  std::vector<Aabb> leaf_boxes;
  leaf_boxes.reserve(building.items.size());
  for (int item : building.items) leaf_boxes.push_back(boxes[item]);
  nodes_ = std::move(building.nodes);
  items_ = std::move(building.items);
  leaf_boxes_ = std::move(leaf_boxes);
}

namespace {
// Half the surface area of a box (0 when empty): what a split is priced by.
double half_area(const Aabb& box) {
  if (box.empty()) return 0.0;
  const Eigen::Vector3d extent = box.max - box.min;
  return extent.x() * extent.y() + extent.y() * extent.z() + extent.z() * extent.x();
}

// `box` grown to hold `other`; unchanged by an empty `other` (whose corners
// are infinities).
void extend_by_box(Aabb& box, const Aabb& other) {
  if (other.empty()) return;
  box.extend(other.min);
  box.extend(other.max);
}
} // namespace

int AabbTree::surface_area_split(std::vector<int>& items, int begin, int end, const std::vector<Aabb>& boxes,
                                 const std::vector<Eigen::Vector3d>& centres, const Aabb& centre_box) {
  // A line or a box meets a child about in proportion to its surface area,
  // so the split that minimises area x items on both sides opens the fewest
  // items per walk. Binned, as in most ray-tracing trees: kSplitBins
  // candidate planes per axis, each priced in one pass over the items.
  double best_cost = std::numeric_limits<double>::infinity();
  int best_axis = -1, best_bin = -1;
  const Eigen::Vector3d extent = centre_box.max - centre_box.min;
  const Eigen::Vector3d scale = Eigen::Vector3d::Constant(kSplitBins).cwiseQuotient(extent);
  // The bin of an item's centre on an axis; the top edge goes to the last
  // bin. Never cast outside an int's range: a box with infinite corners has
  // a NaN centre (left out of centre_box), and an extent below 16 / DBL_MAX
  // an infinite scale; both go to an end bin, the same in every pass.
  const auto bin_of = [&](int item, int axis) {
    const double at = (centres[item][axis] - centre_box.min[axis]) * scale[axis];
    if (at >= kSplitBins - 1) return kSplitBins - 1;
    return at > 0.0 ? static_cast<int>(at) : 0;
  };
  for (int axis = 0; axis < 3; ++axis) {
    // No plane along an axis the centres do not spread on, nor along one
    // too long for a double.
    if (!(extent[axis] > 0.0) || !std::isfinite(extent[axis])) continue;
    Aabb bin_box[kSplitBins];
    int bin_count[kSplitBins] = {};
    for (int i = begin; i < end; ++i) {
      const int bin = bin_of(items[i], axis);
      ++bin_count[bin];
      extend_by_box(bin_box[bin], boxes[items[i]]);
    }
    // Above each plane, swept from the top; below it, from the bottom.
    double above_area[kSplitBins] = {};
    int above_count[kSplitBins] = {};
    Aabb above;
    int count = 0;
    for (int bin = kSplitBins - 1; bin > 0; --bin) {
      extend_by_box(above, bin_box[bin]);
      count += bin_count[bin];
      above_area[bin] = half_area(above);
      above_count[bin] = count;
    }
    Aabb below;
    int below_count = 0;
    for (int bin = 0; bin + 1 < kSplitBins; ++bin) {
      extend_by_box(below, bin_box[bin]);
      below_count += bin_count[bin];
      if (below_count == 0 || above_count[bin + 1] == 0) continue;
      // A NaN cost (an infinite area) is never below the best.
      const double cost = half_area(below) * below_count + above_area[bin + 1] * above_count[bin + 1];
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_bin = bin;
      }
    }
  }
  if (best_axis < 0) return -1;
  const auto middle = std::partition(items.begin() + begin, items.begin() + end,
                                     [&](int item) { return bin_of(item, best_axis) <= best_bin; });
  return static_cast<int>(middle - items.begin());
}

AabbTree::ChildRef AabbTree::build(Building& building, int begin, int end, int depth, const std::vector<Aabb>& boxes,
                                   const std::vector<Eigen::Vector3d>& centres, Aabb& box) {
  Aabb centre_box;
  for (int i = begin; i < end; ++i) {
    extend_by_box(box, boxes[building.items[i]]);
    centre_box.extend(centres[building.items[i]]);
  }
  if (end - begin <= kLeafSize) return ChildRef{begin, end - begin};
  // The parent before its children, the left child (when inner) right after
  // it: a walk going left reads the next cache line.
  const int index = static_cast<int>(building.nodes.size());
  building.nodes.emplace_back();
  int middle =
      depth < kMaxSurfaceAreaDepth ? surface_area_split(building.items, begin, end, boxes, centres, centre_box) : -1;
  if (middle <= begin || middle >= end) {
    // All centres in one bin (or too deep): the median on the longest axis,
    // which halves the items and so bounds the depth.
    Eigen::Index axis = 0;
    (centre_box.max - centre_box.min).maxCoeff(&axis);
    middle = begin + (end - begin) / 2;
    std::nth_element(building.items.begin() + begin, building.items.begin() + middle, building.items.begin() + end,
                     [&](int a, int b) {
      return centres[a][axis] < centres[b][axis] || (centres[a][axis] == centres[b][axis] && a < b);
    });
  }
  Aabb left_box, right_box;
  const ChildRef left = build(building, begin, middle, depth + 1, boxes, centres, left_box);
  const ChildRef right = build(building, middle, end, depth + 1, boxes, centres, right_box);
  Node& node = building.nodes[index];
  node.box[0] = outward(left_box);
  node.box[1] = outward(right_box);
  node.child[0] = left;
  node.child[1] = right;
  return ChildRef{index, 0};
}

void AabbTree::overlapping(const Aabb& query, std::vector<int>& out) const {
  // The walk of any_overlapping, never stopped: the same boxes in the same
  // order (right child first, as the walk has always taken them).
  any_overlapping(query, [&out](int i) {
    out.push_back(i);
    return false;
  });
}

} // namespace hullcover

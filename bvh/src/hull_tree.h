#pragma once
// The broad phase of HullWorld (private to bvh/): FCL's dynamic AABB tree
// over each hull's exact box, built by FCL (Morton order), then packed into
// one array in depth-first order for the queries to walk directly: no
// callback, no virtual or library call, no allocation per query, 32 bytes a
// node. Boxes are kept as floats rounded outward, so a packed box holds
// FCL's box and a walk never misses a hull its exact box would find: box
// walks compare them with the query box rounded outward too, ray walks in
// double.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <algorithm>
#include <cstdint>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace fcl {
template <typename S>
class AABB;
namespace detail {
template <typename BV>
struct NodeBase;
} // namespace detail
} // namespace fcl

namespace hullcover::bvh::detail {

/// A node of FCL's dynamic AABB tree (fcl/broadphase/detail/hierarchy_tree.h).
using FclTreeNode = fcl::detail::NodeBase<fcl::AABB<double>>;

/// The hulls' boxes in FCL's dynamic AABB tree, packed for direct walks.
/// Immutable once built: any number of threads may walk it at once.
class HullTree {
public:
  /// Builds the tree over `hulls`' boxes (at least one hull).
  explicit HullTree(const std::vector<RuntimeHull>& hulls);
  /// Packs a tree FCL already holds, of height `height`, whose leaves' data
  /// point to their numbers (int): what visits are given.
  HullTree(const FclTreeNode& root, size_t height);

  /// Calls `visit(h)` for each hull h whose box meets the closed box `box`,
  /// in tree order, until a call returns true. Returns whether one did.
  template <typename Visit>
  bool find_in_box(const Aabb& box, Visit&& visit) const {
    return find_where(box, [](const PackedNode&) { return true; }, visit);
  }

  /// The same for the boxes within `radius` of `centre` (a sphere's
  /// candidates: tighter than its box at the corners). The leaf test allows
  /// kTouchingFraction of slack relative to the coordinates' size, far above
  /// the narrow phase's rounding, so it never drops a hull the sphere's
  /// contact would find.
  template <typename Visit>
  bool find_near_point(const Eigen::Vector3d& centre, double radius, Visit&& visit) const {
    const double reach = radius + kTouchingFraction * (1.0 + radius + centre.cwiseAbs().maxCoeff());
    Aabb box;
    box.min = centre.array() - reach;
    box.max = centre.array() + reach;
    return find_where(
        box,
        [&, reach2 = reach * reach](const PackedNode& leaf) {
          double d2 = 0.0;
          for (int k = 0; k < 3; ++k) {
            const double out = std::max({leaf.min[k] - centre[k], centre[k] - leaf.max[k], 0.0});
            d2 += out * out;
          }
          return d2 <= reach2;
        },
        visit);
  }

  /// Calls `visit(h, reach)` for each hull whose box the ray
  /// origin + t * direction meets for some t in [0, reach], nearer child
  /// boxes first. `visit` may shorten `reach` (to the best hit so far), which
  /// prunes the rest of the walk. `inverse` is 1 / direction, per axis.
  template <typename Visit>
  void walk_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& inverse, double& reach, Visit&& visit) const;

  /// The box of every hull (rounded outward to floats).
  Aabb bounds() const { return box_of(nodes_.front()); }

private:
  // A node of the packed tree. Node i's subtree is nodes i to after - 1; an
  // inner node's first child is i + 1 and its second starts where the first
  // child's subtree ends.
  struct PackedNode {
    float min[3], max[3];
    std::int32_t after;  // one past this node's subtree: where a walk goes when it misses the box
    std::int32_t hull;   // a leaf's hull index; -1 for an inner node
  };
  // Pending nodes a ray walk keeps without the heap: a depth-first walk holds
  // at most one pending sibling per level, and FCL's Morton build is at most
  // about 30 + log2(hulls) high (its codes have 30 bits).
  static constexpr size_t kStackOnCaller = 96;

  std::vector<PackedNode> nodes_;

  void pack(const FclTreeNode& root);

public:
  /// The float nearest `x` at or below it (at or above it): a box rounded
  /// outward to floats holds the box. Beyond float's range: its largest
  /// value or infinity, still outward.
  static float float_at_or_below(double x) {
    constexpr float kLargest = std::numeric_limits<float>::max();
    if (x > kLargest) return kLargest;  // beyond float's range: the cast would not be defined
    if (x < -kLargest) return -std::numeric_limits<float>::infinity();
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
  }
  /// See float_at_or_below.
  static float float_at_or_above(double x) {
    constexpr float kLargest = std::numeric_limits<float>::max();
    if (x < -kLargest) return -kLargest;
    if (x > kLargest) return std::numeric_limits<float>::infinity();
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  }

private:
  size_t height_ = 0;

  static Aabb box_of(const PackedNode& n) {
    Aabb box;
    box.min = Eigen::Vector3d(n.min[0], n.min[1], n.min[2]);
    box.max = Eigen::Vector3d(n.max[0], n.max[1], n.max[2]);
    return box;
  }

  // A ray walk's stack of pending nodes and where the ray enters them: on
  // the caller's stack unless the tree is deeper than kStackOnCaller.
  class WalkStack {
  public:
    explicit WalkStack(size_t height) {
      if (height + 2 > kStackOnCaller) heap_.resize(height + 2);
    }
    void push(std::int32_t node, double entry) { data()[size_++] = {node, entry}; }
    double top_entry() { return data()[size_ - 1].second; }
    std::int32_t pop() { return data()[--size_].first; }
    bool empty() const { return size_ == 0; }

  private:
    struct Entry {  // no initialisers: the array is not cleared on every walk
      std::int32_t first;
      double second;
    };
    Entry* data() { return heap_.empty() ? local_.data() : heap_.data(); }
    std::array<Entry, kStackOnCaller> local_;
    std::vector<Entry> heap_;
    size_t size_ = 0;
  };

  // Calls visit(h) for the leaves whose boxes, and whose ancestors' boxes,
  // meet `box`, and which pass `leaf_test`, until a call returns true. The
  // box tests run on floats: `box` is rounded outward first, so they never
  // miss.
  template <typename LeafTest, typename Visit>
  bool find_where(const Aabb& box, LeafTest&& leaf_test, Visit&& visit) const;

  // A ray set up for slab tests: per axis, which of a box's two faces it
  // crosses first.
  struct RaySlabs {
    Eigen::Vector3d origin, inverse;
    bool negative[3];
  };

  // Where the ray enters `node` within [0, reach], or +infinity when it
  // misses it. Along an axis the ray runs parallel to, a product is NaN only
  // when the origin lies on the box's face; std::max(t, NaN) and
  // std::min(t, NaN) keep t, so such an axis sets no limit, as it should.
  static double ray_entry(const PackedNode& node, const RaySlabs& ray, double reach) {
    double t0 = 0.0, t1 = reach;
    for (int k = 0; k < 3; ++k) {
      const double near = ((ray.negative[k] ? node.max[k] : node.min[k]) - ray.origin[k]) * ray.inverse[k];
      const double far = ((ray.negative[k] ? node.min[k] : node.max[k]) - ray.origin[k]) * ray.inverse[k];
      t0 = std::max(t0, near);
      t1 = std::min(t1, far);
    }
    return t0 <= t1 ? t0 : std::numeric_limits<double>::infinity();
  }
};

template <typename LeafTest, typename Visit>
bool HullTree::find_where(const Aabb& box, LeafTest&& leaf_test, Visit&& visit) const {
  float lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = float_at_or_below(box.min[k]);
    hi[k] = float_at_or_above(box.max[k]);
  }
  const PackedNode* const all = nodes_.data();
  const std::int32_t end = static_cast<std::int32_t>(nodes_.size());
  for (std::int32_t i = 0; i < end;) {
    const PackedNode& node = all[i];
    // One branch for the six comparisons: misses are the common case.
    const bool miss = (node.min[0] > hi[0]) | (node.max[0] < lo[0]) | (node.min[1] > hi[1]) | (node.max[1] < lo[1]) |
                      (node.min[2] > hi[2]) | (node.max[2] < lo[2]);
    if (miss) {
      i = node.after;
      continue;
    }
    if (node.hull >= 0 && leaf_test(node) && visit(node.hull)) return true;
    ++i;
  }
  return false;
}

template <typename Visit>
void HullTree::walk_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& inverse, double& reach,
                        Visit&& visit) const {
  constexpr double kMissed = std::numeric_limits<double>::infinity();
  RaySlabs ray{origin, inverse, {inverse[0] < 0.0, inverse[1] < 0.0, inverse[2] < 0.0}};
  const PackedNode* const all = nodes_.data();
  double entry = ray_entry(all[0], ray, reach);
  if (entry == kMissed) return;
  // Pending nodes with where the ray enters them: one skipped when the best
  // hit so far comes before that.
  WalkStack stack(height_);
  std::int32_t i = 0;
  for (;;) {
    const PackedNode& node = all[i];
    if (node.hull >= 0) {
      visit(node.hull, reach);
    } else {
      const std::int32_t a = i + 1, b = all[a].after;
      const double ta = ray_entry(all[a], ray, reach);
      const double tb = ray_entry(all[b], ray, reach);
      // Go on into the nearer child; keep the farther for later.
      if (ta <= tb && ta != kMissed) {
        if (tb != kMissed) stack.push(b, tb);
        i = a;
        continue;
      }
      if (tb < ta) {
        if (ta != kMissed) stack.push(a, ta);
        i = b;
        continue;
      }
    }
    // Next pending node the ray still reaches before the best hit.
    do {
      if (stack.empty()) return;
      entry = stack.top_entry();
      i = stack.pop();
    } while (entry > reach);
  }
}

} // namespace hullcover::bvh::detail

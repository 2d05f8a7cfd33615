#pragma once
// The broad phase of HullWorld and of each streamed section (private to
// bvh/): a tree of four-wide nodes over each hull's exact box, built top
// down by the surface area heuristic and packed in one array, depth first. A walk
// tests a node's four child boxes at once (float4.h) and keeps its pending
// nodes on the caller's stack: no callback, virtual or library call, and
// no allocation per query. Boxes are floats rounded outward, and every
// float comparison is made so that it never drops a box the exact one
// would meet: box walks compare with the query box rounded outward, ray
// walks with the origin rounded both ways and the entry and exit widened
// by their rounding (docs/definitions-and-proofs.md, "The runtime's float
// pre-tests").

#include "float4.h"

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace hullcover::bvh::detail {

/// Relative widening of a float ray-box entry and exit: each is a
/// difference and a product of floats, with the inverse direction rounded
/// once, so within 3 u of its exact value (u = 2^-24); 16 u covers that
/// and the rounding of the widening product itself.
inline constexpr float kRaySlabWidening = static_cast<float>(1.0 + 16.0 * kFloatUnit);

/// The hulls' boxes in four-wide nodes, packed for direct walks.
/// Immutable once built: any number of threads may walk it at once.
class HullTree {
public:
  /// Builds the tree over `hulls`' boxes (at least one hull).
  explicit HullTree(const std::vector<RuntimeHull>& hulls);
  /// Builds the tree over boxes (at least one): leaf i is boxes[i].
  explicit HullTree(const std::vector<Aabb>& boxes);

  /// Calls `visit(h)` for each hull h whose box meets the closed box `box`,
  /// until a call returns true. Returns whether one did.
  template <typename Visit>
  bool find_in_box(const Aabb& box, Visit&& visit) const {
    Float4 lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = Float4::all(float_at_or_below(box.min[k]));
      hi[k] = Float4::all(float_at_or_above(box.max[k]));
    }
    return find_where(
        0.5 * (box.min + box.max), [&](const WideNode& node, Float4) { return lanes_meeting(node, lo, hi); }, visit);
  }

  /// The same for the boxes within `radius` of `centre` (a sphere's
  /// candidates: tighter than its box at the corners), tested at every
  /// level. The test allows kTouchingFraction of slack relative to the
  /// coordinates' size, far above the narrow phase's rounding, and float
  /// rounding on top, so it never drops a hull the sphere's contact would
  /// find.
  template <typename Visit>
  bool find_near_point(const Eigen::Vector3d& centre, double radius, Visit&& visit) const;

  /// Calls `visit(h, reach)` for each hull whose box, grown by `grow` on
  /// every side, the ray origin + t * direction meets for some t in
  /// [0, reach], nearer boxes first. `visit` may shorten `reach` (to the
  /// best hit so far), which prunes the rest of the walk; a negative reach
  /// ends it. `inverse` is 1 / direction, per axis.
  template <typename Visit>
  void walk_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& inverse, double& reach, Visit&& visit,
                double grow = 0.0) const;

  /// Calls `visit(h)` for each hull whose box comes within `radius` of
  /// segment a-b (a capsule's candidates: along a slanted axis far fewer
  /// than its box holds), nearer a first, until a call returns true;
  /// returns whether one did. The segment's walk is the ray walk from a
  /// towards b over [0, 1] through boxes grown by the radius plus the
  /// exact tests' touching allowance (kTouchingFraction of the sizes), so
  /// it never drops a hull a capsule test would find touching.
  template <typename Visit>
  bool find_near_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, Visit&& visit) const {
    const double grow = touching_reach(radius, std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()));
    double reach = 1.0;
    bool stopped = false;
    walk_ray(
        a, (b - a).cwiseInverse(), reach,
        [&](int h, double& r) {
      if (visit(h)) {
        stopped = true;
        r = -1.0;
      }
        },
        grow);
    return stopped;
  }

  /// The box of every hull (rounded outward to floats).
  Aabb bounds() const { return bounds_; }

private:
  // Up to four children, in the first `count` lanes: an inner node's index
  // (>= 0) or a leaf, as ~number (< 0).
  struct alignas(64) WideNode {
    // Lane i's box: face[k][i] its least coordinate on axis k, face[3 + k][i]
    // its greatest.
    float face[6][4];
    std::int32_t child[4];
    std::int32_t count;
  };
  // How far from a sphere's centre or a capsule's axis the exact tests
  // still count a hull as touching: the radius and kTouchingFraction of
  // the sizes (`scale`: the largest coordinate of the centre or axis ends).
  static double touching_reach(double radius, double scale) {
    return radius + kTouchingFraction * (1.0 + radius + scale);
  }

  // Pending nodes a walk keeps without the heap: each step takes one and
  // adds at most four, so a walk holds at most 3 x height + 1.
  static constexpr size_t kStackOnCaller = 256;

  std::vector<WideNode> nodes_;
  Aabb bounds_;
  size_t height_ = 0;

  struct Item; // a hull's box and centre while building
  std::int32_t build_node(std::vector<Item>& items, size_t begin, size_t end, size_t depth);

  template <typename Entry>
  class WalkStack {
  public:
    explicit WalkStack(size_t height) {
      if (3 * height + 5 > kStackOnCaller) heap_.resize(3 * height + 5);
      data_ = heap_.empty() ? local_.data() : heap_.data();
    }
    WalkStack(const WalkStack&) = delete;
    WalkStack& operator=(const WalkStack&) = delete;
    void push(const Entry& e) { data_[size_++] = e; }
    Entry pop() { return data_[--size_]; }
    bool empty() const { return size_ == 0; }

  private:
    std::array<Entry, kStackOnCaller> local_; // not cleared: written before read
    std::vector<Entry> heap_;
    Entry* data_ = nullptr;
    size_t size_ = 0;
  };

  // The lanes set in `lanes` (bit i: lane i) least `key` first: their
  // children into `child` and keys into `key_out`; returns how many. At
  // most four: an insertion sort (one lane met, the usual case, is no sort).
  static int lanes_by_key(int lanes, Float4 key, const std::int32_t children[4], std::int32_t child[4],
                          float key_out[4]) {
    float k[4];
    key.store(k);
    int met = 0;
    for (; lanes; lanes &= lanes - 1) {
      const int i = __builtin_ctz(static_cast<unsigned>(lanes));
      int j = met++;
      for (; j > 0 && key_out[j - 1] > k[i]; --j) {
        key_out[j] = key_out[j - 1];
        child[j] = child[j - 1];
      }
      key_out[j] = k[i];
      child[j] = children[i];
    }
    return met;
  }

  // Lanes (bit i: child i) whose boxes meet the float box [lo, hi].
  static int lanes_meeting(const WideNode& n, const Float4 lo[3], const Float4 hi[3]) {
    const Float4 miss = (Float4::load(n.face[0]) > hi[0]) | (Float4::load(n.face[3]) < lo[0]) |
                        (Float4::load(n.face[1]) > hi[1]) | (Float4::load(n.face[4]) < lo[1]) |
                        (Float4::load(n.face[2]) > hi[2]) | (Float4::load(n.face[5]) < lo[2]);
    return ~miss.bits() & ((1 << n.count) - 1);
  }

  // Calls visit(h) for the leaves whose boxes, and whose ancestors' boxes,
  // pass `lane_test(node, gap2)` (a lane mask from a node and its lanes'
  // squared float gaps to `centre`), nearest to `centre` first, until a
  // call returns true.
  template <typename LaneTest, typename Visit>
  bool find_where(const Eigen::Vector3d& centre, LaneTest&& lane_test, Visit&& visit) const;
};

template <typename LaneTest, typename Visit>
bool HullTree::find_where(const Eigen::Vector3d& centre, LaneTest&& lane_test, Visit&& visit) const {
  // Children are taken nearest to the query's centre first, so a yes/no
  // query, which stops at the first touching hull, tends to meet it early.
  // Any order finds the same hulls.
  Float4 mid[3];
  for (int k = 0; k < 3; ++k) mid[k] = Float4::all(float_at_or_below(centre[k]));
  const Float4 zero = Float4::all(0.0f);
  WalkStack<std::int32_t> stack(height_);
  stack.push(0);
  while (!stack.empty()) {
    const WideNode& node = nodes_[stack.pop()];
    Float4 gap2 = zero;
    for (int k = 0; k < 3; ++k) {
      const Float4 g = max(max(Float4::load(node.face[k]) - mid[k], mid[k] - Float4::load(node.face[3 + k])), zero);
      gap2 = gap2 + g * g;
    }
    const int lanes = lane_test(node, gap2) & ((1 << node.count) - 1);
    if (!lanes) continue;
    std::int32_t child[4];
    float key[4];
    const int met = lanes_by_key(lanes, gap2, node.child, child, key);
    // Leaves now, nearest first; inner nodes pushed farthest first, so the
    // nearest is walked next.
    for (int j = met - 1; j >= 0; --j)
      if (child[j] >= 0) stack.push(child[j]);
    for (int j = 0; j < met; ++j)
      if (child[j] < 0 && visit(~child[j])) return true;
  }
  return false;
}

template <typename Visit>
bool HullTree::find_near_point(const Eigen::Vector3d& centre, double radius, Visit&& visit) const {
  const double scale = centre.cwiseAbs().maxCoeff();
  const double reach = touching_reach(radius, scale);
  // Float gaps from the rounded centre are off by at most a few roundings
  // of the coordinates' size: widen the reach by that before squaring. (A
  // box within the reach also meets the sphere's box: no box test.)
  const float limit = float_at_or_above(reach + 8.0 * kFloatUnit * (scale + reach));
  const Float4 limit2 = Float4::all(limit) * Float4::all(limit);
  return find_where(
      centre, [&](const WideNode&, Float4 gap2) { return (gap2 <= limit2).bits(); }, visit);
}

template <typename Visit>
void HullTree::walk_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& inverse, double& reach, Visit&& visit,
                        double grow) const {
  // Per axis, the slab's near and far faces (rows of a node's face array:
  // no branch per node) and the origin rounded so that the entry
  // comes out no later and the exit no earlier than exactly. Growing the
  // boxes by `grow` is moving the origin towards each near face by it and
  // away from each far face.
  Float4 near_origin[3], far_origin[3], inv[3];
  int near_face[3], far_face[3];
  // An axis whose inverse direction is beyond float's range (a direction
  // component under 3e-39, not zero) sets no limit: its float inverse is
  // NaN, which max and min pass over (float4.h), so the walk keeps every
  // box that axis would have cut, never fewer.
  for (int k = 0; k < 3; ++k) {
    const bool negative = inverse[k] < 0.0;
    float below, above;
    if (grow == 0.0) {
      float_bracket(origin[k], below, above); // a ray's walk: one rounding
    } else {
      below = float_at_or_below(origin[k] - grow);
      above = float_at_or_above(origin[k] + grow);
    }
    near_origin[k] = Float4::all(negative ? below : above);
    far_origin[k] = Float4::all(negative ? above : below);
    const bool in_range = std::abs(inverse[k]) <= std::numeric_limits<float>::max() || std::isinf(inverse[k]);
    inv[k] = Float4::all(in_range ? static_cast<float>(inverse[k]) : std::numeric_limits<float>::quiet_NaN());
    near_face[k] = negative ? 3 + k : k;
    far_face[k] = negative ? k : 3 + k;
  }
  const Float4 zero = Float4::all(0.0f), widen = Float4::all(kRaySlabWidening);
  struct Pending {
    std::int32_t child; // as in WideNode::child
    float entry;
  };
  // The reach as a float at or above it, and the entry past which a box
  // is beyond it whatever the rounding: updated when a visit shortens it.
  double known_reach = reach;
  float reach_up = float_at_or_above(reach);
  float prune = float_at_or_above(reach * static_cast<double>(kRaySlabWidening));
  WalkStack<Pending> stack(height_);
  // The nearest lane a node meets is walked next without the stack (the
  // same order as pushing it last and popping it at once).
  Pending top{0, 0.0f};
  for (;;) {
    if (top.child < 0) {
      visit(~top.child, reach);
      if (reach != known_reach) {
        known_reach = reach;
        reach_up = float_at_or_above(reach);
        prune = float_at_or_above(reach * static_cast<double>(kRaySlabWidening));
      }
    } else {
      const WideNode& n = nodes_[top.child];
      // A lane where the origin lies on a face of a slab the ray runs along
      // gives 0 x infinity = NaN; max and min keep their second operand
      // then, so such an axis sets no limit, as it should.
      Float4 entry = zero, exit = Float4::all(reach_up);
      for (int k = 0; k < 3; ++k) {
        entry = max((Float4::load(n.face[near_face[k]]) - near_origin[k]) * inv[k], entry);
        exit = min((Float4::load(n.face[far_face[k]]) - far_origin[k]) * inv[k], exit);
      }
      const int lanes = (entry <= exit * widen).bits() & ((1 << n.count) - 1);
      if (lanes && !(lanes & (lanes - 1))) { // one lane: no order to keep
        top = {n.child[__builtin_ctz(static_cast<unsigned>(lanes))], 0.0f};
        continue;
      }
      if (lanes) {
        // The rest pushed farthest first, so the nearer are walked sooner.
        std::int32_t child[4];
        float key[4];
        for (int j = lanes_by_key(lanes, entry, n.child, child, key) - 1; j > 0; --j) stack.push({child[j], key[j]});
        if (!(key[0] > prune)) {
          top = {child[0], key[0]};
          continue;
        }
      }
    }
    do {
      if (stack.empty()) return;
      top = stack.pop();
    } while (top.entry > prune);
  }
}

} // namespace hullcover::bvh::detail

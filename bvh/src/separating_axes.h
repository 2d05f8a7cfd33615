#pragma once
// Separating axes between a world hull and a query shape (private to bvh/),
// shared by the contacts (hull_contact.cpp) and the yes/no tests
// (hull_touch.cpp) so that both decide "do they meet" the same way.
// Nothing here allocates: axes are produced one at a time.

#include "hullcover/bvh/query_types.h"
#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <limits>
#include <optional>
#include <utility>

namespace hullcover::bvh::detail {

/// Gaps below this (scene units) are "touching": closest points that near
/// are rounding noise in direction.
inline double touching_distance(const RuntimeHull& hull) { return kTouchingFraction * (1.0 + hull.box.diagonal()); }

/// Where a point stands against a hull's planes: the largest signed
/// distance over every plane (<= 0: inside), and the facet whose plane it
/// is farthest in front of (first of equals), with that distance.
struct FrontFacet {
  double outside = -std::numeric_limits<double>::infinity();
  int facet = 0;
  double distance = -std::numeric_limits<double>::infinity();
  /// The largest of the other facets' distances: a facet that ties with
  /// `facet` (closest_to_point_outside) can only be there.
  double runner_up = -std::numeric_limits<double>::infinity();
};
/// One pass over the planes; shared by the sphere's contact and yes/no.
FrontFacet front_facet(const RuntimeHull& hull, const Eigen::Vector3d& p);
/// closest_to_point for a point with `front.outside` > 0. It may stop as
/// soon as it finds a hull point within `good_enough` (scene units; pass -1
/// for the closest): a yes/no test asks only whether the distance is within
/// a radius, and each candidate's distance is computed the same way either
/// way, so both decide alike.
ClosestPoints closest_to_point_outside(const RuntimeHull& hull, const Eigen::Vector3d& p, const FrontFacet& front,
                                       double good_enough);
/// True when segment a-b has a point behind every hull plane (clipped by
/// them), with such a point.
bool segment_meets_hull(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        Eigen::Vector3d& meet);
/// closest_to_segment for a segment segment_meets_hull finds apart; it may
/// stop as closest_to_point_outside does.
ClosestPoints closest_to_segment_apart(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       double good_enough);
/// The smallest push separating segment a-b from the hull over the
/// capsule's separating axes, or nothing when one separates them.
std::optional<std::pair<double, Eigen::Vector3d>> capsule_axis_push(const RuntimeHull& hull, const Eigen::Vector3d& a,
                                                                    const Eigen::Vector3d& b);

/// The hull's extent [min, max] along `w`.
inline std::pair<double, double> hull_extent(const RuntimeHull& hull, const Eigen::Vector3d& w) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Eigen::Vector3d& v : hull.shape.vertices) {
    const double x = v.dot(w);
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  return {lo, hi};
}

/// A box's extent [min, max] along `w` (its centre pose, half extents).
inline std::pair<double, double> box_extent(const Eigen::Isometry3d& pose, const Eigen::Vector3d& half_extents,
                                            const Eigen::Vector3d& w) {
  const double reach = (pose.linear().transpose() * w).cwiseAbs().dot(half_extents);
  const double centre = pose.translation().dot(w);
  return {centre - reach, centre + reach};
}

/// Calls `axis(w)` for `d` crossed with each hull edge (unit; a pair near
/// parallel gives no axis), until a call returns false, and says so.
template <typename Axis>
bool for_each_edge_axis(const RuntimeHull& hull, const Eigen::Vector3d& d, Axis&& axis) {
  for (const auto& [u, v] : hull.edges) {
    const Eigen::Vector3d e = hull.shape.vertices[v] - hull.shape.vertices[u];
    const Eigen::Vector3d c = d.cross(e);
    const double n = c.norm();
    if (n > kTouchingFraction * d.norm() * e.norm() && !axis(Eigen::Vector3d(c / n))) return false;
  }
  return true;
}

/// Calls `axis(w)` for the candidate axes of a hull against a shape whose
/// edges run along `directions` (none for a sphere, the axis for a
/// capsule, three for a box): the hull's plane normals, each direction, and
/// each direction crossed with each hull edge (unit; near-parallel pairs
/// give no axis). Stops at the first call returning false, and says so.
template <typename Axis>
bool for_each_axis(const RuntimeHull& hull, const Eigen::Vector3d* directions, int direction_count, Axis&& axis) {
  for (const Plane& p : hull.shape.planes)
    if (!axis(p.normal)) return false;
  for (int i = 0; i < direction_count; ++i) {
    const Eigen::Vector3d& d = directions[i];
    if (!axis(Eigen::Vector3d(d.normalized())) || !for_each_edge_axis(hull, d, axis)) return false;
  }
  return true;
}

/// The same for two hulls: the world hull's plane normals, the shape's, and
/// each shape edge crossed with each hull edge.
template <typename Axis>
bool for_each_axis_between(const RuntimeHull& hull, const RuntimeHull& shape, Axis&& axis) {
  for (const Plane& p : hull.shape.planes)
    if (!axis(p.normal)) return false;
  for (const Plane& p : shape.shape.planes)
    if (!axis(p.normal)) return false;
  for (const auto& [s, t] : shape.edges)
    if (!for_each_edge_axis(hull, Eigen::Vector3d(shape.shape.vertices[t] - shape.shape.vertices[s]), axis))
      return false;
  return true;
}

/// Separating-axis penetration: over the axes `enumerate` gives (it takes
/// the per-axis callback, as for_each_axis does), the smallest push of the
/// shape along an axis, either sense, that separates it from the hull.
/// `project(w)` gives the shape's [min, max] along w. Returns depth and push
/// direction, or nothing when some axis separates them (touching, a push
/// of 0, is meeting).
template <typename Enumerate, typename Project>
std::optional<std::pair<double, Eigen::Vector3d>> smallest_push(const RuntimeHull& hull, Enumerate&& enumerate,
                                                                Project&& project) {
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_axis = Eigen::Vector3d::UnitZ();
  const bool meet = enumerate([&](const Eigen::Vector3d& w) {
    const auto [hmin, hmax] = hull_extent(hull, w);
    const auto [smin, smax] = project(w);
    const double push_plus = hmax - smin, push_minus = smax - hmin;
    if (push_plus < 0.0 || push_minus < 0.0) return false;
    if (push_plus < best) {
      best = push_plus;
      best_axis = w;
    }
    if (push_minus < best) {
      best = push_minus;
      best_axis = -w;
    }
    return true;
  });
  if (!meet) return std::nullopt;
  return std::make_pair(best, best_axis);
}

/// True when no axis `enumerate` gives separates the hull from the shape:
/// exactly when smallest_push would give a push, without computing it.
template <typename Enumerate, typename Project>
bool no_separating_axis(const RuntimeHull& hull, Enumerate&& enumerate, Project&& project) {
  return enumerate([&](const Eigen::Vector3d& w) {
    const auto [hmin, hmax] = hull_extent(hull, w);
    const auto [smin, smax] = project(w);
    return hmax - smin >= 0.0 && smax - hmin >= 0.0;
  });
}

/// Clips segment a-b (parameter 0 at a, 1 at b) by every hull plane moved
/// out by `grow` (scene units; 0 for the hull itself): true when a part is
/// left, [enter, leave] then being it. Stops as soon as nothing is left.
inline bool clip_segment_to_hull(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 double grow, double& enter, double& leave) {
  enter = 0.0;
  leave = 1.0;
  for (const Plane& plane : hull.shape.planes) {
    const double da = plane.signed_distance(a) - grow, db = plane.signed_distance(b) - grow;
    if (da > 0.0 && db > 0.0) return false;
    if (da <= 0.0 && db <= 0.0) continue;
    const double t = da / (da - db);
    if (da > 0.0)
      enter = std::max(enter, t);
    else
      leave = std::min(leave, t);
    if (enter > leave) return false;
  }
  return true;
}

/// True when no point of segment a-b lies within `radius` behind every hull
/// plane moved out by `radius`: then the capsule (a-b, radius) and the hull
/// are apart, as the planes moved out bound the hull grown by `radius`. The
/// cheap first step of both capsule_contact and capsule_touches, so that
/// they decide alike; it also rejects the segment passing a corner, which
/// no single plane separates.
inline bool segment_clear_of_grown_planes(const RuntimeHull& hull, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          double radius) {
  double enter, leave;
  return !clip_segment_to_hull(hull, a, b, radius, enter, leave);
}

} // namespace hullcover::bvh::detail

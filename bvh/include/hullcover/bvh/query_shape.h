#pragma once
/// \file query_shape.h
/// The shapes characters are, at a rigid pose, and their exact world boxes.
///
/// Conventions: lengths in scene units; a pose maps the shape's local frame
/// to the world; a capsule's axis is its local z, from -half_height to
/// +half_height between the centres of its end spheres; a box is centred on
/// its local origin.

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/status.h"

#include <Eigen/Geometry>

#include <vector>

namespace hullcover::bvh {

enum class ShapeKind { sphere, capsule, box, convex };

/// A query shape in its local frame.
struct QueryShape {
  ShapeKind kind = ShapeKind::sphere;
  double radius = 0.5;                                      ///< sphere, capsule
  double half_height = 0.5;                                 ///< capsule: half the axis segment
  Eigen::Vector3d half_extents = Eigen::Vector3d::Constant(0.5);  ///< box
  std::vector<Eigen::Vector3d> points;                      ///< convex: its vertices

  static QueryShape sphere(double r) { QueryShape s; s.kind = ShapeKind::sphere; s.radius = r; return s; }
  static QueryShape capsule(double r, double half_height) {
    QueryShape s; s.kind = ShapeKind::capsule; s.radius = r; s.half_height = half_height; return s;
  }
  static QueryShape box(const Eigen::Vector3d& half_extents) {
    QueryShape s; s.kind = ShapeKind::box; s.half_extents = half_extents; return s;
  }
};

/// The tight world-space box of `shape` at `pose` (not the cube around its
/// bounding sphere that FCL computes for rotated objects).
Aabb world_box(const QueryShape& shape, const Eigen::Isometry3d& pose);

/// Fails (false, with `why`) for a shape FCL or the narrow phase cannot use:
/// non-positive or non-finite sizes, a convex with fewer than 4 points, a
/// non-finite pose.
bool check_query_shape(const QueryShape& shape, const Eigen::Isometry3d& pose, const char** why);

} // namespace hullcover::bvh

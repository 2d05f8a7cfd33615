#pragma once
/// \file aabb.h
/// Axis-aligned bounding boxes: what every tree (the decomposer's AabbTree,
/// the runtime's FCL tree) and every "is it near" test is built on.

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace hullcover {

/// Axis-aligned bounding box. An empty box has min > max.
struct Aabb {
  /// Lowest corner, scene units (+infinity when empty).
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  /// Highest corner, scene units (-infinity when empty).
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  /// True when the box holds no point (min > max on some axis).
  bool empty() const { return (min.array() > max.array()).any(); }
  /// Length of the diagonal; 0 for a point, 0 for an empty box.
  double diagonal() const { return empty() ? 0.0 : (max - min).norm(); }
  /// Grows the box to hold `p`.
  void extend(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
};

/// True when the closed boxes share a point.
inline bool boxes_overlap(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

/// `box` grown by `margin` on every side.
inline Aabb grown(Aabb box, double margin) {
  box.min.array() -= margin;
  box.max.array() += margin;
  return box;
}

/// Bounding box of points (empty for none).
inline Aabb bounding_box_of(const std::vector<Eigen::Vector3d>& points) {
  Aabb box;
  for (const Eigen::Vector3d& p : points) box.extend(p);
  return box;
}

} // namespace hullcover

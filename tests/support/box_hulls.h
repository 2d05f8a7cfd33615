#pragma once
// An axis-aligned box as a runtime hull: the hand-made hull the runtime and
// audit tests place in scenes (a block on a floor, a blob filling a room).

#include "hullcover/bvh/hull_contact.h"

#include <Eigen/Geometry>

namespace hullcover::test {

/// The box from corner `lo` to corner `hi`.
inline bvh::RuntimeHull box_hull(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Eigen::Isometry3d centre = Eigen::Isometry3d::Identity();
  centre.translation() = 0.5 * (lo + hi);
  return bvh::placed_box(centre, 0.5 * (hi - lo));
}

} // namespace hullcover::test

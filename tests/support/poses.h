#pragma once
// Poses the runtime tests place query shapes at.

#include <Eigen/Geometry>

namespace hullcover::test {

/// Unrotated, at `p` (scene units).
inline Eigen::Isometry3d at(const Eigen::Vector3d& p) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = p;
  return pose;
}

} // namespace hullcover::test

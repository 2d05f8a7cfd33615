#include "cut_away.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::app::render {
namespace {

// Below this length the viewing direction has no horizontal part worth a
// direction (a view within a hundredth of a degree of vertical).
constexpr double kLeastHorizontalLength = 1e-4;

// Lowest and highest of the box's corners along `axis`.
std::pair<double, double> box_extent_along(const Aabb& box, const Eigen::Vector3d& axis) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? box.max.x() : box.min.x(), (corner & 2) ? box.max.y() : box.min.y(),
                            (corner & 4) ? box.max.z() : box.min.z());
    low = std::min(low, p.dot(axis));
    high = std::max(high, p.dot(axis));
  }
  return {low, high};
}

} // namespace

CutAway::CutAway(const Aabb& box, const SceneAxes& axes, const Eigen::Vector3d& camera_forward)
    : box_(box), up_(axes.up) {
  const Eigen::Vector3d horizontal = camera_forward - camera_forward.dot(up_) * up_;
  horizontal_forward_ = horizontal.norm() > kLeastHorizontalLength ? horizontal.normalized() : Eigen::Vector3d::Zero();
  const auto [low, high] = box_extent_along(box_, up_);
  roof_height_ = low + kRoofCutHeightFraction * (high - low);
}

bool CutAway::is_roof(const std::vector<Eigen::Vector3d>& vertices) const {
  return std::all_of(vertices.begin(), vertices.end(),
                     [&](const Eigen::Vector3d& v) { return v.dot(up_) > roof_height_; });
}

bool CutAway::is_front_wall(const std::vector<Eigen::Vector3d>& vertices, const Eigen::Vector3d& normal) const {
  if (horizontal_forward_.isZero() || !normal.allFinite() || normal.isZero()) return false;
  if (std::abs(normal.dot(up_)) > std::sin(kWallTiltDeg * kRadiansPerDegree)) return false;
  Eigen::Vector3d towards_camera = (normal - normal.dot(up_) * up_).normalized();
  // The camera looks along horizontal_forward_: a face it sees points against it.
  if (towards_camera.dot(horizontal_forward_) > 0.0) towards_camera = -towards_camera;
  if (-towards_camera.dot(horizontal_forward_) < std::cos(kWallFacingDeg * kRadiansPerDegree)) return false;
  const auto [low, high] = box_extent_along(box_, towards_camera);
  const double slice_start = high - kFrontCutFraction * (high - low);
  return std::all_of(vertices.begin(), vertices.end(),
                     [&](const Eigen::Vector3d& v) { return v.dot(towards_camera) >= slice_start; });
}

bool CutAway::leaves_out(const std::vector<Eigen::Vector3d>& vertices, const Eigen::Vector3d& normal) const {
  return !vertices.empty() && (is_roof(vertices) || is_front_wall(vertices, normal));
}

} // namespace hullcover::app::render

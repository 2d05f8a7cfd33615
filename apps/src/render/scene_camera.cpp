#include "scene_camera.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace hullcover::app::render {
namespace {

// Half the vertical field of view: wide enough for depth to show, narrow
// enough that near walls do not balloon.
constexpr double kHalfFieldOfViewDeg = 18.0;
// Image left free on every side, as a fraction of its width or height.
constexpr double kFrameMargin = 0.04;
// The nearest depth drawn, as a fraction of the camera's distance from the
// box centre: a hull poking far out of the scene's box towards the camera
// is cut there instead of projecting through the eye.
constexpr double kNearDepthFraction = 0.02;

Status bad(const std::string& what, const std::string& text, const std::string& expected) {
  return {StatusCode::invalid_argument, what + " '" + text + "': " + expected};
}

} // namespace

SceneAxes scene_axes(UpAxis up) {
  using V = Eigen::Vector3d;
  switch (up) {
    case UpAxis::x: return {V::UnitX(), -V::UnitZ(), V::UnitY()};
    case UpAxis::z: return {V::UnitZ(), -V::UnitY(), V::UnitX()};
    case UpAxis::y: break;
  }
  return {V::UnitY(), V::UnitZ(), V::UnitX()};
}

Result<UpAxis> parse_up_axis(const std::string& text) {
  if (text == "x") return UpAxis::x;
  if (text == "y") return UpAxis::y;
  if (text == "z") return UpAxis::z;
  return bad("--up", text, "expected x, y or z");
}

Result<ViewAngles> parse_view(const std::string& text) {
  if (text == "iso") return ViewAngles{45.0, kIsometricElevationDeg};
  if (text == "top") return ViewAngles{0.0, 90.0};
  if (text == "front") return ViewAngles{0.0, 0.0};
  double azimuth = 0.0, elevation = 0.0;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%n", &azimuth, &elevation, &consumed) != 2 ||
      consumed != static_cast<int>(text.size()) || !std::isfinite(azimuth) || !std::isfinite(elevation) ||
      elevation < -90.0 || elevation > 90.0)
    return bad("--view", text, "expected iso, top, front or AZIMUTH,ELEVATION in degrees (elevation in [-90, 90])");
  return ViewAngles{azimuth, elevation};
}

Result<ImageSize> parse_image_size(const std::string& text) {
  long width = 0, height = 0;
  int consumed = 0;
  const std::string expected = "expected WIDTHxHEIGHT in pixels, each from " + std::to_string(kMinImageSide) + " to " +
                               std::to_string(kMaxImageSide);
  // Digits and one 'x' only, and short enough that no number can overflow.
  constexpr size_t kLongestSizeText = 2 * 6 + 1;
  if (text.size() > kLongestSizeText || text.find_first_not_of("0123456789x") != std::string::npos ||
      std::sscanf(text.c_str(), "%ldx%ld%n", &width, &height, &consumed) != 2 ||
      consumed != static_cast<int>(text.size()))
    return bad("--size", text, expected);
  if (width < kMinImageSide || height < kMinImageSide || width > kMaxImageSide || height > kMaxImageSide)
    return bad("--size", text, expected);
  return ImageSize{static_cast<int>(width), static_cast<int>(height)};
}

SceneCamera::SceneCamera(const Aabb& box, const SceneAxes& axes, const ViewAngles& view, const ImageSize& size) {
  const double azimuth = view.azimuth_deg * kRadiansPerDegree, elevation = view.elevation_deg * kRadiansPerDegree;
  const Eigen::Vector3d ground = std::cos(azimuth) * axes.front + std::sin(azimuth) * axes.right;
  const Eigen::Vector3d to_camera = std::cos(elevation) * ground + std::sin(elevation) * axes.up;
  // The derivative of `to_camera` by elevation: unit, square to it, and
  // defined straight overhead too (the front then at the image's bottom).
  up_ = (-std::sin(elevation) * ground + std::cos(elevation) * axes.up).normalized();
  forward_ = -to_camera.normalized();
  right_ = forward_.cross(up_).normalized();

  const Eigen::Vector3d centre = 0.5 * (box.min + box.max);
  const double radius = std::max(0.5 * box.diagonal(), std::numeric_limits<double>::min());
  const double distance = radius / std::sin(kHalfFieldOfViewDeg * kRadiansPerDegree);
  eye_ = centre + distance * to_camera.normalized();
  near_depth_ = kNearDepthFraction * distance;

  double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x, min_y = min_x, max_y = -min_x;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? box.max.x() : box.min.x(), (corner & 2) ? box.max.y() : box.min.y(),
                            (corner & 4) ? box.max.z() : box.min.z());
    const Eigen::Vector3d v = p - eye_;
    const double depth = v.dot(forward_);
    min_x = std::min(min_x, v.dot(right_) / depth);
    max_x = std::max(max_x, v.dot(right_) / depth);
    min_y = std::min(min_y, v.dot(up_) / depth);
    max_y = std::max(max_y, v.dot(up_) / depth);
  }
  const double usable_w = size.width * (1.0 - 2.0 * kFrameMargin), usable_h = size.height * (1.0 - 2.0 * kFrameMargin);
  const double span_x = max_x - min_x, span_y = max_y - min_y;
  // A box seen edge-on spans nothing one way: the other way decides.
  if (span_x > 0.0 && span_y > 0.0)
    scale_ = std::min(usable_w / span_x, usable_h / span_y);
  else if (span_x > 0.0)
    scale_ = usable_w / span_x;
  else if (span_y > 0.0)
    scale_ = usable_h / span_y;
  offset_x_ = 0.5 * size.width - scale_ * 0.5 * (min_x + max_x);
  offset_y_ = 0.5 * size.height + scale_ * 0.5 * (min_y + max_y);
}

ImagePoint SceneCamera::project(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d v = p - eye_;
  const double depth = v.dot(forward_);
  if (depth <= near_depth_) return {0.0, 0.0, depth};
  return {offset_x_ + scale_ * v.dot(right_) / depth, offset_y_ - scale_ * v.dot(up_) / depth, depth};
}

double SceneCamera::plane_depth_at(const Eigen::Vector3d& normal, double offset, double x, double y) const {
  // The ray eye + t * direction, with direction . forward = 1, is at depth t.
  const Eigen::Vector3d direction = forward_ + ((x - offset_x_) / scale_) * right_ + ((offset_y_ - y) / scale_) * up_;
  const double along = normal.dot(direction);
  if (along == 0.0) return std::numeric_limits<double>::infinity();
  return (offset - normal.dot(eye_)) / along;
}

Eigen::Vector3d SceneCamera::towards_camera(const Eigen::Vector3d& p) const { return (eye_ - p).normalized(); }

} // namespace hullcover::app::render

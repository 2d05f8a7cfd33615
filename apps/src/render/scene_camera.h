#pragma once
// The camera of `hullcover render` and of the audit's HTML pictures: where
// it stands around the scene's bounding box, and how a scene point lands on
// the image.

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/status.h"

#include <Eigen/Core>

#include <cmath>
#include <string>

namespace hullcover::app::render {

/// Radians in one degree: views and cut-away angles are given in degrees.
constexpr double kRadiansPerDegree = M_PI / 180.0;

/// Which scene axis points up: game formats (OBJ, glTF) are y-up, CAD
/// formats (STL) often z-up.
enum class UpAxis { x, y, z };

/// The scene's frame for a camera: `up`, and `front` and `right` in the
/// ground plane with right x up = front (right-handed), so a camera at
/// azimuth 0 looks along -front and sees `right` to its right.
struct SceneAxes {
  Eigen::Vector3d up, front, right;
};

/// The axes of an up axis: y-up looks from +z with +x right (OBJ, glTF),
/// z-up from -y with +x right, x-up from -z with +y right.
SceneAxes scene_axes(UpAxis up);

/// Reads "x", "y" or "z". Fails with `invalid_argument` naming the text.
[[nodiscard]] Result<UpAxis> parse_up_axis(const std::string& text);

/// The true isometric elevation, atan(1 / sqrt(2)), degrees: at azimuth 45
/// the three box axes foreshorten alike.
inline constexpr double kIsometricElevationDeg = 35.26438968275;

/// A direction to look from: azimuth around the up axis from the front,
/// towards the right, and elevation above the ground plane.
struct ViewAngles {
  double azimuth_deg = 45.0;                     ///< degrees, any value
  double elevation_deg = kIsometricElevationDeg; ///< degrees, in [-90, 90]
};

/// Reads "iso" (azimuth 45, elevation 35.26), "top" (0, 90), "front" (0, 0)
/// or "AZIMUTH,ELEVATION" in degrees. Fails with `invalid_argument` naming
/// the text for anything else or an elevation outside [-90, 90].
[[nodiscard]] Result<ViewAngles> parse_view(const std::string& text);

/// An image size in pixels.
struct ImageSize {
  int width = 1200;
  int height = 900;
};

/// Largest width or height accepted: a 8192 x 8192 picture takes 256 MiB.
inline constexpr int kMaxImageSide = 8192;
/// Smallest width or height accepted: below it nothing can be recognised.
inline constexpr int kMinImageSide = 16;

/// Reads "WIDTHxHEIGHT". Fails with `invalid_argument` naming the text
/// unless both are whole numbers in [kMinImageSide, kMaxImageSide].
[[nodiscard]] Result<ImageSize> parse_image_size(const std::string& text);

/// A point on the image: pixels from the top-left corner, and its depth in
/// front of the camera (scene units; > 0 in front).
struct ImagePoint {
  double x = 0.0, y = 0.0, depth = 0.0;
};

/// A perspective camera framing a box: it stands on the line from the box's
/// centre in the view's direction, far enough out for its field of view to
/// hold the box's bounding sphere, and the projected corners of the box are
/// then scaled and centred to fill the image less a margin.
class SceneCamera {
public:
  /// Frames `box` (not empty) seen from `view` on an image of `size`.
  SceneCamera(const Aabb& box, const SceneAxes& axes, const ViewAngles& view, const ImageSize& size);

  /// Where `p` lands (depth <= near_depth() when behind the camera: not drawable).
  ImagePoint project(const Eigen::Vector3d& p) const;
  /// Unit vector from the scene towards the camera's position (scene units).
  Eigen::Vector3d towards_camera(const Eigen::Vector3d& p) const;
  /// Unit direction the camera looks along.
  const Eigen::Vector3d& forward() const { return forward_; }
  /// Unit direction of the image's up (the camera's up).
  const Eigen::Vector3d& image_up() const { return up_; }
  /// Unit direction of the image's right.
  const Eigen::Vector3d& image_right() const { return right_; }
  /// Nearest depth drawn, scene units: anything nearer is behind or at the eye.
  double near_depth() const { return near_depth_; }
  /// Depth (along forward(), scene units) at which the ray through pixel
  /// (x, y) meets the plane normal . p = offset; infinity when the ray runs
  /// parallel to it.
  double plane_depth_at(const Eigen::Vector3d& normal, double offset, double x, double y) const;
  /// Pixels per scene unit at depth `depth` (for discs of a scene radius).
  double pixels_per_unit(double depth) const { return scale_ / depth; }

private:
  Eigen::Vector3d eye_, forward_, up_, right_;
  double scale_ = 1.0;                     // pixels per unit of the image plane at depth 1
  double offset_x_ = 0.0, offset_y_ = 0.0; // pixels added after scaling
  double near_depth_ = 0.0;
};

} // namespace hullcover::app::render

#pragma once
// The paper's cut-away (its Fig. 1: "front and top walls are culled to
// reveal the interior structures"), as a rule a reader can check.
//
// An element is a hull (judged whole, so what stays keeps its solid look)
// or a scene triangle (judged alone). With U the up axis, B the scene's
// bounding box, and n the unit outward normal of the element's largest
// facet (a triangle's own normal), the element is left out when
//
//  - it is a roof: every vertex lies higher than kRoofCutHeightFraction of
//    B's height along U; or
//  - it is a front wall: n is within kWallTiltDeg of horizontal
//    (|n . U| <= sin kWallTiltDeg); n's horizontal part, taken with the sign
//    that faces the camera, call it a, is within kWallFacingDeg of the
//    camera's horizontal direction (|a . f| >= cos kWallFacingDeg, f the
//    horizontal part of the viewing direction; both faces of a thick wall
//    qualify); and every vertex lies in the slice of B nearest the camera
//    along a, no deeper than kFrontCutFraction of B's extent along a.
//
// A view from straight above or below has no horizontal direction: only
// roofs are left out. Judging walls along their own normal (not the view's
// direction) is what cuts the two outer walls an oblique view faces
// without taking the walls inside that stand the same distance away along
// the view.

#include "scene_camera.h"

#include <Eigen/Core>

#include <vector>

namespace hullcover::app::render {

/// Fraction of the scene box's height above which whole elements are roofs.
inline constexpr double kRoofCutHeightFraction = 0.8;
/// Most a wall's normal may tilt from horizontal, degrees.
inline constexpr double kWallTiltDeg = 30.0;
/// Most a wall's horizontal normal may turn from the camera's horizontal direction, degrees.
inline constexpr double kWallFacingDeg = 60.0;
/// Depth of the slice of the scene box, nearest the camera along a wall's
/// normal, that a front wall lies in, as a fraction of the box's extent.
inline constexpr double kFrontCutFraction = 0.2;

/// The cut-away of one view of one scene box.
class CutAway {
public:
  /// The cut of `box` (the scene's, not empty) seen along `camera_forward` (unit).
  CutAway(const Aabb& box, const SceneAxes& axes, const Eigen::Vector3d& camera_forward);

  /// True when the element with `vertices`, whose largest facet has unit
  /// outward normal `normal`, is a roof or a front wall (see above).
  bool leaves_out(const std::vector<Eigen::Vector3d>& vertices, const Eigen::Vector3d& normal) const;

private:
  bool is_roof(const std::vector<Eigen::Vector3d>& vertices) const;
  bool is_front_wall(const std::vector<Eigen::Vector3d>& vertices, const Eigen::Vector3d& normal) const;

  Aabb box_;
  Eigen::Vector3d up_;
  Eigen::Vector3d horizontal_forward_; // zero for a view from straight above or below
  double roof_height_ = 0.0;           // along up_
};

} // namespace hullcover::app::render

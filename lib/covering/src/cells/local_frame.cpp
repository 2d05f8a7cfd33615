#include "cells/local_frame.h"

#include <algorithm>
#include <cmath>

namespace hullcover::detail {
namespace {

Aabb moved(const Aabb& box, const Eigen::Vector3d& by) {
  if (box.empty()) return box;
  Aabb out = box;
  out.min += by;
  out.max += by;
  return out;
}

} // namespace

Eigen::Vector3d local_frame_origin(const PreparedSceneView& prepared) {
  const Aabb box = referenced_bounding_box(prepared.mesh);
  if (box.empty()) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d centre = 0.5 * (box.min + box.max);
  const double diagonal = box.diagonal();
  if (!(centre.cwiseAbs().maxCoeff() > kFarFromOriginInDiagonals * diagonal)) return Eigen::Vector3d::Zero();
  // Each far coordinate snapped to a grid of a power of two at least the
  // diagonal (and at least 1): an edit that moves the box a little keeps
  // the frame (and so the cell cache's keys), and moving a coordinate by a
  // multiple of a power of two near it is exact. Near coordinates stay.
  const double step = std::exp2(std::ceil(std::log2(std::max(diagonal, 1.0))));
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    if (std::abs(centre[k]) > kFarFromOriginInDiagonals * diagonal) origin[k] = std::round(centre[k] / step) * step;
  return origin;
}

PreparedMesh in_local_frame(const PreparedSceneView& prepared, const Eigen::Vector3d& origin) {
  PreparedMesh local = copy_of(prepared);
  for (Eigen::Vector3d& p : local.mesh.positions) p -= origin;
  for (Aabb& box : local.islands.boxes) box = moved(box, -origin);
  for (Aabb& zone : local.tolerance.island_zones) zone = moved(zone, -origin);
  return local;
}

void to_scene_frame(Covering& covering, const Eigen::Vector3d& origin) {
  for (CoveringHull& hull : covering.hulls) move_polytope(hull.polytope, origin);
}

} // namespace hullcover::detail

#include "validity/exact_conditions.h"

#include "validity/shadow_pieces.h"
#include "validity/witness_rays.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace hullcover {
namespace {

// Quick rejection: a plane of the interior with every corner of the sweep
// on its far side, or a plane of the sweep with the whole interior beyond.
bool separated(const FreeSpaceSweep& sweep, const HullInterior& interior) {
  for (const Plane& plane : interior.planes) {
    bool all_out = true;
    for (const Eigen::Vector3d& c : sweep.corners) all_out &= plane.signed_distance(c) >= 0.0;
    if (all_out) return true;
  }
  for (size_t i = 0; i < sweep.planes.size(); ++i) {
    bool all_out = true;
    for (const std::vector<Eigen::Vector3d>& facet : interior.facets)
      for (const Eigen::Vector3d& v : facet) all_out &= sweep.planes[i].signed_distance(v) + sweep.insets[i] > 0.0;
    if (all_out) return true;
  }
  return false;
}

// Whether the rays of `sweep` through `region` (where they are inside the
// interior) lose space: rays leaving through different facets may end
// differently, so each way out is judged as a region of its own (the part
// of `region` in that facet's column along the rays).
bool leaves_through_some_facet_losing_space(const SceneIndex& index, const FreeSpaceSweep& sweep,
                                            const HullInterior& interior, const std::vector<Eigen::Vector3d>& region,
                                            detail::SweepJudgeStorage& storage) {
  for (size_t j = 0; j < interior.facets.size(); ++j) {
    if (interior.facets[j].empty() || interior.planes[j].normal.dot(sweep.direction) <= 0.0) continue;
    detail::clip_to_column(region, interior.facets[j], sweep.direction, storage.through, storage.spare);
    if (!storage.through.empty() && detail::region_loses_space(index, sweep, interior, storage.through, storage))
      return true;
  }
  return false;
}

} // namespace

bool sweep_enters_hull(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                       detail::SweepJudgeStorage& storage) {
  if (interior.empty() || separated(sweep, interior)) return false;
  const Eigen::Vector3d& dir = sweep.direction;
  std::vector<Eigen::Vector3d>& part = storage.part;
  for (size_t k = 0; k < interior.facets.size(); ++k) {
    // The sweep enters through facets it meets from their outer side.
    if (interior.facets[k].empty() || interior.planes[k].normal.dot(dir) >= 0.0) continue;
    part = interior.facets[k];
    for (size_t i = 0; i < sweep.planes.size() && !part.empty(); ++i)
      clip_polygon_in_place(part, sweep.planes[i], sweep.insets[i], storage.spare);
    if (part.empty()) continue;
    if (leaves_through_some_facet_losing_space(index, sweep, interior, part, storage)) return true;
  }
  return false;
}

bool crossing_face_leaks(const SceneIndex& index, const FreeSpaceSweep& sweep, const HullInterior& interior,
                         detail::SweepJudgeStorage& storage) {
  if (interior.empty()) return false;
  for (const Plane& plane : interior.planes) {
    bool beyond = true;
    for (const Eigen::Vector3d& c : sweep.base) beyond &= plane.signed_distance(c) > 0.0;
    if (beyond) return false;
  }
  std::vector<Eigen::Vector3d>& inside = storage.part;
  inside = sweep.base;
  clip_polygon_to_planes_in_place(inside, interior.planes, 0.0, storage.spare);
  return !inside.empty() && leaves_through_some_facet_losing_space(index, sweep, interior, inside, storage);
}

bool sheet_enters_interior(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& sheet, double tol) {
  return !clip_polygon_to_planes(sheet, planes, tol).empty();
}

bool bar_crosses_polygon(const FlatPolygon& polygon, const BoundaryBar& bar, double tol) {
  if (!bar.is_sheet()) {
    const double da = polygon.plane.signed_distance(bar.a);
    const double db = polygon.plane.signed_distance(bar.b);
    if ((da > tol && db > tol) || (da < -tol && db < -tol)) return false;
    if (std::abs(da - db) <= tol) return false;
    const Eigen::Vector3d crossing = bar.a + (bar.b - bar.a) * (da / (da - db));
    return deepest_signed_distance(polygon.sides, crossing) < -tol;
  }
  // A sheet crosses only when it reaches beyond tol on both sides: one that
  // ends on the plane (a door jamb's sheet standing on the floor that runs
  // through the doorway) touches it and closes nothing.
  const std::vector<Eigen::Vector3d> sheet = bar.outline();
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const Eigen::Vector3d& p : sheet) {
    lowest = std::min(lowest, polygon.plane.signed_distance(p));
    highest = std::max(highest, polygon.plane.signed_distance(p));
  }
  if (lowest >= -tol || highest <= tol) return false;
  return meets_polygon_interior(polygon, sheet, tol);
}

} // namespace hullcover
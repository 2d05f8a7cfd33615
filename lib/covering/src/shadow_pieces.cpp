#include "shadow_pieces.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::detail {

namespace {

// column_planes, appended to `planes`.
void append_column_planes(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& dir,
                          std::vector<Plane>& planes) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : outline) centre += v;
  centre /= static_cast<double>(outline.size());
  for (size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector3d& u = outline[i];
    const Eigen::Vector3d& v = outline[(i + 1) % outline.size()];
    const Eigen::Vector3d side = (v - u).cross(dir);
    if (side.norm() <= kParallelSine * (v - u).norm()) continue;
    Plane plane{side.normalized(), side.normalized().dot(u)};
    if (plane.signed_distance(centre) > 0.0) plane = plane.flipped();
    planes.push_back(plane);
  }
}

} // namespace

std::vector<Plane> column_planes(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& dir) {
  std::vector<Plane> planes;
  planes.reserve(outline.size());
  append_column_planes(outline, dir, planes);
  return planes;
}

bool negligible(const std::vector<Eigen::Vector3d>& polygon, double tol) {
  if (polygon.size() < 3) return true;
  const Eigen::Vector3d normal = [&] {
    Eigen::Vector3d twice = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < polygon.size(); ++i) twice += polygon[i].cross(polygon[(i + 1) % polygon.size()]);
    return twice;
  }();
  if (!(normal.norm() > 0.0)) return true;
  // Negligible when the polygon lies within the width of some edge's line
  // (its narrowest width). Each edge is dropped at its first point beyond:
  // the checks on the hot path of every judged piece stay near linear.
  const double width = kNegligibleWidthInTolerances * tol;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d edge = polygon[(i + 1) % polygon.size()] - polygon[i];
    const Eigen::Vector3d across = normal.cross(edge);
    if (!(across.norm() > 0.0)) continue;
    const Eigen::Vector3d unit = across.normalized();
    const bool within = std::all_of(polygon.begin(), polygon.end(), [&](const Eigen::Vector3d& p) {
      return std::abs(unit.dot(p - polygon[i])) <= width;
    });
    if (within) return true;
  }
  return false;
}

namespace {

// The column along `dir` of the points of the triangle's plane inside its
// box grown by kFaceBoxMarginInTolerances x tol: rays meet a face only
// there (mesh_ray.h: past a sharp corner, the edges pushed out by tol reach
// further than the box's margin, where the face tree does not look). Two
// planes per axis; none for an axis the plane is perpendicular to (every
// point of it lies inside that slab).
void append_grown_box_column_planes(const std::vector<Eigen::Vector3d>& triangle, const Eigen::Vector3d& normal,
                                    const Eigen::Vector3d& dir, double tol, std::vector<Plane>& planes) {
  const double box_margin = kFaceBoxMarginInTolerances * tol;
  const double rate = normal.dot(dir);
  const double on_plane = normal.dot(triangle[0]);
  for (int k = 0; k < 3; ++k) {
    // Where the ray through x meets the plane, coordinate k is the affine
    // function x_k - dir_k (n.x - on_plane) / rate.
    const Eigen::Vector3d gradient = Eigen::Vector3d::Unit(k) - (dir[k] / rate) * normal;
    const double scale = gradient.norm();
    if (!(scale > 0.0)) continue;
    const double constant = dir[k] * on_plane / rate;
    const double highest = std::max({triangle[0][k], triangle[1][k], triangle[2][k]}) + box_margin;
    const double lowest = std::min({triangle[0][k], triangle[1][k], triangle[2][k]}) - box_margin;
    planes.push_back({gradient / scale, (highest - constant) / scale});
    planes.push_back({-gradient / scale, (constant - lowest) / scale});
  }
}

} // namespace

ShadowColumn shadow_column(const std::vector<Eigen::Vector3d>& triangle, const Eigen::Vector3d& dir, double tol) {
  const Eigen::Vector3d normal = (triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).normalized();
  ShadowColumn column;
  column.sides.reserve(9);  // three sides and two planes per axis of the box
  append_column_planes(triangle, dir, column.sides);
  for (Plane& plane : column.sides) {
    // The side's edge moved out by tol in the triangle's plane moves the
    // column's side by tol times the cosine between the two outward
    // normals (the edge's, in the plane, is the side's projected into it).
    const double across = plane.normal.dot(normal);
    plane.offset += tol * std::sqrt(std::max(0.0, 1.0 - across * across));
  }
  append_grown_box_column_planes(triangle, normal, dir, tol, column.sides);
  return column;
}

bool ShadowColumn::misses(const std::vector<Eigen::Vector3d>& region) const {
  for (const Plane& plane : sides) {
    bool all_beyond = true;
    for (const Eigen::Vector3d& p : region) all_beyond &= plane.signed_distance(p) > 0.0;
    if (all_beyond) return true;
  }
  return false;
}

ShadowSplit split_by_shadow(const std::vector<Eigen::Vector3d>& region, const ShadowColumn& column, double tol) {
  ShadowSplit split;
  split.inside = region;
  std::vector<Eigen::Vector3d> beside, clipped;
  for (const Plane& plane : column.sides) {
    split_polygon(split.inside, plane, clipped, beside);
    if (!negligible(beside, tol)) split.beside.push_back(beside);
    split.inside.swap(clipped);
  }
  if (negligible(split.inside, tol)) split.inside.clear();
  return split;
}

ShadowSplit split_by_shadow(const std::vector<Eigen::Vector3d>& region, const std::vector<Eigen::Vector3d>& triangle,
                            const Eigen::Vector3d& dir, double tol) {
  return split_by_shadow(region, shadow_column(triangle, dir, tol), tol);
}

Eigen::Vector3d ray_base(const FreeSpaceSweep& sweep, const Eigen::Vector3d& point) {
  return point + sweep.start.signed_distance(point) * sweep.direction;
}

std::pair<double, double> range_over(const Affine& f, const std::vector<Eigen::Vector3d>& polygon) {
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const Eigen::Vector3d& p : polygon) {
    lowest = std::min(lowest, f(p));
    highest = std::max(highest, f(p));
  }
  return {lowest, highest};
}

std::optional<Plane> splitting_cut(const std::vector<Eigen::Vector3d>& piece, const Affine& margin, double tol) {
  if (!(margin.gradient.norm() > 0.0)) return std::nullopt;
  const Plane cut = margin.zero_plane();
  const std::vector<Eigen::Vector3d> negative = clip_polygon(piece, cut.flipped(), 0.0);
  if (negligible(negative, tol)) return std::nullopt;
  return cut;
}

Affine distance_to_point(const FreeSpaceSweep& sweep) {
  return {-sweep.start.normal, sweep.start.offset};
}

Affine distance_to_plane(const FreeSpaceSweep& sweep, const Plane& face) {
  // The base is p + (start.p - start.offset) dir; the face's plane lies
  // -face.sd(base) / slope further along.
  const double slope = face.normal.dot(sweep.direction);
  return {-(face.normal + slope * sweep.start.normal) / slope, (face.offset + slope * sweep.start.offset) / slope};
}

} // namespace hullcover::detail

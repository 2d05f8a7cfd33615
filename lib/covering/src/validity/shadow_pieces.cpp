#include "validity/shadow_pieces.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace hullcover::detail {

namespace {

// The outward planes of the column of `outline` along `dir`, one by one
// to `emit` (column_planes).
template <class Emit>
void for_each_column_plane(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& dir, Emit&& emit) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : outline) centre += v;
  centre /= static_cast<double>(outline.size());
  for (size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector3d& u = outline[i];
    const Eigen::Vector3d& v = outline[(i + 1) % outline.size()];
    const Eigen::Vector3d side = (v - u).cross(dir);
    const double length = side.norm();
    if (length <= kParallelSine * (v - u).norm()) continue;
    const Eigen::Vector3d normal = side / length;
    Plane plane{normal, normal.dot(u)};
    if (plane.signed_distance(centre) > 0.0) plane = plane.flipped();
    emit(plane);
  }
}

} // namespace

std::vector<Plane> column_planes(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& dir) {
  std::vector<Plane> planes;
  planes.reserve(outline.size());
  for_each_column_plane(outline, dir, [&](const Plane& plane) { planes.push_back(plane); });
  return planes;
}

void clip_to_column(const std::vector<Eigen::Vector3d>& polygon, const std::vector<Eigen::Vector3d>& outline,
                    const Eigen::Vector3d& dir, std::vector<Eigen::Vector3d>& out,
                    std::vector<Eigen::Vector3d>& spare) {
  out.assign(polygon.begin(), polygon.end());
  for_each_column_plane(outline, dir, [&](const Plane& plane) {
    if (!out.empty()) clip_polygon_in_place(out, plane, 0.0, spare);
  });
}

bool negligible(const std::vector<Eigen::Vector3d>& polygon, double tol) {
  if (polygon.size() < 3) return true;
  // Twice the area, as a vector along the normal. Taken about a corner:
  // about the origin, a piece far smaller than its coordinates would lose
  // its area, and its normal with it, to cancellation.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double perimeter = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d& next = polygon[(i + 1) % polygon.size()];
    normal += (polygon[i] - polygon[0]).cross(next - polygon[0]);
    perimeter += (next - polygon[i]).norm();
  }
  if (!(normal.norm() > 0.0)) return true;
  const double width = kNegligibleWidthInTolerances * tol;
  // Most pieces are far wider, and a bound tells at once: a convex
  // polygon's width is at least its area over its diameter, and its
  // diameter at most half its perimeter, so width >= twice its area over
  // its perimeter. Twice the threshold leaves rounding no say in it.
  if (normal.norm() > 2.0 * width * perimeter) return false;
  // Negligible when the polygon lies within the width of some edge's line
  // (its narrowest width). Each edge is dropped at its first point beyond:
  // the checks on the hot path of every judged piece stay near linear.
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
                                    const Eigen::Vector3d& dir, double tol, ShadowColumn& column) {
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
    column.side_planes[column.side_count++] = {gradient / scale, (highest - constant) / scale};
    column.side_planes[column.side_count++] = {-gradient / scale, (constant - lowest) / scale};
  }
}

} // namespace

ShadowColumn shadow_column(const std::vector<Eigen::Vector3d>& triangle, const Eigen::Vector3d& dir, double tol) {
  // Three sides and six box planes fill the column's array: more corners
  // would overrun it.
  assert(triangle.size() == 3);
  const Eigen::Vector3d normal = (triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).normalized();
  ShadowColumn column;
  for_each_column_plane(triangle, dir, [&](Plane plane) {
    // The side's edge moved out by tol in the triangle's plane moves the
    // column's side by tol times the cosine between the two outward
    // normals (the edge's, in the plane, is the side's projected into it).
    const double across = plane.normal.dot(normal);
    plane.offset += tol * std::sqrt(std::max(0.0, 1.0 - across * across));
    column.side_planes[column.side_count++] = plane;
  });
  append_grown_box_column_planes(triangle, normal, dir, tol, column);
  return column;
}

bool ShadowColumn::misses(const std::vector<Eigen::Vector3d>& region) const {
  for (const Plane& plane : *this) {
    bool all_beyond = true;
    for (const Eigen::Vector3d& p : region) all_beyond &= plane.signed_distance(p) > 0.0;
    if (all_beyond) return true;
  }
  return false;
}

void split_by_shadow(const std::vector<Eigen::Vector3d>& region, const ShadowColumn& column, double tol,
                     ShadowSplit& split) {
  split.inside.assign(region.begin(), region.end());
  split.beside.clear();
  for (const Plane& plane : column) {
    // Every corner strictly inside: nothing beside, the inside unchanged.
    if (corners_strictly_inside(split.inside, plane, 0.0)) continue;
    split_polygon(split.inside, plane, split.cut, split.off_cut);
    if (!negligible(split.off_cut, tol)) split.beside.push_back(split.off_cut);
    split.inside.swap(split.cut);
  }
  if (negligible(split.inside, tol)) split.inside.clear();
}

ShadowSplit split_by_shadow(const std::vector<Eigen::Vector3d>& region, const ShadowColumn& column, double tol) {
  ShadowSplit split;
  split_by_shadow(region, column, tol, split);
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

Affine distance_to_point(const FreeSpaceSweep& sweep) { return {-sweep.start.normal, sweep.start.offset}; }

Affine distance_to_plane(const FreeSpaceSweep& sweep, const Plane& face) {
  // The base is p + (start.p - start.offset) dir; the face's plane lies
  // -face.sd(base) / slope further along.
  const double slope = face.normal.dot(sweep.direction);
  return {-(face.normal + slope * sweep.start.normal) / slope, (face.offset + slope * sweep.start.offset) / slope};
}

} // namespace hullcover::detail

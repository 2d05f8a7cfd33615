#include "hullcover/geometry/point_hull.h"

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/incremental_hull.h"

#include <Eigen/Geometry>

#include <array>

namespace hullcover {
namespace {

// The index of the point farthest by `distance`, and that distance.
template <typename Distance>
std::pair<int, double> farthest(const std::vector<Eigen::Vector3d>& points, Distance distance) {
  int best = 0;
  double best_distance = -1.0;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const double d = distance(points[i]);
    if (d > best_distance) {
      best = i;
      best_distance = d;
    }
  }
  return {best, best_distance};
}

} // namespace

std::optional<ConvexPolytope> convex_hull_of_points(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 4) return std::nullopt;
  for (const Eigen::Vector3d& p : points)
    if (!p.allFinite()) return std::nullopt;
  const Aabb bounds = bounding_box_of(points);
  const Eigen::Vector3d& low = bounds.min;
  const double tol = kPointHullRelativeTolerance * bounds.diagonal();
  if (!(tol > 0.0)) return std::nullopt;

  // The largest tetrahedron the extremes give: two far points, the point
  // farthest from their line, the point farthest from their plane.
  const int i0 = farthest(points, [&](const Eigen::Vector3d& p) { return (p - low).squaredNorm(); }).first;
  const int i1 = farthest(points, [&](const Eigen::Vector3d& p) { return (p - points[i0]).squaredNorm(); }).first;
  const Eigen::Vector3d axis = (points[i1] - points[i0]).normalized();
  const auto [i2, line_distance] =
      farthest(points, [&](const Eigen::Vector3d& p) { return (p - points[i0]).cross(axis).norm(); });
  if (line_distance <= tol) return std::nullopt;
  const Eigen::Vector3d normal = (points[i1] - points[i0]).cross(points[i2] - points[i0]).normalized();
  const auto [i3, plane_distance] =
      farthest(points, [&](const Eigen::Vector3d& p) { return std::abs(normal.dot(p - points[i0])); });
  if (plane_distance <= tol) return std::nullopt;

  ConvexPolytope hull;
  const std::array<int, 4> corners{i0, i1, i2, i3};
  for (int c : corners) {
    hull.vertices.push_back(points[c]);
    hull.vertex_ids.push_back(c);
  }
  const Eigen::Vector3d centre = (hull.vertices[0] + hull.vertices[1] + hull.vertices[2] + hull.vertices[3]) / 4.0;
  const std::array<std::array<int, 3>, 4> triangles{{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};
  for (std::array<int, 3> t : triangles) {
    Eigen::Vector3d n = (hull.vertices[t[1]] - hull.vertices[t[0]]).cross(hull.vertices[t[2]] - hull.vertices[t[0]]);
    if (n.dot(hull.vertices[t[0]] - centre) < 0.0) {
      std::swap(t[1], t[2]);
      n = -n;
    }
    n.normalize();
    hull.facets.push_back({t[0], t[1], t[2]});
    hull.planes.push_back({n, n.dot(hull.vertices[t[0]])});
  }
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    if (i == i0 || i == i1 || i == i2 || i == i3) continue;
    std::optional<ConvexPolytope> grown = add_point_to_hull(hull, points[i], i, tol);
    if (!grown) return std::nullopt;
    hull = std::move(*grown);
  }
  return hull;
}

} // namespace hullcover

#pragma once
/// \file planar_hull.h
/// Convex hulls of points lying in one plane (the paper's planar patches),
/// computed in 2D in a frame of that plane.

#include "hullcover/geometry/convex_polytope.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace hullcover {

/// An orthonormal frame (u, v, normal) with its origin on a plane.
struct PlaneFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();
  Eigen::Vector3d v = Eigen::Vector3d::UnitY();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();

  /// A frame with the given unit normal; u and v are chosen from the normal
  /// alone, so the same normal always gives the same frame.
  static PlaneFrame from_normal(const Eigen::Vector3d& origin, const Eigen::Vector3d& unit_normal);

  Eigen::Vector2d to_plane(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = p - origin;
    return {d.dot(u), d.dot(v)};
  }
};

/// Indices of the convex hull of `points`, counter-clockwise. A corner
/// within `tol` of the line through its neighbours (or of a neighbour) is
/// dropped, so near-collinear drift adds no vertex; every point then lies
/// inside the polygon or within `tol` of it. An empty result means the
/// points are collinear within `tol`.
std::vector<int> convex_hull_2d(const std::vector<Eigen::Vector2d>& points, double tol);

/// The mean of `points` (a polygon's vertex centroid; in its interior when
/// the polygon is convex). Requires at least one point.
Eigen::Vector3d centroid_of(const std::vector<Eigen::Vector3d>& points);

/// Outward side planes of the convex polygon `corners` (counter-clockwise
/// seen from `normal`): one plane per edge, containing the edge and
/// `normal`, its own normal pointing away from the polygon.
std::vector<Plane> polygon_side_planes(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal);

} // namespace hullcover

namespace hullcover {

/// A convex polygon in 3D: what a planar patch's hull is (paper 4.1, "when
/// p is planar, the QHull package would return H as a convex 2D polygon").
struct FlatPolygon {
  /// Corners on `plane`, counter-clockwise seen from the front.
  std::vector<Eigen::Vector3d> corners;
  /// Mesh vertex id of each corner.
  std::vector<int> corner_vertices;
  /// The polygon's plane; its normal is the front normal.
  Plane plane;
  /// Outward side planes, one per edge (corner i to i+1).
  std::vector<Plane> sides;
};

/// How far the points `vertex_ids` (of `positions`) reach along unit
/// `normal`: {lowest, highest} of normal.p. `vertex_ids` must not be empty.
std::pair<double, double> extent_along(const Eigen::Vector3d* positions, const std::vector<int>& vertex_ids,
                                       const Eigen::Vector3d& normal);
/// The same, positions in an owned or a mapped array.
template <class Positions>
std::pair<double, double> extent_along(const Positions& positions, const std::vector<int>& vertex_ids,
                                       const Eigen::Vector3d& normal) {
  return extent_along(positions.data(), vertex_ids, normal);
}

/// The convex polygon of mesh vertices `vertex_ids` (positions from
/// `positions`) in the plane with unit normal `normal` through the middle
/// of their slab along it; corners are projected onto that plane. Points within `tol` of
/// a hull edge are not corners. Returns an empty polygon when the points
/// are collinear within `tol`.
FlatPolygon make_flat_polygon(const Eigen::Vector3d* positions, const std::vector<int>& vertex_ids,
                              const Eigen::Vector3d& normal, double tol);
/// The same, positions in an owned or a mapped array.
template <class Positions>
FlatPolygon make_flat_polygon(const Positions& positions, const std::vector<int>& vertex_ids,
                              const Eigen::Vector3d& normal, double tol) {
  return make_flat_polygon(positions.data(), vertex_ids, normal, tol);
}

/// Triangle a, b, c as a flat polygon facing the way it winds: corners in
/// that order, no mesh vertex ids (-1). The corners must not be collinear
/// (a zero normal gives NaN planes); callers check the triangle's height
/// first. Cannot fail otherwise.
FlatPolygon flat_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// True when the part of convex polygon `part` (a triangle, a sheet) lying
/// within `tol` of `polygon`'s plane reaches the polygon's relative interior
/// shrunk by `tol`.
bool meets_polygon_interior(const FlatPolygon& polygon, const std::vector<Eigen::Vector3d>& part, double tol);

/// The flat polygon as a polytope of thickness 0: a front and a back facet
/// on the same corners; with `side_planes`, also the planes that bound it
/// sideways (see ConvexPolytope), without them a closed surface that
/// add_point_to_hull can grow.
ConvexPolytope flat_polytope(const FlatPolygon& polygon, bool side_planes);

} // namespace hullcover

#pragma once
/// \file point_hull.h
/// The convex hull of a small point set (a query shape's vertices) without
/// Qhull, so the runtime links no hull library. The decomposer builds its
/// hulls with Qhull (hullcover/covering/convex_hull_3d.h), which also
/// merges coplanar facets; this one keeps triangles.

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/tolerances.h"

#include <optional>
#include <vector>

namespace hullcover {

/// The convex hull of `points`: triangle facets counter-clockwise seen from
/// outside, outward unit planes, `vertex_ids` the indices of the points used.
/// Grown from the largest tetrahedron of the points, one point at a time
/// (add_point_to_hull). O(n h) for h hull vertices: meant for tens of
/// points, not thousands.
/// Returns nothing for fewer than 4 points, non-finite points, points
/// within kPointHullRelativeTolerance x extent of a plane (no 3D hull), or a
/// point set the incremental update cannot take cleanly.
std::optional<ConvexPolytope> convex_hull_of_points(const std::vector<Eigen::Vector3d>& points);

} // namespace hullcover

#pragma once
/// \file validity_conditions.h
/// The paper's validity conditions (section 4.1) for a candidate hull,
/// tested against the whole mesh with the one tolerance.
///
///  1. the hull contains no mesh vertex and no part of a mesh edge in its
///     interior;
///  2. every face of the patch lies on the hull's boundary with its normal
///     pointing out (`planes_support_points`);
///  3. no boundary constraint bar penetrates the hull (for a flat polygon:
///     crosses its relative interior);
///  4. for a flat polygon, no face outside the patch that touches the
///     polygon's relative interior has a vertex on its negative side.
///
/// In `ValidityMode::exact` (the index's mode) the conditions of
/// exact_conditions.h are checked too: bars become sheets along whole open
/// edges, and faces must not face into or cross a solid hull.

#include "hullcover/lib/convex_polytope.h"
#include "hullcover/lib/planar_hull.h"
#include "hullcover/lib/scene_index.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace hullcover {

/// Which condition a candidate broke first (or `valid`).
enum class Validity : std::uint8_t {
  valid,
  vertex_inside,       ///< condition 1
  edge_inside,         ///< condition 1
  face_not_on_hull,    ///< condition 2
  bar_inside,          ///< condition 3, solid hull
  bar_crosses_polygon, ///< condition 3, flat polygon
  face_below_polygon,  ///< condition 4
  too_many_vertices,   ///< the option max_hull_vertices
  materials_differ,    ///< materials are kept apart
  hull_failed,         ///< Qhull rejected the points (treated as invalid)
  front_space_inside,    ///< exact E1: a face's front space enters the hull
  opening_inside,        ///< exact E2: the opening beyond an open edge enters the hull
  face_crosses_hull,     ///< exact E3: a face's interior deeper than tol inside
};
inline constexpr int kValidityCount = 13;

/// Stable snake_case name, for reports.
const char* validity_name(Validity v);

/// Condition 2 between two point sets: every plane (outward, from faces of
/// one patch) has every point (hull vertices of the other patch) behind it
/// or within `tol` in front.
bool planes_support_points(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& points, double tol);

/// Conditions 1 and 3 (exact mode: and E1-E3) for a solid hull. `scratch`
/// is reused storage.
Validity check_solid_hull(const SceneIndex& index, const ConvexPolytope& hull, std::vector<int>& scratch);

/// Conditions 3 (exact mode: E2) and 4 for a flat polygon; `in_patch(face)` tells whether a
/// face belongs to the patch (condition 4 looks only at faces outside it).
Validity check_flat_polygon(const SceneIndex& index, const FlatPolygon& polygon,
                            const std::function<bool(int)>& in_patch, std::vector<int>& scratch);

/// Bounding box of points.
Aabb bounding_box_of(const std::vector<Eigen::Vector3d>& points);

} // namespace hullcover

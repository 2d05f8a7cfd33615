#pragma once
/// \file incremental_hull.h
/// Growing a convex hull by a few points without rebuilding it
/// (beneath-beyond). During merging most merges add one triangle to a
/// curved patch, i.e. one point to a known hull; rebuilding that hull with
/// Qhull costs tens of microseconds of set-up each time.

#include "hullcover/geometry/convex_polytope.h"

#include <optional>
#include <vector>

namespace hullcover {

/// `hull` with point `p` (mesh vertex id `id`) added: the facets `p` sees
/// are replaced by triangles from `p` to their horizon. A point less than
/// kVisibleBeyondTolerances x tol in front of every facet leaves the hull
/// unchanged when it is also that near its facets (past a sharp edge a point
/// can be that near every plane and far from the hull: then nothing is
/// returned, and the caller rebuilds). New facets
/// are triangles even where nearly coplanar with a neighbour (a rebuild by
/// Qhull merges those).
///
/// Returns nothing when the update cannot be made cleanly (a degenerate new
/// triangle, an open surface, or a result that fails its own convexity
/// check); the caller then rebuilds the hull from scratch. `hull` must be a closed polytope (every facet edge shared
/// by exactly two facets) with `vertex_ids` filled; a flat polygon given as
/// its front and back facets qualifies, for points off its plane.
std::optional<ConvexPolytope> add_point_to_hull(const ConvexPolytope& hull, const Eigen::Vector3d& p, int id,
                                                double tol);

} // namespace hullcover

#pragma once
/// \file flat_polygon_cover.h
/// Exact mode: a flat polygon may lie only where the mesh has faces. A flat
/// hull has no inside for the free-space rays (docs/definitions-and-proofs.md), yet a ray or a
/// shape crossing it collides; the paper's condition 4 catches a polygon
/// spanning a hole only when a face lies below it (a pit), not a window in
/// a wall with free space through it.

#include "hullcover/covering/validity.h"
#include "hullcover/geometry/planar_hull.h"
#include "validity/scene_index.h"

#include <vector>

namespace hullcover {

/// How many pieces the uncovered part of a polygon may break into before
/// the check gives up (and refuses the merge): a bound on the work, where
/// giving up is conservative.
inline constexpr int kMaxUncoveredPieces = 256;

/// Whether `merged`, the flat polygon of two planar patches whose own
/// polygons have the corners `corners_a` and `corners_b` (each covered by
/// mesh faces, by induction from single triangles), spans area of its plane
/// that no face within the planar slab (kPlanarSlabInTolerances x tol of
/// the plane, either winding) covers: `polygon_spans_gap`, else `valid`.
/// Decided exactly with convex pieces in the plane: the merged polygon less
/// both parts, less every face that reaches the rest; pieces no wider than
/// about 2 tol (area <= tol x perimeter) are dropped. Also
/// `polygon_spans_gap` past kMaxUncoveredPieces pieces. `slab_in_tolerances`
/// widens the slab for a re-check of a finished patch
/// (kRecheckSlabInTolerances).
Validity check_polygon_covered(const SceneIndex& index, const FlatPolygon& merged,
                               const std::vector<Eigen::Vector3d>& corners_a,
                               const std::vector<Eigen::Vector3d>& corners_b, std::vector<int>& scratch,
                               double slab_in_tolerances = kPlanarSlabInTolerances);

} // namespace hullcover

#pragma once
/// \file uncovered_boundary.h
/// The parts of a candidate hull's boundary that no face of its own lies
/// on: where the hull's surface runs through space, the only places a
/// movement covering must prove far enough from every reachable centre
/// (movement_validity.h). A point of the boundary on a face is as far from
/// every centre as the face, at least r.

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/mesh.h"
#include "movement/scene_clearance.h"

#include <vector>

namespace hullcover::detail {

/// A convex polygon on a plane of a hull's boundary.
struct BoundaryPiece {
  std::vector<Eigen::Vector3d> corners;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); ///< the hull's outward normal there (either side of a flat hull)
};

/// A stretch of one of the hull's edges (where two facets meet, or a flat
/// hull's rim) along an uncovered piece.
struct BoundarySegment {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
};

/// The uncovered boundary: polygons in the hull's facets, and the stretches
/// of the hull's edges that bound them. A point of space nearest to the
/// hull at a point of the boundary that is uncovered lies over a piece
/// (along its normal) or around one of these stretches.
struct UncoveredBoundary {
  std::vector<BoundaryPiece> pieces;
  std::vector<BoundarySegment> segments;
  /// The pieces outgrew kMostUncoveredPieces (a facet cut by many triangles
  /// that do not tile it): the boundary is not complete, so nothing may be
  /// proven from it.
  bool overflow = false;
  void clear() {
    pieces.clear();
    segments.clear();
    overflow = false;
  }
};

/// The most pieces one hull's uncovered boundary is split into before it
/// is given up (UncoveredBoundary::overflow): each triangle taken from a
/// piece can split it in up to six, so the count is bounded, not the
/// triangles.
inline constexpr size_t kMostUncoveredPieces = 4096;

/// Appends to `out` the parts of the boundary of `hull` (a flat hull: its
/// polygon, once) that lie on no triangle of the scene (any triangle: a
/// point on one is as far from every centre as it) and on no part of the
/// boundaries of `known` (hulls inside `hull` whose own boundaries were
/// proven before: where the two boundaries meet, the merged one is
/// theirs). A triangle or polygon whose corners lie within `tol` of the
/// facet's plane covers the part of the facet within `tol` of it (its
/// sides pushed out by tol, its corners capped at tol beyond them, so no
/// point counts as covered farther than tol * sqrt(2) from it). A side of
/// a piece within `tol` of a side of its facet is a segment. Stops with
/// `out.overflow` set once the pieces outnumber kMostUncoveredPieces.
void uncovered_boundary(const SceneClearance& scene, const ConvexPolytope& hull, bool flat,
                        const std::vector<const ConvexPolytope*>& known, double tol, UncoveredBoundary& out);

} // namespace hullcover::detail

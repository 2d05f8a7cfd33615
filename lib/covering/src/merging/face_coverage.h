#pragma once
// Coverage (docs/definitions-and-proofs.md: every point of every face on the boundary of some
// hull, within tol), made sure of once the hulls are made. Two kinds of
// face can be left off every hull:
// - Faces thinner than tol (MeshConnectivity::zero_area: their smallest
//   height at most tol) join no patch: their normal is not reliable enough
//   for the validity conditions. Most lie along a neighbour's edge, within
//   tol of its hull. Some do not: a fan of slivers 1 unit wide and 40 long
//   (a Cube map's trimmed wall) has real area, and nothing else covers it.
// - A face can lie off its own patch's hull. On recast's dungeon a hull
//   grown through a stair rail 0.56 tol thick missed corners of 6 faces by
//   up to 140 tol: growing a hull took a point within a sliver of every
//   plane as on it, though it lay far past a sharp edge. That growth is
//   fixed (incremental_hull.h); this pass stays, as the guarantee.
// Such faces get flat hulls of their own, which have no inside and so take
// no free space: one convex polygon for a group of them that is exactly
// their union, else each its own triangle.

#include "cells/cell_merging.h"

namespace hullcover::detail {

/// What making sure of coverage did.
struct FaceCoverageCount {
  /// Faces no patch's hull covered that got a flat hull of their own (a
  /// polygon per group, or a triangle each); of them, thinner than tol:
  int covered = 0;
  int thin_covered = 0;
  /// Faces no hull covers and too thin for even a flat triangle (the sine
  /// of their smallest angle under kParallelSine: no plane to give it).
  /// Their points lie within their height (under tol) of their longest edge.
  int bare = 0;
};

/// Appends to `covering.hulls` flat hulls for the faces of `stages` (those
/// with three distinct corners) that no hull of `covering` covers within
/// the island's tol: some corner farther than that from every hull whose
/// box it reaches (distance to the hull's facets, 0 inside it; within tol
/// of one hull at every corner, the whole face is, the hull being convex).
/// A face a hull claims but does not cover leaves that hull's claims (a
/// hull left claiming nothing is dropped: it covers none of its faces).
/// Uncovered faces sharing edges form a group; a group that is exactly one
/// convex polygon gets it, else each face gets its own triangle. Hulls are
/// appended in the order of their groups' first faces; the caller sorts.
/// Faces are checked on `threads` threads; the result does not depend on
/// how many. Deterministic. Throws only std::bad_alloc.
FaceCoverageCount cover_uncovered_faces(const DecompositionStages& stages, Covering& covering, int threads);

} // namespace hullcover::detail

#pragma once
// Faces thinner than tol (MeshConnectivity::zero_area: their smallest
// height is at most tol) join no patch: their normal is not reliable enough
// for the validity conditions. Most lie along a neighbour's edge, within
// tol of its hull. Some do not: a fan of slivers 1 unit wide and 40 long
// (a Cube map's trimmed wall) has real area, and nothing else covers it.
// DESIGN.md's coverage asks that every point of every face lie on a hull
// within tol, so such faces get flat hulls of their own, which have no
// inside and so take no free space: one convex polygon for a group of them
// that is exactly their union, else each its own triangle.

#include "cell_merging.h"

namespace hullcover::detail {

/// What covering the thin faces did.
struct ThinFaceCount {
  int covered = 0;  ///< thin faces given a flat hull of their own (a polygon per group, or a triangle each)
  /// Thin faces no hull covers and too thin for a flat triangle (a sine of
  /// their smallest angle under kParallelSine: no plane to give it). Their
  /// points lie within their height (under tol) of their longest edge.
  int bare = 0;
};

/// Appends to `covering.hulls` flat hulls for the thin faces of `stages`
/// (those with distinct corners) that no hull of `covering` covers: some
/// corner farther than the island's tol from every hull (distance to the
/// hull's facets, 0 inside it; within tol of one hull, the whole face is,
/// the hull being convex). Uncovered thin faces sharing edges form a group;
/// a group that is exactly one convex polygon (see thin_face_cover.cpp)
/// gets it, else each face gets its own triangle. Hulls are appended in
/// the order of their groups' first faces; the caller sorts.
/// Deterministic. Throws only std::bad_alloc.
ThinFaceCount cover_thin_faces(const DecompositionStages& stages, Covering& covering);

} // namespace hullcover::detail

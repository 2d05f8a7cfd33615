#pragma once
/// \file flat_hull_thickening.h
/// Flat hulls as engines take them. A covering's flat hulls are convex
/// polygons of thickness 0 (exact where a double-sided sheet leaves no room
/// for a prism); engines reject or drop flat convex shapes, so an export
/// gives each one a thickness:
///
///  - backwards, behind its front face, where nothing faces back at it: the
///    space behind a face is free only along rays from other faces, and
///    rays whose first hit is that back are enclosed (docs/definitions-and-proofs.md);
///  - split across both sides, half each, where a double-sided sheet leaves
///    no room behind (another flat hull lies in the same plane facing the
///    other way and overlaps it): the back is the other side's front space.
///
/// Either way every point a thickened hull adds lies within the thickness
/// of its polygon, so the free space an export can lose lies within the
/// thickness of the mesh (`hullcover audit --max-deviation` proves it of
/// the written file). `.hcw` files and HullWorld keep the exact polygons.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/convex_polytope.h"

#include <vector>

namespace hullcover::app {

/// Hulls ready for an engine, and what thickening did.
struct ThickenedHulls {
  std::vector<ConvexPolytope> hulls; ///< one per input hull, same order
  int flat = 0;                      ///< flat hulls given a thickness
  int split = 0;                     ///< of those, split across both sides (double-sided sheets)
  double thickness = 0.0;            ///< scene units
};

/// Gives every flat hull of `hulls` the thickness `thickness` (scene units,
/// > 0) as described above; solid hulls are kept as they are. `tol` (scene
/// units) decides coplanarity and overlap of a double-sided sheet's two
/// sides.
ThickenedHulls thicken_flat_hulls(const std::vector<bvh::RuntimeHull>& hulls, double thickness, double tol);

/// True when `shape` is a flat polygon: two facets on the same corners
/// facing opposite ways (the front is facets[0]).
bool is_flat_polygon(const ConvexPolytope& shape);

} // namespace hullcover::app

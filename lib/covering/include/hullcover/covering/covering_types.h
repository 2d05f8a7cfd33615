#pragma once
/// \file covering_types.h
/// What a covering is: its hulls and everything needed to reproduce them.
/// Apart from covering.h (the entry point, decompose()) so that code that
/// only reads a covering does not depend on how one is made.

#include "hullcover/covering/decompose_options.h"
#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/mesh/tolerance.h"

#include <vector>

namespace hullcover {

/// One convex hull of the covering.
struct CoveringHull {
  ConvexPolytope polytope;
  std::vector<int> faces; ///< mesh faces it covers, ascending
  bool planar = false;    ///< from a planar patch (a prism or flat polygon)
  double thickness = 0.0; ///< prism thickness (planar only; 0 = flat polygon)
  int material = 0;       ///< material id of its faces (the smallest, if they differ)
  /// The cell of its lowest face (merge_cells.h): the section the runtime
  /// file puts it in, for a server that streams a world cell by cell.
  int cell = 0;
  double volume = 0.0;
  /// Per plane of `polytope`: whether a contact there is the surface's own
  /// (a facet on a mesh face; a flat polygon's rim edge where the surface
  /// ends or bends), false where the surface runs on into other hulls. The
  /// runtime turns contact normals away from the others (no ghost
  /// collisions at seams).
  std::vector<bool> surface_planes;
};

/// The result: hulls and everything needed to reproduce them.
struct Covering {
  std::vector<CoveringHull> hulls; ///< ordered by their first face
  Tolerance tolerance;
  double bar_half_length = 0.0;
  /// Exact mode: how far free space is kept, scene units. Without a cap
  /// (the default) a length beyond which no hull lies.
  double free_space_reach = 0.0;
  bool free_space_capped = false;   ///< the user asked for a reach
  double prism_thickness_cap = 0.0; ///< the given one, or the largest island's (each island has its own)
  double near_merge_distance = 0.0; ///< scene units; 0 = no near merges; the given one, or the largest island's
  bool dissolve = false;            ///< whether dissolving ran (resolved DecomposeOptions::dissolve)
  /// Diagonal of each island (hullcover/mesh/mesh_islands.h numbering), scene
  /// units: its default near-merge distance and prism cap scale with it.
  std::vector<double> island_extents;
  /// Cell side per island (hullcover/mesh/mesh_islands.h numbering), scene
  /// units; 0 where an island is one cell (merge_cells.h).
  std::vector<double> cell_sizes;
  DecomposeOptions options; ///< as given (progress callback included)
  CoveringStatistics statistics;
};

} // namespace hullcover

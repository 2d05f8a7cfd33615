#pragma once
/// \file mesh_islands.h
/// Islands: the pieces of a scene that sit together (a map, a building), as
/// opposed to a world that lays many of them side by side. The defaults that
/// scale with a scene follow islands, not the whole world's extent, so a map
/// keeps its tolerance and its hulls when it is placed in a larger world
/// (../shared/DESIGN.md, "tolerance"): each island has its own tolerance
/// (hullcover/mesh/tolerance.h), near-merge distance and prism cap; and the decomposer lays its cells
/// out per island (hullcover/covering/merge_cells.h).

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/mesh.h"

#include <vector>

namespace hullcover {

/// Connected pieces whose boxes, each grown by this fraction of its own
/// diagonal, overlap belong to one island (transitively). The fraction is
/// the default prism cap's: what sits closer than a hull may reach is one
/// place. Far-apart maps (any gap wider than 1% of each map) stay apart.
inline constexpr double kIslandGapRelative = 0.01;

/// The islands of a mesh.
struct MeshIslands {
  /// Island of each triangle (0 .. boxes.size() - 1), numbered by their
  /// lowest triangle, so the numbering does not depend on vertex order.
  std::vector<int> island_of_face;
  /// Box of each island's referenced vertices, scene units.
  std::vector<Aabb> boxes;
  /// Triangles per island.
  std::vector<int> face_counts;

  /// The largest island diagonal (0 for no islands).
  double largest_diagonal() const;
  /// The smallest island diagonal above 0 (0 when every island is a
  /// point): the extent an island of no extent takes for its tolerance.
  double smallest_diagonal() const;
};

/// Finds the islands of `mesh`. Triangles are connected when they share a
/// vertex index or a bit-identical position (no tolerance is known yet: the
/// tolerance is chosen from the islands). O(n log n). The mesh must pass
/// validate_mesh; an empty mesh has no islands.
MeshIslands find_mesh_islands(const Mesh& mesh);

} // namespace hullcover

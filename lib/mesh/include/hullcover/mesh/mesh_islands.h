#pragma once
/// \file mesh_islands.h
/// Islands: the pieces of a scene that sit together (a map, a building), as
/// opposed to a world that lays many of them side by side. The defaults that
/// scale with a scene follow islands, not the whole world's extent, so a map
/// keeps its tolerance and its hulls when it is placed in a larger world
/// (docs/definitions-and-proofs.md, "The tolerance"): each island has its own tolerance
/// (hullcover/mesh/tolerance.h), near-merge distance and prism cap; and the decomposer lays its cells
/// out per island (hullcover/covering/merge_cells.h).

#include "hullcover/geometry/aabb.h"
#include "hullcover/geometry/mesh.h"

#include <vector>

namespace hullcover {

/// Connected pieces whose boxes, each grown by this fraction of its own
/// diagonal, overlap belong to one island (transitively): pieces that touch
/// but for rounding or a crack (kit pieces, terrain tiles) are one place,
/// and a map's props inside its box join it. Maps laid side by side stay
/// apart when the gap between them is wider than 0.1% of their diagonals
/// added up: a world of maps 7,000 units across laid 64 units apart keeps
/// each map its own island, so its tolerance, cells and hulls are those it
/// has alone.
inline constexpr double kIslandJoinRelative = 0.001;

/// How far an island's zone (hullcover/mesh/tolerance.h: where its
/// tolerance holds and its hulls may lie) reaches beyond its box, as a
/// fraction of its diagonal: the default prism cap, so a prism behind an
/// outer wall keeps its thickness.
inline constexpr double kIslandZoneRelative = 0.01;

/// A zone never reaches further than this share of the gap to the nearest
/// island whose box its own box does not meet: below one half, so the zones
/// of islands apart never meet, whatever their sizes.
inline constexpr double kZoneShareOfGap = 0.45;

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

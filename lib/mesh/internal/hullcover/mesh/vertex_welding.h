#pragma once
/// \file vertex_welding.h
/// Merging of coincident vertices, so that faces which touch in space also
/// share vertices and edges (glTF and STL store one vertex per corner).

#include "hullcover/geometry/mesh.h"

#include <vector>

namespace hullcover {

/// A welded mesh and how its vertices relate to the input's.
struct WeldResult {
  /// Same triangles (same order, same materials) on merged vertices; only
  /// vertices some triangle references are kept.
  Mesh mesh;
  /// For each input vertex, its index in `mesh.positions`; -1 for an input
  /// vertex no triangle references.
  std::vector<int> new_index_of_input_vertex;
  /// Input vertices no triangle referenced (dropped).
  int unreferenced_dropped = 0;
};

/// Merges every referenced vertex into the first earlier kept vertex within
/// `radius` (Euclidean, scene units), nearest first, ties to the lower index;
/// a vertex with none nearby is kept. Expected O(n) with a spatial hash of
/// cell size `radius`. Deterministic: depends only on the input order.
///
/// Merging is not transitive: a chain of vertices each within `radius` of
/// the next but not of the first keeps more than one representative, so no
/// vertex ever moves by more than `radius`.
///
/// Triangles that get a repeated vertex are kept (they become zero-area
/// faces that connectivity reports), so face ids stay those of the input.
/// Preconditions: `validate_mesh(mesh)` passes and `radius` > 0.
WeldResult weld_vertices(const Mesh& mesh, double radius);

/// The same per group: a vertex merges only into a vertex of its own group
/// (`group_of_vertex`, one per input vertex, 0 .. radius_of_group.size() - 1)
/// within that group's radius (> 0). The decomposer's groups are islands
/// (mesh_islands.h), each welded at its own tolerance.
WeldResult weld_vertices(const Mesh& mesh, const std::vector<int>& group_of_vertex,
                         const std::vector<double>& radius_of_group);

} // namespace hullcover

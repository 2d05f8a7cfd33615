#pragma once
/// \file mesh_connectivity.h
/// Edges, face adjacency, boundaries and components of a (welded) mesh.
///
/// Definitions (docs/definitions-and-proofs.md): an edge is an unordered vertex pair
/// used by at least one triangle. With exactly one incident face it is a
/// *boundary* edge; with two faces that traverse it in opposite directions it
/// is *manifold* and the faces are neighbours; two faces traversing it in the
/// same direction are an *orientation conflict*; three or more faces make it
/// *non-manifold*. Patches are only ever merged across manifold edges.

#include "hullcover/geometry/mesh.h"

#include <cstdint>
#include <vector>

namespace hullcover {

/// How many faces use an edge and whether they agree on orientation.
enum class EdgeKind : std::uint8_t { boundary, manifold, orientation_conflict, non_manifold };

/// One undirected edge; its faces are `edge_uses[first_use .. first_use + use_count)`.
struct MeshEdge {
  int v0 = -1; ///< smaller vertex index
  int v1 = -1; ///< larger vertex index
  int first_use = 0;
  int use_count = 0;
  EdgeKind kind = EdgeKind::boundary;
};

/// A face's use of an edge: the edge runs from corner `corner` of `face` to
/// corner `(corner + 1) % 3`.
struct EdgeUse {
  int face = -1;
  int corner = -1;
};

/// Connectivity of a whole mesh. Faces with a repeated vertex index
/// (collapsed to a segment or point) use no edge and have no neighbour.
struct MeshConnectivity {
  /// Every edge, ordered by (v0, v1).
  std::vector<MeshEdge> edges;
  /// Incidences grouped by edge, each group ordered by (face, corner).
  std::vector<EdgeUse> edge_uses;
  /// Per face: the edge index of corner k's edge (corner k to k+1); -1 for
  /// a collapsed face.
  std::vector<Eigen::Vector3i> face_edges;
  /// Per face: the face across corner k's edge when that edge is manifold
  /// and consistently oriented, else -1.
  std::vector<Eigen::Vector3i> face_neighbours;
  /// Per face: 1 when its smallest altitude is at most the tolerance (this
  /// includes every collapsed face), else 0. Such faces have no reliable
  /// normal.
  std::vector<char> zero_area;
  /// Per face: its connected component, faces being connected when they
  /// share a vertex. Components are numbered in order of their first face.
  std::vector<int> face_component;
  int component_count = 0;
};

/// Builds the connectivity of `mesh`; `tolerance` (scene units, > 0) decides
/// which faces are zero-area. Cost O(F log F). Cannot fail on a mesh that
/// passes `validate_mesh`.
MeshConnectivity build_connectivity(const Mesh& mesh, double tolerance);

/// The same with a tolerance per face (scene units, > 0; one per triangle):
/// each island's own (hullcover/mesh/prepared_mesh.h).
MeshConnectivity build_connectivity(const Mesh& mesh, const std::vector<double>& tolerance_of_face);

/// Number of edges of the given kind.
int count_edges(const MeshConnectivity& connectivity, EdgeKind kind);

/// Number of faces flagged zero-area.
int count_zero_area_faces(const MeshConnectivity& connectivity);

} // namespace hullcover

#pragma once
/// \file recheck_mesh.h
/// What the re-check reads off the raw triangles (private to validate):
/// faces with a surface and their normals, each edge once, the paper's bars
/// on open edges, and the grids that give each hull its candidates. All of
/// it is found again here, not taken from the decomposer's connectivity.

#include "recheck_geometry.h"

#include "hullcover/geometry/mesh.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <utility>
#include <vector>

namespace hullcover::validate::recheck {

/// A segment p-q.
struct Segment {
  Eigen::Vector3d a, b;
};

/// The mesh as the re-check sees it.
struct MeshFacts {
  std::vector<Eigen::Vector3d> normal;    ///< unit normal of each face with a surface, else zero
  std::vector<char> has_surface;          ///< area beyond tol x the face's longest edge
  std::vector<std::pair<int, int>> edges; ///< each undirected edge once (smaller id first), sorted
  std::vector<Segment> bars;              ///< condition 3: one across each open edge's midpoint, along the normal
  double longest_edge = 0.0;
};

/// Reads the prepared mesh's faces and edges again, each face at its
/// island's tolerance; open edges (one face with a surface) get bars
/// reaching `bar_half_length` either side of the face.
MeshFacts read_mesh_facts(const PreparedMesh& prepared, double bar_half_length);

/// Uniform grids, one per kind of candidate, on the same cells.
struct CandidateGrids {
  CandidateGrid vertices, edges, bars, faces;
};

/// The grids' cell is no smaller than the longest edge, so an edge or face
/// spans few cells, nor than the scene's diagonal over this, so a scene of
/// tiny faces does not need millions of cells.
inline constexpr double kMaxCellsAlongDiagonal = 200.0;

/// Grids over `mesh`'s vertices, `facts`' edges and bars, and `mesh`'s faces;
/// `cell` and `origin` are the grid's.
CandidateGrids build_candidate_grids(const Mesh& mesh, const MeshFacts& facts, double cell,
                                     const Eigen::Vector3d& origin);

} // namespace hullcover::validate::recheck

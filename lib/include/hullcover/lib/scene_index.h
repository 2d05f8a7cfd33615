#pragma once
/// \file scene_index.h
/// Everything the validity conditions test a candidate hull against, for
/// the WHOLE mesh (paper section 3: checks run on the entire mesh, not the
/// patch's component): vertices, edges, faces and boundary constraint bars,
/// each in a bounding-volume tree.

#include "hullcover/lib/aabb_tree.h"
#include "hullcover/lib/prepared_mesh.h"

#include <vector>

namespace hullcover {

/// A boundary constraint bar (paper 4.1, condition 3): the segment through
/// an open edge's midpoint along its face's unit normal, `bar_half_length`
/// to each side.
struct BoundaryBar {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();  ///< behind the face
  Eigen::Vector3d b = Eigen::Vector3d::Zero();  ///< in front of the face
  int edge = -1;  ///< the mesh edge it guards
  int face = -1;  ///< the face whose normal it follows
};

/// What bars guard.
struct BarOptions {
  /// Half-length of each bar, scene units (> 0).
  double half_length = 1.0;
  /// Also put bars on edges between faces of different materials (one per
  /// face), so hulls keep materials apart (paper 4.3).
  bool material_boundaries = false;
};

/// The mesh as the validity checks see it. Holds a reference to `prepared`,
/// which must outlive it.
struct SceneIndex {
  const PreparedMesh* prepared = nullptr;
  /// Unit front normal per face; zero for zero-area faces.
  std::vector<Eigen::Vector3d> face_normals;
  /// Area per face, scene units squared.
  std::vector<double> face_areas;
  std::vector<BoundaryBar> bars;
  AabbTree vertex_tree;  ///< over mesh vertices
  AabbTree edge_tree;    ///< over MeshConnectivity::edges
  AabbTree face_tree;    ///< over faces
  AabbTree bar_tree;     ///< over pieces of bars (long bars are split, so boxes stay small)
  std::vector<int> bar_of_piece;  ///< bar index of each piece in bar_tree

  /// Appends, once each and ascending, the bars with a piece overlapping `box`.
  void bars_overlapping(const Aabb& box, std::vector<int>& out) const;

  const Mesh& mesh() const { return prepared->mesh; }
  double tol() const { return prepared->tolerance.length; }
};

/// Bars are indexed in pieces no longer than the diagonal / this: a bar
/// is long (a tenth of the scene by default), and one long box per bar would
/// make every query visit most of the tree.
inline constexpr double kBarPiecesPerDiagonal = 64.0;

/// Builds the index: face normals and areas, bars on every boundary edge
/// (and material boundary when asked), and the four trees. O(n log n).
SceneIndex build_scene_index(const PreparedMesh& prepared, const BarOptions& bars);

} // namespace hullcover

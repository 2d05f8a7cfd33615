#pragma once
// The prepared scene as the decomposer reads it (internal): the arrays of a
// PreparedMesh, viewed where they lie. In one process they lie in the
// PreparedMesh the caller gave; on a bake's worker they lie in the pages of
// the prepared scene file it maps (cells/prepared_scene_file.h), so the
// worker never copies the scene and holds in memory only the pages its
// cells read. Fields are named as in Mesh, MeshIslands, MeshConnectivity
// and PreparedMesh, whose documentation they follow.

#include "hullcover/geometry/mappable_array.h"
#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/mesh_triangles.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <string>
#include <vector>

namespace hullcover {

/// Mesh's arrays, viewed.
struct MeshView {
  MappableArray<Eigen::Vector3d> positions;
  MappableArray<Eigen::Vector3i> triangles;
  MappableArray<int> material_ids;
  std::vector<std::string> material_names;
  double coordinate_error = 0.0;
  double coordinate_relative_error = 0.0;
};

/// MeshIslands' arrays, viewed.
struct IslandsView {
  MappableArray<int> island_of_face;
  MappableArray<Aabb> boxes;
  MappableArray<int> face_counts;
};

/// MeshConnectivity's arrays, viewed.
struct ConnectivityView {
  MappableArray<MeshEdge> edges;
  MappableArray<EdgeUse> edge_uses;
  MappableArray<Eigen::Vector3i> face_edges;
  MappableArray<Eigen::Vector3i> face_neighbours;
  MappableArray<char> zero_area;
  MappableArray<int> face_component;
  int component_count = 0;
};

/// PreparedMesh, viewed: the arrays where they lie, the tolerance (one
/// entry per island) copied.
struct PreparedSceneView {
  MeshView mesh;
  Tolerance tolerance;
  IslandsView islands;
  ConnectivityView connectivity;
  int vertices_before_weld = 0;
  int unreferenced_dropped = 0;

  /// As PreparedMesh::face_tolerance.
  double face_tolerance(int f) const { return tolerance.island_lengths[islands.island_of_face[f]]; }
  /// As PreparedMesh::face_place.
  int face_place(int f) const { return tolerance.island_place[islands.island_of_face[f]]; }
};

/// Views of `prepared`'s arrays; `prepared` must outlive the view and every
/// copy of it, unchanged.
PreparedSceneView view_of(const PreparedMesh& prepared);

/// Views of `islands`' arrays, which must outlive the view.
IslandsView view_of(const MeshIslands& islands);

/// The view's arrays copied into a PreparedMesh of their own.
PreparedMesh copy_of(const PreparedSceneView& view);

/// As the Mesh functions of the same names (hullcover/geometry/mesh.h),
/// which share their code (hullcover/geometry/mesh_triangles.h).
inline Eigen::Vector3d triangle_area_vector(const MeshView& mesh, int t) {
  return mesh_triangles::area_vector(mesh, t);
}
inline void triangle_corners(const MeshView& mesh, int t, std::vector<Eigen::Vector3d>& corners) {
  mesh_triangles::corners(mesh, t, corners);
}
inline bool triangle_has_repeated_vertex(const MeshView& mesh, int t) {
  return mesh_triangles::has_repeated_vertex(mesh, t);
}
inline Aabb referenced_bounding_box(const MeshView& mesh) { return mesh_triangles::referenced_box(mesh); }

} // namespace hullcover

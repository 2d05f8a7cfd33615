#pragma once
// The measures of a mesh's triangles (hullcover/geometry/mesh.h), for any
// mesh whose `positions` and `triangles` read as Mesh's do: a Mesh, or the
// decomposer's view of one lying in a mapped file. The functions of mesh.h
// and the view's overloads of them both call these.

#include "hullcover/geometry/aabb.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace hullcover::mesh_triangles {

/// As triangle_area_vector.
template <class MeshArrays>
Eigen::Vector3d area_vector(const MeshArrays& mesh, int t) {
  const Eigen::Vector3i& tri = mesh.triangles[t];
  const Eigen::Vector3d& a = mesh.positions[tri[0]];
  return (mesh.positions[tri[1]] - a).cross(mesh.positions[tri[2]] - a);
}

/// As triangle_corners.
template <class MeshArrays>
void corners(const MeshArrays& mesh, int t, std::vector<Eigen::Vector3d>& out) {
  out.resize(3);
  for (int k = 0; k < 3; ++k) out[k] = mesh.positions[mesh.triangles[t][k]];
}

/// As triangle_has_repeated_vertex.
template <class MeshArrays>
bool has_repeated_vertex(const MeshArrays& mesh, int t) {
  const Eigen::Vector3i& tri = mesh.triangles[t];
  return tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0];
}

/// As referenced_bounding_box.
template <class MeshArrays>
Aabb referenced_box(const MeshArrays& mesh) {
  Aabb box;
  for (const Eigen::Vector3i& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) box.extend(mesh.positions[tri[k]]);
  return box;
}

} // namespace hullcover::mesh_triangles

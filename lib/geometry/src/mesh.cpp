#include "hullcover/geometry/mesh.h"

#include <Eigen/Geometry>

#include <cmath>

namespace hullcover {

Aabb referenced_bounding_box(const Mesh& mesh) {
  Aabb box;
  for (const Eigen::Vector3i& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) box.extend(mesh.positions[tri[k]]);
  return box;
}

double largest_coordinate_magnitude(const Mesh& mesh) {
  double largest = 0.0;
  for (const Eigen::Vector3i& tri : mesh.triangles)
    for (int k = 0; k < 3; ++k) largest = std::max(largest, mesh.positions[tri[k]].cwiseAbs().maxCoeff());
  return largest;
}

Status validate_mesh(const Mesh& mesh) {
  if (mesh.triangles.empty()) return {StatusCode::empty_scene, "the scene has no triangles"};
  if (mesh.material_ids.size() != mesh.triangles.size())
    return {StatusCode::invalid_argument, "material_ids has " + std::to_string(mesh.material_ids.size()) +
                                              " entries for " + std::to_string(mesh.triangles.size()) + " triangles"};
  const auto vertex_count = static_cast<long long>(mesh.positions.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (v < 0 || v >= vertex_count)
        return {StatusCode::index_out_of_range, "triangle " + std::to_string(t) + " names vertex " + std::to_string(v) +
                                                    " but there are " + std::to_string(vertex_count) + " vertices"};
      if (!mesh.positions[v].allFinite())
        return {StatusCode::non_finite_coordinate, "vertex " + std::to_string(v) + " (used by triangle " +
                                                       std::to_string(t) + ") has a NaN or infinite coordinate"};
    }
  }
  return Status::success();
}

Eigen::Vector3d triangle_area_vector(const Mesh& mesh, int t) {
  const Eigen::Vector3i& tri = mesh.triangles[t];
  const Eigen::Vector3d& a = mesh.positions[tri[0]];
  return (mesh.positions[tri[1]] - a).cross(mesh.positions[tri[2]] - a);
}

void triangle_corners(const Mesh& mesh, int t, std::vector<Eigen::Vector3d>& corners) {
  corners.resize(3);
  for (int k = 0; k < 3; ++k) corners[k] = mesh.positions[mesh.triangles[t][k]];
}

bool triangle_has_repeated_vertex(const Mesh& mesh, int t) {
  const Eigen::Vector3i& tri = mesh.triangles[t];
  return tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0];
}

} // namespace hullcover

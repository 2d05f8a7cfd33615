#include "hullcover/geometry/mesh.h"

#include "hullcover/geometry/mesh_triangles.h"

#include <Eigen/Geometry>

#include <cmath>

namespace hullcover {

Aabb referenced_bounding_box(const Mesh& mesh) { return mesh_triangles::referenced_box(mesh); }

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

Eigen::Vector3d triangle_area_vector(const Mesh& mesh, int t) { return mesh_triangles::area_vector(mesh, t); }

void triangle_corners(const Mesh& mesh, int t, std::vector<Eigen::Vector3d>& corners) {
  mesh_triangles::corners(mesh, t, corners);
}

bool triangle_has_repeated_vertex(const Mesh& mesh, int t) { return mesh_triangles::has_repeated_vertex(mesh, t); }

} // namespace hullcover

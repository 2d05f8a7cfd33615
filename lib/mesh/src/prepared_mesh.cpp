#include "hullcover/mesh/prepared_mesh.h"

#include "hullcover/mesh/vertex_welding.h"

namespace hullcover {

namespace {
Result<PreparedMesh> prepare_unchecked(const Mesh& raw, std::optional<double> user_tolerance) {
  if (Status valid = validate_mesh(raw); !valid.ok()) return valid;
  PreparedMesh prepared;
  prepared.islands = find_mesh_islands(raw);
  Result<Tolerance> tolerance = choose_tolerance(raw, prepared.islands, user_tolerance);
  if (!tolerance.ok()) return tolerance.status();
  prepared.tolerance = tolerance.value();
  prepared.vertices_before_weld = static_cast<int>(raw.positions.size());
  // A vertex belongs to the island of the faces using it (faces sharing a
  // vertex are one island).
  std::vector<int> island_of_vertex(raw.positions.size(), 0);
  for (size_t f = 0; f < raw.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) island_of_vertex[raw.triangles[f][k]] = prepared.islands.island_of_face[f];
  WeldResult welded = weld_vertices(raw, island_of_vertex, prepared.tolerance.island_lengths);
  prepared.unreferenced_dropped = welded.unreferenced_dropped;
  prepared.mesh = std::move(welded.mesh);
  std::vector<double> face_tolerance(raw.triangles.size());
  for (size_t f = 0; f < face_tolerance.size(); ++f) face_tolerance[f] = prepared.face_tolerance(static_cast<int>(f));
  prepared.connectivity = build_connectivity(prepared.mesh, face_tolerance);
  return prepared;
}

} // namespace

Result<PreparedMesh> prepare_mesh(const Mesh& raw, std::optional<double> user_tolerance) {
  try {
    return prepare_unchecked(raw, user_tolerance);
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("preparing the mesh failed: ") + e.what()};
  }
}

} // namespace hullcover

#include "hullcover/mesh/prepared_mesh.h"

#include "hullcover/mesh/vertex_welding.h"

namespace hullcover {

namespace {
Result<PreparedMesh> prepare_unchecked(const Mesh& raw, std::optional<double> user_tolerance) {
  if (Status valid = validate_mesh(raw); !valid.ok()) return valid;
  Result<Tolerance> tolerance = choose_tolerance(raw, user_tolerance);
  if (!tolerance.ok()) return tolerance.status();

  PreparedMesh prepared;
  prepared.tolerance = tolerance.value();
  prepared.vertices_before_weld = static_cast<int>(raw.positions.size());
  WeldResult welded = weld_vertices(raw, prepared.tolerance.length);
  prepared.unreferenced_dropped = welded.unreferenced_dropped;
  prepared.mesh = std::move(welded.mesh);
  prepared.connectivity = build_connectivity(prepared.mesh, prepared.tolerance.length);
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

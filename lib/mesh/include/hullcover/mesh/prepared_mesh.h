#pragma once
/// \file prepared_mesh.h
/// The one way every command turns a raw mesh into what the algorithms
/// read: validated, tolerance chosen, vertices welded, connectivity built.

#include "hullcover/geometry/mesh.h"
#include "hullcover/mesh/mesh_connectivity.h"
#include "hullcover/geometry/status.h"
#include "hullcover/mesh/tolerance.h"

#include <optional>

namespace hullcover {

/// A welded mesh with its tolerance and connectivity.
struct PreparedMesh {
  Mesh mesh;  ///< welded; face ids equal the raw mesh's
  Tolerance tolerance;
  MeshConnectivity connectivity;
  int vertices_before_weld = 0;  ///< raw vertex records, referenced or not
  int unreferenced_dropped = 0;  ///< raw vertices no triangle used
};

/// Validates `raw`, chooses the tolerance (`user_tolerance` in scene units,
/// see tolerance.h), welds vertices within it and builds connectivity.
/// Fails as `validate_mesh` and `choose_tolerance` do.
Result<PreparedMesh> prepare_mesh(const Mesh& raw, std::optional<double> user_tolerance);

} // namespace hullcover

#pragma once
/// \file prepared_mesh.h
/// The one way every command turns a raw mesh into what the algorithms
/// read: validated, tolerance chosen, vertices welded, connectivity built.

#include "hullcover/geometry/mesh.h"
#include "hullcover/mesh/mesh_connectivity.h"
#include "hullcover/mesh/mesh_islands.h"
#include "hullcover/geometry/status.h"
#include "hullcover/mesh/tolerance.h"

#include <optional>

namespace hullcover {

/// A welded mesh with its tolerance and connectivity.
struct PreparedMesh {
  Mesh mesh; ///< welded; face ids equal the raw mesh's
  Tolerance tolerance;
  /// The islands (found on the raw mesh; face ids are the same). Vertices
  /// weld only within an island, each at its island's tolerance.
  MeshIslands islands;
  MeshConnectivity connectivity;
  int vertices_before_weld = 0; ///< raw vertex records, referenced or not
  int unreferenced_dropped = 0; ///< raw vertices no triangle used

  /// The tolerance of tests on face `f` alone: its island's
  /// (Tolerance::island_lengths), scene units.
  double face_tolerance(int f) const { return tolerance.island_lengths[islands.island_of_face[f]]; }
  /// The place of face f (Tolerance::island_place).
  int face_place(int f) const { return tolerance.island_place[islands.island_of_face[f]]; }
};

/// Validates `raw`, finds its islands, chooses the tolerance
/// (`user_tolerance` in scene units, see tolerance.h), welds each island's
/// vertices within its tolerance and builds connectivity.
/// Fails as `validate_mesh` and `choose_tolerance` do.
Result<PreparedMesh> prepare_mesh(const Mesh& raw, std::optional<double> user_tolerance);

} // namespace hullcover

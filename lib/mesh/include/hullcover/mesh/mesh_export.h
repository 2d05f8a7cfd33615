#pragma once
/// \file mesh_export.h
/// Writing a `Mesh` as Wavefront OBJ, for looking at it in any viewer.

#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <string>

namespace hullcover {

/// Writes `mesh` to `path` as OBJ: one `v` line per position (17 significant
/// digits, so doubles survive the round trip), one `usemtl` group per run of
/// equal material ids, one `f` line per triangle (1-based, winding kept).
/// Fails with `unwritable_file` when the file cannot be written.
Status write_mesh_obj(const Mesh& mesh, const std::string& path);

} // namespace hullcover

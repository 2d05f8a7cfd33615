#pragma once
// The OBJ pre-check (scene_file_checks.h): what an OBJ file names before
// Assimp reads it.

#include "hullcover/geometry/status.h"
#include "hullcover/mesh/import_limits.h"

#include <istream>

namespace hullcover::detail {

/// Reads the OBJ text in `in` line by line: each `mtllib` name must stay in
/// the scene's folder (reference_text_leaves_folder), and `usemtl` may name
/// at most limits.max_materials distinct materials. Fails with
/// `reference_outside_folder` or `limit_exceeded`; the message names the
/// line. Lines are at most the file's length, which the size limit bounds.
Status check_obj(std::istream& in, const ImportLimits& limits);

} // namespace hullcover::detail

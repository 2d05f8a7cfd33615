#pragma once
// The glTF part of scene_file_checks.h: the JSON's nesting, the node
// hierarchy, and every accessor, buffer view and buffer against the bytes
// actually present.

#include "hullcover/geometry/status.h"
#include "hullcover/mesh/import_limits.h"

#include <cstdint>
#include <fstream>
#include <string>

namespace hullcover::detail {

/// Checks glTF file `path` (open as `in`, `file_bytes` long; `binary` for a
/// GLB container) as check_scene_file does.
Status check_gltf(const std::string& path, std::ifstream& in, std::uint64_t file_bytes, bool binary,
                  const ImportLimits& limits);

} // namespace hullcover::detail

#pragma once
// What a scene file says about itself, checked before Assimp reads it:
// Assimp trusts declared counts and recurses over node trees, so a small
// hostile file could make it allocate without bound, hang or run out of
// stack. Each check reads only the file's own bytes (and the sizes of the
// files it names, inside its folder).

#include "hullcover/geometry/status.h"
#include "hullcover/mesh/import_limits.h"

#include <string>

namespace hullcover::detail {

/// Checks a glTF (.gltf, .glb), PLY, binary STL or OBJ file against itself
/// and `limits`; other formats pass (Assimp reads them within the file's
/// bytes).
/// Fails with `unreadable_file` when the file contradicts itself (a GLB
/// chunk past the end, a PLY header with no end, counts or accessors that
/// need more bytes than there are, a node graph that is not a forest), and
/// `limit_exceeded` when JSON nesting or the node hierarchy is deeper than
/// limits.max_node_depth or an OBJ names more than limits.max_materials
/// materials, and `reference_outside_folder` for a reference whose text
/// leads out of the folder. Messages do not start with the path.
Status check_scene_file(const std::string& path, const ImportLimits& limits);

} // namespace hullcover::detail

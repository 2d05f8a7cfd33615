#pragma once
/// \file mesh_import.h
/// Reading a scene file into one `Mesh`, through Assimp.

#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <string>

namespace hullcover {

/// What an import saw besides the mesh itself.
struct ImportReport {
  /// Assimp meshes placed by the node hierarchy (a mesh used by two nodes
  /// counts twice).
  int mesh_instances = 0;
  /// Points and line segments in the file; a collision scene has no use for
  /// them, so they are skipped.
  int skipped_non_triangle_primitives = 0;
};

/// A mesh read from a file, with what the import saw.
struct ImportedMesh {
  Mesh mesh;
  ImportReport report;
};

/// Reads OBJ, PLY, STL, glTF/GLB, FBX (and anything else the installed
/// Assimp reads) into one `Mesh` in the file's own units and frame: every
/// node's transform is applied, polygons are triangulated, each triangle
/// keeps its source material. Vertices are NOT welded (see vertex_welding.h)
/// and degenerate faces are kept, so face ids follow the file.
///
/// Debian's Assimp reads coordinates as float32, so the returned mesh's
/// `coordinate_error` is set to the float32 rounding bound at the scene's
/// magnitude.
///
/// Fails, with a message that starts with the path, with `file_not_found`,
/// `unknown_format` (no reader for the extension), `unreadable_file` (the
/// reader failed; Assimp's reason is quoted), `empty_scene` (no triangle),
/// `non_finite_coordinate` or `index_out_of_range`. Never throws.
Result<ImportedMesh> import_mesh(const std::string& path);

} // namespace hullcover

#pragma once
/// \file mesh_import.h
/// Reading a scene file into one `Mesh`: OBJ by the project's own reader,
/// every other format through Assimp.

#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"
#include "hullcover/mesh/import_limits.h"

#include <cstdint>
#include <optional>
#include <string>

namespace hullcover {

/// Placed triangles the default rule allows for `input_bytes` read (the
/// scene file and the files it refers to): one per
/// `kInputBytesPerDefaultTriangle` bytes, at least
/// `kDefaultTriangleLimitFloor`, at most `kDefaultTriangleLimitCeiling`. A
/// file stores a triangle in 9 bytes or more (a GLB with 16-bit indices and
/// shared vertices), so only instancing meets the rule; and at about 450
/// bytes of memory per placed triangle a file under 1 MB stays under
/// 512 MB.
inline constexpr std::uint64_t kInputBytesPerDefaultTriangle = 8;
/// The default rule's least limit, whatever the files' size.
inline constexpr std::uint64_t kDefaultTriangleLimitFloor = std::uint64_t{1} << 16;
/// The default rule's greatest limit, whatever the files' size.
inline constexpr std::uint64_t kDefaultTriangleLimitCeiling = std::uint64_t{4} << 20;
/// The default rule: the placed triangles allowed for `input_bytes` read.
std::uint64_t default_triangle_limit(std::uint64_t input_bytes);

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
/// OBJ files are read by the project's own reader, in double and in time
/// linear in the file (every coordinate the double nearest its text; faces
/// in file order; a concave polygon cut by ear clipping, at most 128
/// corners; no material library opened: materials are the `usemtl` names).
/// Every other format goes through Assimp, which Debian builds with float32
/// coordinates. The returned mesh's `coordinate_error` is the rounding bound
/// of its reader at the scene's magnitude: half a double unit for OBJ, half
/// a float32 unit otherwise.
///
/// Confined: files the scene refers to (glTF buffers and images, OBJ
/// material libraries, any reference of another format) are read only when
/// they resolve, symlinks followed, to a regular file inside the scene
/// file's own folder; data URIs are read in place; nothing else is opened.
///
/// Fails, with a message that starts with the path, with `file_not_found`,
/// `unknown_format` (no reader for the extension), `unreadable_file` (the
/// reader failed, Assimp's reason quoted, or the file contradicts itself: a
/// PLY header with no end, counts the bytes cannot hold, a glTF node graph
/// with a cycle), `reference_outside_folder` (naming the reference),
/// `limit_exceeded` (naming the limit and how to raise it), `empty_scene` (no
/// triangle), `non_finite_coordinate` or `index_out_of_range`. Never throws.
Result<ImportedMesh> import_mesh(const std::string& path, const ImportLimits& limits = {});

} // namespace hullcover

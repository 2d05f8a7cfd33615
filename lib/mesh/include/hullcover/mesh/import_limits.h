#pragma once
/// \file import_limits.h
/// The bounds a scene import keeps to (mesh_import.h), apart so that the
/// checks of each file format can take them without the importer.

#include <cstdint>
#include <optional>

namespace hullcover {

/// Bounds on what one import may read and build, checked before the reader
/// allocates for it (a file may come from anyone: a baking service's upload).
/// Every limit is the user's to raise (`--max-file-size`, `--max-node-depth`,
/// `--max-triangles`, `--max-materials` on every command that reads a scene).
struct ImportLimits {
  /// Bytes of the scene file, and of each file it refers to (glTF buffers
  /// and images, OBJ material libraries). 1 GiB.
  std::uint64_t max_file_bytes = std::uint64_t{1} << 30;
  /// Depth of a glTF node hierarchy (and of its JSON). Real scenes nest a few
  /// tens deep; a 100,000-deep one would run the importer out of stack.
  int max_node_depth = 256;
  /// Triangles after node instancing (a mesh placed by two nodes counts
  /// twice): a small file can place a mesh millions of times. Unset: the
  /// default rule, `default_triangle_limit` of the bytes read. Set: that
  /// many, whatever the files' size.
  std::optional<std::uint64_t> max_triangles;
  /// Distinct materials an OBJ file may name with `usemtl` (Assimp's OBJ
  /// reader takes about 35 KB and quadratic time per name).
  int max_materials = 4096;
};

} // namespace hullcover

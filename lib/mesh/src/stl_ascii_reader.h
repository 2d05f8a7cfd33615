#pragma once
// The project's reader of ASCII STL (internal to the mesh module):
// coordinates in double, as the file writes them. Assimp's STL reader keeps
// float32 coordinates; binary STL is float32 by its format and stays
// Assimp's.

#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <cstdint>
#include <istream>
#include <string>

namespace hullcover::detail {

/// Whether the STL file at `path`, of `file_bytes`, is ASCII: its text
/// starts with "solid" and its size is not the one a binary header would
/// declare (a binary header may start with "solid" too), as the STL check
/// (scene_file_checks.h) decides.
bool is_ascii_stl(const std::string& path, std::uint64_t file_bytes);

/// Reads ASCII STL text: one or more `solid` ... `endsolid` blocks of
/// `facet normal nx ny nz` / `outer loop` / three `vertex x y z` /
/// `endloop` / `endfacet` (keywords in any case; the facet normal is
/// ignored, the corners' order gives the front). Corners at bit-identical
/// positions are one position (an STL repeats every corner per facet).
/// Faces keep the file's order, all material 0.
///
/// Fails with `unreadable_file` (a statement out of place or unknown, a
/// facet of other than three vertices, text ending inside a facet, a number
/// that does not parse), `non_finite_coordinate` (NaN, infinite, or beyond
/// double's range), `limit_exceeded` (more than `triangle_limit` facets) and
/// `empty_scene` (no facet); messages name the line.
Result<Mesh> read_ascii_stl(std::istream& in, std::uint64_t triangle_limit);

} // namespace hullcover::detail

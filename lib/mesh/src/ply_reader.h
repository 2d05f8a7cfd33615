#pragma once
// The project's PLY reader (internal to the mesh module), ASCII and binary:
// coordinates in double, as the file writes them (a decimal to its nearest
// double, a binary float or double exactly). Assimp's PLY reader keeps
// float32 coordinates, and its binary path has freed memory it did not own
// on damaged headers, so no PLY reaches it.

#include "ply_header.h"

#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <cstdint>
#include <fstream>

namespace hullcover::detail {

/// Reads the body of a PLY file `file_bytes` long from `in` (checked first
/// by check_ply), whose header `h` read_ply_header has read: ASCII from
/// h.after_line, whitespace-separated values; binary from h.data_at, each
/// value its property's type in the header's byte order; element after
/// element. Positions are the `x`, `y`, `z` of each `vertex`; faces the
/// `vertex_indices` (or `vertex_index`) list of each `face`, triangulated as
/// triangulate_polygon does, and of each `tristrips` (-1 restarts a strip),
/// in file order, all material 0. Other elements and properties are read
/// past. Faces of fewer than three corners are skipped and counted in
/// `skipped`. A file may hold at most three vertices per allowed triangle,
/// and triangles are counted as faces are read, so the limit bounds the
/// memory kept.
///
/// Fails with `unreadable_file` (a value that does not parse, a list length
/// or corner that is not a whole number, a body that ends too soon, a vertex
/// element without x, y and z), `non_finite_coordinate`,
/// `index_out_of_range` (a corner naming no vertex), `limit_exceeded` (more
/// than `triangle_limit` triangles or three times as many vertices, or a
/// concave face beyond kMostConcaveCorners) and `empty_scene`; messages
/// name the element and its number.
Result<Mesh> read_ply_body(std::ifstream& in, const PlyHeader& h, std::uint64_t file_bytes,
                           std::uint64_t triangle_limit, int& skipped);

} // namespace hullcover::detail

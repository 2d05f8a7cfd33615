#pragma once
// The project's reader of ASCII PLY (internal to the mesh module):
// coordinates in double, as the file writes them. Assimp's PLY reader keeps
// float32 coordinates; binary PLY stays Assimp's (its float properties are
// float32 by the format, its double ones are rare).

#include "ply_header.h"

#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <cstdint>
#include <istream>

namespace hullcover::detail {

/// Reads the body of an ASCII PLY file from `in` (checked first by
/// check_ply), whose header `h` read_ply_header has read (h.ascii): the body
/// as the format has it, whitespace-separated values, element after element.
/// Positions are the `x`, `y`, `z` of each `vertex`; faces the
/// `vertex_indices` (or `vertex_index`) list of each `face`, triangulated as
/// triangulate_polygon does, and of each `tristrips` (-1 restarts a strip),
/// in file order, all material 0. Other elements and properties are read
/// past. Faces of fewer than three corners are skipped and counted in
/// `skipped`. A file may hold at most three vertices per allowed triangle,
/// and triangles are counted as faces are read, so the limit bounds the
/// memory kept.
///
/// Fails with `unreadable_file` (a value that does not parse, a list length
/// that is not a whole number, a body that ends too soon, a vertex element
/// without x, y and z), `non_finite_coordinate`, `index_out_of_range` (a
/// corner naming no vertex), `limit_exceeded` (more than `triangle_limit`
/// triangles or three times as many vertices, or a concave face beyond
/// kMostConcaveCorners) and
/// `empty_scene`; messages name the element and its number.
Result<Mesh> read_ascii_ply(std::istream& in, const PlyHeader& h, std::uint64_t triangle_limit, int& skipped);

} // namespace hullcover::detail

#pragma once
// The project's reader of Wavefront OBJ text (internal to the mesh module):
// coordinates in double, as the file writes them, in time linear in the
// file's size, however many objects it holds. Assimp's OBJ reader keeps
// float32 coordinates and looks every new object up among all before it.

#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <cstdint>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace hullcover::detail {

/// Reads the OBJ text in `in` (checked first by check_obj): `v` positions
/// (x y z; a w or colour after them is ignored), `f` polygons (corners
/// `i`, `i/t`, `i//n` or `i/t/n`; negative i counts back from the last
/// position so far), triangulated as triangulate_polygon does, and
/// `usemtl` materials (ids in order of first use; faces before any are
/// material "default"). `l` and `p` elements, and faces of fewer than three
/// corners, are skipped and counted; `mtllib` names are listed (the caller
/// judges where they lead: no other file is opened here); other statements
/// (normals, texture coordinates, groups, objects, smoothing) are ignored.
/// Faces keep the file's order; positions are the file's, unwelded.
///
/// Fails with `unreadable_file` (a number that does not parse, a corner
/// that is not an index), `non_finite_coordinate` (NaN or infinite, or
/// beyond double's range), `index_out_of_range` (a corner naming no
/// position), `limit_exceeded` (more than `triangle_limit` triangles, or a
/// concave polygon beyond kMostConcaveCorners) and `empty_scene` (no
/// triangle); messages name the line and do not start with the path.
/// What read_obj saw besides the mesh.
struct ObjSideFacts {
  int skipped_primitives = 0;                  ///< lines, points, faces of fewer than three corners
  std::vector<std::string> material_libraries; ///< `mtllib` names, as written: never opened here
};

Result<Mesh> read_obj(std::istream& in, std::uint64_t triangle_limit, ObjSideFacts& facts);

} // namespace hullcover::detail

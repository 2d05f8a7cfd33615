#pragma once
/// \file collider_obj_writer.h
/// Hulls as an OBJ whose object names tell an engine's importer what they
/// are: Unreal's `UCX_<mesh>_<NN>` (collision for the render mesh named
/// <mesh> in the same file) or Godot's `-convcolonly` suffix (a convex
/// collider without a mesh). hullcover's audit reads the same names back
/// (validate/hull_set.h): where such names appear, only those objects are
/// hulls.

#include "export/collider_glb_writer.h"

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/status.h"

#include <string>
#include <vector>

namespace hullcover::app {

/// Writes `render` (when given) as object `render.name`, then each hull as
/// an object named `names[h]` with its facets as polygons, counter-clockwise
/// seen from outside, to `path` atomically. Fails with `invalid_argument`
/// when the names do not match the hulls, and `unwritable_file`.
[[nodiscard]] Status write_collider_obj(const std::vector<ConvexPolytope>& hulls, const std::vector<std::string>& names,
                                        const RenderMesh& render, const std::string& path);

} // namespace hullcover::app

#pragma once
/// \file collider_glb_writer.h
/// Hulls as a binary glTF (.glb) that engines import as static convex
/// colliders. Each hull is one node carrying its mesh, declared a convex
/// collider by both physics extensions in use:
///
///  - `KHR_physics_rigid_bodies`: `collider.geometry = {"node": n,
///    "convexHull": true}` (n the node itself; no `motion`: static);
///  - `OMI_physics_body` + `OMI_physics_shape` (which Godot imports): the
///    node's `collider.shape` names a document-level shape `{"type":
///    "convex", "convex": {"mesh": m}}`.
///
/// Both are optional extensions (in `extensionsUsed`, not required), so a
/// viewer without them still shows the hulls. Positions are the scene's own
/// coordinates, as float32, with no node transform.

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <string>
#include <vector>

namespace hullcover::app {

/// The scene's triangles to carry beside the hulls, as one render node.
struct RenderMesh {
  const Mesh* mesh = nullptr; ///< nothing when null
  std::string name;           ///< the node's and mesh's name
};

/// Writes `hulls` (facets fanned into triangles) as nodes named `names`
/// (one per hull) and, when given, `render` as one more node without a
/// collider, to `path` atomically. Fails with `invalid_argument` when the
/// names do not match the hulls or the buffer would pass glTF's 4 GiB, and
/// `unwritable_file`.
[[nodiscard]] Status write_collider_glb(const std::vector<ConvexPolytope>& hulls, const std::vector<std::string>& names,
                                        const RenderMesh& render, const std::string& path);

} // namespace hullcover::app

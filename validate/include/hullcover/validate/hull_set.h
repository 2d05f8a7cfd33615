#pragma once
/// \file hull_set.h
/// Hulls to audit, from any source: hullcover's runtime file, or an OBJ
/// with one `o` or `g` group per hull (V-HACD output, hand-made UCX meshes),
/// each hull being the convex hull of the vertices its group's faces use.
/// A group whose vertices lie in one plane (within kDefaultRelativeTolerance
/// x the group's own extent: a set carries no scene tolerance) is a flat
/// hull, a convex polygon of thickness 0 facing the way its faces wind, as
/// hullcover writes its flat hulls: an OBJ and the `.hcw` of one covering
/// are the same hulls.
///
/// Engine exports (`hullcover export`) mean to the audit what they mean to
/// the engine: in an OBJ whose groups carry Unreal's `UCX_` prefix, or
/// else Godot's `-convcolonly` / `-convcol` suffix, only those groups are
/// hulls (the rest is the render mesh); in a glTF binary (`.glb`), the
/// meshes of the nodes declared static convex colliders
/// (KHR_physics_rigid_bodies, OMI_physics_shape), or every node's mesh when
/// none is declared.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/status.h"

#include <string>
#include <vector>

namespace hullcover::validate {

/// Hulls read from a file, and what could not be made a hull.
struct HullSet {
  std::vector<bvh::RuntimeHull> hulls;
  int groups_without_area = 0; ///< OBJ groups whose points span no area (collinear or one point: skipped)
};

/// Reads `path`: a `.hcw` runtime file, a `.glb`, or else an OBJ with groups; only a
/// regular file of at most 1 GiB (kDefaultMaxInputFileBytes). Fails with
/// `file_not_found`, `unreadable_file` (a malformed line, named by number, a
/// vertex beyond float32 range, a damaged runtime file, a FIFO or device),
/// `limit_exceeded` (over 1 GiB) or `empty_scene` (no hull).
Result<HullSet> load_hull_set(const std::string& path);

} // namespace hullcover::validate

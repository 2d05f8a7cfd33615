#pragma once
// Hull files as groups of points before they become hulls (hull_set.cpp):
// an OBJ's `o`/`g` groups, a glTF binary's collider nodes. Each group's
// hull is the convex hull of its points, or a flat polygon facing the way
// its faces wind when they lie in one plane.

#include "hullcover/geometry/status.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hullcover::validate::detail {

/// One group: its name, the points its faces use (indices into
/// HullGroups::positions), and the sum of its faces' winding normals.
struct HullGroup {
  std::string name;
  std::vector<int> vertices;
  Eigen::Vector3d winding = Eigen::Vector3d::Zero();
};

/// Every group of a file and the points they index.
struct HullGroups {
  std::vector<Eigen::Vector3d> positions;
  std::vector<HullGroup> groups;
};

/// The deepest JSON nesting a hull glTF may have (its parser recurses per
/// level), the same as a scene's default node depth limit.
inline constexpr int kMaxHullGltfNesting = 256;

/// The hull groups of glTF binary `bytes` (read from `path`, named in
/// messages): the meshes of the nodes declared static convex colliders
/// (KHR_physics_rigid_bodies with convexHull, or OMI_physics_body with an
/// OMI_physics_shape of type convex), in world coordinates; when no node
/// declares one, every node's mesh. Positions come only from the GLB's own
/// binary chunk (a hull file never makes the reader open another file).
/// Fails with `unreadable_file` naming what is wrong (a chunk, accessor or
/// index past the bytes present, a node graph that is not a forest, a
/// primitive that is not triangles, a position beyond float32 range) and
/// `limit_exceeded` for JSON nested deeper than kMaxHullGltfNesting.
Result<HullGroups> read_glb_hull_groups(const std::string& path, const std::string& bytes);

/// Keeps only the groups an engine would take as colliders when their names
/// say so: Unreal's `UCX_` prefix, else Godot's `-convcolonly` or
/// `-convcol` suffix; every group when no name does.
void keep_named_colliders(HullGroups& groups);

} // namespace hullcover::validate::detail

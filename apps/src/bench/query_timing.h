#pragma once
// Timing the runtime against the triangles it stands for: the same capsule
// poses and rays near the surfaces, asked of a HullWorld and of a
// TriangleWorld side by side in one process (speed-ups are ratios of the
// two, which a noisy shared machine disturbs far less than either time).

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/triangle_world.h"
#include "hullcover/geometry/mesh.h"

#include <Eigen/Geometry>

#include <vector>

namespace hullcover::app::bench {

/// Capsule poses and rays near the surfaces of a mesh.
struct QueryPoses {
  double radius = 0.0, half_height = 0.0; ///< the capsule, scene units
  double ray_length = 0.0;                ///< 4 radii
  /// Randomly rotated, centred -0.5 to 1.5 radii in front of a point drawn
  /// uniformly (by area) on the faces: about a third touch, as a moving
  /// character's queries do.
  std::vector<Eigen::Isometry3d> poses;
  /// From each pose's centre, towards its face (tilted at random).
  std::vector<bvh::RayRequest> rays;
};

/// `count` poses of a capsule of `radius` and `half_height` (scene units,
/// > 0) near the faces of `mesh`, from `seed`: the same arguments, the same
/// poses. Empty when the mesh has no face with an area.
QueryPoses surface_poses(const Mesh& mesh, double radius, double half_height, int count, unsigned seed);

/// Microseconds per query on both worlds.
struct QueryTiming {
  double hull_us = 0.0, triangle_us = 0.0;
  /// How many times faster the hulls answer (triangles / hulls); 0 when
  /// nothing was timed.
  double speedup() const { return hull_us > 0.0 ? triangle_us / hull_us : 0.0; }
};

/// The three queries a server asks most, each timed on every pose.
struct QueryTimings {
  QueryTiming touches;  ///< yes/no: does the capsule touch anything
  QueryTiming contacts; ///< up to 8 contacts of the capsule, deepest first
  QueryTiming ray;      ///< first hit along each ray
};

/// Times each query kind over all poses, alternating rounds on the hulls
/// and on the triangles until both have run at least `min_seconds` (> 0)
/// and at least 2 rounds. Fails with the first query's failure (a malformed
/// pose or shape: `invalid_argument`); nothing else can fail.
[[nodiscard]] Result<QueryTimings> time_queries(const bvh::HullWorld& hulls, const bvh::TriangleWorld& triangles,
                                                const QueryPoses& poses, double min_seconds);

} // namespace hullcover::app::bench

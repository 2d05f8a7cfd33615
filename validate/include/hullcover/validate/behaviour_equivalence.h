#pragma once
/// \file behaviour_equivalence.h
/// Do characters collide with the hulls as they do with the triangles?
/// Character proxies (sphere, capsule, box) are placed at seeded random
/// poses near the surfaces, in accessible space (a pose whose centre lies in
/// enclosed space is skipped), and queried against both worlds.

#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/triangle_world.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <cstdint>
#include <optional>

namespace hullcover::validate {

/// How many proxies, where from, how big.
struct BehaviourOptions {
  int proxies = 3000;         ///< poses tried (a third of each shape)
  std::uint64_t seed = 1;     ///< seed of the poses: the same seed, the same poses
  std::optional<double> size; ///< proxy radius / half extent, scene units (default 0.005 x diagonal)
};

/// Where a proxy clear of the triangles stood deepest in a hull.
struct FalseContactPlace {
  int hull = -1;                                    ///< the hull touched; -1 for none
  int face = -1;                                    ///< the face whose front the proxy's centre stood on
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< the proxy's centre, scene coordinates
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< the contact point on the hull's surface
  double depth = 0.0;                               ///< penetration into the hull, scene units
};

/// How the proxies collided with both worlds.
struct BehaviourReport {
  double size = 0.0;                        ///< proxy radius / half extent used, scene units
  long poses = 0;                           ///< poses used (accessible ones)
  long both_touch = 0, neither_touches = 0; ///< poses on which the two worlds agree
  long missed = 0;                          ///< triangles touched, hulls not
  long false_contacts = 0;                  ///< hulls touched, triangles not
  /// False contacts deeper than tol into a hull by a proxy whose centre lies
  /// on its face's open front ray, reaching free space there (a point on a
  /// face's open front ray): lost space, a violation.
  long deep_false_contacts = 0;
  /// The same contacts reaching into enclosed space only, past an opening
  /// no triangle closes (the space behind it is the strict definition's
  /// enclosed space, which hulls may fill): allowed, counted apart.
  long enclosed_false_contacts = 0;
  /// Of those, by box proxies: a box is no union of balls, so under an
  /// agent radius its false contacts are measured, not judged.
  long deep_false_boxes = 0;
  double max_false_depth = 0.0;    ///< deepest false contact of either kind, scene units
  FalseContactPlace deepest_false; ///< the deepest of the lost (deep, free) false contacts (hull -1 when none)
  double max_normal_angle =
      0.0; ///< degrees, from the hulls' deepest normal to the nearest triangle normal, when both touch
  double mean_normal_angle = 0.0; ///< degrees, the same angle on average
};

/// Runs the proxies. Fails with `invalid_argument` for proxies < 1 or a
/// non-positive size.
Result<BehaviourReport> compare_behaviour(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles,
                                          const bvh::HullWorld& hulls, const BehaviourOptions& options);

} // namespace hullcover::validate

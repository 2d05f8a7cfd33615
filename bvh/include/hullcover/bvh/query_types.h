#pragma once
/// \file query_types.h
/// The questions a hull world answers and its answers, as plain structs:
/// a Request per query kind (a shape at a pose, a ray, a sweep) and the
/// Result it fills, with the Contact, RayHit and ClosestPoints they hold
/// (world frame, scene units; normals point out of the world hull, towards
/// the query shape). hull_queries.h lists the calls that take them.

#include "hullcover/bvh/query_shape.h"

#include <Eigen/Geometry>

#include <vector>

namespace hullcover::bvh {

/// A contact between a world hull and the query shape (world frame, scene
/// units).
struct Contact {
  int hull = -1;                                     ///< hull index in its world (-1 from the free functions)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< on the hull's surface
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); ///< unit, out of the hull towards the shape
  double depth = 0.0;                                ///< penetration along `normal`, >= 0 (0: touching)
};

/// Closest points between a hull and a point, segment or shape (world
/// frame, scene units).
struct ClosestPoints {
  double distance = 0.0; ///< >= 0; 0 when they meet
  /// Closest point on the hull; when they meet, a point in or on the hull
  /// that only locates the meeting.
  Eigen::Vector3d on_hull = Eigen::Vector3d::Zero();
  /// Closest point on the other; when they meet, the same point as on_hull.
  Eigen::Vector3d on_other = Eigen::Vector3d::Zero();
};

/// A ray hit on a hull (world frame, scene units).
struct RayHit {
  int hull = -1;                                     ///< hull index in its world (-1 from ray_hit)
  double t = 0.0;                                    ///< distance from the origin along the unit direction, >= 0
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< origin + t * direction (the origin if inside)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); ///< unit, outward normal of the facet hit
};

/// Which hulls a shape at a pose touches.
struct OverlapRequest {
  /// Any kind; limits in check_query_shape.
  QueryShape shape;
  /// The shape's local frame in the world: rotation and translation (scene
  /// units), finite. Default: identity.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};
/// What overlap() found.
struct OverlapResult {
  /// Ascending indices of every hull that overlaps or touches the shape:
  /// exactly the hulls contacts() gives a contact for (hull_contact.h's
  /// yes/no tests decide as its contacts do).
  std::vector<int> hulls;
};

/// Does a shape at a pose touch any hull: the yes/no query a server asks
/// most. It stops at the first hull found.
struct TouchResult {
  /// Some hull overlaps or touches the shape (as contacts() decides).
  bool touching = false;
  /// The first such hull found, or -1. Which one depends on the tree (the
  /// same world and request always give the same one), not on its index.
  int hull = -1;
};

/// Up to `max_contacts` contacts of a shape at a pose, deepest first.
struct ContactRequest {
  /// Any kind; limits in check_query_shape.
  QueryShape shape;
  /// The shape's local frame in the world (scene units), finite. Default:
  /// identity.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  /// Most contacts returned, >= 1 (else `invalid_argument`); the deepest
  /// are kept. Default 8.
  int max_contacts = 8;
};
/// What contacts() found.
struct ContactResult {
  /// At most one per hull the shape overlaps or touches (depth 0), at most
  /// `max_contacts` in all; deepest first, equal depths by hull index.
  std::vector<Contact> contacts;
};

/// First hit along a ray.
struct RayRequest {
  /// Where the ray starts (scene units), finite. Default: the origin.
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  /// Finite and non-zero; need not be unit: the ray is normalised, so the
  /// hit's t is a length in scene units. Default: +x.
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  /// Hits farther than this (scene units, >= 0, may be infinite) are
  /// ignored. Default 1e30: unlimited.
  double max_distance = 1e30;
};
/// What ray_cast() found.
struct RayResult {
  bool hit = false; ///< some hull is hit within max_distance
  /// The nearest hit (equal t: the lower hull index); valid when `hit`. A
  /// ray starting inside a hull hits it at t = 0.
  RayHit first;
};

/// Fails with `invalid_argument` for a non-finite origin, a zero or
/// non-finite direction or a negative (or NaN) max_distance; else gives the
/// unit direction.
[[nodiscard]] Status check_ray_request(const RayRequest& request, Eigen::Vector3d& unit_direction);

/// The nearest hull to a shape and the gap between them.
struct DistanceRequest {
  /// Any kind; limits in check_query_shape.
  QueryShape shape;
  /// The shape's local frame in the world (scene units), finite. Default:
  /// identity.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};
/// What distance() found.
struct DistanceResult {
  /// The shape overlaps or touches a hull: `distance` is exactly 0.
  bool touching = false;
  /// Gap from the shape to the nearest hull, scene units, >= 0; infinite
  /// when no hull was found (`hull` -1, see HullWorld::distance).
  double distance = 0.0;
  /// The nearest hull (equal distances: the lower index), or -1.
  int hull = -1;
  /// Closest point on the hull when apart. When touching it only locates
  /// the meeting (a point in or on the hull): contacts() gives depth and
  /// normal.
  Eigen::Vector3d on_world = Eigen::Vector3d::Zero();
  /// Closest point on the shape when apart; when touching, like on_world,
  /// it only locates the meeting (for a sphere or capsule, the point of its
  /// surface toward on_world).
  Eigen::Vector3d on_shape = Eigen::Vector3d::Zero();
};

/// A shape moving from `start` to `end`: its origin in a straight line, its
/// rotation turning the shorter way at a steady rate (slerp), both over the
/// same fraction of the way.
struct SweepRequest {
  /// Any kind; limits in check_query_shape.
  QueryShape shape;
  /// The shape's pose at fraction 0 (scene units), finite. Default:
  /// identity.
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  /// The pose at fraction 1, finite; its rotation may differ from start's
  /// (rotations agreeing to kSweepSameRotation count as the same: a pure
  /// translation). Default: identity.
  Eigen::Isometry3d end = Eigen::Isometry3d::Identity();
  /// Most advancement steps, >= 1 (else `invalid_argument`); each costs one
  /// exact distance to every hull whose box meets the swept box. A head-on
  /// approach needs a few; one grazing a hull advances ever more slowly.
  /// When they run out the sweep stops where it stands and reports that as
  /// a hit: `hit` true, `fraction` how far it got (the shape is still apart
  /// from every hull there, by more than `touch`), `hull` the nearest one,
  /// `normal` as for any hit. Conservative: it never reports a pose inside
  /// a hull, but the hit may come short of the real touch, or be reported
  /// for a path that would only graze past. Default 200.
  int max_steps = 200;
};
/// What sweep() found.
struct SweepResult {
  /// The shape comes within `touch` of a hull on the way (or ran out of
  /// steps, see SweepRequest::max_steps).
  bool hit = false;
  /// Of the way from start to end, in [0, 1], where the shape first comes
  /// within `touch` of a hull: 0 when it is that near (or overlapping) at
  /// start, 1 when no hit. Advancement never steps into a hull, so a shape
  /// that starts apart is apart (by at most `touch`) at this fraction.
  double fraction = 1.0;
  /// The hull hit, or -1.
  int hull = -1;
  /// Unit, out of the hull: the normal of the exact contact of the shape
  /// moved a further 2 x `touch` along the way; when that still makes no
  /// contact (out of steps, a grazing approach), minus the direction of
  /// travel (zero for a sweep that does not move).
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

} // namespace hullcover::bvh

#pragma once
/// \file hull_world.h
/// The runtime a game server links: a covering's hulls as `fcl::Convex`
/// objects in FCL's dynamic AABB tree (broad phase, yes/no overlap,
/// separated distance) with hullcover's exact narrow phase for contacts
/// and rays (hull_contact.h).
///
/// Every query takes a Request and fills a Result (as FCL does), returns a
/// [[nodiscard]] Status and never throws. Queries are const and safe to run
/// from many threads at once on one world.

#include "hullcover/bvh/hull_contact.h"
#include "hullcover/bvh/query_shape.h"
#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/status.h"

#include <functional>
#include <memory>
#include <vector>

namespace hullcover::bvh {

/// Which hulls a shape at a pose touches.
struct OverlapRequest {
  QueryShape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};
struct OverlapResult {
  std::vector<int> hulls;  ///< ascending hull indices
};

/// Up to `max_contacts` contacts of a shape at a pose, deepest first.
struct ContactRequest {
  QueryShape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  int max_contacts = 8;
};
struct ContactResult {
  std::vector<Contact> contacts;  ///< deepest first; ties by hull index
};

/// First hit along a ray.
struct RayRequest {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< need not be unit; t is in length units
  double max_distance = 1e30;
};
struct RayResult {
  bool hit = false;
  RayHit first;  ///< valid when hit
};

/// Fails with `invalid_argument` for a non-finite origin, a zero or
/// non-finite direction or a negative max_distance; else gives the unit
/// direction.
Status check_ray_request(const RayRequest& request, Eigen::Vector3d& unit_direction);

/// Minimum separation of a shape from the world, when not touching.
struct DistanceRequest {
  QueryShape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};
struct DistanceResult {
  bool touching = false;  ///< some hull overlaps the shape (then distance is 0)
  double distance = 0.0;
  int hull = -1;          ///< the nearest hull
  Eigen::Vector3d on_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d on_shape = Eigen::Vector3d::Zero();
};

/// A shape moving in a straight line, without turning, from `start` to
/// `end` (the two poses must share their rotation).
struct SweepRequest {
  QueryShape shape;
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d end = Eigen::Isometry3d::Identity();
};
struct SweepResult {
  bool hit = false;
  double fraction = 1.0;  ///< of the way from start to end where it first touches (0 if touching at start)
  int hull = -1;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< out of the hull, at the first touch
};

/// A convex query shape's hull placed at `pose`; nothing when its points
/// have no 3D hull.
std::optional<RuntimeHull> placed_convex(const QueryShape& shape, const Eigen::Isometry3d& pose);

class HullWorld {
public:
  /// Builds from runtime hulls (index i is hull i in every result).
  /// Fails with `invalid_argument` for an empty list or a hull with no
  /// facets or non-finite data.
  static Result<std::shared_ptr<const HullWorld>> build(std::vector<RuntimeHull> hulls);

  ~HullWorld();
  HullWorld(const HullWorld&) = delete;
  HullWorld& operator=(const HullWorld&) = delete;

  /// Fails with `invalid_argument` for a bad shape or pose (check_query_shape).
  [[nodiscard]] Status overlap(const OverlapRequest& request, OverlapResult& result) const;
  /// As overlap; exact contacts for every shape (a convex one is hulled
  /// once per call, then tested by separating axes).
  [[nodiscard]] Status contacts(const ContactRequest& request, ContactResult& result) const;
  /// Fails with `invalid_argument` for a zero or non-finite direction.
  [[nodiscard]] Status ray_cast(const RayRequest& request, RayResult& result) const;
  /// Exact for every shape (closest features; FCL's GJK distance between a
  /// box and a hull was found to overestimate, see hull_contact.h).
  [[nodiscard]] Status distance(const DistanceRequest& request, DistanceResult& result) const;

  /// Time of impact by conservative advancement on the exact distance:
  /// every step is at most the current distance, so a thin wall is never
  /// tunnelled through; the touch is found within `touch` (scene units, > 0).
  /// Any shape; `invalid_argument` for poses that turn.
  [[nodiscard]] Status sweep(const SweepRequest& request, SweepResult& result, double touch) const;

  const std::vector<RuntimeHull>& hulls() const { return hulls_; }

private:
  HullWorld() = default;
  struct Fcl;  // FCL objects, kept out of this header: fcl headers are slow to compile
  std::vector<RuntimeHull> hulls_;
  std::unique_ptr<Fcl> fcl_;

  /// The distance from hull h to `shape` at `pose` (0 when they meet) with
  /// the closest points, as a function of h; empty for a convex shape
  /// without a 3D hull.
  std::function<double(int, Eigen::Vector3d&, Eigen::Vector3d&)> separation_from(const QueryShape& shape,
                                                                                 const Eigen::Isometry3d& pose) const;
  /// Hull indices whose tree boxes overlap `box`, ascending.
  void candidates(const Aabb& box, std::vector<int>& out) const;
};

} // namespace hullcover::bvh

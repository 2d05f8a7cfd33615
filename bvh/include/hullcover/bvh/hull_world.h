#pragma once
/// \file hull_world.h
/// The runtime a game server links: a covering's hulls in a four-wide float
/// box tree with every hull's planes packed in floats (walked directly: no
/// callback or allocation per query; float tests only skip or confirm
/// beyond their rounding bounds), and hullcover's exact narrow phase for
/// every answer: yes/no, contacts, rays, distances and sweeps
/// (hull_contact.h); collector and filter forms (collectors.h) and batches
/// on threads (query_threads.h).
///
/// Every query takes a Request and fills a Result (as FCL does), returns a
/// [[nodiscard]] Status and never throws. Queries are const and safe to run
/// from many threads at once on one world.

#include "hullcover/bvh/collectors.h"
#include "hullcover/bvh/hull_contact.h"
#include "hullcover/bvh/query_threads.h"
#include "hullcover/bvh/query_shape.h"
#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/status.h"

#include <memory>
#include <optional>
#include <vector>

namespace hullcover::bvh {

namespace detail {
class HullTree;
class PackedPlanes;
struct TreeSource;
} // namespace detail

/// Which hulls a shape at a pose touches.
struct OverlapRequest {
  /// Any kind; limits in check_query_shape.
  QueryShape shape;
  /// The shape's local frame in the world: rotation and translation (scene
  /// units), finite. Default: identity.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};
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
struct RayResult {
  bool hit = false;  ///< some hull is hit within max_distance
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

/// A convex query shape's hull placed at `pose`; nothing when its points
/// have no 3D hull.
std::optional<RuntimeHull> placed_convex(const QueryShape& shape, const Eigen::Isometry3d& pose);

/// The queries every hull world answers, in the same code for all: a world
/// class `World` derives from HullQueries<World> and hands them its hulls
/// (HullWorld its one tree; StreamedWorld, streamed_world.h, the sections
/// loaded when the call starts, and "the world" below means those). Indices
/// in results are the world's hull indices. Every query leaves its result
/// meaningful only when the Status is ok, and never throws.
template <typename World>
class HullQueries {
public:
  /// Fails with `invalid_argument` for a bad shape or pose
  /// (check_query_shape) or a convex shape whose points have no 3D hull.
  /// Walks the tree and tests hulls only until one touches.
  [[nodiscard]] Status touches(const OverlapRequest& request, TouchResult& result) const;
  /// Every touching hull; fails as touches() does.
  [[nodiscard]] Status overlap(const OverlapRequest& request, OverlapResult& result) const;
  /// Fails as overlap does, and for max_contacts < 1. Exact contacts for
  /// every shape (a convex one is hulled once per call, then tested by
  /// separating axes).
  [[nodiscard]] Status contacts(const ContactRequest& request, ContactResult& result) const;
  /// Fails with `invalid_argument` as check_ray_request does. The tree is
  /// walked nearer boxes first and pruned at the best hit so far.
  [[nodiscard]] Status ray_cast(const RayRequest& request, RayResult& result) const;

  /// The collector forms (collectors.h, after Jolt's NarrowPhaseQuery):
  /// each hull `filter` admits is tested, and each hit handed to
  /// `collector` (reset first) in walk order, until it stops the walk.
  /// Fail as the plain calls do. The plain calls are these with a
  /// collector of their own: touches() an AnyHitCollector, overlap() and
  /// contacts() every hit then sorted, ray_cast() the closest.
  ///
  /// Every hull the shape touches, as its index.
  [[nodiscard]] Status overlapping(const OverlapRequest& request, const HullFilter& filter,
                                   HitCollector<int>& collector) const;
  /// The exact contact of every hull the shape touches (Contact::hull set).
  [[nodiscard]] Status collide(const OverlapRequest& request, const HullFilter& filter,
                               HitCollector<Contact>& collector) const;
  /// Each hull's first hit along the ray within max_distance and the
  /// collector's reach(); a collector that lowers its reach (closest hit)
  /// prunes the walk there.
  [[nodiscard]] Status cast_ray(const RayRequest& request, const HullFilter& filter,
                                HitCollector<RayHit>& collector) const;

  /// Batches: `results[i]` answers `requests[i]` as the plain call would,
  /// run on `threads` (query_threads.h) when given, else on the caller's
  /// thread; the same answers for any thread count. When requests fail,
  /// the lowest failing index is reported (its code, and a message naming
  /// it) and `results` is left empty.
  [[nodiscard]] Status touches_batch(const std::vector<OverlapRequest>& requests, std::vector<TouchResult>& results,
                                     QueryThreads* threads = nullptr) const;
  [[nodiscard]] Status contacts_batch(const std::vector<ContactRequest>& requests,
                                      std::vector<ContactResult>& results, QueryThreads* threads = nullptr) const;
  [[nodiscard]] Status ray_cast_batch(const std::vector<RayRequest>& requests, std::vector<RayResult>& results,
                                      QueryThreads* threads = nullptr) const;
  /// Fails as overlap does. The distance is exact for every shape: spheres
  /// and capsules from their axis, boxes and convex shapes from closest
  /// features (closest_between; FCL's GJK distance was found to
  /// overestimate). The search box grows from the shape's box until it
  /// holds the nearest hull, but stops once it reaches more than four world
  /// diagonals out: from farther away `hull` is -1 (distance infinite) or
  /// a hull that need not be the nearest.
  [[nodiscard]] Status distance(const DistanceRequest& request, DistanceResult& result) const;

  /// Time of impact by conservative advancement on the exact distance: no
  /// point of the shape moves farther in a step than the current distance
  /// (the origin's travel plus the turn's angle times the shape's reach
  /// from its origin bound every point's), so a thin wall is never
  /// tunnelled through; the touch is found within `touch` (scene units,
  /// finite, > 0; a smaller one costs more steps near a hull). Any shape.
  /// Fails with `invalid_argument` for a bad shape or pose, a bad `touch`
  /// or max_steps < 1.
  [[nodiscard]] Status sweep(const SweepRequest& request, SweepResult& result, double touch) const;

protected:
  HullQueries() = default;
  ~HullQueries() = default;
};

/// A covering's hulls, built once, then queried from any number of threads.
/// What a game server writes (tests/support/runtime_only_example.cpp runs
/// it):
///
///     using namespace hullcover;
///     Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file("level.hcw");
///     if (!hulls.ok()) return fail(hulls.status());  // message says what and where
///     Result<std::shared_ptr<const bvh::HullWorld>> built = bvh::HullWorld::build(std::move(hulls).value());
///     if (!built.ok()) return fail(built.status());
///     const std::shared_ptr<const bvh::HullWorld> world = built.value();
///
///     // Once per character per tick, from any thread:
///     bvh::ContactRequest request;
///     request.shape = bvh::QueryShape::capsule(0.4, 0.5);  // radius, half height (scene units)
///     request.pose.linear() = up_is_y;                     // the capsule's axis is its local z
///     request.pose.translation() = position;
///     bvh::ContactResult result;
///     if (Status s = world->contacts(request, result); !s.ok()) return fail(s);
///     if (!result.contacts.empty()) {                      // deepest first
///       const bvh::Contact& c = result.contacts.front();
///       position += c.depth * c.normal;                    // out of that hull, to touching
///     }
///
/// Every query leaves its result meaningful only when the Status is ok.
class HullWorld : public HullQueries<HullWorld> {
public:
  /// Builds from runtime hulls (index i is hull i in every result).
  /// Fails with `invalid_argument` for an empty list or a hull with no
  /// facets or non-finite data.
  static Result<std::shared_ptr<const HullWorld>> build(std::vector<RuntimeHull> hulls);

  ~HullWorld();
  HullWorld(const HullWorld&) = delete;
  HullWorld& operator=(const HullWorld&) = delete;

  /// The hulls, in the order given to build (hull i of every result).
  const std::vector<RuntimeHull>& hulls() const { return hulls_; }

private:
  HullWorld() = default;
  std::vector<RuntimeHull> hulls_;
  // The broad phase, kept out of this header: fcl headers are slow to compile.
  std::unique_ptr<detail::HullTree> tree_;
  // Every hull's planes in floats, for the queries' first test of a hull.
  std::unique_ptr<detail::PackedPlanes> planes_;

  friend class HullQueries<HullWorld>;
  // The hulls and tree as a hull source for the queries (world_queries.h).
  detail::TreeSource source() const;
};

} // namespace hullcover::bvh

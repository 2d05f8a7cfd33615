#pragma once
/// \file hull_queries.h
/// The queries every hull world answers (HullWorld, hull_world.h;
/// StreamedWorld, streamed_world.h), written once for both: plain calls,
/// collector and filter forms (collectors.h) and batches on threads
/// (query_threads.h), each taking a Request and filling a Result
/// (query_types.h).

#include "hullcover/bvh/collectors.h"
#include "hullcover/bvh/query_threads.h"
#include "hullcover/bvh/query_types.h"
#include "hullcover/geometry/status.h"

#include <vector>

namespace hullcover::bvh {

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
  /// Whether any hull lies on the ray within max_distance: a line of
  /// sight is clear when it is not. The walk stops at the first hull it
  /// finds hit, so it costs at most what ray_cast() does; `result.hit` is
  /// ray_cast()'s, and `result.first` is that hull's own first hit, which
  /// need not be the nearest (the same one every time). Fails as ray_cast().
  [[nodiscard]] Status ray_blocked(const RayRequest& request, RayResult& result) const;

  /// The collector forms (collectors.h, after Jolt's NarrowPhaseQuery):
  /// each hull `filter` admits is tested, and each hit handed to
  /// `collector` (reset first) in walk order, until it stops the walk.
  /// Fail as the plain calls do. The plain calls give these answers with
  /// a collector of their own: touches() an AnyHitCollector, overlap() and
  /// contacts() every hit then sorted, ray_cast() the closest (kept by the
  /// walk itself, without a collector to call through), and ray_blocked()
  /// an AnyHitCollector.
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
  /// contacts() for each request, as touches_batch.
  [[nodiscard]] Status contacts_batch(const std::vector<ContactRequest>& requests, std::vector<ContactResult>& results,
                                      QueryThreads* threads = nullptr) const;
  /// ray_cast() for each request, as touches_batch.
  [[nodiscard]] Status ray_cast_batch(const std::vector<RayRequest>& requests, std::vector<RayResult>& results,
                                      QueryThreads* threads = nullptr) const;
  /// ray_blocked() for each request, as touches_batch.
  [[nodiscard]] Status ray_blocked_batch(const std::vector<RayRequest>& requests, std::vector<RayResult>& results,
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

} // namespace hullcover::bvh

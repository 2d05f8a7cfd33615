#pragma once
// The hit-finding queries (private to bvh/): yes/no, overlap, contacts and
// rays, each written once as a walk that hands hits to a collector
// (collectors.h) after a filter; the plain calls of HullQueries are these
// with a collector of their own, and the batches run them on QueryThreads.
// Hull sources are as world_queries.h describes.

#include "hullcover/bvh/collectors.h"
#include "hullcover/bvh/query_threads.h"

#include "world_queries.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <string>
#include <vector>

namespace hullcover::bvh::detail {

/// Appends every hit to a vector the caller owns (a result's own list), so
/// the plain calls fill their results without a vector of their own.
template <typename Hit>
class AppendTo final : public HitCollector<Hit> {
public:
  explicit AppendTo(std::vector<Hit>& out) : out_(out) {}
  void add(const Hit& hit) override { out_.push_back(hit); }

private:
  std::vector<Hit>& out_;
};

/// The nearer ray hit; at equal t the lower hull index, whatever order the
/// walk visits hulls in.
struct NearerRayHit {
  bool operator()(const RayHit& a, const RayHit& b) const { return a.t < b.t || (a.t == b.t && a.hull < b.hull); }
  static double reach_after(const RayHit& hit) { return hit.t; }
};
using ClosestRayHit = BestHitCollector<RayHit, NearerRayHit>;

/// Every hull the placed shape touches, as its index, to `collector` (reset
/// first), skipping hulls `filter` does not admit.
template <typename Source>
Status overlapping_query(const Source& source, const OverlapRequest& request, const HullFilter& filter,
                         HitCollector<int>& collector) {
  return guarded("overlap query", [&]() -> Status {
    collector.reset();
    std::optional<PlacedShape> placed;
    if (Status s = place(request.shape, request.pose, placed); !s.ok()) return s;
    const bool all = filter.admits_all();
    find_candidates(source, *placed, [&](int h, const RuntimeHull& hull, PlanesOf planes) {
      if ((!all && !filter.admits(h, hull.material)) || !placed->touches(hull, planes)) return false;
      collector.add(h);
      return collector.stopped();
    });
    return Status::success();
  });
}

/// The exact contact of every hull the placed shape touches (hull set).
template <typename Source>
Status collide_query(const Source& source, const OverlapRequest& request, const HullFilter& filter,
                     HitCollector<Contact>& collector) {
  return guarded("contact query", [&]() -> Status {
    collector.reset();
    std::optional<PlacedShape> placed;
    if (Status s = place(request.shape, request.pose, placed); !s.ok()) return s;
    const bool all = filter.admits_all();
    find_every_candidate(source, *placed, [&](int h, const RuntimeHull& hull, PlanesOf) {
      if (!all && !filter.admits(h, hull.material)) return false;
      if (std::optional<Contact> c = placed->contact(hull)) {
        c->hull = h;
        collector.add(*c);
      }
      return collector.stopped();
    });
    return Status::success();
  });
}

/// A checked ray (unit direction): each admitted hull's first hit within
/// the reach, which is max_distance lowered to the collector's reach().
template <typename Source>
void cast_checked_ray(const Source& source, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                      double max_distance, const HullFilter& filter, HitCollector<RayHit>& collector) {
  collector.reset();
  double reach = std::min(max_distance, collector.reach());
  const bool all = filter.admits_all();
  source.along_ray(origin, dir.cwiseInverse(), reach,
                   [&](int h, const RuntimeHull& hull, PlanesOf planes, double& best) {
    if (!all && !filter.admits(h, hull.material)) return;
    // The exact clip on the hull's packed planes, which leaves a hull after
    // the first plane that shows a miss (a float pre-test first measured no
    // faster). A hull entered exactly at the reach is kept: equal t may go
    // to the lower index.
    if (std::optional<RayHit> hit = planes.ray_hit(hull, origin, dir, best)) {
      hit->hull = h;
      collector.add(*hit);
      // A stopped walk prunes every box (their entries are >= 0).
      best = collector.stopped() ? -1.0 : std::min(best, collector.reach());
    }
  });
}

template <typename Source>
Status cast_ray_query(const Source& source, const RayRequest& request, const HullFilter& filter,
                      HitCollector<RayHit>& collector) {
  return guarded("ray query", [&]() -> Status {
    collector.reset();
    Eigen::Vector3d dir;
    if (Status s = check_ray_request(request, dir); !s.ok()) return s;
    cast_checked_ray(source, request.origin, dir, request.max_distance, filter, collector);
    return Status::success();
  });
}

// ---- The plain calls --------------------------------------------------------

template <typename Source>
Status touch_query(const Source& source, const OverlapRequest& request, TouchResult& result) {
  AnyHitCollector<int> any;
  Status s = overlapping_query(source, request, HullFilter{}, any);
  result = {};
  if (s.ok() && any.found()) {
    result.touching = true;
    result.hull = any.hit();
  }
  return s;
}

template <typename Source>
Status overlap_query(const Source& source, const OverlapRequest& request, OverlapResult& result) {
  result.hulls.clear();
  AppendTo<int> append(result.hulls);
  Status s = overlapping_query(source, request, HullFilter{}, append);
  std::sort(result.hulls.begin(), result.hulls.end());
  return s;
}

/// Room a result's contact list gets at its first query: a large sphere or
/// capsule touches tens of hulls, and a list grown one doubling at a time
/// from nothing would be allocated six times for them. A result that is
/// reused keeps what it has grown to and is never allocated again.
inline constexpr size_t kFirstContactRoom = 64;

template <typename Source>
Status contact_query(const Source& source, const ContactRequest& request, ContactResult& result) {
  result.contacts.clear();
  if (result.contacts.capacity() == 0) result.contacts.reserve(kFirstContactRoom);
  if (request.max_contacts < 1) return {StatusCode::invalid_argument, "max_contacts must be at least 1"};
  AppendTo<Contact> append(result.contacts);
  Status s = collide_query(source, OverlapRequest{request.shape, request.pose}, HullFilter{}, append);
  // Deepest first, equal depths by hull index: a total order, so the
  // answer does not depend on the tree's walk.
  std::sort(result.contacts.begin(), result.contacts.end(), [](const Contact& x, const Contact& y) {
    return x.depth > y.depth || (x.depth == y.depth && x.hull < y.hull);
  });
  if (static_cast<int>(result.contacts.size()) > request.max_contacts) result.contacts.resize(request.max_contacts);
  return s;
}

template <typename Source>
Status ray_query(const Source& source, const RayRequest& request, RayResult& result) {
  // cast_ray_query with ClosestRayHit, written out: the plain call a server
  // makes most keeps its nearest hit itself, with no collector to call
  // through. The same hit: NearerRayHit's order, and the same pruning.
  return guarded("ray query", [&]() -> Status {
    result = {};
    Eigen::Vector3d dir;
    if (Status s = check_ray_request(request, dir); !s.ok()) return s;
    double reach = request.max_distance;
    source.along_ray(request.origin, dir.cwiseInverse(), reach,
                     [&](int h, const RuntimeHull& hull, PlanesOf planes, double& best) {
      if (std::optional<RayHit> hit = planes.ray_hit(hull, request.origin, dir, best)) {
        hit->hull = h;
        if (result.hit && !NearerRayHit{}(*hit, result.first)) return;
        result.hit = true;
        result.first = *hit;
        best = std::min(best, hit->t);
      }
    });
    return Status::success();
  });
}

template <typename Source>
Status ray_blocked_query(const Source& source, const RayRequest& request, RayResult& result) {
  AnyHitCollector<RayHit> any;
  Status s = cast_ray_query(source, request, HullFilter{}, any);
  result = {};
  if (s.ok() && any.found()) {
    result.hit = true;
    result.first = any.hit();
  }
  return s;
}

// ---- Batches ------------------------------------------------------------------

// Items per chunk a thread takes: small enough that threads finish
// together, large enough that taking one costs nothing next to its queries.
inline constexpr size_t kBatchChunk = 16;

/// Runs `answer(i)` (a Status) for every i < count, on `threads` when given,
/// else on the caller's. The failure of the lowest failing index is
/// returned, naming it, whatever the thread count.
template <typename Answer>
Status run_batch(size_t count, QueryThreads* threads, const char* what, Answer&& answer) {
  std::atomic<size_t> first_bad{count};
  std::mutex bad_mutex;
  Status bad;
  auto one = [&](size_t i) {
    Status s = answer(i);
    if (s.ok()) return;
    std::lock_guard<std::mutex> lock(bad_mutex);
    if (i < first_bad.load()) {
      first_bad.store(i);
      bad = std::move(s);
    }
  };
  if (threads == nullptr || threads->size() == 1 || count <= kBatchChunk) {
    for (size_t i = 0; i < count; ++i) one(i);
  } else {
    struct Job {
      decltype(one)* call;
    } job{&one};
    threads->run(
        count, kBatchChunk,
        [](size_t begin, size_t end, void* context) {
      for (size_t i = begin; i < end; ++i) (*static_cast<Job*>(context)->call)(i);
        },
        &job);
  }
  if (first_bad.load() == count) return Status::success();
  return {bad.code(), std::string(what) + " " + std::to_string(first_bad.load()) + " of the batch: " + bad.message()};
}

template <typename Source, typename Request, typename Answer, typename ResultT>
Status batch_query(const Source& source, const std::vector<Request>& requests, std::vector<ResultT>& results,
                   QueryThreads* threads, const char* what, Answer answer) {
  return guarded("batch query", [&]() -> Status {
    results.resize(requests.size());
    Status s =
        run_batch(requests.size(), threads, what, [&](size_t i) { return answer(source, requests[i], results[i]); });
    if (!s.ok()) results.clear();
    return s;
  });
}

} // namespace hullcover::bvh::detail

namespace hullcover::bvh {

template <typename World>
Status HullQueries<World>::touches(const OverlapRequest& request, TouchResult& result) const {
  return detail::touch_query(static_cast<const World&>(*this).source(), request, result);
}
template <typename World>
Status HullQueries<World>::overlap(const OverlapRequest& request, OverlapResult& result) const {
  return detail::overlap_query(static_cast<const World&>(*this).source(), request, result);
}
template <typename World>
Status HullQueries<World>::contacts(const ContactRequest& request, ContactResult& result) const {
  return detail::contact_query(static_cast<const World&>(*this).source(), request, result);
}
template <typename World>
Status HullQueries<World>::ray_cast(const RayRequest& request, RayResult& result) const {
  return detail::ray_query(static_cast<const World&>(*this).source(), request, result);
}
template <typename World>
Status HullQueries<World>::ray_blocked(const RayRequest& request, RayResult& result) const {
  return detail::ray_blocked_query(static_cast<const World&>(*this).source(), request, result);
}
template <typename World>
Status HullQueries<World>::overlapping(const OverlapRequest& request, const HullFilter& filter,
                                       HitCollector<int>& collector) const {
  return detail::overlapping_query(static_cast<const World&>(*this).source(), request, filter, collector);
}
template <typename World>
Status HullQueries<World>::collide(const OverlapRequest& request, const HullFilter& filter,
                                   HitCollector<Contact>& collector) const {
  return detail::collide_query(static_cast<const World&>(*this).source(), request, filter, collector);
}
template <typename World>
Status HullQueries<World>::cast_ray(const RayRequest& request, const HullFilter& filter,
                                    HitCollector<RayHit>& collector) const {
  return detail::cast_ray_query(static_cast<const World&>(*this).source(), request, filter, collector);
}
template <typename World>
Status HullQueries<World>::touches_batch(const std::vector<OverlapRequest>& requests, std::vector<TouchResult>& results,
                                         QueryThreads* threads) const {
  const auto source = static_cast<const World&>(*this).source();
  return detail::batch_query(
      source, requests, results, threads, "request",
      [](const auto& src, const OverlapRequest& q, TouchResult& r) { return detail::touch_query(src, q, r); });
}
template <typename World>
Status HullQueries<World>::contacts_batch(const std::vector<ContactRequest>& requests,
                                          std::vector<ContactResult>& results, QueryThreads* threads) const {
  const auto source = static_cast<const World&>(*this).source();
  return detail::batch_query(
      source, requests, results, threads, "request",
      [](const auto& src, const ContactRequest& q, ContactResult& r) { return detail::contact_query(src, q, r); });
}
template <typename World>
Status HullQueries<World>::ray_cast_batch(const std::vector<RayRequest>& requests, std::vector<RayResult>& results,
                                          QueryThreads* threads) const {
  const auto source = static_cast<const World&>(*this).source();
  return detail::batch_query(
      source, requests, results, threads, "ray",
      [](const auto& src, const RayRequest& q, RayResult& r) { return detail::ray_query(src, q, r); });
}
template <typename World>
Status HullQueries<World>::ray_blocked_batch(const std::vector<RayRequest>& requests, std::vector<RayResult>& results,
                                             QueryThreads* threads) const {
  const auto source = static_cast<const World&>(*this).source();
  return detail::batch_query(
      source, requests, results, threads, "ray",
      [](const auto& src, const RayRequest& q, RayResult& r) { return detail::ray_blocked_query(src, q, r); });
}

} // namespace hullcover::bvh

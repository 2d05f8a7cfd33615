#pragma once
// The queries of HullWorld and StreamedWorld (private to bvh/), written once
// over a "hull source": whatever finds candidate hulls for a box, a point's
// neighbourhood or a ray. HullWorld's source is one packed tree; a streamed
// world's is a tree of sections, each a packed tree of its own. Both hand
// each candidate to the query as (index in the answers, the hull), so the
// narrow phase, the order rules and the numbers are the same code for both.
// HullQueries' members (hull_world.h), at the end, take the world's source
// and call these; the queries that hand hits to collectors, and the
// batches, are in collected_queries.h.
//
// A source S provides, every visit returning true to stop the walk, and
// every visit given the hull's index in the answers, the hull and its
// packed planes (packed_planes.h):
//   bool in_box(const Aabb&, visit(int, const RuntimeHull&, PlanesOf) -> bool)
//   bool near_point(centre, radius, visit(int, const RuntimeHull&, PlanesOf) -> bool)
//   bool near_segment(a, b, radius, visit(int, const RuntimeHull&, PlanesOf) -> bool)
//   void along_ray(origin, inverse, double& reach, visit(int, const RuntimeHull&, PlanesOf, double& reach))
//   std::optional<Aabb> bounds()  (nothing when it holds no hull)
// with HullTree's guarantees (hull_tree.h): a box walk never misses a hull
// whose box meets the box; a ray walk may shorten `reach` to prune.

#include "hullcover/bvh/hull_contact.h"
#include "hullcover/bvh/hull_queries.h"

#include "packed_planes.h"
#include "query_guard.h"

#include "hullcover/geometry/tolerances.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace hullcover::bvh::detail {

/// A query shape placed at its pose, ready for the yes/no test and the
/// contact against any number of hulls (a capsule's ends found and a convex
/// shape hulled once). Keeps references to the shape and the pose.
struct PlacedShape {
  const QueryShape& shape;
  const Eigen::Isometry3d& pose;
  Eigen::Vector3d a, b;              ///< capsule axis ends; a sphere's centre twice
  std::optional<RuntimeHull> convex; ///< a convex shape's hull in the world

  bool touches(const RuntimeHull& hull) const;
  std::optional<Contact> contact(const RuntimeHull& hull) const;

  /// The float pre-test of a sphere or capsule on the hull's packed planes
  /// (unsure for the other shapes).
  FloatVerdict float_verdict(PlanesOf planes) const;
  /// touches(hull), first settled by the float pre-test where it can: the
  /// same answers. Contacts take no pre-test: most hulls a contact query's
  /// walk reaches touch the shape and need the exact contact anyway, and
  /// the pre-test measured a net cost there (docs/definitions-and-proofs.md,
  /// "The runtime's float pre-tests").
  bool touches(const RuntimeHull& hull, PlanesOf planes) const {
    const FloatVerdict v = float_verdict(planes);
    return v == FloatVerdict::unsure ? touches(hull) : v == FloatVerdict::meets;
  }
};

/// Checks a shape and pose and places the shape; fails as
/// HullWorld::overlap documents.
Status place(const QueryShape& shape, const Eigen::Isometry3d& pose, std::optional<PlacedShape>& placed);

/// The distance from a hull to `shape` at `pose` (0 when they meet) with the
/// closest points; empty for a convex shape without a 3D hull.
using Separation = std::function<double(const RuntimeHull&, Eigen::Vector3d&, Eigen::Vector3d&)>;
Separation separation_from(const QueryShape& shape, const Eigen::Isometry3d& pose);

/// Fails with `invalid_argument` naming the hull (by `names[i]` when given,
/// else i) that has no facets, non-finite data or surface flags neither
/// absent nor one per plane: what HullWorld::build refuses.
Status check_hulls(const std::vector<RuntimeHull>& hulls, const std::vector<int>* names);

/// A hull a query reaches: its index in the answers and the hull.
struct Candidate {
  int index;
  const RuntimeHull* hull;
};

/// A sweep's path, checked: poses along it and how fast any point moves.
struct SweepPath {
  Eigen::Isometry3d start;
  Eigen::Vector3d travel;
  Eigen::Quaterniond from, to;
  bool turns = false;
  double speed = 0.0; ///< no point of the shape moves farther per unit of the way
  Eigen::Isometry3d pose_at(double t) const;
};

/// Checks a sweep (fails as HullWorld::sweep documents) and gives its path
/// and the box every pose along it stays in.
Status plan_sweep(const SweepRequest& request, double touch, SweepPath& path, Aabb& swept);

/// Conservative advancement along a planned path against the hulls `near`
/// (ascending index: equal distances go to the lower index).
Status advance_sweep(const SweepRequest& request, const SweepPath& path, const std::vector<Candidate>& near,
                     double touch, SweepResult& result);

/// Every hull whose box meets `box`, ascending index.
template <typename Source>
void candidates_in_box(const Source& source, const Aabb& box, std::vector<Candidate>& out) {
  out.clear();
  source.in_box(box, [&](int h, const RuntimeHull& hull, PlanesOf) {
    out.push_back({h, &hull});
    return false;
  });
  std::sort(out.begin(), out.end(), [](const Candidate& x, const Candidate& y) { return x.index < y.index; });
}

/// Calls visit(h, hull) for the hulls the placed shape may touch, until it
/// returns true: the hulls whose boxes meet its box, or for a sphere those
/// within its radius, nearest its centre first (a yes/no query meets a
/// touching hull early).
template <typename Source, typename Visit>
void find_candidates(const Source& source, const PlacedShape& placed, Visit&& visit) {
  if (placed.shape.kind == ShapeKind::sphere)
    source.near_point(placed.a, placed.shape.radius, visit);
  else
    source.in_box(world_box(placed.shape, placed.pose), visit);
}

/// The same for a query that visits every candidate (contacts): a
/// capsule's are then the hulls whose boxes come within its radius of its
/// axis, far fewer than its box holds when the axis slants, found from one
/// end to the other.
template <typename Source, typename Visit>
void find_every_candidate(const Source& source, const PlacedShape& placed, Visit&& visit) {
  if (placed.shape.kind == ShapeKind::capsule)
    source.near_segment(placed.a, placed.b, placed.shape.radius, visit);
  else
    find_candidates(source, placed, visit);
}

template <typename Source>
Status distance_query(const Source& source, const DistanceRequest& request, DistanceResult& result) {
  return guarded("distance query", [&]() -> Status {
    result = {};
    if (Status s = check_query_shape(request.shape, request.pose); !s.ok()) return s;
    const Aabb core = world_box(request.shape, request.pose);
    const Separation separation = separation_from(request.shape, request.pose);
    if (!separation) return {StatusCode::invalid_argument, "the convex query shape has no 3D hull"};
    result.distance = std::numeric_limits<double>::infinity();
    const std::optional<Aabb> world = source.bounds();
    if (!world) return Status::success(); // no hull to be near
    // Grow the search box until it holds a hull, then until it holds every
    // hull nearer than the best found.
    const double scene = (world->max - world->min).norm();
    double reach = 0.0;
    std::vector<Candidate> near;
    for (int round = 0; round < 64; ++round) {
      candidates_in_box(source, grown(core, reach), near);
      for (const Candidate& c : near) {
        Eigen::Vector3d on_world, on_shape;
        const double d = separation(*c.hull, on_world, on_shape);
        if (d < result.distance || (d == result.distance && c.index < result.hull)) {
          result.distance = d;
          result.hull = c.index;
          result.on_world = on_world;
          result.on_shape = on_shape;
        }
      }
      if (result.hull >= 0 && result.distance <= reach) break;
      if (reach > 4.0 * scene) break;
      reach = result.hull >= 0 ? result.distance : 2.0 * reach + kDistanceReachGrowth * (1.0 + scene);
    }
    result.touching = result.hull >= 0 && result.distance == 0.0;
    return Status::success();
  });
}

template <typename Source>
Status sweep_query(const Source& source, const SweepRequest& request, SweepResult& result, double touch) {
  return guarded("sweep", [&]() -> Status {
    result = {};
    SweepPath path;
    Aabb swept;
    if (Status s = plan_sweep(request, touch, path, swept); !s.ok()) return s;
    std::vector<Candidate> near;
    candidates_in_box(source, swept, near);
    return advance_sweep(request, path, near, touch, result);
  });
}

} // namespace hullcover::bvh::detail

namespace hullcover::bvh {

// HullQueries' members (hull_world.h), instantiated by each world's source
// file for its own World: each takes the world's hull source for the call.
template <typename World>
Status HullQueries<World>::distance(const DistanceRequest& request, DistanceResult& result) const {
  return detail::distance_query(static_cast<const World&>(*this).source(), request, result);
}
template <typename World>
Status HullQueries<World>::sweep(const SweepRequest& request, SweepResult& result, double touch) const {
  return detail::sweep_query(static_cast<const World&>(*this).source(), request, result, touch);
}

} // namespace hullcover::bvh

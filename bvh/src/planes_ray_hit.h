#pragma once
// The first hit of a ray on a convex hull given by its planes alone
// (private to bvh/): what ray_hit computes on a RuntimeHull, and the
// packed store (packed_planes.h) on its own contiguous copy of the same
// planes, in the same operations, so both give the same bits.

#include "hullcover/bvh/query_types.h"
#include "hullcover/geometry/convex_polytope.h"

#include <algorithm>
#include <optional>

namespace hullcover::bvh::detail {

/// Of planes [0, facets), the one `p` is least deep behind (the first of
/// equals).
inline int least_deep_plane(const Plane* planes, int facets, const Eigen::Vector3d& p) {
  int best = 0;
  for (int f = 1; f < facets; ++f)
    if (planes[f].signed_distance(p) > planes[best].signed_distance(p)) best = f;
  return best;
}

/// First hit of origin + t * direction (unit), 0 <= t <= max_t, on the hull
/// bounded by `count` planes whose first `facets` are its facets'. An
/// origin inside hits at t = 0 with the normal of the facet it is least
/// deep behind.
inline std::optional<RayHit> first_hit_on_planes(const Plane* planes, int count, int facets,
                                                 const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                                 double max_t) {
  double enter = 0.0, leave = max_t;
  int entering_plane = -1;
  for (int i = 0; i < count; ++i) {
    const Plane& plane = planes[i];
    const double dist = plane.signed_distance(origin), denom = plane.normal.dot(direction);
    if (denom == 0.0) {
      if (dist > 0.0) return std::nullopt;
      continue;
    }
    const double t = -dist / denom;
    if (denom < 0.0) {
      if (t > enter) {
        enter = std::max(enter, t);
        entering_plane = i;
      }
    } else {
      leave = std::min(leave, t);
    }
    if (enter > leave) return std::nullopt;
  }
  if (entering_plane < 0) // the origin is inside (or on) the hull
    return RayHit{-1, 0.0, origin, planes[least_deep_plane(planes, facets, origin)].normal};
  return RayHit{-1, enter, origin + enter * direction, planes[entering_plane].normal};
}

} // namespace hullcover::bvh::detail

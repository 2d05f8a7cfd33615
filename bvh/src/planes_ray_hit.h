#pragma once
// The first hit of a ray on a convex hull given by its planes alone
// (private to bvh/): what ray_hit computes on a RuntimeHull's planes, and
// the packed store (packed_planes.h) on its own copy of them, two planes
// at a time. Both give the same bits: each plane's distance and slope are
// the same correctly rounded operations in the same order, and the answer
// does not depend on the order the planes are taken in (the entry is the
// largest entering t, the exit the smallest leaving one, and the entering
// plane the lowest-numbered of those giving the entry).

#include "hullcover/bvh/query_types.h"
#include "hullcover/geometry/convex_polytope.h"

#include <algorithm>
#include <limits>
#include <optional>

// SSE2 where the compiler offers it (every x86-64 build); a build may set
// HULLCOVER_PLANE_PAIRS_SSE2 to 0 for the plain loop, which gives the same
// answers.
#ifndef HULLCOVER_PLANE_PAIRS_SSE2
#if defined(__SSE2__) || defined(_M_X64)
#define HULLCOVER_PLANE_PAIRS_SSE2 1
#else
#define HULLCOVER_PLANE_PAIRS_SSE2 0
#endif
#endif
#if HULLCOVER_PLANE_PAIRS_SSE2
#include <emmintrin.h>
#endif

namespace hullcover::bvh::detail {

/// n . p - offset, as (n.x p.x + n.y p.y) + n.z p.z - offset: written out
/// so that every copy of a hull's planes computes the same bits.
inline double plane_height(double nx, double ny, double nz, double offset, const Eigen::Vector3d& p) {
  return nx * p.x() + ny * p.y() + nz * p.z() - offset;
}
/// n . v, in the same order.
inline double plane_slope(double nx, double ny, double nz, const Eigen::Vector3d& v) {
  return nx * v.x() + ny * v.y() + nz * v.z();
}

/// Of planes [0, facets), the one `p` is least deep behind (the first of
/// equals).
inline int least_deep_plane(const Plane* planes, int facets, const Eigen::Vector3d& p) {
  int best = 0;
  double most = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < facets; ++f) {
    const Plane& q = planes[f];
    const double h = plane_height(q.normal.x(), q.normal.y(), q.normal.z(), q.offset, p);
    if (f == 0 || h > most) {
      most = h;
      best = f;
    }
  }
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
    const Eigen::Vector3d& n = planes[i].normal;
    const double dist = plane_height(n.x(), n.y(), n.z(), planes[i].offset, origin);
    const double denom = plane_slope(n.x(), n.y(), n.z(), direction);
    if (denom == 0.0) {
      if (dist > 0.0) return std::nullopt;
      continue;
    }
    const double t = -dist / denom;
    if (denom < 0.0) {
      if (t > enter) {
        enter = t;
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

/// Two planes side by side, for the clip two at a time. A hull with an odd
/// plane count pads its last pair with a plane of zero normal and the
/// largest offset: parallel to every ray and behind every point, it
/// changes no clip. One cache line each, aligned to one: a pair spread over
/// two would cost two reads.
struct alignas(64) PlanePair {
  double nx[2], ny[2], nz[2], offset[2];
};

/// first_hit_on_planes on planes stored as `pairs` (count planes, padded).
inline std::optional<RayHit> first_hit_on_plane_pairs(const PlanePair* pairs, int count, int facets,
                                                      const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                                      double max_t) {
  double enter = 0.0;
  int entering_plane = -1;
#if HULLCOVER_PLANE_PAIRS_SSE2
  const int pair_count = (count + 1) / 2;
  const __m128d ox = _mm_set1_pd(origin.x()), oy = _mm_set1_pd(origin.y()), oz = _mm_set1_pd(origin.z());
  const __m128d dx = _mm_set1_pd(direction.x()), dy = _mm_set1_pd(direction.y()), dz = _mm_set1_pd(direction.z());
  const __m128d zero = _mm_setzero_pd(), sign = _mm_set1_pd(-0.0);
  const __m128d up = _mm_set1_pd(std::numeric_limits<double>::infinity());
  // Per lane: the largest entering t (strictly above the ones before, as
  // the one-at-a-time clip takes them) with its plane, and the least
  // leaving t. Plane numbers are doubles to share the lanes' masks.
  __m128d lane_enter = zero, lane_plane = _mm_set1_pd(-1.0), lane_leave = _mm_set1_pd(max_t);
  __m128d plane = _mm_set_pd(1.0, 0.0);
  const __m128d next_pair = _mm_set1_pd(2.0);
  for (int p = 0; p < pair_count; ++p, plane = _mm_add_pd(plane, next_pair)) {
    const PlanePair& q = pairs[p];
    const __m128d nx = _mm_loadu_pd(q.nx), ny = _mm_loadu_pd(q.ny), nz = _mm_loadu_pd(q.nz);
    const __m128d dist = _mm_sub_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(nx, ox), _mm_mul_pd(ny, oy)), _mm_mul_pd(nz, oz)),
                                    _mm_loadu_pd(q.offset));
    const __m128d denom = _mm_add_pd(_mm_add_pd(_mm_mul_pd(nx, dx), _mm_mul_pd(ny, dy)), _mm_mul_pd(nz, dz));
    // A plane parallel to the ray with the origin in front: no hit.
    if (_mm_movemask_pd(_mm_and_pd(_mm_cmpeq_pd(denom, zero), _mm_cmpgt_pd(dist, zero)))) return std::nullopt;
    const __m128d t = _mm_div_pd(_mm_xor_pd(dist, sign), denom);
    const __m128d entering = _mm_cmplt_pd(denom, zero), leaving = _mm_cmpgt_pd(denom, zero);
    const __m128d later = _mm_and_pd(entering, _mm_cmpgt_pd(t, lane_enter));
    lane_enter = _mm_or_pd(_mm_and_pd(later, t), _mm_andnot_pd(later, lane_enter));
    lane_plane = _mm_or_pd(_mm_and_pd(later, plane), _mm_andnot_pd(later, lane_plane));
    lane_leave = _mm_min_pd(lane_leave, _mm_or_pd(_mm_and_pd(leaving, t), _mm_andnot_pd(leaving, up)));
    // Out once the entry passes the exit (both only move that way).
    const __m128d most_enter = _mm_max_pd(lane_enter, _mm_unpackhi_pd(lane_enter, lane_enter));
    const __m128d least_leave = _mm_min_pd(lane_leave, _mm_unpackhi_pd(lane_leave, lane_leave));
    if (_mm_comigt_sd(most_enter, least_leave)) return std::nullopt;
  }
  double e[2], f[2];
  _mm_storeu_pd(e, lane_enter);
  _mm_storeu_pd(f, lane_plane);
  // The larger entry; at equal entries the lower plane (the one-at-a-time
  // clip keeps the first of equals).
  const int first = e[1] > e[0] || (e[1] == e[0] && f[1] >= 0.0 && (f[0] < 0.0 || f[1] < f[0])) ? 1 : 0;
  enter = e[first];
  entering_plane = static_cast<int>(f[first]);
#else
  double leave = max_t;
  for (int i = 0; i < count; ++i) {
    const PlanePair& q = pairs[i / 2];
    const int l = i % 2;
    const double dist = plane_height(q.nx[l], q.ny[l], q.nz[l], q.offset[l], origin);
    const double denom = plane_slope(q.nx[l], q.ny[l], q.nz[l], direction);
    if (denom == 0.0) {
      if (dist > 0.0) return std::nullopt;
      continue;
    }
    const double t = -dist / denom;
    if (denom < 0.0) {
      if (t > enter) {
        enter = t;
        entering_plane = i;
      }
    } else {
      leave = std::min(leave, t);
    }
    if (enter > leave) return std::nullopt;
  }
#endif
  const auto normal = [&](int i) {
    const PlanePair& q = pairs[i / 2];
    return Eigen::Vector3d(q.nx[i % 2], q.ny[i % 2], q.nz[i % 2]);
  };
  if (entering_plane < 0) { // the origin is inside (or on) the hull
    int best = 0;
    double most = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < facets; ++i) {
      const PlanePair& q = pairs[i / 2];
      const double h = plane_height(q.nx[i % 2], q.ny[i % 2], q.nz[i % 2], q.offset[i % 2], origin);
      if (i == 0 || h > most) {
        most = h;
        best = i;
      }
    }
    return RayHit{-1, 0.0, origin, normal(best)};
  }
  return RayHit{-1, enter, origin + enter * direction, normal(entering_plane)};
}

} // namespace hullcover::bvh::detail

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
#include <utility>

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

/// One plane's normal and offset, as a copy of a hull's planes stores it.
struct PlaneTerms {
  double nx, ny, nz, offset;
};

/// n . p - offset, as (n.x p.x + n.y p.y) + n.z p.z - offset: written out
/// so that every copy of a hull's planes computes the same bits.
inline double plane_height(const PlaneTerms& q, const Eigen::Vector3d& p) {
  return q.nx * p.x() + q.ny * p.y() + q.nz * p.z() - q.offset;
}
/// n . v, in the same order.
inline double plane_slope(const PlaneTerms& q, const Eigen::Vector3d& v) {
  return q.nx * v.x() + q.ny * v.y() + q.nz * v.z();
}

/// Of planes [0, facets) (plane_at(i): the PlaneTerms of plane i), the one
/// `p` is least deep behind (the first of equals).
template <typename PlaneAt>
int least_deep_of(int facets, PlaneAt&& plane_at, const Eigen::Vector3d& p) {
  int best = 0;
  double most = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < facets; ++f) {
    const double h = plane_height(plane_at(f), p);
    if (f == 0 || h > most) {
      most = h;
      best = f;
    }
  }
  return best;
}

/// The clip one plane at a time: the entry (t > 0, or 0 when the origin is
/// inside) and the plane entered through (-1: inside), or nothing on a
/// miss.
template <typename PlaneAt>
std::optional<std::pair<double, int>> clip_one_plane_at_a_time(int count, PlaneAt&& plane_at,
                                                               const Eigen::Vector3d& origin,
                                                               const Eigen::Vector3d& direction, double max_t) {
  double enter = 0.0, leave = max_t;
  int entering_plane = -1;
  for (int i = 0; i < count; ++i) {
    const PlaneTerms q = plane_at(i);
    const double dist = plane_height(q, origin), denom = plane_slope(q, direction);
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
  return std::make_pair(enter, entering_plane);
}

/// The hit of a clip's entry through plane `entering` (-1: the origin is
/// inside, t = 0, with the normal of the facet it is least deep behind).
template <typename PlaneAt>
RayHit hit_of_clip(double enter, int entering, int facets, PlaneAt&& plane_at, const Eigen::Vector3d& origin,
                   const Eigen::Vector3d& direction) {
  const bool inside = entering < 0;
  const PlaneTerms q = plane_at(inside ? least_deep_of(facets, plane_at, origin) : entering);
  const Eigen::Vector3d normal(q.nx, q.ny, q.nz);
  return inside ? RayHit{-1, 0.0, origin, normal} : RayHit{-1, enter, origin + enter * direction, normal};
}

/// The PlaneTerms of a hull's Plane.
inline PlaneTerms terms_of(const Plane& plane) {
  return {plane.normal.x(), plane.normal.y(), plane.normal.z(), plane.offset};
}

/// Of planes [0, facets), the one `p` is least deep behind (the first of
/// equals).
inline int least_deep_plane(const Plane* planes, int facets, const Eigen::Vector3d& p) {
  return least_deep_of(
      facets, [planes](int i) { return terms_of(planes[i]); }, p);
}

/// First hit of origin + t * direction (unit), 0 <= t <= max_t, on the hull
/// bounded by `count` planes whose first `facets` are its facets'. An
/// origin inside hits at t = 0 with the normal of the facet it is least
/// deep behind.
inline std::optional<RayHit> first_hit_on_planes(const Plane* planes, int count, int facets,
                                                 const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                                 double max_t) {
  const auto plane_at = [planes](int i) { return terms_of(planes[i]); };
  const auto clip = clip_one_plane_at_a_time(count, plane_at, origin, direction, max_t);
  if (!clip) return std::nullopt;
  return hit_of_clip(clip->first, clip->second, facets, plane_at, origin, direction);
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
  const auto plane_at = [pairs](int i) {
    const PlanePair& q = pairs[i / 2];
    return PlaneTerms{q.nx[i % 2], q.ny[i % 2], q.nz[i % 2], q.offset[i % 2]};
  };
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
  return hit_of_clip(e[first], static_cast<int>(f[first]), facets, plane_at, origin, direction);
#else
  const auto clip = clip_one_plane_at_a_time(count, plane_at, origin, direction, max_t);
  if (!clip) return std::nullopt;
  return hit_of_clip(clip->first, clip->second, facets, plane_at, origin, direction);
#endif
}

} // namespace hullcover::bvh::detail

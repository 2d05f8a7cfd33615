#pragma once
// The nearest of a hull's edges to a segment (private to bvh/): the step
// that costs most in a capsule's contact, which tests its axis against
// every edge of most hulls it touches. Two edges at a time: each lane makes
// the same correctly rounded operations, in the same order, as
// closest_points_of_segments and the squared distance of its points, and
// the nearest is the first of equals in edge order, so the answer is the
// same bits as a scan of the edges one at a time. A build without SSE2
// (HULLCOVER_PLANE_PAIRS_SSE2 = 0, planes_ray_hit.h) scans them so.

#include "planes_ray_hit.h" // HULLCOVER_PLANE_PAIRS_SSE2

#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Core>

#include <tuple>
#include <utility>
#include <vector>

namespace hullcover::bvh::detail {

/// The nearest points of a segment and edge i of a hull, whose ends are
/// vertices[edges[i].first] and vertices[edges[i].second].
struct NearestEdge {
  int edge = -1;        ///< -1: none nearer than the bound given
  double squared = 0.0; ///< squared distance between the two points
  Eigen::Vector3d on_segment = Eigen::Vector3d::Zero(), on_edge = Eigen::Vector3d::Zero();
};

namespace nearest_edges {
#if HULLCOVER_PLANE_PAIRS_SSE2
inline __m128d pick(__m128d mask, __m128d yes, __m128d no) {
  return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
}
// unit_clamp in each lane (maxpd gives its second operand, 0, for a NaN).
inline __m128d unit_clamp2(__m128d x) { return _mm_min_pd(_mm_max_pd(x, _mm_setzero_pd()), _mm_set1_pd(1.0)); }
// One coordinate of two edges' ends: (first edge's, second edge's).
inline __m128d lanes(double first, double second) { return _mm_set_pd(second, first); }
// The lane with the nearer edge (at equal distances the lower edge; a lane
// that found none keeps the bound) into `best`.
inline void take_nearer_lane(__m128d lane_least, __m128d lane_edge, NearestEdge& best) {
  double least[2], which[2];
  _mm_storeu_pd(least, lane_least);
  _mm_storeu_pd(which, lane_edge);
  const int lane =
      least[1] < least[0] || (least[1] == least[0] && which[1] >= 0.0 && (which[0] < 0.0 || which[1] < which[0])) ? 1
                                                                                                                  : 0;
  if (which[lane] >= 0.0) {
    best.edge = static_cast<int>(which[lane]);
    best.squared = least[lane];
  }
}
#endif
} // namespace nearest_edges

/// Of the edges, the first whose closest points to `axis` are at a squared
/// distance below `bound` and below every edge's before it (edge -1 and
/// `bound` when none is).
inline NearestEdge nearest_edge_to_segment(const SegmentTerms& axis, const std::vector<Eigen::Vector3d>& vertices,
                                           const std::vector<std::pair<int, int>>& edges, double bound) {
  NearestEdge best;
  best.squared = bound;
  const int count = static_cast<int>(edges.size());
  int from = 0; // edges before this one are done
#if HULLCOVER_PLANE_PAIRS_SSE2
  if (axis.length2 > 0.0) {
    const __m128d sx = _mm_set1_pd(axis.start.x()), sy = _mm_set1_pd(axis.start.y()), sz = _mm_set1_pd(axis.start.z());
    const __m128d d1x = _mm_set1_pd(axis.direction.x()), d1y = _mm_set1_pd(axis.direction.y()),
                  d1z = _mm_set1_pd(axis.direction.z());
    using namespace nearest_edges;
    const __m128d a = _mm_set1_pd(axis.length2), zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
    // Per lane: its least squared distance so far (strictly less replaces)
    // and that edge's number.
    __m128d lane_least = _mm_set1_pd(bound), lane_edge = _mm_set1_pd(-1.0);
    for (; from + 1 < count; from += 2) {
      const Eigen::Vector3d& u0 = vertices[edges[from].first];
      const Eigen::Vector3d& w0 = vertices[edges[from].second];
      const Eigen::Vector3d& u1 = vertices[edges[from + 1].first];
      const Eigen::Vector3d& w1 = vertices[edges[from + 1].second];
      const __m128d qx = lanes(u0.x(), u1.x()), qy = lanes(u0.y(), u1.y()), qz = lanes(u0.z(), u1.z());
      const __m128d d2x = _mm_sub_pd(lanes(w0.x(), w1.x()), qx), d2y = _mm_sub_pd(lanes(w0.y(), w1.y()), qy),
                    d2z = _mm_sub_pd(lanes(w0.z(), w1.z()), qz);
      const __m128d rx = _mm_sub_pd(sx, qx), ry = _mm_sub_pd(sy, qy), rz = _mm_sub_pd(sz, qz);
      const __m128d e = _mm_add_pd(_mm_add_pd(_mm_mul_pd(d2x, d2x), _mm_mul_pd(d2y, d2y)), _mm_mul_pd(d2z, d2z));
      // An edge of no length takes the scalar path below (its own case there).
      if (_mm_movemask_pd(_mm_cmpeq_pd(e, zero))) break;
      const __m128d f = _mm_add_pd(_mm_add_pd(_mm_mul_pd(d2x, rx), _mm_mul_pd(d2y, ry)), _mm_mul_pd(d2z, rz));
      const __m128d c = _mm_add_pd(_mm_add_pd(_mm_mul_pd(d1x, rx), _mm_mul_pd(d1y, ry)), _mm_mul_pd(d1z, rz));
      const __m128d b = _mm_add_pd(_mm_add_pd(_mm_mul_pd(d1x, d2x), _mm_mul_pd(d1y, d2y)), _mm_mul_pd(d1z, d2z));
      const __m128d denominator = _mm_sub_pd(_mm_mul_pd(a, e), _mm_mul_pd(b, b));
      // Parallel (no positive denominator): s = 0, as the scalar code.
      __m128d s = _mm_and_pd(_mm_cmpgt_pd(denominator, zero),
                             unit_clamp2(_mm_div_pd(_mm_sub_pd(_mm_mul_pd(b, f), _mm_mul_pd(c, e)), denominator)));
      __m128d t = _mm_div_pd(_mm_add_pd(_mm_mul_pd(b, s), f), e);
      const __m128d past_start = unit_clamp2(_mm_div_pd(_mm_xor_pd(c, _mm_set1_pd(-0.0)), a));
      const __m128d past_end = unit_clamp2(_mm_div_pd(_mm_sub_pd(b, c), a));
      const __m128d below = _mm_cmplt_pd(t, zero), above = _mm_cmpgt_pd(t, one);
      s = pick(below, past_start, pick(above, past_end, s));
      t = pick(below, zero, pick(above, one, t));
      const __m128d gx = _mm_sub_pd(_mm_add_pd(sx, _mm_mul_pd(s, d1x)), _mm_add_pd(qx, _mm_mul_pd(t, d2x)));
      const __m128d gy = _mm_sub_pd(_mm_add_pd(sy, _mm_mul_pd(s, d1y)), _mm_add_pd(qy, _mm_mul_pd(t, d2y)));
      const __m128d gz = _mm_sub_pd(_mm_add_pd(sz, _mm_mul_pd(s, d1z)), _mm_add_pd(qz, _mm_mul_pd(t, d2z)));
      const __m128d d2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(gx, gx), _mm_mul_pd(gy, gy)), _mm_mul_pd(gz, gz));
      const __m128d nearer = _mm_cmplt_pd(d2, lane_least);
      lane_least = pick(nearer, d2, lane_least);
      lane_edge = pick(nearer, _mm_set_pd(from + 1.0, from), lane_edge);
    }
    take_nearer_lane(lane_least, lane_edge, best);
  }
#endif
  // The rest one at a time (all of them without SSE2).
  for (int i = from; i < count; ++i) {
    const auto [on_segment, on_edge] =
        closest_points_of_segments(axis, vertices[edges[i].first], vertices[edges[i].second]);
    const double d2 = (on_segment - on_edge).squaredNorm();
    if (d2 < best.squared) {
      best.squared = d2;
      best.edge = i;
    }
  }
  if (best.edge >= 0)
    std::tie(best.on_segment, best.on_edge) =
        closest_points_of_segments(axis, vertices[edges[best.edge].first], vertices[edges[best.edge].second]);
  return best;
}

} // namespace hullcover::bvh::detail

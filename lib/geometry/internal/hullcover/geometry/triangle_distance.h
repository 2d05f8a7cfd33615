#pragma once
/// \file triangle_distance.h
/// The nearest point of a triangle to a point: what "clearance from the
/// mesh" means for the agent-radius and max-deviation allowances and their
/// audit.

#include <Eigen/Core>

#include <algorithm>
#include <utility>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#endif

namespace hullcover {

/// The point of triangle a, b, c nearest to `p` (a degenerate triangle
/// gives the nearest point of its three sides). Scene units; cannot fail.
Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c);

/// x clamped to [0, 1] by a max and a min, which compile to two
/// instructions and no branch (std::clamp's comparisons branch, and the
/// runtime's closest-point loops meet each side of the clamp at random);
/// equal to std::clamp(x, 0.0, 1.0) for every x but NaN (-0 gives +0, an
/// equal value). Callers pass finite parameters.
inline double unit_clamp(double x) {
#if defined(__SSE2__) || defined(_M_X64)
  // maxsd(x, 0) is x > 0 ? x : 0 and minsd(y, 1) is y < 1 ? y : 1: as
  // written, since compilers turn the plain min and max back into branches.
  return _mm_cvtsd_f64(_mm_min_sd(_mm_max_sd(_mm_set_sd(x), _mm_setzero_pd()), _mm_set_sd(1.0)));
#else
  return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0;
#endif
}

/// The point of segment a-b nearest to `p` (`a` when a = b). Inline: the
/// runtime's contact tests call it for every edge of a hull.
inline Eigen::Vector3d closest_point_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                                const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  if (!(length2 > 0.0)) return a;
  return a + unit_clamp((p - a).dot(ab) / length2) * ab;
}

/// One segment p0-p1 with the terms every closest-points computation
/// against it shares (its direction and squared length), made once when it
/// is tested against many (a capsule's axis against a hull's edges).
struct SegmentTerms {
  Eigen::Vector3d start, direction;
  double length2;

  SegmentTerms(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1)
      : start(p0), direction(p1 - p0), length2(direction.squaredNorm()) {}
};

/// The nearest points of segment `p` and segment q0-q1, the first on `p`
/// (either may be a single point), as in Ericson's Real-Time Collision
/// Detection, 5.1.9: the parameters of the nearest points, clamped to the
/// segments in turn. Inline: the runtime's capsule tests call it for every
/// edge of a hull.
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> closest_points_of_segments(const SegmentTerms& p,
                                                                              const Eigen::Vector3d& q0,
                                                                              const Eigen::Vector3d& q1) {
  const Eigen::Vector3d& d1 = p.direction;
  const Eigen::Vector3d d2 = q1 - q0, r = p.start - q0;
  const double a = p.length2, e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a == 0.0 && e == 0.0) return {p.start, q0};
  if (a == 0.0) {
    t = unit_clamp(f / e);
  } else {
    const double c = d1.dot(r);
    if (e == 0.0) {
      s = unit_clamp(-c / a);
    } else {
      const double b = d1.dot(d2), denominator = a * e - b * b;
      s = denominator > 0.0 ? unit_clamp((b * f - c * e) / denominator) : 0.0; // parallel: any s
      t = (b * s + f) / e;
#if defined(__SSE2__) || defined(_M_X64)
      // t past an end moves it there and s to the point nearest that end.
      // Along a hull's edges t falls on either side at random, so both
      // new s are computed (one division for the two) and the one t calls
      // for is chosen by masks, not branches; the same values as below.
      const __m128d again = _mm_div_pd(_mm_set_pd(b - c, -c), _mm_set1_pd(a));
      const __m128d past_start = _mm_set_sd(unit_clamp(_mm_cvtsd_f64(again)));
      const __m128d past_end = _mm_set_sd(unit_clamp(_mm_cvtsd_f64(_mm_unpackhi_pd(again, again))));
      const __m128d tv = _mm_set_sd(t), one = _mm_set_sd(1.0);
      const __m128d below = _mm_cmplt_sd(tv, _mm_setzero_pd()), above = _mm_cmpgt_sd(tv, one);
      const auto pick = [](__m128d mask, __m128d yes, __m128d no) {
        return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
      };
      s = _mm_cvtsd_f64(pick(below, past_start, pick(above, past_end, _mm_set_sd(s))));
      t = _mm_cvtsd_f64(pick(below, _mm_setzero_pd(), pick(above, one, tv)));
#else
      if (t < 0.0) {
        t = 0.0;
        s = unit_clamp(-c / a);
      } else if (t > 1.0) {
        t = 1.0;
        s = unit_clamp((b - c) / a);
      }
#endif
    }
  }
  return {p.start + s * d1, q0 + t * d2};
}

/// The nearest points of segments p0-p1 and q0-q1, the first on p0-p1
/// (either segment may be a single point); cannot fail.
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> closest_points_of_segments(const Eigen::Vector3d& p0,
                                                                              const Eigen::Vector3d& p1,
                                                                              const Eigen::Vector3d& q0,
                                                                              const Eigen::Vector3d& q1) {
  return closest_points_of_segments(SegmentTerms(p0, p1), q0, q1);
}

/// Distance between segments p0-p1 and q0-q1 (either may be a single
/// point), scene units; cannot fail.
double segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                        const Eigen::Vector3d& q1);

/// Distance between two triangles, each given by its three corners: 0 when
/// they touch or cross, and the same whichever way the scene is turned or
/// moved (up to rounding), unlike a distance between their bounding boxes.
/// Scene units; cannot fail (degenerate triangles measure as their sides).
double triangle_distance(const Eigen::Vector3d (&s)[3], const Eigen::Vector3d (&t)[3]);

/// Whether triangle_distance(s, t) <= `distance` (scene units), exactly as
/// that comparison answers it, stopping at the first pair of points that
/// close: near-merge searches ask this of many pairs that touch.
bool triangles_within(const Eigen::Vector3d (&s)[3], const Eigen::Vector3d (&t)[3], double distance);

} // namespace hullcover

#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace hullcover {

Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c) {
  // Which Voronoi region of the triangle p lies in, read off barycentric
  // dot products (the regions of the corners, then the sides, then the
  // inside), as in Ericson's Real-Time Collision Detection, 5.1.5.
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return closest_point_on_segment(p, a, b);
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return closest_point_on_segment(p, a, c);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return closest_point_on_segment(p, b, c);
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {
    // Degenerate (no area): the nearest of the three sides.
    const Eigen::Vector3d candidates[3] = {closest_point_on_segment(p, a, b), closest_point_on_segment(p, b, c),
                                           closest_point_on_segment(p, a, c)};
    return *std::min_element(std::begin(candidates), std::end(candidates), [&](const auto& x, const auto& y) {
      return (x - p).squaredNorm() < (y - p).squaredNorm();
    });
  }
  return a + ab * (vb / sum) + ac * (vc / sum);
}

double segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                        const Eigen::Vector3d& q1) {
  const auto [on_p, on_q] = closest_points_of_segments(p0, p1, q0, q1);
  return (on_p - on_q).norm();
}

namespace {

// Calls `take(d)` with the distance of each candidate pair of points, one on
// each triangle, until it returns true. Every candidate is the distance of
// a real pair, so none is below the true distance; and the true one is
// among them: it is met at a corner against a face, at two sides, or, where
// the triangles cross, at a side's crossing of the other's plane
// (distance 0). One list of candidates serves both the distance and the
// bounded test, so they agree to the last bit.
template <class Take>
void triangle_pair_candidates(const Eigen::Vector3d (&s)[3], const Eigen::Vector3d (&t)[3], Take&& take) {
  const auto corners_against = [&take](const Eigen::Vector3d(&from)[3], const Eigen::Vector3d(&onto)[3]) {
    const Eigen::Vector3d normal = (onto[1] - onto[0]).cross(onto[2] - onto[0]);
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d& p = from[i];
      if (take((p - closest_point_on_triangle(p, onto[0], onto[1], onto[2])).norm())) return true;
      const Eigen::Vector3d& q = from[(i + 1) % 3];
      const double side_p = normal.dot(p - onto[0]), side_q = normal.dot(q - onto[0]);
      if ((side_p <= 0.0) != (side_q <= 0.0)) {
        const Eigen::Vector3d crossing = p + (side_p / (side_p - side_q)) * (q - p);
        if (take((crossing - closest_point_on_triangle(crossing, onto[0], onto[1], onto[2])).norm())) return true;
      }
    }
    return false;
  };
  if (corners_against(s, t) || corners_against(t, s)) return;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (take(segment_distance(s[i], s[(i + 1) % 3], t[j], t[(j + 1) % 3]))) return;
}

} // namespace

double triangle_distance(const Eigen::Vector3d (&s)[3], const Eigen::Vector3d (&t)[3]) {
  double best = std::numeric_limits<double>::infinity();
  triangle_pair_candidates(s, t, [&best](double d) {
    best = std::min(best, d);
    return false;
  });
  return best;
}

bool triangles_within(const Eigen::Vector3d (&s)[3], const Eigen::Vector3d (&t)[3], double distance) {
  bool within = false;
  triangle_pair_candidates(s, t, [&](double d) { return within = d <= distance; });
  // With no candidate a number (NaN corners), the distance is infinity.
  return within || std::numeric_limits<double>::infinity() <= distance;
}

} // namespace hullcover

#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>

namespace hullcover {

Eigen::Vector3d closest_point_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  if (!(length2 > 0.0)) return a;
  return a + std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) * ab;
}

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

} // namespace hullcover

#include "hullcover/geometry/convex_polytope.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace hullcover {

double deepest_signed_distance(const std::vector<Plane>& planes, const Eigen::Vector3d& p) {
  double deepest = -std::numeric_limits<double>::infinity();
  for (const Plane& plane : planes) deepest = std::max(deepest, plane.signed_distance(p));
  return deepest;
}

bool segment_enters_interior(const std::vector<Plane>& planes, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             double tol) {
  // Cyrus-Beck clipping of the parameter interval against each shrunk plane.
  double enter = 0.0, leave = 1.0;
  for (const Plane& plane : planes) {
    const double da = plane.signed_distance(a) + tol;
    const double db = plane.signed_distance(b) + tol;
    if (da >= 0.0 && db >= 0.0) return false;
    if (da < 0.0 && db < 0.0) continue;
    const double t = da / (da - db);
    if (da >= 0.0)
      enter = std::max(enter, t);
    else
      leave = std::min(leave, t);
    if (enter >= leave) return false;
  }
  return enter < leave;
}

std::vector<Eigen::Vector3d> clip_polygon(const std::vector<Eigen::Vector3d>& polygon, const Plane& plane,
                                          double inset) {
  std::vector<Eigen::Vector3d> out;
  const size_t n = polygon.size();
  out.reserve(n + 1);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = polygon[i];
    const Eigen::Vector3d& q = polygon[(i + 1) % n];
    const double dp = plane.signed_distance(p) + inset;
    const double dq = plane.signed_distance(q) + inset;
    if (dp <= 0.0) out.push_back(p);
    if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return out;
}

std::vector<Eigen::Vector3d> clip_polygon_to_planes(std::vector<Eigen::Vector3d> polygon,
                                                    const std::vector<Plane>& planes, double inset) {
  for (const Plane& plane : planes) {
    if (polygon.empty()) break;
    polygon = clip_polygon(polygon, plane, inset);
  }
  return polygon;
}

double polytope_volume(const ConvexPolytope& polytope) {
  if (polytope.vertices.empty()) return 0.0;
  const Eigen::Vector3d& apex = polytope.vertices.front();
  double six_volume = 0.0;
  for (const std::vector<int>& facet : polytope.facets)
    for (size_t k = 1; k + 1 < facet.size(); ++k) {
      const Eigen::Vector3d a = polytope.vertices[facet[0]] - apex;
      const Eigen::Vector3d b = polytope.vertices[facet[k]] - apex;
      const Eigen::Vector3d c = polytope.vertices[facet[k + 1]] - apex;
      six_volume += a.dot(b.cross(c));
    }
  return std::max(0.0, six_volume / 6.0);
}

} // namespace hullcover

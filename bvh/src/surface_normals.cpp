#include "surface_normals.h"

#include <cmath>
#include <limits>

namespace hullcover::bvh::detail {

bool has_plane_off_surface(const RuntimeHull& hull) {
  for (bool on_surface : hull.surface_planes)
    if (!on_surface) return true;
  return false;
}

SeamTurn surface_facet_for(const RuntimeHull& hull, const Eigen::Vector3d& on_hull, const Eigen::Vector3d& normal,
                           double near) {
  // (A hull whose every plane is the surface's finds every plane through
  // the point on the surface: no seam. Callers test has_plane_off_surface
  // first, which is cheaper.)
  const int facets = static_cast<int>(hull.shape.facets.size());
  bool all_on_surface = true;
  int through = -1;
  double through_facing = -std::numeric_limits<double>::infinity();
  for (int p = 0; p < static_cast<int>(hull.shape.planes.size()); ++p) {
    const Plane& plane = hull.shape.planes[p];
    if (!(std::abs(plane.signed_distance(on_hull)) <= near)) continue; // not through the point
    const bool surface = hull.plane_on_surface(p);
    if (!surface) all_on_surface = false;
    if (p >= facets || !surface) continue;
    const double facing = plane.normal.dot(normal);
    if (facing > through_facing) {
      through_facing = facing;
      through = p;
    }
  }
  if (all_on_surface) return {};
  return {true, through};
}

int least_deep_surface_facet(const RuntimeHull& hull, const Eigen::Vector3d& p) {
  int best = -1;
  double best_distance = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < static_cast<int>(hull.shape.facets.size()); ++f) {
    if (!hull.plane_on_surface(f)) continue;
    const double d = hull.shape.planes[f].signed_distance(p);
    if (d > best_distance) {
      best_distance = d;
      best = f;
    }
  }
  return best;
}

} // namespace hullcover::bvh::detail

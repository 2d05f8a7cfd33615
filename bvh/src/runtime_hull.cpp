#include "hullcover/bvh/runtime_hull.h"

#include "hullcover/geometry/planar_hull.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace hullcover::bvh {

RuntimeHull make_runtime_hull(ConvexPolytope shape, int material) {
  RuntimeHull hull;
  hull.shape = std::move(shape);
  hull.material = material;
  for (const Eigen::Vector3d& v : hull.shape.vertices) hull.box.extend(v);
  size_t corners = 0;
  for (const std::vector<int>& facet : hull.shape.facets) corners += facet.size();
  hull.edges.reserve(corners);
  for (const std::vector<int>& facet : hull.shape.facets)
    for (size_t i = 0; i < facet.size(); ++i) {
      const int a = facet[i], b = facet[(i + 1) % facet.size()];
      hull.edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(hull.edges.begin(), hull.edges.end());
  hull.edges.erase(std::unique(hull.edges.begin(), hull.edges.end()), hull.edges.end());
  return hull;
}

RuntimeHull flat_triangle_hull(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return make_runtime_hull(flat_polytope(flat_triangle(a, b, c), true), 0);
}

} // namespace hullcover::bvh

#include "hullcover/bvh/runtime_hull.h"

#include <algorithm>

namespace hullcover::bvh {

RuntimeHull make_runtime_hull(const ConvexPolytope& shape, int material) {
  RuntimeHull hull;
  hull.shape = shape;
  hull.material = material;
  for (const Eigen::Vector3d& v : shape.vertices) hull.box.extend(v);
  for (const std::vector<int>& facet : shape.facets)
    for (size_t i = 0; i < facet.size(); ++i) {
      const int a = facet[i], b = facet[(i + 1) % facet.size()];
      hull.edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(hull.edges.begin(), hull.edges.end());
  hull.edges.erase(std::unique(hull.edges.begin(), hull.edges.end()), hull.edges.end());
  return hull;
}

} // namespace hullcover::bvh

#include "fcl_objects.h"

#include "hullcover/geometry/point_hull.h"

namespace hullcover::bvh::detail {

std::shared_ptr<fcl::Convexd> fcl_convex(const ConvexPolytope& polytope) {
  auto vertices = std::make_shared<std::vector<Eigen::Vector3d>>(polytope.vertices);
  auto faces = std::make_shared<std::vector<int>>();
  for (const std::vector<int>& facet : polytope.facets) {
    faces->push_back(static_cast<int>(facet.size()));
    faces->insert(faces->end(), facet.begin(), facet.end());
  }
  return std::make_shared<fcl::Convexd>(vertices, static_cast<int>(polytope.facets.size()), faces);
}

std::shared_ptr<fcl::CollisionGeometryd> fcl_geometry(const QueryShape& shape) {
  switch (shape.kind) {
    case ShapeKind::sphere: return std::make_shared<fcl::Sphered>(shape.radius);
    case ShapeKind::capsule: return std::make_shared<fcl::Capsuled>(shape.radius, 2.0 * shape.half_height);
    case ShapeKind::box: return std::make_shared<fcl::Boxd>(2.0 * shape.half_extents);
    case ShapeKind::convex: {
      const std::optional<ConvexPolytope> hull = convex_hull_of_points(shape.points);
      if (!hull) return nullptr;
      return fcl_convex(*hull);
    }
  }
  return nullptr;
}

} // namespace hullcover::bvh::detail

#include "hullcover/bvh/hull_world.h"

#include "hull_tree.h"
#include "packed_planes.h"
#include "query_guard.h"
#include "collected_queries.h"

namespace hullcover::bvh {
namespace detail {
// HullWorld as a hull source (world_queries.h): one packed tree whose leaf
// numbers are the hulls' indices.
struct TreeSource {
  const detail::HullTree& tree;
  const std::vector<RuntimeHull>& hulls;
  const PackedPlanes& planes;

  template <typename Visit>
  bool in_box(const Aabb& box, Visit&& visit) const {
    return tree.find_in_box(box, [&](int h) { return visit(h, hulls[h], PlanesOf{&planes, h}); });
  }
  template <typename Visit>
  bool near_point(const Eigen::Vector3d& centre, double radius, Visit&& visit) const {
    return tree.find_near_point(centre, radius, [&](int h) { return visit(h, hulls[h], PlanesOf{&planes, h}); });
  }
  template <typename Visit>
  bool near_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, Visit&& visit) const {
    return tree.find_near_segment(a, b, radius, [&](int h) { return visit(h, hulls[h], PlanesOf{&planes, h}); });
  }
  template <typename Visit>
  void along_ray(const Eigen::Vector3d& origin, const Eigen::Vector3d& inverse, double& reach, Visit&& visit) const {
    tree.walk_ray(origin, inverse, reach, [&](int h, double& best) { visit(h, hulls[h], PlanesOf{&planes, h}, best); });
  }
  std::optional<Aabb> bounds() const { return tree.bounds(); }
};
} // namespace detail

HullWorld::~HullWorld() = default;

Result<std::shared_ptr<const HullWorld>> HullWorld::build(std::vector<RuntimeHull> hulls) {
  using Built = Result<std::shared_ptr<const HullWorld>>;
  return detail::guarded("building the hull world", [&]() -> Built {
    if (hulls.empty()) return Status{StatusCode::invalid_argument, "a hull world needs at least one hull"};
    if (Status s = detail::check_hulls(hulls, nullptr); !s.ok()) return s;
    std::shared_ptr<HullWorld> world(new HullWorld());
    world->hulls_ = std::move(hulls);
    world->tree_ = std::make_unique<detail::HullTree>(world->hulls_);
    world->planes_ = std::make_unique<detail::PackedPlanes>(world->hulls_);
    return std::shared_ptr<const HullWorld>(std::move(world));
  });
}

detail::TreeSource HullWorld::source() const { return {*tree_, hulls_, *planes_}; }

template class HullQueries<HullWorld>;

} // namespace hullcover::bvh

#include "hullcover/bvh/fcl_covering.h"

#include "fcl_objects.h"
#include "query_guard.h"
#include "world_queries.h"

#include <string>
#include <utility>

namespace hullcover::bvh {
namespace {

/// Everything an FclCovering hands out, in one block that every handed-out
/// pointer holds (aliasing shared_ptrs). Members are destroyed in reverse
/// order: the manager, which keeps raw pointers to the objects, goes first,
/// then the objects, then the indices their user data points to.
struct FclStore {
  /// hull_indices[i] == i; filled before any object points into it and
  /// never resized after, so the pointers stay valid.
  std::vector<int> hull_indices;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  fcl::DynamicAABBTreeCollisionManagerd manager;
};

/// Fewest corners of a facet polygon (the runtime file reader's rule).
constexpr size_t kFewestFacetCorners = 3;

/// Fails with `invalid_argument` naming the first hull with a facet of too
/// few corners or a corner index out of range. HullWorld::build does not
/// look at facet indices, but FCL's Convex follows them unchecked to build
/// its vertex neighbours, so a bad index would read out of bounds.
Status check_facets(const std::vector<RuntimeHull>& hulls) {
  for (size_t i = 0; i < hulls.size(); ++i) {
    const ConvexPolytope& shape = hulls[i].shape;
    const int vertex_count = static_cast<int>(shape.vertices.size());
    for (const std::vector<int>& facet : shape.facets) {
      bool in_range = facet.size() >= kFewestFacetCorners;
      for (const int v : facet) in_range = in_range && v >= 0 && v < vertex_count;
      if (!in_range)
        return {StatusCode::invalid_argument,
                "hull " + std::to_string(i) + " has a facet with fewer than 3 corners or a corner out of range"};
    }
  }
  return Status::success();
}

} // namespace

Result<FclCovering> make_fcl_covering(const std::vector<RuntimeHull>& hulls) {
  using Built = Result<FclCovering>;
  return detail::guarded("building the FCL covering", [&]() -> Built {
    if (hulls.empty()) return Status{StatusCode::invalid_argument, "an FCL covering needs at least one hull"};
    // HullWorld::build's own rules, so both accept the same hull lists.
    if (Status s = detail::check_hulls(hulls, nullptr); !s.ok()) return s;
    if (Status s = check_facets(hulls); !s.ok()) return s;

    auto store = std::make_shared<FclStore>();
    store->hull_indices.resize(hulls.size());
    for (size_t i = 0; i < hulls.size(); ++i) store->hull_indices[i] = static_cast<int>(i);

    std::vector<fcl::CollisionObjectd*> registered;
    registered.reserve(hulls.size());
    store->objects.reserve(hulls.size());
    for (size_t i = 0; i < hulls.size(); ++i) {
      // Identity pose: the vertices are world coordinates, and FCL's box of
      // an unrotated object is its geometry's own tight box.
      auto object = std::make_unique<fcl::CollisionObjectd>(detail::fcl_convex(hulls[i].shape));
      object->setUserData(&store->hull_indices[i]);
      registered.push_back(object.get());
      store->objects.push_back(std::move(object));
    }
    store->manager.registerObjects(registered);
    store->manager.setup();

    FclCovering covering;
    covering.objects.reserve(hulls.size());
    for (const std::unique_ptr<fcl::CollisionObjectd>& object : store->objects)
      covering.objects.emplace_back(store, object.get());
    covering.manager = std::shared_ptr<fcl::DynamicAABBTreeCollisionManagerd>(store, &store->manager);
    return covering;
  });
}

} // namespace hullcover::bvh

#pragma once
// FCL pieces of the triangle world (private to bvh/).
// Only the FCL headers used are included: fcl/fcl.h costs seconds and
// hundreds of MB per translation unit.

#include "hullcover/bvh/query_shape.h"
#include "hullcover/geometry/convex_polytope.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <memory>

namespace hullcover::bvh::detail {

/// A collision object whose world box hullcover sets itself (FCL's own box
/// for a rotated shape is the cube around its bounding sphere).
class QueryObject : public fcl::CollisionObjectd {
public:
  QueryObject(const std::shared_ptr<fcl::CollisionGeometryd>& geometry, const Eigen::Isometry3d& pose, const Aabb& box)
      : fcl::CollisionObjectd(geometry, pose) {
    aabb = fcl::AABBd(box.min, box.max);
  }
};

/// FCL geometry for a query shape (a convex shape gets its hull's facets).
/// Returns nothing for a convex whose points have no 3D hull.
std::shared_ptr<fcl::CollisionGeometryd> fcl_geometry(const QueryShape& shape);

/// FCL geometry of a convex polytope, sharing nothing with it.
std::shared_ptr<fcl::Convexd> fcl_convex(const ConvexPolytope& polytope);

} // namespace hullcover::bvh::detail

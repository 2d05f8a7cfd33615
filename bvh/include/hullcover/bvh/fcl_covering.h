#pragma once
/// \file fcl_covering.h
/// A covering's hulls as FCL collision objects in FCL's dynamic AABB tree
/// manager, for programs that already query FCL (the design card's form).
/// It lives in its own target, hullcover::bvh_fcl, so hullcover::bvh keeps
/// FCL out of its public headers; this header includes FCL's on purpose.
///
/// HullWorld (hull_world.h) remains the runtime's own query path: its
/// narrow phase is exact, while FCL's on `fcl::Convex` is iterative (GJK)
/// and decides touches only to within its tolerance. The objects here are
/// the same hulls, in the same order, so answers can be compared hull by hull.
///
///     Result<bvh::FclCovering> built = bvh::make_fcl_covering(hulls);
///     if (!built.ok()) return fail(built.status());
///     const bvh::FclCovering covering = std::move(built).value();
///     fcl::CollisionObjectd player(std::make_shared<fcl::Sphered>(0.4), pose);
///     fcl::DefaultCollisionData<double> data;  // fcl/broadphase/default_broadphase_callbacks.h
///     covering.manager->collide(&player, &data, fcl::DefaultCollisionFunction<double>);
///     // data.result.isCollision(); a callback of its own can read
///     // bvh::fcl_hull_index(*object) for the hull an object is.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/status.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/narrowphase/collision_object.h>

#include <memory>
#include <vector>

namespace hullcover::bvh {

/// Every hull of a covering as an FCL object, registered in one manager.
///
/// Ownership: the objects, the manager and the hull indices their user data
/// point to are kept in one shared block; every pointer here (each object,
/// the manager) holds that whole block, so any one of them kept alone stays
/// valid, with its user data, for as long as it is held. Copies of an
/// FclCovering share the same objects.
///
/// The manager is set up once (`setup()` done); its `collide` and
/// `distance` for a query object are const walks of the tree. Registering,
/// moving or removing objects is the caller's to synchronise.
struct FclCovering {
  /// objects[i] is hull i as an `fcl::Convexd` at the identity pose (the
  /// hull's vertices are already in world coordinates, so FCL's box around
  /// it is the hull's own). Its user data points to an int holding i (read
  /// it with fcl_hull_index).
  std::vector<std::shared_ptr<fcl::CollisionObjectd>> objects;
  /// Every object of `objects`, registered and set up.
  std::shared_ptr<fcl::DynamicAABBTreeCollisionManagerd> manager;
};

/// FCL objects of `hulls` (index i is hull i), in one set-up manager.
/// Fails with `invalid_argument` for an empty list or a hull with no facets
/// or non-finite data (what HullWorld::build refuses), and for a facet with
/// fewer than 3 corners or a corner index out of range (what the runtime
/// file reader refuses: FCL reads facets unchecked); with `internal_error`
/// if FCL or memory fails. Never throws.
[[nodiscard]] Result<FclCovering> make_fcl_covering(const std::vector<RuntimeHull>& hulls);

/// The hull index an object of an FclCovering carries in its user data, or
/// -1 for an object without user data (a query object of the caller's).
/// Only for objects whose user data, when set, points to an int.
inline int fcl_hull_index(const fcl::CollisionObjectd& object) {
  const void* data = object.getUserData();
  return data ? *static_cast<const int*>(data) : -1;
}

} // namespace hullcover::bvh

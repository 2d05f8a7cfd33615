#pragma once
// Contact normals the scene's surface has (private to bvh/). A hull's plane
// that is not the surface's own (RuntimeHull::surface_planes: a prism's
// side, a flat polygon's rim where the floor runs on into the next hull)
// would give a shape sliding over the seam a normal no face has: a ghost
// collision. These pick the surface facet to use instead.

#include "hullcover/bvh/runtime_hull.h"

#include <Eigen/Core>

namespace hullcover::bvh::detail {

/// Where a contact at a hull point stands against the seams.
struct SeamTurn {
  /// Some plane through the point is not the surface's own: the contact's
  /// normal is a seam's, not the surface's.
  bool at_seam = false;
  /// The surface facet through the point that faces the contact's normal
  /// most, or -1 (the point lies inside a seam side's face).
  int facet = -1;
};

/// For a contact at hull point `on_hull` with unit normal `normal`. Planes
/// within `near` (scene units) of on_hull pass through it.
SeamTurn surface_facet_for(const RuntimeHull& hull, const Eigen::Vector3d& on_hull, const Eigen::Vector3d& normal,
                           double near);

/// For a point inside the hull: the surface facet it is least deep behind,
/// or -1 when the hull has none.
int least_deep_surface_facet(const RuntimeHull& hull, const Eigen::Vector3d& p);

/// True when some plane of the hull is not the surface's own.
bool has_plane_off_surface(const RuntimeHull& hull);

} // namespace hullcover::bvh::detail

#pragma once
// Contact normals the scene's surface has (private to bvh/). A hull's plane
// that is not the surface's own (RuntimeHull::surface_planes: a prism's
// side, a flat polygon's rim where the floor runs on into the next hull)
// would give a shape sliding over the seam a normal no face has: a ghost
// collision. These pick the surface facet to use instead.

#include "hullcover/bvh/runtime_hull.h"

#include <Eigen/Core>

namespace hullcover::bvh::detail {

/// For a contact at hull point `on_hull` with unit normal `normal`: the
/// surface facet through on_hull that faces `normal` most, when some other
/// plane through on_hull is not the surface's own (a seam's edge); -1 to
/// keep the contact as found (every plane there is the surface's, or no
/// surface facet passes there). Planes within `near` (scene units) of
/// on_hull pass through it.
int surface_facet_for(const RuntimeHull& hull, const Eigen::Vector3d& on_hull, const Eigen::Vector3d& normal,
                      double near);

/// For a point inside the hull: the surface facet it is least deep behind,
/// or -1 when the hull has none.
int least_deep_surface_facet(const RuntimeHull& hull, const Eigen::Vector3d& p);

/// True when some plane of the hull is not the surface's own.
bool has_plane_off_surface(const RuntimeHull& hull);

} // namespace hullcover::bvh::detail

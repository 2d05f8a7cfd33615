#pragma once
/// \file surface_facets.h
/// Which facets of a hull lie on the scene's surface. A facet that lies on
/// no face (a prism's sides and bottom, a facet across enclosed space) is
/// internal: a contact there has a normal the surface does not have, so the
/// runtime turns such contacts to the hull's surface facets (the ghost
/// collisions of a shape sliding over a seam between hulls).

#include "validity/scene_index.h"

#include "hullcover/geometry/convex_polytope.h"

#include <vector>

namespace hullcover::detail {

/// Per plane of `polytope`, whether a contact there is the surface's own
/// (false: the surface runs on past it, into another hull). The surface
/// runs on past an edge when a mesh face in the plane of the facet on that
/// side (its part within tol of the plane, the face within 5 degrees of
/// it, facing either way) reaches the strip 4 tol wide just beyond the
/// edge.
/// - A facet that some mesh face lies in (reaching its polygon's interior
///   shrunk by tol): true.
/// - Another facet (a prism's side): false when the surface runs on past
///   an edge it shares with a facet of the first kind (a seam), else true
///   (a ledge where the surface ends keeps its rounded normals).
/// - A flat polygon's side plane (after the facets): false when the
///   surface runs on past that rim edge.
/// `scratch` is reused between calls.
std::vector<bool> surface_planes(const SceneIndex& index, const ConvexPolytope& polytope, std::vector<int>& scratch);

} // namespace hullcover::detail

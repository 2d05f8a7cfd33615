#pragma once
/// \file planar_prism.h
/// The solid a planar patch becomes (paper 4.3, "Convex hull output"): its
/// convex polygon extruded along the negative normal.
///
/// The paper uses a fixed thickness; that swallows mesh elements wherever
/// something lies close behind the polygon (back-to-back double-sided walls,
/// thin slabs, neighbours leaving at an acute angle). Here the thickness is
/// the largest value up to a cap for which the prism's interior holds no
/// part of any face outside the patch and no bar, and no face that is
/// coincident with the polygon faces into it; it may be 0 (the flat polygon
/// itself). The final prism is re-checked as a solid hull (conditions 1 and
/// 3) and made flat if that check fails.

#include "hullcover/lib/planar_hull.h"
#include "hullcover/lib/scene_index.h"

#include <functional>

namespace hullcover {

/// A prism below `polygon` of the given thickness (scene units, >= 0).
/// Thickness 0 gives the flat polygon: two facets (front and back) and the
/// side planes.
ConvexPolytope prism_polytope(const FlatPolygon& polygon, double thickness);

/// The largest allowed thickness in [0, cap] for a prism under `polygon`
/// (see the file comment); `in_patch(face)` tells the patch's own faces.
double allowed_prism_thickness(const SceneIndex& index, const FlatPolygon& polygon,
                               const std::function<bool(int)>& in_patch, double cap, std::vector<int>& scratch);

} // namespace hullcover

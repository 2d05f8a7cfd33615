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

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/planar_hull.h"
#include "validity/scene_index.h"

#include <functional>

namespace hullcover {

/// Side planes for a prism under `polygon`: one per polygon edge, through
/// the edge, tilted inward with depth just enough to pass above every face
/// that leaves that edge downward at an acute angle (a bevel), vertical
/// where nothing does. Tilts are capped at `kMaxBevelSlope`; a face steeper
/// than that stays inside the column and limits the thickness instead.
std::vector<Plane> beveled_side_planes(const SceneIndex& index, const FlatPolygon& polygon,
                                       const std::function<bool(int)>& in_patch, std::vector<int>& scratch);

/// Largest inward run per unit of depth a side plane may get (about 84
/// degrees from vertical).
inline constexpr double kMaxBevelSlope = 10.0;

/// The largest allowed thickness in [0, cap] for a prism under `polygon`
/// bounded by `sides` (see the file comment); `in_patch(face)` tells the
/// patch's own faces.
double allowed_prism_thickness(const SceneIndex& index, const FlatPolygon& polygon, const std::vector<Plane>& sides,
                               const std::function<bool(int)>& in_patch, double cap, std::vector<int>& scratch);

/// How deep a prism under `polygon` may reach before its bounding box meets
/// `box` (another island's zone, hullcover/mesh/tolerance.h): infinity when
/// it never does, 0 when the polygon's own box meets it. The bevelled sides
/// only narrow the prism, so its box stays in the box of its corners'
/// columns, which this measures.
double depth_before_box(const FlatPolygon& polygon, const Aabb& box);

/// The prism under `polygon` of the given thickness (scene units, >= 0)
/// between the side planes `sides`, built by `hulls`. Where the sides meet
/// before that depth the thickness is reduced until the bottom is a proper
/// polygon (corners more than `tol` apart and off each other's lines); `thickness` returns what was used. Thickness 0 gives the flat
/// polygon: front and back facets and the vertical side planes. A polygon
/// of fewer than 3 corners gives that flat polytope too (thickness 0).
ConvexPolytope prism_polytope(const FlatPolygon& polygon, const std::vector<Plane>& sides, double& thickness,
                              double tol, ConvexHullBuilder& hulls);

} // namespace hullcover

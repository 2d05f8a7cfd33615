#pragma once
/// \file runtime_hull.h
/// What the runtime keeps of one hull: only what queries use (vertices,
/// outward facet planes, facet polygons, edges, material), nothing per
/// triangle (docs/design.md, "The runtime").

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/aabb.h"

#include <utility>
#include <vector>

namespace hullcover::bvh {

/// One convex hull at run time. Flat hulls (a polygon, thickness 0) have a
/// front and a back facet and bound themselves sideways with extra planes
/// (see ConvexPolytope).
struct RuntimeHull {
  ConvexPolytope shape;
  /// Each undirected edge of the facet polygons once (vertex index pairs).
  std::vector<std::pair<int, int>> edges;
  int material = 0;
  Aabb box;
  /// Per plane of `shape`: whether a contact there is the scene surface's
  /// own (CoveringHull::surface_planes). Empty: unknown, every plane counts
  /// as the surface's (hulls from other tools, version 1 runtime files).
  std::vector<bool> surface_planes;

  /// Whether plane `p` bounds the scene's surface (see surface_planes).
  bool plane_on_surface(int p) const { return surface_planes.empty() || surface_planes[p]; }
};

/// The runtime form of a hull (pass the shape by move to avoid a copy).
RuntimeHull make_runtime_hull(ConvexPolytope shape, int material);

/// One mesh triangle as a flat hull (front and back facets, side planes),
/// material 0: how TriangleWorld and the audit's clearance queries see a
/// face. The corners must span an area (the caller skips zero-area faces).
RuntimeHull flat_triangle_hull(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

} // namespace hullcover::bvh

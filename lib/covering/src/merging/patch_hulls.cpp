#include "merging/patch_hulls.h"

#include "hullcover/geometry/tolerances.h"

#include "cells/decomposition_stages.h"
#include "validity/planar_prism.h"
#include "merging/surface_facets.h"

#include <algorithm>

namespace hullcover::detail {
namespace {

// The solid for a planar patch: the thickest allowed beveled prism,
// re-checked as a solid against conditions 1 and 3, flat if that fails.
CoveringHull planar_hull(const SceneIndex& index, const PlaceTolerance& places, const PatchMerger& merger, int patch_id,
                         const Patch& patch, double cap, ConvexHullBuilder& hulls, std::vector<int>& scratch) {
  CoveringHull hull;
  hull.planar = true;
  const FlatPolygon polygon = make_flat_polygon(index.mesh().positions, vertices_of_faces(index.mesh(), patch.faces),
                                                patch.area_vector.normalized(), index.tol());
  const auto in_patch = [&](int f) { return merger.in_patch(f, patch_id); };
  const std::vector<Plane> sides = beveled_side_planes(index, polygon, in_patch, scratch);
  // The prism stays out of the zones of islands with a smaller tolerance
  // than the one it is checked at (hullcover/mesh/tolerance.h), where the
  // audit would judge it more strictly: behind a map's outer wall, short of
  // a smaller neighbour.
  std::vector<int>& zones = scratch;
  zones.clear();
  Aabb column = bounding_box_of(polygon.corners);
  for (const Eigen::Vector3d& c : polygon.corners) column.extend(c - cap * polygon.plane.normal);
  places.smaller_zones_meeting(column, index.tol(), zones);
  for (int z : zones)
    cap = std::min(cap,
                   std::max(0.0, depth_before_box(polygon, index.prepared->tolerance.island_zones[z]) - index.tol()));
  hull.thickness = allowed_prism_thickness(index, polygon, sides, in_patch, cap, scratch);
  hull.polytope = prism_polytope(polygon, sides, hull.thickness, index.tol(), hulls);
  if (hull.thickness > 0.0 && check_solid_hull(index, hull.polytope, scratch) != Validity::valid) {
    hull.thickness = 0.0;
    hull.polytope = prism_polytope(polygon, sides, hull.thickness, index.tol(), hulls);
  }
  return hull;
}

bool same_planes(const std::vector<Plane>& a, const std::vector<Plane>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const Plane& x, const Plane& y) { return x.normal == y.normal && x.offset == y.offset; });
}

} // namespace

double prism_cap_of(const DecompositionStages& stages, const Patch& patch) {
  const Covering& covering = stages.covering;
  if (covering.options.prism_thickness_cap) return *covering.options.prism_thickness_cap;
  double extent = 0.0;
  for (int f : patch.faces)
    extent = std::max(extent, covering.island_extents[stages.prepared.islands.island_of_face[f]]);
  return kDefaultPrismCapRelative * extent;
}

PatchHull make_patch_hull(const DecompositionStages& stages, const SceneIndex& index, const PatchMerger& merger, int id,
                          ConvexHullBuilder& builder, std::vector<int>& scratch) {
  const Patch& patch = merger.patches()[id];
  PatchHull made;
  CoveringHull& hull = made.hull;
  if (patch.planar) {
    hull = planar_hull(index, stages.place_tolerance, merger, id, patch, prism_cap_of(stages, patch), builder, scratch);
  } else {
    // Rebuild once with Qhull: hulls grown during merging keep the
    // triangles they grew by, Qhull merges coplanar facets into polygons.
    std::vector<Eigen::Vector3d> points;
    for (int v : patch.hull_vertices) points.push_back(index.mesh().positions[v]);
    Result<ConvexPolytope> rebuilt = builder.build(points, patch.hull_vertices);
    // The hull validated during merging may differ from the rebuilt one by
    // up to tol (points within tol of it were not added): the rebuilt hull
    // is kept only if it passes the same checks.
    const bool rebuilt_valid = rebuilt.ok() && check_solid_hull(index, rebuilt.value(), scratch) == Validity::valid;
    hull.polytope = rebuilt_valid ? std::move(rebuilt).value() : *patch.solid;
    made.kept_as_grown = !rebuilt_valid;
  }
  hull.faces = patch.faces;
  std::sort(hull.faces.begin(), hull.faces.end());
  hull.material = patch.material;
  hull.volume = polytope_volume(hull.polytope);
  hull.surface_planes = surface_planes(index, hull.polytope, scratch);
  return made;
}

void count_hull_making(CoveringStatistics& stats, const PatchHull& made) {
  stats.qhull_calls += !made.hull.planar;
  stats.prisms_made_flat += made.hull.planar && made.hull.thickness == 0.0;
  stats.solids_kept_as_grown += made.kept_as_grown;
}

bool same_hull(const PatchHull& a, const PatchHull& b) {
  const CoveringHull& x = a.hull;
  const CoveringHull& y = b.hull;
  return a.kept_as_grown == b.kept_as_grown && x.planar == y.planar && x.thickness == y.thickness &&
         x.volume == y.volume && x.material == y.material && x.faces == y.faces &&
         x.surface_planes == y.surface_planes && x.polytope.vertices == y.polytope.vertices &&
         x.polytope.facets == y.polytope.facets && same_planes(x.polytope.planes, y.polytope.planes) &&
         x.polytope.vertex_ids == y.polytope.vertex_ids;
}

} // namespace hullcover::detail

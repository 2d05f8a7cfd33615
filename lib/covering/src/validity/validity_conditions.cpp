#include "validity/validity_conditions.h"

#include <algorithm>
#include <optional>

#include "validity/exact_conditions.h"

namespace hullcover {

bool planes_support_points(const std::vector<Plane>& planes, const std::vector<Eigen::Vector3d>& points, double tol) {
  for (const Plane& plane : planes)
    for (const Eigen::Vector3d& p : points)
      if (plane.signed_distance(p) > tol) return false;
  return true;
}

namespace {

// E1-E3 of one piece of free space against a hull's interior. `sweep` and
// `storage` are reused storage. `index` is the hull's view: the interior is
// shrunk by its tolerance. The rays are judged at their own face's, as the
// audit judges them (a ray from another place, whose tolerance differs,
// meets faces and stands off by its own).
Validity judge_sweep(const SceneIndex& hull_view, const SweepRef& ref, const HullInterior& interior,
                     FreeSpaceSweep& sweep, detail::SweepJudgeStorage& storage) {
  const PreparedSceneView& prepared = *hull_view.prepared;
  const int face = ref.fan < 0 ? ref.item : prepared.connectivity.edge_uses[hull_view.open_edge_use[ref.item]].face;
  const double ray_tol = prepared.face_tolerance(face);
  std::optional<SceneIndex> ray_view;
  if (ray_tol != hull_view.tol()) ray_view.emplace(hull_view.at_tolerance(ray_tol));
  const SceneIndex& index = ray_view ? *ray_view : hull_view;
  const double tol = index.tol();
  const MeshView& mesh = index.mesh();
  const int own_place = prepared.face_place(face) == hull_view.place ? hull_view.place : -1;
  if (ref.fan < 0) {
    const int f = ref.item;
    std::vector<Eigen::Vector3d>& triangle = storage.triangle;
    triangle_corners(mesh, f, triangle);
    front_space_sweep(triangle, index.face_normals[f], index.front_reach[f], tol, sweep);
    sweep.place = own_place;
    if (crossing_face_leaks(index, sweep, interior, storage)) return Validity::face_crosses_hull;
    if (sweep_enters_hull(index, sweep, interior, storage)) return Validity::front_space_inside;
    return Validity::valid;
  }
  // The use names the face and where the edge sits in it: its far corner
  // is the face's side of the edge.
  const EdgeUse& use = prepared.connectivity.edge_uses[index.open_edge_use[ref.item]];
  const Eigen::Vector3i& t = mesh.triangles[use.face];
  const Eigen::Vector3d& p0 = mesh.positions[t[use.corner]];
  const Eigen::Vector3d& p1 = mesh.positions[t[(use.corner + 1) % 3]];
  const Eigen::Vector3d& inner = mesh.positions[t[(use.corner + 2) % 3]];
  const double reach = index.opening_reach[ref.item][ref.fan];
  opening_fan(p0, p1, inner, index.face_normals[use.face], ref.fan, reach, tol, sweep);
  sweep.place = own_place;
  if (sweep_enters_hull(index, sweep, interior, storage)) return Validity::opening_inside;
  return Validity::valid;
}

// The items of `tree` whose boxes meet `box`, as their owners (a sweep has a
// box per hull zone it crosses: each face or edge once), ascending.
void sweep_owners(const AabbTree& tree, const MappableArray<int>& owner_of_item, const Aabb& box,
                  std::vector<int>& out) {
  out.clear();
  tree.overlapping(box, out);
  for (int& item : out) item = owner_of_item[item];
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

// E1-E3 (exact_conditions.h) for a solid hull whose box grown by tol is `box`.
Validity check_exact_solid_hull(const SceneIndex& index, const ConvexPolytope& hull, const Aabb& box,
                                std::vector<int>& scratch, RecentRejections* recent) {
  // Kept for every piece this hull's check judges.
  FreeSpaceSweep sweep;
  detail::SweepJudgeStorage storage;
  const HullInterior interior = hull_interior(hull, index.tol());
  if (interior.empty()) return Validity::valid; // thinner than 2 tol: nothing is strictly inside
  std::vector<int>& fronts = scratch;
  std::vector<int> openings;
  sweep_owners(index.front_sweep_tree, index.front_sweep_face, box, fronts);
  sweep_owners(index.opening_sweep_tree, index.opening_sweep_edge, box, openings);
  // Judged first: pieces that rejected the latest hulls, where this hull's
  // box meets them (the same pieces the loops below would judge).
  const auto meets = [&](const SweepRef& ref) {
    const std::vector<int>& owners = ref.fan < 0 ? fronts : openings;
    return ref.item >= 0 && std::binary_search(owners.begin(), owners.end(), ref.item);
  };
  const auto rejects = [&](const SweepRef& ref, Validity& validity) {
    validity = judge_sweep(index, ref, interior, sweep, storage);
    if (validity == Validity::valid) return false;
    if (recent) recent->note(ref);
    return true;
  };
  Validity validity = Validity::valid;
  SweepRef judged[RecentRejections::kKept];
  int judged_count = 0;
  if (recent)
    for (const SweepRef& ref : *recent)
      if (meets(ref)) {
        if (rejects(ref, validity)) return validity;
        judged[judged_count++] = ref;
      }
  const auto judged_already = [&](const SweepRef& ref) {
    return std::find(judged, judged + judged_count, ref) != judged + judged_count;
  };
  for (int f : fronts)
    if (!judged_already({f, -1}) && rejects({f, -1}, validity)) return validity;
  for (int e : openings)
    for (int fan = 0; fan < kOpeningFans; ++fan)
      if (!judged_already({e, fan}) && rejects({e, fan}, validity)) return validity;
  return Validity::valid;
}

} // namespace

Validity check_solid_hull(const SceneIndex& index, const ConvexPolytope& hull, std::vector<int>& scratch,
                          RecentRejections* recent) {
  const double tol = index.tol();
  const Aabb box = grown(bounding_box_of(hull.vertices), tol);
  const MeshView& mesh = index.mesh();

  // Condition 1 keeps mesh elements out of hulls; with an allowance a hull
  // may swallow them where the exact conditions prove the space around them
  // harmless.
  // The walks stop at the first element inside: most candidates that fail
  // fail here, and a large hull's box holds thousands of elements.
  // A hull that fills little of its box (a slab's box, most of it off the
  // slab) leaves whole nodes of the trees outside one of its planes: those
  // are passed over. The same answers either way.
  if (!index.has_allowance()) {
    const InteriorRegionTest region_test(hull, box, tol);
    const auto outside = [&](const Aabb& region) { return region_test.outside(region); };
    const auto vertex_inside = [&](int v) { return deepest_signed_distance(hull.planes, mesh.positions[v]) < -tol; };
    const auto edge_inside = [&](int e) {
      const MeshEdge& edge = index.prepared->connectivity.edges[e];
      return segment_enters_interior(hull.planes, mesh.positions[edge.v0], mesh.positions[edge.v1], tol);
    };
    const bool prune = region_test.worthwhile();
    if (prune ? index.vertex_tree.any_overlapping_pruned(box, outside, vertex_inside)
              : index.vertex_tree.any_overlapping(box, vertex_inside))
      return Validity::vertex_inside;
    if (prune ? index.edge_tree.any_overlapping_pruned(box, outside, edge_inside)
              : index.edge_tree.any_overlapping(box, edge_inside))
      return Validity::edge_inside;
  }

  scratch.clear();
  index.bars_overlapping(box, scratch);
  for (int b : scratch) {
    const BoundaryBar& bar = index.bars[b];
    if (bar.is_sheet() ? sheet_enters_interior(hull.planes, bar.outline(), tol)
                       : segment_enters_interior(hull.planes, bar.a, bar.b, tol))
      return Validity::bar_inside;
  }
  if (index.mode != ValidityMode::exact) return Validity::valid;

  return check_exact_solid_hull(index, hull, box, scratch, recent);
}

Validity check_faces_below_polygon(const SceneIndex& index, const FlatPolygon& polygon, double half_width,
                                   const std::function<bool(int)>& in_patch, std::vector<int>& scratch) {
  const Aabb box = grown(bounding_box_of(polygon.corners), half_width);
  const MeshView& mesh = index.mesh();
  scratch.clear();
  index.face_tree.overlapping(box, scratch);
  std::vector<Eigen::Vector3d> triangle(3);
  for (int f : scratch) {
    if (in_patch(f)) continue;
    triangle_corners(mesh, f, triangle);
    bool below = false;
    for (const Eigen::Vector3d& corner : triangle) below |= polygon.plane.signed_distance(corner) < -half_width;
    if (below && meets_polygon_interior(polygon, triangle, half_width)) return Validity::face_below_polygon;
  }
  return Validity::valid;
}

Validity check_flat_polygon(const SceneIndex& index, const FlatPolygon& polygon,
                            const std::function<bool(int)>& in_patch, std::vector<int>& scratch) {
  const double tol = index.tol();
  const Aabb box = grown(bounding_box_of(polygon.corners), tol);
  scratch.clear();
  index.bars_overlapping(box, scratch);
  for (int b : scratch)
    if (bar_crosses_polygon(polygon, index.bars[b], tol)) return Validity::bar_crosses_polygon;
  return check_faces_below_polygon(index, polygon, tol, in_patch, scratch);
}

} // namespace hullcover

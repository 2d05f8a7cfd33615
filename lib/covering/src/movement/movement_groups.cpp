#include "movement/movement_groups.h"

#include "hullcover/geometry/planar_hull.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <utility>

namespace hullcover::detail {
namespace {

// The group of the faces of `faces` with an area that are also in `wanted`
// (ascending), its outline without the edges two of them share; false when
// none is left.
bool gather(const Mesh& mesh, const std::vector<int>& faces, const std::vector<int>& wanted, MovementGroup& group) {
  group = MovementGroup{};
  std::vector<std::pair<int, int>> edges;
  for (int f : faces) {
    if (!std::binary_search(wanted.begin(), wanted.end(), f)) continue;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0.0)) continue;
    group.faces.push_back(f);
    group.corners.insert(group.corners.end(), {t[0], t[1], t[2]});
    group.area += 0.5 * n.norm();
    group.area_vector += 0.5 * n;
    for (int k = 0; k < 3; ++k) edges.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
  }
  if (group.faces.empty()) return false;
  std::sort(group.corners.begin(), group.corners.end());
  group.corners.erase(std::unique(group.corners.begin(), group.corners.end()), group.corners.end());
  // An edge counts once in the outline, and not at all when faces of the
  // group meet along it.
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) group.boundary += (mesh.positions[edges[i].first] - mesh.positions[edges[i].second]).norm();
    i = j;
  }
  return true;
}

} // namespace

bool make_group_hull(const MovementContext& context, int max_hull_vertices, const Eigen::Vector3d& fallback_normal,
                     ConvexHullBuilder& builder, MovementGroup& group) {
  const Mesh& mesh = context.mesh;
  const double tol = context.tol;
  std::vector<Eigen::Vector3d> points;
  points.reserve(group.corners.size());
  for (int v : group.corners) points.push_back(mesh.positions[v]);
  Result<ConvexPolytope> solid = builder.build(points, group.corners);
  if (solid.ok()) {
    group.hull = std::move(solid).value();
    group.flat = false;
  } else {
    // Flat (or too thin for Qhull): one polygon, every point within tol of
    // its plane, or no hull.
    Eigen::Vector3d normal = group.area_vector;
    if (!(normal.norm() > 0.0)) normal = fallback_normal;
    normal.normalize();
    const auto [low, high] = extent_along(mesh.positions, group.corners, normal);
    if (!(high - low <= 2.0 * tol)) return false;
    FlatPolygon polygon = make_flat_polygon(mesh.positions, group.corners, normal, tol);
    if (polygon.corners.size() < 3) return false;
    group.hull = flat_polytope(polygon, true);
    group.flat = true;
  }
  if (static_cast<int>(group.hull.vertices.size()) > max_hull_vertices) return false;
  group.corners.clear();
  for (int id : group.hull.vertex_ids)
    if (id >= 0) group.corners.push_back(id);
  std::sort(group.corners.begin(), group.corners.end());
  group.corners.erase(std::unique(group.corners.begin(), group.corners.end()), group.corners.end());
  group.box = bounding_box_of(group.hull.vertices);
  return true;
}

std::vector<MovementGroup> starting_groups(const MovementContext& context, const std::vector<int>& faces,
                                           const std::vector<std::vector<int>>& start_groups, int max_hull_vertices,
                                           GroupProver& prover) {
  const Mesh& mesh = context.mesh;
  // Per face of `faces` (a region's, not the scene's: many regions run).
  std::vector<char> grouped(faces.size(), 0);
  const auto slot = [&](int f) { return std::lower_bound(faces.begin(), faces.end(), f) - faces.begin(); };
  std::vector<MovementGroup> groups;
  MovementGroup group;
  for (const std::vector<int>& start : start_groups) {
    if (!gather(mesh, start, faces, group) || group.faces.size() < 2) continue;
    if (std::any_of(group.faces.begin(), group.faces.end(), [&](int f) { return grouped[slot(f)] != 0; })) continue;
    if (!make_group_hull(context, max_hull_vertices, group.area_vector, prover.builder, group)) continue;
    ++prover.candidates;
    const MovementVerdict verdict = check_movement_hull(context, group.hull, group.flat, {}, prover.boundary);
    if (verdict == MovementVerdict::undecided) ++prover.undecided;
    if (verdict != MovementVerdict::valid) continue;
    for (int f : group.faces) grouped[slot(f)] = 1;
    groups.push_back(std::move(group));
  }
  for (size_t i = 0; i < faces.size(); ++i) {
    const int f = faces[i];
    if (grouped[i] || !gather(mesh, {f}, faces, group)) continue;
    // A face alone keeps the promise: it is the scene's own surface.
    const Eigen::Vector3i& t = mesh.triangles[f];
    FlatPolygon polygon = flat_triangle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    polygon.corner_vertices = {t[0], t[1], t[2]};
    group.hull = flat_polytope(polygon, true);
    group.flat = true;
    group.box = bounding_box_of(polygon.corners);
    groups.push_back(std::move(group));
  }
  return groups;
}

} // namespace hullcover::detail

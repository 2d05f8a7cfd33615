#include "merging/face_coverage.h"

#include "merging/surface_facets.h"
#include "validity/validity_conditions.h"

#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/parallel_for.h"
#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace hullcover::detail {
namespace {

// Whether `p` lies within `tol` of `polytope`: at one of its vertices (most
// face corners are), in it, or within tol of its facets (a distance never
// nearer than the true one, convex_polytope.h). Not the planes alone: past
// a thin hull's sharp edge a point can lie within tol of every plane and
// far from the hull.
bool within_tol(const ConvexPolytope& polytope, const Eigen::Vector3d& p, double tol) {
  for (const Eigen::Vector3d& v : polytope.vertices)
    if ((v - p).squaredNorm() <= tol * tol) return true;
  return deepest_signed_distance(polytope.planes, p) <= 0.0 || distance_to_facet_fans(polytope, p) <= tol;
}

// Within tol of one hull at every corner of a face: so is all of it, the
// hull being convex.
bool covers_face(const ConvexPolytope& polytope, const MeshView& mesh, int f, double tol) {
  const Eigen::Vector3i& t = mesh.triangles[f];
  return within_tol(polytope, mesh.positions[t[0]], tol) && within_tol(polytope, mesh.positions[t[1]], tol) &&
         within_tol(polytope, mesh.positions[t[2]], tol);
}

// Whether a triangle (thinner than tol, perhaps) still has a plane to make a flat hull on: the
// sine of its smallest angle (its doubled area, the norm of its area
// vector, over the product of the two sides meeting there; at least that
// over the longest side squared) above kParallelSine.
bool has_plane(const MeshView& mesh, int f) {
  const Eigen::Vector3i& t = mesh.triangles[f];
  const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
  const double longest_squared = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return triangle_area_vector(mesh, f).norm() > kParallelSine * longest_squared;
}

// Faces joined by a shared edge, each group in face order, groups in the
// order of their first face.
std::vector<std::vector<int>> edge_joined_groups(const MeshView& mesh, const std::vector<int>& faces) {
  std::vector<int> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<std::pair<int, int>, int> first_with_edge;
  for (int i = 0; i < static_cast<int>(faces.size()); ++i) {
    const Eigen::Vector3i& t = mesh.triangles[faces[i]];
    for (int k = 0; k < 3; ++k) {
      const auto edge = std::minmax(t[k], t[(k + 1) % 3]);
      const auto [at, added] = first_with_edge.emplace(edge, i);
      if (!added) parent[root(i)] = root(at->second);
    }
  }
  std::map<int, std::vector<int>> by_root;
  for (int i = 0; i < static_cast<int>(faces.size()); ++i) by_root[root(i)].push_back(faces[i]);
  std::vector<std::vector<int>> groups;
  for (auto& [r, group] : by_root) groups.push_back(std::move(group));
  std::sort(groups.begin(), groups.end(), [](const auto& x, const auto& y) { return x.front() < y.front(); });
  return groups;
}

// One flat polygon for a group of faces, when it is exactly their union:
// they face one way, the convex polygon of their corners has their summed
// area (to tol times its rim), covers each within tol, and passes the
// conditions a flat patch does (nothing crosses it). A strip of slivers
// fanned between two straight lines (a Cube map's trimmed wall) is one.
std::optional<FlatPolygon> group_polygon(const SceneIndex& index, const MeshView& mesh, const std::vector<int>& group,
                                         double tol, std::vector<int>& scratch) {
  if (group.size() < 2) return std::nullopt;
  std::vector<Eigen::Vector3d> area_vectors; // each twice its face's area
  Eigen::Vector3d area_vector = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (int f : group) {
    area_vectors.push_back(triangle_area_vector(mesh, f));
    area_vector += area_vectors.back();
    area += 0.5 * area_vectors.back().norm();
  }
  if (area_vector.norm() == 0.0) return std::nullopt;
  const Eigen::Vector3d normal = area_vector.normalized();
  for (const Eigen::Vector3d& v : area_vectors)
    if (v.dot(normal) <= 0.0) return std::nullopt;
  std::vector<int> vertices;
  for (int f : group)
    for (int k = 0; k < 3; ++k) vertices.push_back(mesh.triangles[f][k]);
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  FlatPolygon polygon = make_flat_polygon(mesh.positions, vertices, normal, tol);
  if (polygon.corners.size() < 3) return std::nullopt;
  double polygon_area = 0.0, rim = 0.0;
  for (size_t i = 0; i < polygon.corners.size(); ++i) {
    const Eigen::Vector3d& p = polygon.corners[i];
    const Eigen::Vector3d& q = polygon.corners[(i + 1) % polygon.corners.size()];
    polygon_area += 0.5 * (p - polygon.corners[0]).cross(q - polygon.corners[0]).dot(normal);
    rim += (q - p).norm();
  }
  if (std::abs(polygon_area - area) > tol * rim) return std::nullopt;
  const ConvexPolytope flat = flat_polytope(polygon, true);
  for (int f : group)
    if (!covers_face(flat, mesh, f, tol)) return std::nullopt;
  const auto in_group = [&](int f) { return std::binary_search(group.begin(), group.end(), f); };
  if (check_flat_polygon(index, polygon, in_group, scratch) != Validity::valid) return std::nullopt;
  return polygon;
}

CoveringHull flat_hull(const SceneIndex& index, const MeshView& mesh, const FlatPolygon& polygon,
                       std::vector<int> faces, std::vector<int>& scratch) {
  CoveringHull hull;
  hull.polytope = flat_polytope(polygon, true);
  hull.faces = std::move(faces);
  hull.planar = true;
  hull.material = mesh.material_ids[hull.faces.front()];
  for (int f : hull.faces) hull.material = std::min(hull.material, mesh.material_ids[f]);
  hull.surface_planes = surface_planes(index, hull.polytope, scratch);
  return hull;
}

} // namespace

FaceCoverageCount cover_uncovered_faces(const DecompositionStages& stages, Covering& covering, int threads) {
  FaceCoverageCount count;
  const PreparedSceneView& prepared = stages.prepared;
  const MeshView& mesh = prepared.mesh;
  const int face_count = static_cast<int>(mesh.triangles.size());
  const auto tol_of = [&](int f) { return stages.island_tolerance[prepared.islands.island_of_face[f]]; };
  std::vector<int> owner(face_count, -1);
  std::vector<Aabb> boxes;
  boxes.reserve(covering.hulls.size());
  for (size_t h = 0; h < covering.hulls.size(); ++h) {
    for (int f : covering.hulls[h].faces) owner[f] = static_cast<int>(h);
    Aabb box;
    for (const Eigen::Vector3d& v : covering.hulls[h].polytope.vertices) box.extend(v);
    boxes.push_back(box);
  }
  const AabbTree tree(boxes);
  // Per face: 1 when no hull covers it. First the faces hulls claim, each
  // against its own hull. A face off its own hull is not given to another
  // it lies within tol of: that hull was never checked to keep the face's
  // front (condition 2; the audit holds a face's hull to it), so it gets
  // its own. Each thread writes only its faces' entries.
  std::vector<char> uncovered_face(face_count, 0);
  parallel_for(face_count, threads, [&](int f) {
    if (owner[f] >= 0 && !triangle_has_repeated_vertex(mesh, f))
      uncovered_face[f] = !covers_face(covering.hulls[owner[f]].polytope, mesh, f, tol_of(f));
  });
  // A hull that covers none of its faces is dropped below: it covers no
  // face in no patch either.
  std::vector<int> claims_kept(covering.hulls.size(), 0);
  for (int f = 0; f < face_count; ++f)
    if (owner[f] >= 0 && !uncovered_face[f]) ++claims_kept[owner[f]];
  // Then the faces in no patch (thinner than tol: no front to keep),
  // against every hull near them.
  parallel_for(face_count, threads, [&](int f) {
    if (owner[f] >= 0 || triangle_has_repeated_vertex(mesh, f)) return;
    const double tol = tol_of(f);
    Aabb box;
    for (int k = 0; k < 3; ++k) box.extend(mesh.positions[mesh.triangles[f][k]]);
    std::vector<int> near;
    tree.overlapping(grown(box, tol), near);
    uncovered_face[f] = std::none_of(near.begin(), near.end(), [&](int h) {
      return claims_kept[h] > 0 && covers_face(covering.hulls[h].polytope, mesh, f, tol);
    });
  });
  std::vector<int> uncovered;
  for (int f = 0; f < face_count; ++f) {
    if (!uncovered_face[f]) continue;
    if (owner[f] >= 0) {
      std::vector<int>& claims = covering.hulls[owner[f]].faces;
      claims.erase(std::lower_bound(claims.begin(), claims.end(), f));
    }
    uncovered.push_back(f);
  }
  std::vector<int> scratch;
  for (std::vector<int>& group : edge_joined_groups(mesh, uncovered)) {
    // A group spans one island (its faces share edges).
    const int island = prepared.islands.island_of_face[group.front()];
    const SceneIndex& index = stages.index_of_island(island);
    const auto count_covered = [&](int f) {
      ++count.covered;
      count.thin_covered += prepared.connectivity.zero_area[f] != 0;
    };
    if (const std::optional<FlatPolygon> polygon = group_polygon(index, mesh, group, tol_of(group.front()), scratch)) {
      for (int f : group) count_covered(f);
      covering.hulls.push_back(flat_hull(index, mesh, *polygon, std::move(group), scratch));
      continue;
    }
    for (int f : group) {
      if (!has_plane(mesh, f)) {
        ++count.bare;
        continue;
      }
      const Eigen::Vector3i& t = mesh.triangles[f];
      FlatPolygon triangle = flat_triangle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
      triangle.corner_vertices = {t[0], t[1], t[2]};
      covering.hulls.push_back(flat_hull(index, mesh, triangle, {f}, scratch));
      count_covered(f);
    }
  }
  // A hull that covers none of its faces keeps none.
  covering.hulls.erase(std::remove_if(covering.hulls.begin(), covering.hulls.end(),
                                      [](const CoveringHull& hull) { return hull.faces.empty(); }),
                       covering.hulls.end());
  return count;
}

} // namespace hullcover::detail

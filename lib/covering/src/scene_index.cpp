#include "scene_index.h"

#include "witness_rays.h"
#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover {
namespace {

Aabb box_of(std::initializer_list<Eigen::Vector3d> points) {
  Aabb box;
  for (const Eigen::Vector3d& p : points) box.extend(p);
  return box;
}

void add_bar(SceneIndex& index, int edge, int face, double half_length) {
  const MeshEdge& e = index.prepared->connectivity.edges[edge];
  const Eigen::Vector3d& p0 = index.mesh().positions[e.v0];
  const Eigen::Vector3d& p1 = index.mesh().positions[e.v1];
  const Eigen::Vector3d offset = half_length * index.face_normals[face];
  if (index.mode == ValidityMode::exact) {
    index.bars.push_back({p0 - offset, p0 + offset, p1 - p0, edge, face});
  } else {
    const Eigen::Vector3d mid = 0.5 * (p0 + p1);
    index.bars.push_back({mid - offset, mid + offset, Eigen::Vector3d::Zero(), edge, face});
  }
}

// `box` within `bounds` (empty when they do not meet).
Aabb clipped(const Aabb& box, const Aabb& bounds) {
  Aabb out;
  out.min = box.min.cwiseMax(bounds.min);
  out.max = box.max.cwiseMin(bounds.max);
  return out;
}

// How far every face's front sweep and every open edge's fans run, and
// their boxes, clipped to where hulls can be: the trees the exact
// conditions look up.
void index_sweeps(SceneIndex& index, double hull_margin) {
  const Mesh& mesh = index.mesh();
  const MeshConnectivity& c = index.prepared->connectivity;
  const double reach = index.free_space_reach;
  const double tol = index.tol();
  const Aabb bounds = grown(referenced_bounding_box(mesh), hull_margin + tol);
  std::vector<int> scratch;
  std::vector<Eigen::Vector3d> triangle(3);
  std::vector<Aabb> boxes;
  index.front_reach.assign(mesh.triangles.size(), 0.0);
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
    if (c.zero_area[f]) continue;
    triangle_corners(mesh, f, triangle);
    const FreeSpaceSweep full = front_space_sweep(triangle, index.face_normals[f], reach, tol);
    index.front_reach[f] = std::min(reach, detail::first_hit_bound(index, full, scratch));
    const FreeSpaceSweep sweep = front_space_sweep(triangle, index.face_normals[f], index.front_reach[f], tol);
    Aabb box;
    for (const Eigen::Vector3d& corner : sweep.corners) box.extend(corner);
    box = clipped(grown(box, tol), bounds);
    if (box.empty()) continue;
    boxes.push_back(box);
    index.front_sweep_face.push_back(f);
  }
  index.front_sweep_tree = AabbTree(boxes);
  boxes.clear();
  index.opening_reach.assign(c.edges.size(), {});
  for (int e = 0; e < static_cast<int>(c.edges.size()); ++e) {
    if (index.open_edge_use[e] < 0) continue;
    const EdgeUse& use = c.edge_uses[index.open_edge_use[e]];
    const Eigen::Vector3i& t = mesh.triangles[use.face];
    const Eigen::Vector3d& p0 = mesh.positions[t[use.corner]];
    const Eigen::Vector3d& p1 = mesh.positions[t[(use.corner + 1) % 3]];
    const Eigen::Vector3d& inner = mesh.positions[t[(use.corner + 2) % 3]];
    Aabb box;
    for (int fan = 0; fan < kOpeningFans; ++fan) {
      const Eigen::Vector3d& n = index.face_normals[use.face];
      const FreeSpaceSweep full = opening_fan(p0, p1, inner, n, fan, reach, tol);
      index.opening_reach[e][fan] = std::min(reach, detail::first_hit_bound(index, full, scratch));
      for (const Eigen::Vector3d& corner : opening_fan(p0, p1, inner, n, fan, index.opening_reach[e][fan], tol).corners)
        box.extend(corner);
    }
    box = clipped(grown(box, tol), bounds);
    if (box.empty()) continue;
    boxes.push_back(box);
    index.opening_sweep_edge.push_back(e);
  }
  index.opening_sweep_tree = AabbTree(boxes);
}

} // namespace

double uncapped_free_space_reach(const PreparedMesh& prepared, double hull_margin) {
  // The box grown by the margin has a diagonal of at most D + 2 sqrt(3) m.
  return prepared.tolerance.diagonal + 4.0 * (hull_margin + prepared.tolerance.length);
}

std::vector<Eigen::Vector3d> BoundaryBar::outline() const {
  if (!is_sheet()) return {a, b};
  return {a, a + along, b + along, b};
}

bool is_fold_edge(const PreparedMesh& prepared, int edge) {
  const MeshConnectivity& c = prepared.connectivity;
  const MeshEdge& e = c.edges[edge];
  if (e.kind != EdgeKind::manifold) return false;
  const EdgeUse& u0 = c.edge_uses[e.first_use];
  const EdgeUse& u1 = c.edge_uses[e.first_use + 1];
  if (c.zero_area[u0.face] || c.zero_area[u1.face]) return false;
  const Mesh& mesh = prepared.mesh;
  const Eigen::Vector3d n0 = triangle_area_vector(mesh, u0.face).normalized();
  const Eigen::Vector3d n1 = triangle_area_vector(mesh, u1.face).normalized();
  if (n0.dot(n1) >= 0.0) return false;
  const Eigen::Vector3d& far_corner = mesh.positions[mesh.triangles[u1.face][(u1.corner + 2) % 3]];
  const Eigen::Vector3d& on_edge = mesh.positions[e.v0];
  return std::abs(n0.dot(far_corner - on_edge)) <= prepared.tolerance.length;
}

SceneIndex build_scene_index(const PreparedMesh& prepared, const BarOptions& options) {
  SceneIndex index;
  index.prepared = &prepared;
  index.mode = options.mode;
  index.free_space_reach = options.free_space_reach;
  index.agent_radius = options.agent_radius;
  index.max_deviation = options.max_deviation;
  index.open_edge_use.assign(prepared.connectivity.edges.size(), -1);
  const Mesh& mesh = prepared.mesh;
  const MeshConnectivity& c = prepared.connectivity;
  const int face_count = static_cast<int>(mesh.triangles.size());

  index.face_normals.resize(face_count, Eigen::Vector3d::Zero());
  index.face_areas.resize(face_count, 0.0);
  for (int f = 0; f < face_count; ++f) {
    const Eigen::Vector3d area_vector = triangle_area_vector(mesh, f);
    index.face_areas[f] = 0.5 * area_vector.norm();
    if (!c.zero_area[f]) index.face_normals[f] = area_vector.normalized();
  }

  for (int e = 0; e < static_cast<int>(c.edges.size()); ++e) {
    const MeshEdge& edge = c.edges[e];
    if (edge.kind == EdgeKind::boundary) {
      const int face = c.edge_uses[edge.first_use].face;
      if (c.zero_area[face]) continue;
      add_bar(index, e, face, options.half_length);
      index.open_edge_use[e] = edge.first_use;
    } else if (options.mode == ValidityMode::exact && is_fold_edge(prepared, e)) {
      add_bar(index, e, c.edge_uses[edge.first_use].face, options.half_length);
      index.open_edge_use[e] = edge.first_use;
    } else if (options.material_boundaries && edge.kind == EdgeKind::manifold) {
      const int f0 = c.edge_uses[edge.first_use].face, f1 = c.edge_uses[edge.first_use + 1].face;
      if (mesh.material_ids[f0] == mesh.material_ids[f1]) continue;
      for (int face : {f0, f1})
        if (!c.zero_area[face]) add_bar(index, e, face, options.half_length);
    }
  }

  std::vector<Aabb> boxes;
  boxes.reserve(mesh.positions.size());
  for (const Eigen::Vector3d& p : mesh.positions) boxes.push_back(box_of({p}));
  index.vertex_tree = AabbTree(boxes);
  boxes.clear();
  for (const MeshEdge& e : c.edges) boxes.push_back(box_of({mesh.positions[e.v0], mesh.positions[e.v1]}));
  index.edge_tree = AabbTree(boxes);
  boxes.clear();
  for (const Eigen::Vector3i& t : mesh.triangles)
    boxes.push_back(box_of({mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]}));
  index.face_tree = AabbTree(boxes);
  boxes.clear();
  const double piece_length = prepared.tolerance.diagonal / kBarPiecesPerDiagonal;
  for (int b = 0; b < static_cast<int>(index.bars.size()); ++b) {
    const BoundaryBar& bar = index.bars[b];
    const int pieces = std::max(1, static_cast<int>(std::ceil((bar.b - bar.a).norm() / piece_length)));
    for (int k = 0; k < pieces; ++k) {
      const Eigen::Vector3d from = bar.a + (bar.b - bar.a) * (static_cast<double>(k) / pieces);
      const Eigen::Vector3d to = bar.a + (bar.b - bar.a) * (static_cast<double>(k + 1) / pieces);
      boxes.push_back(box_of({from, to, from + bar.along, to + bar.along}));
      index.bar_of_piece.push_back(b);
    }
  }
  index.bar_tree = AabbTree(boxes);
  if (index.mode == ValidityMode::exact) index_sweeps(index, options.hull_margin);
  return index;
}

void SceneIndex::bars_overlapping(const Aabb& box, std::vector<int>& out) const {
  const size_t start = out.size();
  bar_tree.overlapping(box, out);
  for (size_t i = start; i < out.size(); ++i) out[i] = bar_of_piece[out[i]];
  std::sort(out.begin() + static_cast<long>(start), out.end());
  out.erase(std::unique(out.begin() + static_cast<long>(start), out.end()), out.end());
}

} // namespace hullcover

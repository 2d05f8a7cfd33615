#include "validity/scene_index.h"

#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover {

double uncapped_free_space_reach(const PreparedSceneView& prepared, double hull_margin) {
  // The box grown by the margin has a diagonal of at most D + 2 sqrt(3) m.
  return prepared.tolerance.diagonal + 4.0 * (hull_margin + prepared.tolerance.largest_length());
}

std::vector<Eigen::Vector3d> BoundaryBar::outline() const {
  if (!is_sheet()) return {a, b};
  return {a, a + along, b + along, b};
}

bool is_fold_edge(const PreparedSceneView& prepared, int edge) {
  const ConnectivityView& c = prepared.connectivity;
  const MeshEdge& e = c.edges[edge];
  if (e.kind != EdgeKind::manifold) return false;
  const EdgeUse& u0 = c.edge_uses[e.first_use];
  const EdgeUse& u1 = c.edge_uses[e.first_use + 1];
  if (c.zero_area[u0.face] || c.zero_area[u1.face]) return false;
  const MeshView& mesh = prepared.mesh;
  const Eigen::Vector3d n0 = triangle_area_vector(mesh, u0.face).normalized();
  const Eigen::Vector3d n1 = triangle_area_vector(mesh, u1.face).normalized();
  if (n0.dot(n1) >= 0.0) return false;
  const Eigen::Vector3d& far_corner = mesh.positions[mesh.triangles[u1.face][(u1.corner + 2) % 3]];
  const Eigen::Vector3d& on_edge = mesh.positions[e.v0];
  return std::abs(n0.dot(far_corner - on_edge)) <= prepared.face_tolerance(u0.face);
}

SceneIndex::SceneIndex(const SceneIndexData& data, double tolerance, double patch_extent)
    : prepared(data.prepared), mode(data.mode), free_space_reach(data.free_space_reach),
      agent_radius(data.agent_radius), max_deviation(data.max_deviation), open_edge_use(data.open_edge_use),
      face_normals(data.face_normals), face_areas(data.face_areas), bars(data.bars), vertex_tree(data.vertex_tree),
      edge_tree(data.edge_tree), face_tree(data.face_tree), bar_tree(data.bar_tree),
      front_sweep_tree(data.front_sweep_tree), front_sweep_face(data.front_sweep_face), front_reach(data.front_reach),
      opening_sweep_tree(data.opening_sweep_tree), opening_sweep_edge(data.opening_sweep_edge),
      opening_reach(data.opening_reach), bar_of_piece(data.bar_of_piece), tolerance_(tolerance),
      patch_extent_(patch_extent) {}

void SceneIndex::bars_overlapping(const Aabb& box, std::vector<int>& out) const {
  const size_t start = out.size();
  bar_tree.overlapping(box, out);
  for (size_t i = start; i < out.size(); ++i) out[i] = bar_of_piece[out[i]];
  std::sort(out.begin() + static_cast<long>(start), out.end());
  out.erase(std::unique(out.begin() + static_cast<long>(start), out.end()), out.end());
}

} // namespace hullcover

#include "hullcover/lib/scene_index.h"

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
  const Eigen::Vector3d mid = 0.5 * (index.mesh().positions[e.v0] + index.mesh().positions[e.v1]);
  const Eigen::Vector3d offset = half_length * index.face_normals[face];
  index.bars.push_back({mid - offset, mid + offset, edge, face});
}

} // namespace

SceneIndex build_scene_index(const PreparedMesh& prepared, const BarOptions& options) {
  SceneIndex index;
  index.prepared = &prepared;
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
      if (!c.zero_area[face]) add_bar(index, e, face, options.half_length);
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
      boxes.push_back(box_of({bar.a + (bar.b - bar.a) * (static_cast<double>(k) / pieces),
                              bar.a + (bar.b - bar.a) * (static_cast<double>(k + 1) / pieces)}));
      index.bar_of_piece.push_back(b);
    }
  }
  index.bar_tree = AabbTree(boxes);
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

#include "hullcover/mesh/mesh_connectivity.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace hullcover {
namespace {

struct DirectedEdge {
  int v0, v1; // sorted pair
  int face, corner;
  bool operator<(const DirectedEdge& o) const {
    return std::tie(v0, v1, face, corner) < std::tie(o.v0, o.v1, o.face, o.corner);
  }
};

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

bool is_zero_area(const Mesh& mesh, int t, double tolerance) {
  if (triangle_has_repeated_vertex(mesh, t)) return true;
  const Eigen::Vector3i& tri = mesh.triangles[t];
  double longest_squared = 0.0;
  for (int k = 0; k < 3; ++k)
    longest_squared =
        std::max(longest_squared, (mesh.positions[tri[(k + 1) % 3]] - mesh.positions[tri[k]]).squaredNorm());
  // Smallest altitude = 2 * area / longest edge; compared squared.
  return triangle_area_vector(mesh, t).squaredNorm() <= tolerance * tolerance * longest_squared;
}

EdgeKind classify(const Mesh& mesh, const std::vector<EdgeUse>& uses, int first, int count) {
  if (count == 1) return EdgeKind::boundary;
  if (count > 2) return EdgeKind::non_manifold;
  const auto start_vertex = [&](const EdgeUse& u) { return mesh.triangles[u.face][u.corner]; };
  return start_vertex(uses[first]) == start_vertex(uses[first + 1]) ? EdgeKind::orientation_conflict
                                                                    : EdgeKind::manifold;
}

} // namespace

MeshConnectivity build_connectivity(const Mesh& mesh, double tolerance) {
  return build_connectivity(mesh, std::vector<double>(mesh.triangles.size(), tolerance));
}

MeshConnectivity build_connectivity(const Mesh& mesh, const std::vector<double>& tolerance_of_face) {
  const int face_count = static_cast<int>(mesh.triangles.size());
  MeshConnectivity c;
  c.face_edges.assign(face_count, Eigen::Vector3i::Constant(-1));
  c.face_neighbours.assign(face_count, Eigen::Vector3i::Constant(-1));
  c.zero_area.resize(face_count);

  std::vector<DirectedEdge> directed;
  directed.reserve(3 * static_cast<size_t>(face_count));
  for (int f = 0; f < face_count; ++f) {
    c.zero_area[f] = is_zero_area(mesh, f, tolerance_of_face[f]) ? 1 : 0;
    if (triangle_has_repeated_vertex(mesh, f)) continue;
    const Eigen::Vector3i& tri = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      directed.push_back({std::min(a, b), std::max(a, b), f, k});
    }
  }
  std::sort(directed.begin(), directed.end());

  c.edge_uses.reserve(directed.size());
  for (size_t i = 0; i < directed.size();) {
    size_t j = i;
    MeshEdge edge;
    edge.v0 = directed[i].v0;
    edge.v1 = directed[i].v1;
    edge.first_use = static_cast<int>(c.edge_uses.size());
    const int edge_index = static_cast<int>(c.edges.size());
    for (; j < directed.size() && directed[j].v0 == edge.v0 && directed[j].v1 == edge.v1; ++j) {
      c.edge_uses.push_back({directed[j].face, directed[j].corner});
      c.face_edges[directed[j].face][directed[j].corner] = edge_index;
    }
    edge.use_count = static_cast<int>(j - i);
    edge.kind = classify(mesh, c.edge_uses, edge.first_use, edge.use_count);
    if (edge.kind == EdgeKind::manifold) {
      const EdgeUse& a = c.edge_uses[edge.first_use];
      const EdgeUse& b = c.edge_uses[edge.first_use + 1];
      c.face_neighbours[a.face][a.corner] = b.face;
      c.face_neighbours[b.face][b.corner] = a.face;
    }
    c.edges.push_back(edge);
    i = j;
  }

  // Components of faces sharing a vertex, by union-find over vertices.
  std::vector<int> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const Eigen::Vector3i& tri : mesh.triangles)
    for (int k = 1; k < 3; ++k) parent[find_root(parent, tri[k])] = find_root(parent, tri[0]);
  std::vector<int> component_of_root(mesh.positions.size(), -1);
  c.face_component.resize(face_count);
  for (int f = 0; f < face_count; ++f) {
    int& id = component_of_root[find_root(parent, mesh.triangles[f][0])];
    if (id < 0) id = c.component_count++;
    c.face_component[f] = id;
  }
  return c;
}

int count_edges(const MeshConnectivity& connectivity, EdgeKind kind) {
  return static_cast<int>(std::count_if(connectivity.edges.begin(), connectivity.edges.end(),
                                        [kind](const MeshEdge& e) { return e.kind == kind; }));
}

int count_zero_area_faces(const MeshConnectivity& connectivity) {
  return static_cast<int>(std::count(connectivity.zero_area.begin(), connectivity.zero_area.end(), 1));
}

} // namespace hullcover

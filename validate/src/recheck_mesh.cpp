#include "recheck_mesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>

namespace hullcover::validate::recheck {

MeshFacts read_mesh_facts(const PreparedMesh& prepared, double bar_half_length) {
  const Mesh& mesh = prepared.mesh;
  MeshFacts facts;
  const int F = static_cast<int>(mesh.triangles.size());
  facts.normal.assign(F, Eigen::Vector3d::Zero());
  facts.has_surface.assign(F, 0);
  // Edges counted again from the triangles: an edge with one face is open.
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (int f = 0; f < F; ++f) {
    const Eigen::Vector3i& t = mesh.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    for (int k = 0; k < 3; ++k) {
      edge_faces[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}].push_back(f);
      facts.longest_edge = std::max(facts.longest_edge, (mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm());
    }
    const Eigen::Vector3d a = mesh.positions[t[0]];
    const Eigen::Vector3d cr = (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a);
    double longest = 0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).norm());
    // Twice the area over the longest edge is the face's height: a face
    // thinner than tol has no reliable normal.
    if (cr.norm() > prepared.face_tolerance(f) * longest) {
      facts.has_surface[f] = 1;
      facts.normal[f] = cr.normalized();
    }
  }
  for (const auto& [e, faces] : edge_faces) {
    facts.edges.push_back(e);
    if (faces.size() == 1 && facts.has_surface[faces[0]]) {
      const Eigen::Vector3d mid = 0.5 * (mesh.positions[e.first] + mesh.positions[e.second]);
      const Eigen::Vector3d& n = facts.normal[faces[0]];
      facts.bars.push_back({mid - bar_half_length * n, mid + bar_half_length * n});
    }
  }
  return facts;
}

CandidateGrids build_candidate_grids(const Mesh& mesh, const MeshFacts& facts, double cell,
                                     const Eigen::Vector3d& origin) {
  CandidateGrids g{{cell, origin, {}}, {cell, origin, {}}, {cell, origin, {}}, {cell, origin, {}}};
  for (int v = 0; v < static_cast<int>(mesh.positions.size()); ++v)
    g.vertices.insert(v, mesh.positions[v], mesh.positions[v]);
  for (int e = 0; e < static_cast<int>(facts.edges.size()); ++e) {
    const auto& p = mesh.positions[facts.edges[e].first];
    const auto& q = mesh.positions[facts.edges[e].second];
    g.edges.insert(e, p.cwiseMin(q), p.cwiseMax(q));
  }
  for (int b = 0; b < static_cast<int>(facts.bars.size()); ++b)
    g.bars.insert(b, facts.bars[b].a.cwiseMin(facts.bars[b].b), facts.bars[b].a.cwiseMax(facts.bars[b].b));
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f) {
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d lo = mesh.positions[t[0]].cwiseMin(mesh.positions[t[1]]).cwiseMin(mesh.positions[t[2]]);
    const Eigen::Vector3d hi = mesh.positions[t[0]].cwiseMax(mesh.positions[t[1]]).cwiseMax(mesh.positions[t[2]]);
    g.faces.insert(f, lo, hi);
  }
  return g;
}

} // namespace hullcover::validate::recheck

#include "probe_rays.h"

#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover::validate::probe {
namespace {

// Points "near a corner" (a face's, or an open edge's end) lie this fraction
// of the way in from it: off the vertex, where neighbouring faces meet and a
// ray's first hit is ill-defined, yet near enough that a hull in front of
// the corner alone is met.
constexpr double kCornerPullIn = 1.0 / 16.0;

// The rim of a double-sided sheet: a manifold edge whose two faces lie back
// to back (opposite normals, the second face's far corner in the first's
// plane). Decided here from the mesh alone, independently of the decomposer.
bool is_sheet_rim(const PreparedMesh& prepared, const MeshEdge& edge) {
  const MeshConnectivity& con = prepared.connectivity;
  if (edge.kind != EdgeKind::manifold) return false;
  const EdgeUse& first = con.edge_uses[edge.first_use];
  const EdgeUse& second = con.edge_uses[edge.first_use + 1];
  if (con.zero_area[first.face] || con.zero_area[second.face]) return false;
  const Mesh& mesh = prepared.mesh;
  const Eigen::Vector3d n = triangle_area_vector(mesh, first.face).normalized();
  if (n.dot(triangle_area_vector(mesh, second.face)) >= 0.0) return false;
  const Eigen::Vector3d& far = mesh.positions[mesh.triangles[second.face][(second.corner + 2) % 3]];
  return std::abs(n.dot(far - mesh.positions[edge.v0])) <= prepared.face_tolerance(first.face);
}

} // namespace

void front_rays_of_face(const PreparedMesh& prepared, double spacing, int f,
                        const std::function<void(const ProbeRay&)>& trace) {
  const Mesh& mesh = prepared.mesh;
  if (prepared.connectivity.zero_area[f]) return;
  const Eigen::Vector3d area = triangle_area_vector(mesh, f);
  const Eigen::Vector3d n = area.normalized();
  const Eigen::Vector3i& t = mesh.triangles[f];
  const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
  const Eigen::Vector3d centroid = (a + b + c) / 3.0;
  trace({centroid, n, f, false});
  for (const Eigen::Vector3d* corner : {&a, &b, &c})
    trace({*corner + kCornerPullIn * (centroid - *corner), n, f, false});
  // A grid of m(m + 1) / 2 points, about one per spacing^2 of area (the
  // area vector's length is twice the area); m = 1 would be the centroid.
  const int m = static_cast<int>(std::ceil(std::sqrt(area.norm()) / spacing));
  if (m < 2) return;
  for (int i = 0; i < m; ++i)
    for (int j = 0; i + j < m; ++j)
      trace({a + (i + 1.0 / 3.0) / m * (b - a) + (j + 1.0 / 3.0) / m * (c - a), n, f, false});
}

void opening_rays_of_edge(const PreparedMesh& prepared, double spacing, int edge,
                          const std::function<void(const ProbeRay&)>& trace) {
  const Mesh& mesh = prepared.mesh;
  const MeshConnectivity& con = prepared.connectivity;
  const double tilt = kOpeningTiltSine, level = std::sqrt(1.0 - tilt * tilt);
  const MeshEdge& e = con.edges[edge];
  if (!(e.kind == EdgeKind::boundary || is_sheet_rim(prepared, e))) return;
  const EdgeUse& use = con.edge_uses[e.first_use];
  if (con.zero_area[use.face]) return;
  const Eigen::Vector3i& t = mesh.triangles[use.face];
  const Eigen::Vector3d& p0 = mesh.positions[t[use.corner]];
  const Eigen::Vector3d& p1 = mesh.positions[t[(use.corner + 1) % 3]];
  const Eigen::Vector3d& other = mesh.positions[t[(use.corner + 2) % 3]];
  const Eigen::Vector3d n = triangle_area_vector(mesh, use.face).normalized();
  Eigen::Vector3d out = (p1 - p0).cross(n).normalized();
  if (out.dot(other - p0) > 0.0) out = -out;
  const Eigen::Vector3d directions[3] = {out, level * out + tilt * n, level * out - tilt * n};
  const int m = std::max(1, static_cast<int>(std::ceil((p1 - p0).norm() / spacing)));
  std::vector<double> along = {kCornerPullIn, 1.0 - kCornerPullIn};
  for (int k = 0; k < m; ++k) along.push_back((k + 0.5) / m);
  for (double s : along)
    for (const Eigen::Vector3d& d : directions) trace({p0 + s * (p1 - p0), d, use.face, true});
}

bool ends_on_backs(const bvh::TriangleWorld& triangles, const Mesh& mesh, const Eigen::Vector3d& start,
                   const Eigen::Vector3d& dir, double first_hit, double tol) {
  std::vector<bvh::RayHit> at_hit;
  if (!triangles.ray_hits({start, dir, first_hit + tol}, at_hit).ok() || at_hit.empty()) return false;
  for (const bvh::RayHit& h : at_hit)
    if (triangle_area_vector(mesh, h.hull).dot(dir) <= 0.0) return false;
  return true;
}

} // namespace hullcover::validate::probe

#include "hullcover/lib/mesh_ray.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace hullcover {

std::optional<MeshRayHit> first_mesh_hit(const SceneIndex& index, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& dir, double min_t, double max_t,
                                         std::vector<int>& scratch) {
  const Mesh& mesh = index.mesh();
  const double tol = index.tol();
  scratch.clear();
  index.face_tree.along_segment(origin + min_t * dir, origin + max_t * dir, tol, scratch);
  std::optional<MeshRayHit> first;
  double first_t = std::numeric_limits<double>::infinity();
  // Each face met: its distance and side; the nearest decide.
  std::vector<std::pair<double, bool>> met;
  for (int f : scratch) {
    const Eigen::Vector3d& n = index.face_normals[f];
    const double rate = n.dot(dir);
    if (n.isZero() || std::abs(rate) * (max_t - min_t) <= tol) continue;  // zero area, or running along it
    const Eigen::Vector3i& tri = mesh.triangles[f];
    const Eigen::Vector3d& a = mesh.positions[tri[0]];
    const double t = n.dot(a - origin) / rate;
    if (t < min_t || t > max_t) continue;
    const Eigen::Vector3d p = origin + t * dir;
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const Eigen::Vector3d& u = mesh.positions[tri[k]];
      const Eigen::Vector3d& v = mesh.positions[tri[(k + 1) % 3]];
      inside = (v - u).cross(n).normalized().dot(p - u) <= tol;
    }
    if (!inside) continue;
    met.emplace_back(t, rate > 0.0);
    if (t < first_t) {
      first_t = t;
      first = MeshRayHit{t, f, false};
    }
  }
  if (first)
    for (const auto& [t, behind] : met)
      if (t <= first_t + tol && behind) first->from_behind = true;
  return first;
}

} // namespace hullcover

#include "hullcover/lib/mesh_ray.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover {

namespace {

// The first hit among faces met on t in [from, to] (nothing when none).
std::optional<MeshRayHit> first_hit_between(const SceneIndex& index, const Eigen::Vector3d& origin,
                                            const Eigen::Vector3d& dir, double from, double to,
                                            std::vector<int>& scratch) {
  const Mesh& mesh = index.mesh();
  const double tol = index.tol();
  scratch.clear();
  index.face_tree.along_segment(origin + from * dir, origin + to * dir, tol, scratch);
  std::optional<MeshRayHit> first;
  // Each face met: its distance and side; the nearest decide.
  std::vector<std::pair<double, bool>> met;
  for (int f : scratch) {
    const Eigen::Vector3d& n = index.face_normals[f];
    const double rate = n.dot(dir);
    if (n.isZero() || std::abs(rate) * (to - from) <= tol) continue;  // zero area, or running along it
    const Eigen::Vector3i& tri = mesh.triangles[f];
    const double t = n.dot(mesh.positions[tri[0]] - origin) / rate;
    if (t < from || t > to) continue;
    const Eigen::Vector3d p = origin + t * dir;
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const Eigen::Vector3d& u = mesh.positions[tri[k]];
      const Eigen::Vector3d& v = mesh.positions[tri[(k + 1) % 3]];
      inside = (v - u).cross(n).normalized().dot(p - u) <= tol;
    }
    if (!inside) continue;
    met.emplace_back(t, rate > 0.0);
    if (!first || t < first->t) first = MeshRayHit{t, f, false};
  }
  if (first)
    for (const auto& [t, behind] : met)
      if (t <= first->t + tol && behind) first->from_behind = true;
  return first;
}

// The first stretch searched, as a fraction of the diagonal; each next one
// is kSearchGrowth times longer: most rays meet the mesh soon, and a long
// segment's tree query visits much of the tree.
constexpr double kFirstSearchRelative = 1.0 / 64.0;
constexpr double kSearchGrowth = 4.0;

} // namespace

std::optional<MeshRayHit> first_mesh_hit(const SceneIndex& index, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& dir, double min_t, double max_t,
                                         std::vector<int>& scratch) {
  const double tol = index.tol();
  double from = min_t;
  double span = kFirstSearchRelative * index.prepared->tolerance.diagonal;
  while (from < max_t) {
    const double to = std::min(max_t, from + span);
    // Overlapping by tol, so faces coincident at a stretch's end all count.
    if (std::optional<MeshRayHit> hit = first_hit_between(index, origin, dir, from, std::min(max_t, to + tol), scratch))
      return hit;
    from = to;
    span *= kSearchGrowth;
  }
  return std::nullopt;
}

} // namespace hullcover

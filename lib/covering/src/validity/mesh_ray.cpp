#include "validity/mesh_ray.h"

#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover {

std::optional<MeshRayHit> first_mesh_hit(const SceneIndex& index, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& dir, double min_t, double max_t,
                                         std::vector<int>& scratch) {
  return first_mesh_hit(index, origin, dir, min_t, max_t, scratch, index.tol());
}

std::optional<MeshRayHit> first_mesh_hit(const SceneIndex& index, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& dir, double min_t, double max_t,
                                         std::vector<int>& scratch, double parallel_tol) {
  (void)scratch;
  const MeshView& mesh = index.mesh();
  const double tol = index.tol();
  const double box_margin = kFaceBoxMarginInTolerances * tol;
  const double length = max_t - min_t;
  if (!(length > 0.0)) return std::nullopt;
  constexpr double kNotMet = std::numeric_limits<double>::infinity();
  // The nearest face met, and the nearest met from the front: they decide.
  std::optional<MeshRayHit> first;
  double nearest_front = kNotMet;
  index.face_tree.nearest_along_segment(origin + min_t * dir, origin + max_t * dir, box_margin, tol / length,
                                        [&](int f) {
    const Eigen::Vector3d& n = index.face_normals[f];
    const double rate = n.dot(dir);
    if (n.isZero() || std::abs(rate) * length <= parallel_tol) return kNotMet; // zero area, or running along it
    const Eigen::Vector3i& tri = mesh.triangles[f];
    const double t = n.dot(mesh.positions[tri[0]] - origin) / rate;
    if (t < min_t || t > max_t + tol) return kNotMet;
    const Eigen::Vector3d p = origin + t * dir;
    // Only inside the face's grown box, where the tree looks: a sharp
    // corner's edges pushed out by tol reach beyond it, and a hit there
    // would count only when the tree happened to visit the face.
    for (int k = 0; k < 3; ++k) {
      const double c0 = mesh.positions[tri[0]][k], c1 = mesh.positions[tri[1]][k], c2 = mesh.positions[tri[2]][k];
      if (p[k] > std::max({c0, c1, c2}) + box_margin || p[k] < std::min({c0, c1, c2}) - box_margin) return kNotMet;
    }
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& u = mesh.positions[tri[k]];
      const Eigen::Vector3d& v = mesh.positions[tri[(k + 1) % 3]];
      if ((v - u).cross(n).normalized().dot(p - u) > tol) return kNotMet;
    }
    if (rate <= 0.0) nearest_front = std::min(nearest_front, t);
    // Equal t (a ray through a shared edge) goes to the lower face index,
    // not to whichever face the walk happened to meet first.
    if (!first || t < first->t || (t == first->t && f < first->face)) first = MeshRayHit{t, f, false};
    return (t - min_t) / length;
  });
  if (first && first->t > max_t) first.reset();
  // Enclosed only when every face met there is met from behind: where a
  // face met from the front coincides with one met from behind (a ceiling
  // under the floor above), the ray ends on the front of a face: open space.
  if (first) first->from_behind = !(nearest_front <= first->t + tol);
  return first;
}

} // namespace hullcover

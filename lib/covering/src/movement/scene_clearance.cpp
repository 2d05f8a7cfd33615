#include "movement/scene_clearance.h"

#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>
#include <cmath>

namespace hullcover::detail {
namespace {

std::vector<Aabb> face_boxes(const Mesh& mesh) {
  std::vector<Aabb> boxes(mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) boxes[f].extend(mesh.positions[mesh.triangles[f][k]]);
  return boxes;
}

} // namespace

SceneClearance::SceneClearance(const Mesh& mesh) : mesh_(mesh), tree_(face_boxes(mesh)) {}

double SceneClearance::to_face(const Eigen::Vector3d& p, int face) const {
  const Eigen::Vector3i& t = mesh_.triangles[face];
  return (closest_point_on_triangle(p, mesh_.positions[t[0]], mesh_.positions[t[1]], mesh_.positions[t[2]]) - p).norm();
}

NearestFace SceneClearance::nearest(const Eigen::Vector3d& p, double limit) const { return nearest(p, limit, -1); }

NearestFace SceneClearance::nearest(const Eigen::Vector3d& p, double limit, int hint) const {
  NearestFace found{limit, -1};
  if (hint >= 0) {
    const double e = to_face(p, hint);
    if (e < limit) {
      found = {e, hint};
      limit = e;
    }
  }
  double best2 = limit * limit;
  bool nearer = false; // than the hint, or found at all without one
  const double d2 = tree_.nearest_to_point(p, limit, [&](int f) {
    const Eigen::Vector3i& t = mesh_.triangles[f];
    const double e2 =
        (closest_point_on_triangle(p, mesh_.positions[t[0]], mesh_.positions[t[1]], mesh_.positions[t[2]]) - p)
            .squaredNorm();
    if (e2 < best2) {
      best2 = e2;
      found.face = f;
      nearer = true;
    }
    return e2;
  });
  if (nearer) found.distance = std::sqrt(d2);
  return found;
}

double SceneClearance::farthest_in_box(const Aabb& box, int face) const {
  double farthest = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? box.max.x() : box.min.x(), (corner & 2) ? box.max.y() : box.min.y(),
                            (corner & 4) ? box.max.z() : box.min.z());
    farthest = std::max(farthest, to_face(p, face));
  }
  return farthest;
}

} // namespace hullcover::detail

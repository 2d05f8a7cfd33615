#include "movement/scene_clearance.h"

#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover::detail {
namespace {

// A triangle whose sharpest angle's sine is below this is a needle: box_within
// then tests the box's corners, without the plane shortcut.
constexpr double kLeastTrustedSine = 1e-6;

std::vector<Aabb> face_boxes(const Mesh& mesh) {
  std::vector<Aabb> boxes(mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) boxes[f].extend(mesh.positions[mesh.triangles[f][k]]);
  return boxes;
}

} // namespace

SceneClearance::SceneClearance(const Mesh& mesh) : mesh_(mesh), boxes_(face_boxes(mesh)), tree_(boxes_) {
  // The computed normal's direction is off by about the rounding over the
  // sine of the triangle's sharpest angle: a needle's is not trusted, its
  // plane left zero (the searches then pass no triangle by its plane, and
  // box_within judges its boxes by their corners alone).
  planes_.resize(mesh.triangles.size(), Eigen::Vector4d::Zero());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Eigen::Vector3i& t = mesh.triangles[f];
    const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double length = n.norm();
    if (length > kLeastTrustedSine * (b - a).norm() * (c - a).norm()) {
      const Eigen::Vector3d u = n / length;
      planes_[f] << u, u.dot(a);
    }
  }
}

double SceneClearance::squared_to_face(const Eigen::Vector3d& p, int face) const {
  const Eigen::Vector3i& t = mesh_.triangles[face];
  return (closest_point_on_triangle(p, mesh_.positions[t[0]], mesh_.positions[t[1]], mesh_.positions[t[2]]) - p)
      .squaredNorm();
}

double SceneClearance::to_face(const Eigen::Vector3d& p, int face) const { return std::sqrt(squared_to_face(p, face)); }

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
    if (const double plane2 = squared_to_plane(p, f); plane2 >= best2) return plane2;
    const double e2 = squared_to_face(p, f);
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

bool SceneClearance::faces_meeting_at_most(const Aabb& box, size_t most, std::vector<int>& out) const {
  out.clear();
  tree_.any_overlapping(box, [&](int f) {
    out.push_back(f);
    return out.size() > most;
  });
  return out.size() <= most;
}

NearestFace SceneClearance::nearest_among(const std::vector<int>& faces, const Eigen::Vector3d& p, double limit,
                                          int hint) const {
  NearestFace found{limit, -1};
  if (hint >= 0) {
    const double e = to_face(p, hint);
    if (e < limit) found = {e, hint};
  }
  double best2 = found.distance * found.distance;
  bool nearer = false;
  for (int f : faces) {
    const Aabb& box = boxes_[f];
    double gap2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double gap = std::max({box.min[k] - p[k], p[k] - box.max[k], 0.0});
      gap2 += gap * gap;
    }
    if (!(gap2 < best2)) continue;
    if (squared_to_plane(p, f) >= best2) continue;
    const double e2 = squared_to_face(p, f);
    if (e2 < best2) {
      best2 = e2;
      found.face = f;
      nearer = true;
    }
  }
  if (nearer) found.distance = std::sqrt(best2);
  return found;
}

template <class Box>
bool SceneClearance::within(const Box& box, int face, double limit) const {
  const Eigen::Vector3i& t = mesh_.triangles[face];
  const Eigen::Vector3d &a = mesh_.positions[t[0]], &b = mesh_.positions[t[1]], &c = mesh_.positions[t[2]];
  const Eigen::Vector3d middle = centre_of(box);
  // The shortcut trusts the triangle's unit normal: none for a needle.
  const Eigen::Vector3d n = planes_[face].head<3>();
  if (n != Eigen::Vector3d::Zero()) {
    // The largest distance from the plane over the box: no corner is
    // nearer to the triangle than to its plane, so when that is not below
    // the limit, some corner is not.
    const double off_plane = std::abs(n.dot(middle - a)) + reach_along_of(box, n);
    if (!(off_plane < limit)) return false;
    // Every corner on the inner side of each edge (the least of a linear
    // function over the box is at a corner): each projects into the
    // triangle, and its distance is its distance from the plane.
    bool projects_in = true;
    const Eigen::Vector3d* corners[3] = {&a, &b, &c};
    for (int k = 0; k < 3 && projects_in; ++k) {
      const Eigen::Vector3d& from = *corners[k];
      const Eigen::Vector3d inward = n.cross(*corners[(k + 1) % 3] - from);
      projects_in = inward.dot(middle - from) - reach_along_of(box, inward) >= 0.0;
    }
    if (projects_in) return true;
  }
  for (int corner = 0; corner < 8; ++corner)
    if (!(to_face(corner_of(box, corner), face) < limit)) return false;
  return true;
}

bool SceneClearance::box_within(const Aabb& box, int face, double limit) const { return within(box, face, limit); }

bool SceneClearance::box_within(const OrientedBox& box, int face, double limit) const {
  return within(box, face, limit);
}

} // namespace hullcover::detail

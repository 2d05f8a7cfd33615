#include "enclosed_space.h"

#include "probe_rays.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"
#include "hullcover/geometry/triangle_distance.h"

#include <algorithm>
#include <limits>

namespace hullcover::validate::probe {
namespace {

// How many units of rounding a column box's far end may be short by: its
// length and end are each a few rounded operations on coordinates no larger
// than the box's.
constexpr double kColumnBoxRoundingUnits = 8.0;

// The box of a face's column within `bounds` (which holds the face): the
// face's box `triangle` swept along its unit normal n from height 0 to the
// height s1 at which it leaves `bounds` on some axis. Every point x + s n
// with x on the face and s >= 0 that lies in `bounds` has s <= s1 (on an
// axis k with n_k > 0, x_k + s n_k <= max_k while x_k >= the face's
// lowest; alike below), so it lies in this box.
Aabb column_box(const Aabb& triangle, const Eigen::Vector3d& n, const Aabb& bounds) {
  double s1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (n[k] > 0.0) s1 = std::min(s1, (bounds.max[k] - triangle.min[k]) / n[k]);
    if (n[k] < 0.0) s1 = std::min(s1, (triangle.max[k] - bounds.min[k]) / -n[k]);
  }
  s1 = std::max(s1, 0.0);
  Aabb column = triangle;
  column.extend(triangle.min + s1 * n);
  column.extend(triangle.max + s1 * n);
  const double magnitude = std::max(bounds.min.cwiseAbs().maxCoeff(), bounds.max.cwiseAbs().maxCoeff()) + s1;
  return grown(column, kColumnBoxRoundingUnits * std::numeric_limits<double>::epsilon() * magnitude);
}

} // namespace

EnclosedSpace::EnclosedSpace(const PreparedMesh& prepared, const bvh::TriangleWorld& triangles)
    : prepared_(prepared), triangles_(triangles) {
  const Mesh& mesh = prepared.mesh;
  bounds_ = bounding_box_of(mesh.positions);
  std::vector<Aabb> column_boxes;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (prepared.connectivity.zero_area[f]) continue;
    const Eigen::Vector3i& t = mesh.triangles[f];
    const std::vector<Eigen::Vector3d> corners = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    const Eigen::Vector3d n = triangle_area_vector(mesh, static_cast<int>(f)).normalized();
    normals_.push_back(n);
    prisms_.push_back({{n, n.dot(corners[0])}, polygon_side_planes(corners, n), 0, static_cast<int>(f)});
    column_boxes.push_back(column_box(bounding_box_of(corners), n, bounds_));
  }
  columns_ = AabbTree(column_boxes);
  // One ray family per direction: faces sharing a normal to the last bit share it.
  const auto lexicographic = [](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
  };
  std::sort(normals_.begin(), normals_.end(), lexicographic);
  normals_.erase(std::unique(normals_.begin(), normals_.end()), normals_.end());
  for (FrontPrism& prism : prisms_)
    prism.normal = static_cast<int>(
        std::lower_bound(normals_.begin(), normals_.end(), prism.front.normal, lexicographic) - normals_.begin());
}

// Whether the front ray along face normal `m` through `p` is open: the
// mesh behind p along -m is the front of a face with that normal (so p is
// on that face's own ray), and ahead the ray escapes or ends on a front.
// False when p is on no such ray.
bool EnclosedSpace::on_open_ray(const Eigen::Vector3d& p, const Eigen::Vector3d& m, double tol) const {
  const double far = std::numeric_limits<double>::max();
  bvh::RayResult behind, ahead;
  if (!triangles_.ray_cast({p, -m, far}, behind).ok() || !behind.hit) return false;
  const Eigen::Vector3d floor = triangle_area_vector(prepared_.mesh, behind.first.hull).normalized();
  if (floor.dot(m) < 1.0 - kUnitNormalSlack) return false;
  if (!triangles_.ray_cast({p, m, far}, ahead).ok() || !ahead.hit) return true;
  return !ends_on_backs(triangles_, prepared_.mesh, p, m, ahead.first.t, tol);
}

// Only a face whose front column holds p can have p on its ray, so only
// their normals are cast (each column grown by tol sideways, so every face
// whose exact column holds p is tried: the definition's rays start on the
// face itself).
//
// Beside the exact column, in that margin, the ray through p is no ray of
// the face: it may slip past a neighbour's edge and escape (pandora, r =
// 0.3: a point 0.0126 behind a wall, under a ceiling, was called free). The
// face's nearest genuine ray is cast instead, when within tol of p.
bool EnclosedSpace::holds(const Eigen::Vector3d& p, double tol) const {
  std::vector<int> tried; // normals whose ray through p itself was cast
  const Aabb near_p = grown(Aabb{p, p}, tol);
  // A column point within tol of p lies in bounds_ only when p's box does;
  // elsewhere the boxes, cut at bounds_, may miss it: every column is tried.
  const bool indexed =
      (near_p.min.array() >= bounds_.min.array()).all() && (near_p.max.array() <= bounds_.max.array()).all();
  if (!indexed) {
    for (size_t i = 0; i < prisms_.size(); ++i)
      if (open_through(p, static_cast<int>(i), tol, tried)) return false;
    return true;
  }
  std::vector<int> candidates;
  columns_.overlapping(near_p, candidates);
  // The walk's order is the tree's; the answer is not (any open ray ends it).
  for (int i : candidates)
    if (open_through(p, i, tol, tried)) return false;
  return true;
}

bool EnclosedSpace::open_through(const Eigen::Vector3d& p, int index, double tol, std::vector<int>& tried) const {
  const FrontPrism& prism = prisms_[index];
  const double height = prism.front.signed_distance(p);
  if (!(height > 0.0)) return false;
  const double beside = deepest_signed_distance(prism.sides, p);
  if (beside > tol) return false;
  if (beside <= 0.0) {
    if (std::find(tried.begin(), tried.end(), prism.normal) != tried.end()) return false;
    tried.push_back(prism.normal);
    return on_open_ray(p, normals_[prism.normal], tol);
  }
  // Within tol of each side plane is not within tol of the column: a
  // sliver's sharp corner reaches far out that way (pandora: 1.39 away).
  const Mesh& mesh = prepared_.mesh;
  const Eigen::Vector3i& t = mesh.triangles[prism.face];
  const Eigen::Vector3d& n = prism.front.normal;
  const Eigen::Vector3d nearest =
      closest_point_on_triangle(p - height * n, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]) +
      height * n;
  if ((nearest - p).norm() > tol) return false;
  return on_open_ray(nearest, normals_[prism.normal], tol);
}

} // namespace hullcover::validate::probe

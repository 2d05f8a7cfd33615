#include "walker_rest.h"

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/triangle_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hullcover::validate::detail {
namespace {

Eigen::Vector3d up_of(const AuditAgent& agent) {
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  up[agent.up_axis] = agent.up_sign;
  return up;
}

} // namespace

// The part of triangle `f` whose height, as up measures it, lies in
// [low, high]: where a walker standing at height `high` may rest.
std::vector<Eigen::Vector3d> face_in_slab(const Mesh& mesh, const AuditAgent& agent, int f, double low, double high) {
  std::vector<Eigen::Vector3d> polygon;
  for (int k = 0; k < 3; ++k) polygon.push_back(mesh.positions[mesh.triangles[f][k]]);
  const Eigen::Vector3d up = up_of(agent);
  polygon = clip_polygon(polygon, Plane{up, high}, 0.0);
  return clip_polygon(polygon, Plane{-up, -low}, 0.0);
}

// The 2D distance, across up, from p to convex `polygon` (face_in_slab);
// infinity when it is empty.
double across_distance(const AuditAgent& agent, const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& p) {
  if (polygon.empty()) return std::numeric_limits<double>::infinity();
  const Eigen::Vector3d up = up_of(agent);
  // Flattened along up: the nearest point of a convex polygon.
  const auto flat = [&](Eigen::Vector3d q) {
    q[agent.up_axis] = 0.0;
    return q;
  };
  const Eigen::Vector3d target = flat(p);
  const size_t n = polygon.size();
  bool left = true, right = true;
  for (size_t i = 0; i < n; ++i) {
    const double side = (flat(polygon[(i + 1) % n]) - flat(polygon[i])).cross(target - flat(polygon[i])).dot(up);
    left &= side >= 0.0;
    right &= side <= 0.0;
  }
  if (left || right) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i)
    best = std::min(best,
                    (closest_point_on_segment(target, flat(polygon[i]), flat(polygon[(i + 1) % n])) - target).norm());
  return best;
}

// The lowest height, as up measures it, of the part of `polygon` (a face
// in its slab, face_in_slab) that lies within r across up of p: the lowest
// point a walker at p may rest on. Infinity when there is none.
// Height is linear across the face, so its least value on that convex part
// is at a corner of the polygon inside the circle, where a side of it
// crosses the circle, or at the circle's point straight downhill of p.
double lowest_rest_near(const AuditAgent& agent, const std::vector<Eigen::Vector3d>& polygon,
                        const Eigen::Vector3d& p) {
  const Eigen::Vector3d up = up_of(agent);
  const double infinity = std::numeric_limits<double>::infinity();
  if (polygon.size() < 3) return infinity;
  const auto across = [&](const Eigen::Vector3d& q) { return Eigen::Vector3d(q - up.dot(q) * up); };
  const double r = agent.radius, r2 = r * r;
  const Eigen::Vector3d centre = across(p);
  double lowest = infinity;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % n];
    if ((across(a) - centre).squaredNorm() <= r2) lowest = std::min(lowest, agent.height_of(a));
    // Where side a-b crosses the circle: |across(a) + t d - centre| = r.
    const Eigen::Vector3d d = across(b) - across(a), e = across(a) - centre;
    const double qa = d.squaredNorm(), qb = 2.0 * d.dot(e), qc = e.squaredNorm() - r2;
    const double disc = qb * qb - 4.0 * qa * qc;
    if (!(qa > 0.0) || disc < 0.0) continue;
    for (double sign : {-1.0, 1.0}) {
      const double t = (-qb + sign * std::sqrt(disc)) / (2.0 * qa);
      if (t >= 0.0 && t <= 1.0) lowest = std::min(lowest, agent.height_of(a + t * (b - a)));
    }
  }
  // Straight downhill of p on the circle, when the polygon holds it: the
  // face's plane falls fastest along its normal's part across up. A level
  // face falls nowhere: its point under p, when the polygon holds it.
  const Eigen::Vector3d normal = (polygon[1] - polygon[0]).cross(polygon[2] - polygon[0]);
  Eigen::Vector3d downhill = across(normal);
  if (std::abs(normal.dot(up)) > 0.0) {
    const double fall = downhill.norm();
    downhill =
        fall > 0.0 ? Eigen::Vector3d((normal.dot(up) > 0.0 ? 1.0 : -1.0) * downhill / fall) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d foot = centre + r * downhill;
    // The face's point over `foot`, and whether it lies in the polygon.
    const double t = normal.dot(polygon[0] - foot) / normal.dot(up);
    const Eigen::Vector3d q = foot + t * up;
    bool left = true, right = true;
    for (size_t i = 0; i < n; ++i) {
      const double side = (polygon[(i + 1) % n] - polygon[i]).cross(q - polygon[i]).dot(normal);
      left &= side >= 0.0;
      right &= side <= 0.0;
    }
    if (left || right) lowest = std::min(lowest, agent.height_of(q));
  }
  return lowest;
}

} // namespace hullcover::validate::detail

#pragma once
/// \file oriented_box.h
/// A box along any three orthonormal axes: what the movement proofs halve
/// (movement_validity.h) when the region they search is slanted, and what
/// the clearance and the reach grid answer for.

#include "hullcover/geometry/aabb.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace hullcover::detail {

/// A box along three orthonormal axes (the columns of `axes`): the proofs
/// of movement_validity.h halve boxes aligned with the region they search,
/// where boxes along the scene's axes would straddle a slanted region's
/// faces down to their smallest size.
struct OrientedBox {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d half = Eigen::Vector3d::Zero(); ///< half extents along the axes, >= 0

  /// Corner `k` (0 to 7): bit j set is the far side along axis j.
  Eigen::Vector3d corner(int k) const {
    Eigen::Vector3d p = centre;
    for (int j = 0; j < 3; ++j) p += ((k >> j) & 1 ? half[j] : -half[j]) * axes.col(j);
    return p;
  }
  /// Half its diagonal: no point of it is farther from its centre.
  double half_diagonal() const { return half.norm(); }
  /// Half the range of w . x over its points x (half its extent along w
  /// when w is unit).
  double reach_along(const Eigen::Vector3d& w) const { return (axes.transpose() * w).cwiseAbs().dot(half); }
  /// Its bounding box along the scene's axes.
  Aabb bounds() const {
    const Eigen::Vector3d reach = axes.cwiseAbs() * half;
    return {centre - reach, centre + reach};
  }
  /// Its two halves across its longest side. They meet to rounding, far
  /// below the tol-wide margins of the tests made on them.
  std::pair<OrientedBox, OrientedBox> halves() const {
    int axis = 0;
    half.maxCoeff(&axis);
    OrientedBox low = *this, high = *this;
    low.half[axis] = high.half[axis] = 0.5 * half[axis];
    low.centre -= low.half[axis] * axes.col(axis);
    high.centre += high.half[axis] * axes.col(axis);
    return {low, high};
  }
  /// Whether a plane parts it from the cube of half side `half_side` about
  /// `cube_centre`: by the 15 axes of two boxes (the cube's, its own and
  /// their crossings), so a cube that does not meet it is always parted.
  bool apart_from_cube(const Eigen::Vector3d& cube_centre, double half_side) const {
    const Eigen::Vector3d between = cube_centre - centre;
    const auto apart_along = [&](const Eigen::Vector3d& w) {
      return std::abs(w.dot(between)) > reach_along(w) + half_side * w.lpNorm<1>();
    };
    for (int a = 0; a < 3; ++a)
      if (apart_along(Eigen::Vector3d::Unit(a)) || apart_along(axes.col(a))) return true;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (apart_along(Eigen::Vector3d::Unit(a).cross(axes.col(b)))) return true;
    return false;
  }
};

/// How far from orthonormal the axes given to box_along may be (their
/// products against the identity), past which it takes the scene's axes:
/// rounding leaves a few units of the last place, which the padding covers.
inline constexpr double kOrthonormalSlack = 64.0 * std::numeric_limits<double>::epsilon();

/// The axes about direction `d`: d itself, and two directions across it;
/// the scene's axes for a `d` of no length (or not finite).
inline Eigen::Matrix3d axes_about(const Eigen::Vector3d& d) {
  if (!(d.norm() > 0.0) || !d.allFinite()) return Eigen::Matrix3d::Identity();
  Eigen::Matrix3d axes;
  axes.col(0) = d.normalized();
  int least = 0;
  axes.col(0).cwiseAbs().minCoeff(&least);
  axes.col(1) = axes.col(0).cross(Eigen::Vector3d::Unit(least)).normalized();
  axes.col(2) = axes.col(0).cross(axes.col(1));
  return axes;
}

/// The box along `axes` (orthonormal columns; the scene's axes if they are
/// not, to kOrthonormalSlack) holding every point within `reach` of the
/// hull of `points` along the axes `grow` marks (1: that axis, 0: not),
/// widened by `pad` on every side: the first box of a region's search. A
/// piece's column is its corners grown along its normal; a segment's
/// ball-swept neighbourhood, its ends grown along all three.
inline OrientedBox box_along(Eigen::Matrix3d axes, const std::vector<Eigen::Vector3d>& points,
                             const Eigen::Vector3d& grow, double reach, double pad) {
  if (!axes.allFinite() ||
      !((axes.transpose() * axes - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= kOrthonormalSlack))
    axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d local = axes.transpose() * p;
    lo = lo.cwiseMin(local);
    hi = hi.cwiseMax(local);
  }
  lo -= reach * grow + Eigen::Vector3d::Constant(pad);
  hi += reach * grow + Eigen::Vector3d::Constant(pad);
  return {axes * (0.5 * (lo + hi)), axes, 0.5 * (hi - lo)};
}

// The two kinds of box the proofs search with, read alike: along the
// scene's axes (the cheaper, for a region that lies along them) or along
// any.
inline Eigen::Vector3d centre_of(const Aabb& box) { return 0.5 * (box.min + box.max); }
inline Eigen::Vector3d centre_of(const OrientedBox& box) { return box.centre; }
inline double half_diagonal_of(const Aabb& box) { return 0.5 * (box.max - box.min).norm(); }
inline double half_diagonal_of(const OrientedBox& box) { return box.half_diagonal(); }
inline const Aabb& bounds_of(const Aabb& box) { return box; }
inline Aabb bounds_of(const OrientedBox& box) { return box.bounds(); }
inline double reach_along_of(const Aabb& box, const Eigen::Vector3d& w) {
  return w.cwiseAbs().dot(0.5 * (box.max - box.min));
}
inline double reach_along_of(const OrientedBox& box, const Eigen::Vector3d& w) { return box.reach_along(w); }
/// Corner `k` (0 to 7): bit j set is the far side along axis j.
inline Eigen::Vector3d corner_of(const Aabb& box, int k) {
  return {(k & 1) ? box.max.x() : box.min.x(), (k & 2) ? box.max.y() : box.min.y(),
          (k & 4) ? box.max.z() : box.min.z()};
}
inline Eigen::Vector3d corner_of(const OrientedBox& box, int k) { return box.corner(k); }
/// The halves across the longest side.
inline std::pair<Aabb, Aabb> halves_of(const Aabb& box) {
  int axis = 0;
  (box.max - box.min).maxCoeff(&axis);
  const double middle = 0.5 * (box.min[axis] + box.max[axis]);
  Aabb low = box, high = box;
  low.max[axis] = middle;
  high.min[axis] = middle;
  return {low, high};
}
inline std::pair<OrientedBox, OrientedBox> halves_of(const OrientedBox& box) { return box.halves(); }

} // namespace hullcover::detail

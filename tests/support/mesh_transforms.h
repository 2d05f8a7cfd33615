#pragma once
// The transforms of the metamorphic suite: a scene moved, turned, scaled or
// mirrored in double precision, which must decompose to the same covering
// (up to rounding) and audit clean.

#include "hullcover/geometry/mesh.h"

#include <Eigen/Geometry>

#include <random>
#include <string>
#include <vector>

namespace hullcover::test {

/// A hull count may differ by this fraction of the untransformed one: the
/// greedy merging is order-sensitive, and a transform's rounding reorders
/// candidates of equal compactness (repeated or symmetric geometry).
inline constexpr double kHullCountSpread = 0.02;

/// Far from the origin the spread is wider. At 1e7 a double position
/// carries 1e7 x 2^-53 = 1.1e-9 units of rounding: hull facet normals that
/// were exactly perpendicular to a face's front direction tilt by ~1e-9, so
/// a front-space sweep that grazed a hull's interior (the hull shrunk by
/// tol) now enters it at the tolerance's very boundary, or no longer does.
/// Each such decision is right either way (every transformed covering audits
/// clean), but the greedy merging that follows takes another path:
/// collision-world needs 407 hulls at the origin, 405 at 1e5 and 391 at 1e7
/// (-3.9%).
inline constexpr double kFarHullCountSpread = 0.05;

/// One transform of the suite, with the name a failure prints and the
/// spread of hull counts it may cause.
struct MeshTransform {
  std::string name;
  Eigen::Affine3d map;
  double hull_count_spread = kHullCountSpread;
};

/// `mesh` under `map`. A map that mirrors (negative determinant) has its
/// triangles' winding flipped too, so fronts stay fronts. The rounding error
/// the positions carried in scales with the map's scale: moving and turning
/// keep it, scaling by s multiplies it by s.
inline Mesh transformed(const Mesh& mesh, const Eigen::Affine3d& map) {
  Mesh out = mesh;
  for (Eigen::Vector3d& p : out.positions) p = map * p;
  const double determinant = map.linear().determinant();
  if (determinant < 0.0)
    for (Eigen::Vector3i& t : out.triangles) std::swap(t[1], t[2]);
  out.coordinate_error = mesh.coordinate_error * std::cbrt(std::abs(determinant));
  out.coordinate_relative_error = 0.0; // it bounded the magnitudes before the move
  return out;
}

/// A rotation drawn uniformly (a normalised Gaussian quaternion).
inline Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  return Eigen::Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized().toRotationMatrix();
}

/// The transforms: translation by 1e5 and 1e7 along the diagonal,
/// two random rotations (fixed seed), uniform scaling by 1e-3 and 1e3, and
/// a mirror in x.
inline std::vector<MeshTransform> metamorphic_transforms() {
  std::mt19937 rng(20261124);
  std::vector<MeshTransform> transforms;
  for (const double offset : {1e5, 1e7}) {
    Eigen::Affine3d move = Eigen::Affine3d::Identity();
    move.translation() = Eigen::Vector3d::Constant(offset);
    transforms.push_back(
        {"translated by " + std::to_string(offset), move, offset > 1e5 ? kFarHullCountSpread : kHullCountSpread});
  }
  for (int k = 0; k < 2; ++k) {
    Eigen::Affine3d turn = Eigen::Affine3d::Identity();
    turn.linear() = random_rotation(rng);
    transforms.push_back({"random rotation " + std::to_string(k), turn});
  }
  for (const double scale : {1e-3, 1e3}) {
    Eigen::Affine3d grow = Eigen::Affine3d::Identity();
    grow.linear() *= scale;
    transforms.push_back({"scaled by " + std::to_string(scale), grow});
  }
  Eigen::Affine3d mirror = Eigen::Affine3d::Identity();
  mirror.linear()(0, 0) = -1.0;
  transforms.push_back({"mirrored in x", mirror});
  return transforms;
}

} // namespace hullcover::test

#pragma once
/// \file free_space_sweep.h
/// The pieces of free space the exact conditions (exact_conditions.h) and
/// their witness rays (witness_rays.h) judge: the shapes both read, kept
/// apart so neither includes the other (a hull's interior is
/// hull_interior, convex_polytope.h).

#include "hullcover/geometry/convex_polytope.h"
#include "hullcover/geometry/tolerances.h"

#include <vector>

namespace hullcover {

/// A piece of free space: a face's triangle, or an open edge, swept along
/// unit `direction` from t = 0 to the reach. It is the inner side of
/// `planes`, each shrunk by its `insets` entry (negative: grown).
struct FreeSpaceSweep {
  std::vector<Plane> planes;
  std::vector<double> insets;
  Plane start; ///< the base's plane facing back: signed distance = -t
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> base;    ///< the face or edge swept
  std::vector<Eigen::Vector3d> corners; ///< the base at t = 0 and at the reach
  double reach = 0.0;                   ///< scene units, from the base (the free-space reach plus the rays' stand-off)
  /// When the hull judged belongs to the same place (hullcover/mesh/
  /// tolerance.h) as the face swept, that place, else -1: only faces of
  /// that place then enclose the rays. A ray that runs out of its map into
  /// the back of another map's outer wall is enclosed in the world but open
  /// in the map alone; judged open against the map's own hulls, they are
  /// valid in both. Against another map's hulls the world's rule holds (the
  /// ray does not exist in that map alone).
  int place = -1;
};

/// The front space of triangle `corners` (unit front `normal`); it starts
/// `tol` behind the face, so faces coincident with it are met.
FreeSpaceSweep front_space_sweep(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal,
                                 double reach, double tol);
/// The same, into `sweep` (its storage reused: checks build one for every
/// piece of free space a hull meets).
void front_space_sweep(const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& normal, double reach,
                       double tol, FreeSpaceSweep& sweep);
/// The opening beyond the edge p0-p1 of a face with unit normal
/// `face_normal`, whose far corner is `inner` (the sweep runs away from it),
/// in the plane through the edge normal to `face_normal`.
FreeSpaceSweep opening_sweep(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                             const Eigen::Vector3d& face_normal, double reach, double tol);
/// The same, into `sweep` (its storage reused).
void opening_sweep(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                   const Eigen::Vector3d& face_normal, double reach, double tol, FreeSpaceSweep& sweep);
/// How many fans an opening has (docs/definitions-and-proofs.md): in the face's plane, then
/// tilted by kOpeningTiltSine to its front and to its back.
inline constexpr int kOpeningFans = 3;
/// Fan `fan` (0 <= fan < kOpeningFans) of the opening beyond the edge p0-p1
/// (as opening_sweep).
FreeSpaceSweep opening_fan(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                           const Eigen::Vector3d& face_normal, int fan, double reach, double tol);
/// The same, into `sweep` (its storage reused).
void opening_fan(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& inner,
                 const Eigen::Vector3d& face_normal, int fan, double reach, double tol, FreeSpaceSweep& sweep);

} // namespace hullcover

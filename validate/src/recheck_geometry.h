#pragma once
/// \file recheck_geometry.h
/// The re-check's own geometry (private to validate): hulls as it sees them,
/// with planes fitted to the facet polygons (Newell's method) rather than
/// taken from the decomposer; the depth and segment tests on them; and the
/// uniform grid that gives each hull its candidates in place of the
/// decomposer's trees. Nothing here may come from lib/covering: a bug there
/// must not hide here too.

#include "hullcover/validate/hull_under_check.h"

#include <Eigen/Core>

#include <unordered_map>
#include <vector>

namespace hullcover::validate::recheck {

/// The inner side of a plane: n.x <= d.
struct HalfSpace {
  Eigen::Vector3d n; ///< unit, outward
  double d;
};

/// A hull as the re-check sees it.
struct CheckedHull {
  std::vector<HalfSpace> facets; ///< solid: one per facet; flat: front, back, then the sides
  bool flat = false;
  HalfSpace front;              ///< flat: the polygon's plane
  std::vector<HalfSpace> sides; ///< flat: in-plane edge half-spaces, outward
  Eigen::Vector3d lo, hi;       ///< the vertices' bounding box
  /// The tolerance of tests on this hull, scene units: the scene's at its
  /// box (hullcover/mesh/tolerance.h, PlaceTolerance).
  double tol = 0.0;
};

/// The planes of `hull`'s facets, fitted again from their corners; for a
/// flat hull also the sides, so a point is on it only when on its plane
/// AND within its polygon.
CheckedHull make_checked(const HullUnderCheck& hull);

/// How deep `p` lies inside all of `hs`: the smallest distance to a plane,
/// positive inside. Deeper than tol is strictly inside.
double depth_inside(const std::vector<HalfSpace>& hs, const Eigen::Vector3d& p);

/// True when some sub-interval of segment p-q lies deeper than `tol` inside
/// all of `hs`.
bool segment_deeper_than(const std::vector<HalfSpace>& hs, const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                         double tol);

/// True when segment p-q crosses flat hull `c`'s plane (not running along
/// it) at a point deeper than `tol` inside the polygon's sides.
bool segment_crosses_flat(const CheckedHull& c, const Eigen::Vector3d& p, const Eigen::Vector3d& q, double tol);

/// A uniform grid of ids by bounding box: each id is listed in every cell
/// its box touches.
struct CandidateGrid {
  double cell;
  Eigen::Vector3d origin;
  std::unordered_map<long long, std::vector<int>> cells;

  /// The cell holding `p`.
  Eigen::Vector3i at(const Eigen::Vector3d& p) const;
  void insert(int id, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
  /// The ids whose boxes share a cell with box lo-hi, ascending, each once.
  std::vector<int> query(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const;
};

} // namespace hullcover::validate::recheck

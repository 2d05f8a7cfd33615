#pragma once
// Cutting a region of a sweep's rays into pieces that one face decides:
// what the exact judges of witness_rays.h (whether a hull loses space) and
// first_hit_bound.h (how far rays run) are both made of. Along a sweep's
// rays, distances to a point or to a face's plane are affine over a region,
// so a piece's corners bound them and a piece is cut where one changes
// sign. Internal to the decomposer.

#include "validity/free_space_sweep.h"

#include "hullcover/geometry/convex_polytope.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace hullcover::detail {

/// How many pieces one region of a sweep may be cut into before it counts as losing
/// space: a bound on the work, where giving up is conservative.
inline constexpr int kMaxJudgedPieces = 1024;

/// A piece of a region no wider than this many tolerances is a sliver of
/// rounding: passed over, as it holds no ray apart from its neighbours'.
inline constexpr double kNegligibleWidthInTolerances = 1e-6;

/// The outward planes of the column that convex polygon `outline` sweeps
/// along unit `dir`; edges running along dir (their sine with it within
/// kParallelSine) bound nothing and give no plane.
std::vector<Plane> column_planes(const std::vector<Eigen::Vector3d>& outline, const Eigen::Vector3d& dir);

/// `polygon` clipped to the column of `outline` along `dir` (the planes of
/// column_planes, no inset), written to `out`; `spare` is reused storage.
/// Neither may be `polygon` or `outline`.
/// The same polygon as clip_polygon_to_planes with column_planes, made
/// without building the plane list (on the exact checks' hot path).
void clip_to_column(const std::vector<Eigen::Vector3d>& polygon, const std::vector<Eigen::Vector3d>& outline,
                    const Eigen::Vector3d& dir, std::vector<Eigen::Vector3d>& out, std::vector<Eigen::Vector3d>& spare);

/// True for a piece no wider than kNegligibleWidthInTolerances x `tol`
/// (scene units; its least width over its edges' directions), or with
/// fewer than 3 corners or no area: a sliver of rounding, which cutting
/// would only shave again. Far below anything a ray could be aimed at: an
/// opening's strip alone is 2 tol wide. Corners are finite (a NaN corner
/// makes the area NaN, and the piece counts as negligible).
bool negligible(const std::vector<Eigen::Vector3d>& polygon, double tol);

/// `region` cut along the shadow (the column along `dir`) of a triangle:
/// the part inside it and the parts beside each of its sides (no negligible
/// pieces). The triangle is grown by `tol` in its plane, as rays meet it
/// (mesh_ray.h).
struct ShadowSplit {
  std::vector<Eigen::Vector3d> inside;
  std::vector<std::vector<Eigen::Vector3d>> beside;
  /// Storage the cutting reuses: a split kept from call to call (as the
  /// judges keep theirs) allocates only the pieces it hands out.
  std::vector<Eigen::Vector3d> cut, off_cut;
};
ShadowSplit split_by_shadow(const std::vector<Eigen::Vector3d>& region, const std::vector<Eigen::Vector3d>& triangle,
                            const Eigen::Vector3d& dir, double tol);

/// The shadow of a triangle as split_by_shadow cuts along it: the outward
/// planes of its column along a direction, the triangle grown by tol in
/// its plane and kept inside its grown box (as rays meet it).
struct ShadowColumn {
  /// Three sides and two planes per axis of the box, at most: held in
  /// place, as a column is made for every face near every judged piece.
  static constexpr int kMaxSides = 9;
  /// The first side_count hold the column's outward planes.
  std::array<Plane, kMaxSides> side_planes;
  int side_count = 0;
  /// The planes, for range-for.
  const Plane* begin() const { return side_planes.data(); }
  const Plane* end() const { return side_planes.data() + side_count; }
  /// True when one side has every corner of `region` strictly beyond it:
  /// then no part of the region lies inside the shadow (split_by_shadow's
  /// `inside` is empty), found without cutting anything.
  bool misses(const std::vector<Eigen::Vector3d>& region) const;
};
/// `triangle` has exactly three corners.
ShadowColumn shadow_column(const std::vector<Eigen::Vector3d>& triangle, const Eigen::Vector3d& dir, double tol);
/// split_by_shadow along a column made once.
ShadowSplit split_by_shadow(const std::vector<Eigen::Vector3d>& region, const ShadowColumn& column, double tol);
/// The same, into `split` (its old contents dropped, its storage reused);
/// `region` must not be one of split's own vectors.
void split_by_shadow(const std::vector<Eigen::Vector3d>& region, const ShadowColumn& column, double tol,
                     ShadowSplit& split);

/// The base of the sweep's ray through `point`: where it crosses the
/// sweep's start.
Eigen::Vector3d ray_base(const FreeSpaceSweep& sweep, const Eigen::Vector3d& point);

/// An affine function of a point: value(p) = gradient.p + constant.
struct Affine {
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
  double constant = 0.0;
  double operator()(const Eigen::Vector3d& p) const { return gradient.dot(p) + constant; }
  Affine operator-(const Affine& other) const { return {gradient - other.gradient, constant - other.constant}; }
  /// Where it is zero, facing where it is negative (signed distance > 0
  /// there); its gradient must not be zero.
  Plane zero_plane() const {
    const double norm = gradient.norm();
    return {-gradient / norm, constant / norm};
  }
};

/// Its lowest and highest value over a polygon (at its corners).
std::pair<double, double> range_over(const Affine& f, const std::vector<Eigen::Vector3d>& polygon);

/// Where `margin` is zero across `piece`, when cutting there leaves a piece
/// with area on its negative side (nothing when it is negative only by
/// rounding: a piece of no area holds no ray apart from its neighbours').
std::optional<Plane> splitting_cut(const std::vector<Eigen::Vector3d>& piece, const Affine& margin, double tol);

/// Along the sweep's ray through a point: the distance from the ray's base
/// to the point (where the ray enters the interior, for points on an entry
/// facet)...
Affine distance_to_point(const FreeSpaceSweep& sweep);

/// ... and to the plane `face` (not parallel to the rays).
Affine distance_to_plane(const FreeSpaceSweep& sweep, const Plane& face);

} // namespace hullcover::detail

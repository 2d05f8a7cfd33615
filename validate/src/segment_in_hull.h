#pragma once
// The exact test behind the accessible-space probe: which stretch of a free
// ray segment lies deeper than tol inside one hull, and how deep its deepest
// point is. No sampling along the segment: a hull between two samples, or
// beyond any distance, is still seen.

#include "hullcover/geometry/convex_polytope.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace hullcover::validate::probe {

/// The stretch of a segment strictly inside a hull.
struct InsideStretch {
  double from = 0.0, to = 0.0; ///< distances along the segment (scene units), from < to
  double depth = 0.0;          ///< the deepest point's depth inside the hull (scene units, > tol)
  double deepest_at = 0.0;     ///< where along the segment that point lies
};

/// The part of the segment start + t dir, t in [0, length] (`dir` unit),
/// lying deeper than `tol` behind every plane of `planes` (Cyrus-Beck
/// against the planes each moved inward by tol), with the deepest point
/// over it: the maximum over t of min_i(offset_i - n_i . x(t)), measured
/// from the planes themselves (depth into the hull as it is). Nothing when
/// no point is deeper than tol; so a flat hull (front and back plane
/// coincide) never has such a stretch.
std::optional<InsideStretch> stretch_inside(const std::vector<Plane>& planes, const Eigen::Vector3d& start,
                                            const Eigen::Vector3d& dir, double length, double tol);

} // namespace hullcover::validate::probe

#pragma once
// A polygon face of a scene file cut into triangles that cover exactly the
// polygon (internal to the mesh module): a convex polygon as a fan from its
// first corner, a concave one by ear clipping in its own plane.

#include <Eigen/Core>

#include <vector>

namespace hullcover::detail {

/// Most corners of a concave polygon the ear clipping takes (its cost grows
/// with the cube of the corners at worst); a convex polygon may have any
/// number.
inline constexpr int kMostConcaveCorners = 128;

/// A corner within this fraction of the polygon's extent of the line
/// through its neighbours is straight (its turn's sign is rounding, such
/// as collinear points written with few digits): a tenth of the default
/// tolerance's fraction of a diagonal, so a fan across such a corner moves
/// the surface by less than any default tolerance sees.
inline constexpr double kStraightDeviationRelative = 1e-6;

/// What triangulate_polygon did.
enum class Triangulation {
  fan,      ///< convex (or without area): a fan from corner 0
  ears,     ///< concave: ear clipping
  too_large ///< concave with more than kMostConcaveCorners corners: nothing written
};

/// Triangles (corner numbers, counter-clockwise as the polygon winds) that
/// cover the polygon `corners` (in order, at least 3) and nothing outside
/// it, appended to `out`. A polygon with no area (collinear corners) gets
/// the fan, whose triangles have none either; one that turns one way only
/// and winds once is convex (a fan); any other (concave, or self-crossing
/// like a pentagram) gets ears while any can be found, then a fan of the
/// rest.
Triangulation triangulate_polygon(const std::vector<Eigen::Vector3d>& corners, std::vector<Eigen::Vector3i>& out);

} // namespace hullcover::detail

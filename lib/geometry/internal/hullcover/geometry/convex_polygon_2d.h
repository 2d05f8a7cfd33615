#pragma once
/// \file convex_polygon_2d.h
/// Area and overlap of convex polygons in a plane's 2D frame: enough to
/// tell whether a flat hull spans area its faces leave open.

#include <Eigen/Core>

#include <vector>

namespace hullcover {

/// Signed area of a polygon (positive when counter-clockwise), square
/// units; 0 for fewer than 3 corners.
double polygon_area(const std::vector<Eigen::Vector2d>& corners);

/// Length of a closed polygon's boundary; 0 for fewer than 2 corners.
double polygon_perimeter(const std::vector<Eigen::Vector2d>& corners);

/// The intersection of two convex counter-clockwise polygons (each clipped
/// by the other's edges): convex, counter-clockwise, possibly empty or
/// degenerate (fewer than 3 corners).
std::vector<Eigen::Vector2d> intersect_convex_polygons(const std::vector<Eigen::Vector2d>& a,
                                                       const std::vector<Eigen::Vector2d>& b);

/// `piece` minus `cutter` (both convex, counter-clockwise): disjoint convex
/// pieces, one per edge of the cutter the piece reaches beyond, each
/// counter-clockwise. Empty when the cutter covers the piece; the piece
/// itself, whole, when the two share no interior (an edge of either has the
/// other on its outer side) or the cutter has fewer than 3 corners.
std::vector<std::vector<Eigen::Vector2d>> subtract_convex_polygon(const std::vector<Eigen::Vector2d>& piece,
                                                                  const std::vector<Eigen::Vector2d>& cutter);

/// Whether subtract_convex_polygon gives `piece` back whole: it has 3 or
/// more corners and the cutter fewer, or an edge of either has the other on
/// its outer side (on the line counts as outside).
bool convex_polygons_apart(const std::vector<Eigen::Vector2d>& piece, const std::vector<Eigen::Vector2d>& cutter);

/// Storage subtract_overlapping_convex_polygon reuses from call to call; it
/// carries no meaning between calls.
struct PolygonSubtractionStorage {
  std::vector<Eigen::Vector2d> rest, inside;
};

/// subtract_convex_polygon for a piece and cutter that are not
/// convex_polygons_apart, its pieces appended to `pieces` (for a caller
/// subtracting many cutters, which keeps the pieces' storage): the same
/// pieces, in the same order.
void subtract_overlapping_convex_polygon(const std::vector<Eigen::Vector2d>& piece,
                                         const std::vector<Eigen::Vector2d>& cutter,
                                         std::vector<std::vector<Eigen::Vector2d>>& pieces,
                                         PolygonSubtractionStorage& storage);

} // namespace hullcover

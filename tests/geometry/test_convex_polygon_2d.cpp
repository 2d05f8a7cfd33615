#include "hullcover/geometry/convex_polygon_2d.h"

#include <gtest/gtest.h>

namespace hullcover {
namespace {

using P = std::vector<Eigen::Vector2d>;

P square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

TEST(ConvexPolygon2d, AreaIsSignedByWindingAndPerimeterIsTheBoundary) {
  const P s = square(0, 0, 2);
  EXPECT_DOUBLE_EQ(polygon_area(s), 4.0);
  EXPECT_DOUBLE_EQ(polygon_area(P(s.rbegin(), s.rend())), -4.0);
  EXPECT_DOUBLE_EQ(polygon_perimeter(s), 8.0);
  EXPECT_DOUBLE_EQ(polygon_area(P{{0, 0}, {1, 1}}), 0.0);
}

TEST(ConvexPolygon2d, IntersectionOfOverlappingSquaresIsTheirCommonSquare) {
  EXPECT_NEAR(polygon_area(intersect_convex_polygons(square(0, 0, 2), square(1, 1, 2))), 1.0, 1e-12);
  EXPECT_LT(intersect_convex_polygons(square(0, 0, 1), square(3, 3, 1)).size(), 3u);
}

// The pieces are disjoint and lie outside the cutter: their areas add up to
// the piece's less the overlap, and no piece's centre is inside the cutter.
TEST(ConvexPolygon2d, SubtractionLeavesDisjointPiecesOutsideTheCutter) {
  const P piece = square(0, 0, 4), cutter = square(1, 1, 2);
  const auto pieces = subtract_convex_polygon(piece, cutter);
  double area = 0.0;
  for (const P& p : pieces) {
    EXPECT_GT(polygon_area(p), 0.0);
    area += polygon_area(p);
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& q : p) centre += q / static_cast<double>(p.size());
    EXPECT_FALSE(centre.x() > 1 && centre.x() < 3 && centre.y() > 1 && centre.y() < 3);
  }
  EXPECT_NEAR(area, 16.0 - 4.0, 1e-12);
  EXPECT_TRUE(subtract_convex_polygon(square(1, 1, 1), square(0, 0, 4)).empty());
  const auto apart = subtract_convex_polygon(square(0, 0, 1), square(5, 5, 1));
  ASSERT_EQ(apart.size(), 1u);
  EXPECT_NEAR(polygon_area(apart[0]), 1.0, 1e-12);
}

} // namespace
} // namespace hullcover

#include "hullcover/geometry/convex_polygon_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// A piece that straddles the lines of the cutter's first edges but lies
// beyond a later one comes back whole, not cut along lines that do not
// separate it from the cutter; so does one whose own edge separates them,
// and one merely touching the cutter along an edge.
TEST(ConvexPolygon2d, APieceApartFromTheCutterComesBackWhole) {
  const P cutter = square(0, 0, 1);
  const P beside = square(-2, 3, 5); // across the lines x = 0 and x = 1, above y = 1
  const auto above = subtract_convex_polygon(beside, cutter);
  ASSERT_EQ(above.size(), 1u);
  EXPECT_EQ(above[0], beside);
  // Separated only by an edge of the piece: a triangle whose edge on
  // x + y = 2.05 passes the square's corner (1, 1), reaching past the
  // lines of all four of the square's edges.
  const P leaning = {{2.05, 0.0}, {3.0, 3.0}, {0.0, 2.05}};
  const auto leaning_pieces = subtract_convex_polygon(leaning, cutter);
  ASSERT_EQ(leaning_pieces.size(), 1u);
  EXPECT_EQ(leaning_pieces[0], leaning);
  const auto touching = subtract_convex_polygon(square(1, 0, 1), cutter);
  ASSERT_EQ(touching.size(), 1u);
  EXPECT_NEAR(polygon_area(touching[0]), 1.0, 1e-12);
  // Overlapping, it is still cut: the pieces cover the piece less the cutter.
  const auto overlapping = subtract_convex_polygon(square(0.5, 0.5, 1), cutter);
  double area = 0.0;
  for (const P& p : overlapping) area += polygon_area(p);
  EXPECT_NEAR(area, 0.75, 1e-12);
}

// A random convex polygon: corners on a circle at increasing angles.
P random_convex(std::mt19937& rng) {
  std::uniform_real_distribution<double> centre(-2.0, 2.0), radius(0.2, 2.0), gap(0.3, 2.0);
  std::uniform_int_distribution<int> corners(3, 7);
  const Eigen::Vector2d c(centre(rng), centre(rng));
  const double r = radius(rng);
  P out;
  double angle = 0.0;
  for (int i = 0, n = corners(rng); i < n && angle < 6.0; ++i, angle += gap(rng))
    out.push_back(c + r * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  return out;
}

// The coverage check carries pieces apart from a cutter whole and subtracts
// the others with reused storage: together that is subtract_convex_polygon,
// bit for bit, piece for piece.
TEST(ConvexPolygon2d, ApartAndOverlappingSubtractionAreTheWholeSubtraction) {
  std::mt19937 rng(47);
  PolygonSubtractionStorage storage;
  std::vector<P> pieces;
  int apart = 0, overlapping = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const P piece = random_convex(rng), cutter = random_convex(rng);
    const std::vector<P> whole = subtract_convex_polygon(piece, cutter);
    if (convex_polygons_apart(piece, cutter)) {
      ++apart;
      ASSERT_EQ(whole, std::vector<P>{piece}) << "trial " << trial;
      continue;
    }
    ++overlapping;
    pieces.assign(1, P{{9, 9}}); // appended to, never cleared
    subtract_overlapping_convex_polygon(piece, cutter, pieces, storage);
    ASSERT_EQ(std::vector<P>(pieces.begin() + 1, pieces.end()), whole) << "trial " << trial;
  }
  EXPECT_GT(apart, 200);
  EXPECT_GT(overlapping, 200);
}

} // namespace
} // namespace hullcover

#include "hullcover/geometry/planar_hull.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

namespace hullcover {
namespace {

TEST(ConvexHull2d, DropsInteriorAndNearCollinearPoints) {
  const std::vector<Eigen::Vector2d> points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 1e-9}, {1, 0}, {2, 1}};
  const std::vector<int> hull = convex_hull_2d(points, 1e-6);
  ASSERT_EQ(hull.size(), 4u);
  // Counter-clockwise: every consecutive triple turns left.
  for (size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d a = points[hull[i]], b = points[hull[(i + 1) % 4]], c = points[hull[(i + 2) % 4]];
    EXPECT_GT((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x(), 0.0);
  }
}

TEST(ConvexHull2d, CollinearPointsGiveNoPolygon) {
  EXPECT_LT(convex_hull_2d({{0, 0}, {1, 1e-9}, {2, 0}, {3, -1e-9}}, 1e-6).size(), 3u);
  EXPECT_LT(convex_hull_2d({{1, 1}, {1, 1}, {1, 1}}, 1e-6).size(), 3u);
  EXPECT_TRUE(convex_hull_2d({}, 1e-6).empty());
  EXPECT_TRUE(convex_hull_2d({{1, 1}, {2, 2}}, 1e-6).empty());
}

// Property: every input point is inside (or within tol of) the hull.
TEST(ConvexHull2d, ContainsEveryPointOfRandomClouds) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int round = 0; round < 50; ++round) {
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < 40; ++i) points.emplace_back(1e4 + g(rng), -3e3 + g(rng));
    const double tol = 1e-7;
    const std::vector<int> hull = convex_hull_2d(points, tol);
    ASSERT_GE(hull.size(), 3u);
    for (const Eigen::Vector2d& p : points)
      for (size_t i = 0; i < hull.size(); ++i) {
        const Eigen::Vector2d a = points[hull[i]], b = points[hull[(i + 1) % hull.size()]];
        const double cross = (b - a).x() * (p - a).y() - (b - a).y() * (p - a).x();
        EXPECT_GE(cross / (b - a).norm(), -tol) << "round " << round;
      }
  }
}

TEST(FlatPolygon, IsProjectedOntoItsPlaneWithOutwardSides) {
  std::vector<Eigen::Vector3d> positions = {{0, 0, 0}, {2, 0, 1e-7}, {2, 2, 0}, {0, 2, -1e-7}, {1, 1, 0}};
  const FlatPolygon p = make_flat_polygon(positions, {0, 1, 2, 3, 4}, Eigen::Vector3d::UnitZ(), 1e-6);
  ASSERT_EQ(p.corners.size(), 4u);
  for (const Eigen::Vector3d& c : p.corners) EXPECT_NEAR(p.plane.signed_distance(c), 0.0, 1e-15);
  ASSERT_EQ(p.sides.size(), 4u);
  for (const Plane& side : p.sides) EXPECT_LT(side.signed_distance({1, 1, 0}), -0.5);
}

// Coverage (a case from recast-dungeon): the plane runs through the middle of
// the points' slab, so a lone raised point is half the slab off it, not
// three quarters as through their mean.
TEST(FlatPolygon, PlaneRunsThroughTheMiddleOfTheSlab) {
  const double h = 1e-6;
  std::vector<Eigen::Vector3d> positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, h}};
  const FlatPolygon p = make_flat_polygon(positions, {0, 1, 2, 3, 4}, Eigen::Vector3d::UnitZ(), 1e-9);
  ASSERT_EQ(p.corners.size(), 4u);
  for (const Eigen::Vector3d& q : positions) EXPECT_LE(std::abs(p.plane.signed_distance(q)), 0.5 * h * (1 + 1e-9));
}

} // namespace
} // namespace hullcover

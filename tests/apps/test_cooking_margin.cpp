// The corners an export keeps clear for an engine's hull builder
// (apps/src/export/cooking_margin.h): a corner at the tip of a knife-thin
// wedge, which Jolt's builder drops and then refuses, is pushed out by at
// most twice the engine's hull tolerance; the hull still holds every point
// it held; corners a builder may drop harmlessly are left alone.

#include "export/cooking_margin.h"

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/convex_polytope.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace {

using hullcover::ConvexHullBuilder;
using hullcover::ConvexPolytope;
using hullcover::app::corner_margin;
using hullcover::app::repair_cooking_margins;

constexpr double kHullTolerance = 0.001; // Jolt's default, metres
constexpr double kRounding = 1e-9;

ConvexPolytope hull_of(const std::vector<Eigen::Vector3d>& points) {
  ConvexHullBuilder builder;
  auto hull = builder.build(points);
  EXPECT_TRUE(hull.ok());
  return hull.value();
}

// Hull 3050 of recast-dungeon's covering: a floor slab whose bottom rises
// to its top along its far edge (a wedge of a third of a degree), with a
// top corner, (22.84, 14.95, -88.82), 8.8 mm beyond the edge between its
// neighbours but 0.00005 in front of the bottom's plane. Jolt 5.5.1 refused
// it: "point 3 had an error of 0.0088".
std::vector<Eigen::Vector3d> knife_wedge() {
  return {{23.968902588, 14.925689697, -84.537361145}, {23.56757164, 14.950710297, -88.617889404},
          {23.844284058, 14.950710297, -88.813461304}, {18.301856995, 14.937114716, -86.137916565},
          {22.841461182, 14.950710297, -88.823219299}, {16.841459274, 14.950710297, -88.820114136},
          {16.585369110, 14.950710297, -88.610694885}};
}
const Eigen::Vector3d kTip(22.841461182, 14.950710297, -88.823219299);

double deepest_outside(const ConvexPolytope& hull, const Eigen::Vector3d& p) {
  double worst = -1e300;
  for (const hullcover::Plane& plane : hull.planes) worst = std::max(worst, plane.signed_distance(p));
  return worst;
}

TEST(CookingMargin, TheWedgeTipIsAtRisk) {
  const ConvexPolytope wedge = hull_of(knife_wedge());
  const auto tip = std::find(wedge.vertices.begin(), wedge.vertices.end(), kTip);
  ASSERT_NE(tip, wedge.vertices.end());
  double reach = 0.0;
  const double margin = corner_margin(wedge, static_cast<int>(tip - wedge.vertices.begin()), reach);
  EXPECT_LT(margin, 2 * kHullTolerance);
  EXPECT_GT(reach, 4 * kHullTolerance);
  EXPECT_NEAR(reach, 0.0088, 2e-4); // Jolt's error: its distance from the edge between its neighbours
}

TEST(CookingMargin, RepairHoldsEveryPointMovesNoneFartherThanTheMarginAndLeavesNoCornerAtRisk) {
  const ConvexPolytope wedge = hull_of(knife_wedge());
  const auto repair = repair_cooking_margins({wedge}, kHullTolerance);
  ASSERT_TRUE(repair.failures.empty()) << repair.failures.front();
  EXPECT_EQ(repair.repaired, 1);
  EXPECT_DOUBLE_EQ(repair.margin, 2 * kHullTolerance);
  const ConvexPolytope& fixed = repair.hulls.front();
  // Nothing of the original is lost: every corner is inside the new hull.
  for (const Eigen::Vector3d& p : wedge.vertices) EXPECT_LE(deepest_outside(fixed, p), kRounding);
  // Nothing grew farther than the margin: every new corner is within 2t of
  // the original hull (outside it by at most that in every plane).
  for (const Eigen::Vector3d& p : fixed.vertices) EXPECT_LE(deepest_outside(wedge, p), 2 * kHullTolerance + kRounding);
  for (int v = 0; v < static_cast<int>(fixed.vertices.size()); ++v) {
    double reach = 0.0;
    const double margin = corner_margin(fixed, v, reach);
    EXPECT_TRUE(margin >= 0.99 * 2 * kHullTolerance || reach <= 1.01 * 4 * kHullTolerance)
        << "corner " << v << " margin " << margin << " reach " << reach;
  }
}

TEST(CookingMargin, HullsWithNoCornerAtRiskAreKeptAsTheyAre) {
  // A cube, and a wide face bent by 0.5 mm: that corner may be dropped, but
  // it reaches less than the 4 mm Jolt accepts.
  const ConvexPolytope cube =
      hull_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}});
  const ConvexPolytope bent = hull_of(
      {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {4, 4, 0}, {2, 2, 0.0005}, {0, 0, -1}, {4, 0, -1}, {0, 4, -1}, {4, 4, -1}});
  const auto repair = repair_cooking_margins({cube, bent}, kHullTolerance);
  EXPECT_TRUE(repair.failures.empty());
  EXPECT_EQ(repair.repaired, 0);
  ASSERT_EQ(repair.hulls.size(), 2u);
  EXPECT_EQ(repair.hulls[0].vertices, cube.vertices);
  EXPECT_EQ(repair.hulls[1].vertices, bent.vertices);
}

// A tetrahedron whose apex stands 1 mm over a flat base of the other three
// but 10 mm beyond its rim: its height is its margin, its distance from the
// base its reach, so it is at risk and repaired.
TEST(CookingMargin, AnApexLowOverAFlatBaseButFarBeyondItsRimIsAtRisk) {
  const ConvexPolytope tetra = hull_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1.01, 1.01, 0.001}});
  const auto apex = std::find(tetra.vertices.begin(), tetra.vertices.end(), Eigen::Vector3d(1.01, 1.01, 0.001));
  ASSERT_NE(apex, tetra.vertices.end());
  double reach = 0.0;
  const double margin = corner_margin(tetra, static_cast<int>(apex - tetra.vertices.begin()), reach);
  EXPECT_NEAR(margin, 0.001, 1e-9);
  EXPECT_GT(reach, 4 * kHullTolerance);
  const auto repair = repair_cooking_margins({tetra}, kHullTolerance);
  EXPECT_EQ(repair.repaired, 1);
  EXPECT_TRUE(repair.failures.empty());
}

} // namespace

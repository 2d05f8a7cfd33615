// Contact normals at seams between hulls (surface_normals.h, the
// decomposer's CoveringHull::surface_planes): a shape resting on a floor
// that several hulls cover gets the floor's normal at every seam, never a
// hull side's (a ghost collision), while a ledge where the floor ends keeps
// its rounded normal.

#include "box_hulls.h"
#include "covering_fixture.h"
#include "poses.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;

using test::at;

// An L-shaped floor at y = 0, facing up: no convex hull covers it whole, so
// its covering has a seam.
Mesh l_shaped_floor() {
  Mesh floor;
  test::add_quad_facing(floor, V(0, 0, 0), V(0, 0, 2), V(4, 0, 2), V(4, 0, 0), V(0, 1, 0));
  test::add_quad_facing(floor, V(0, 0, 2), V(0, 0, 6), V(2, 0, 6), V(2, 0, 2), V(0, 1, 0));
  return floor;
}

class FloorSeams : public ::testing::TestWithParam<double> {
}; // prism thickness cap: 0 flat polygons only; 0.25 prisms where the decomposer can extrude

TEST_P(FloorSeams, RestingSpheresAndCapsulesGetTheFloorNormalEverywhere) {
  DecomposeOptions options;
  options.prism_thickness_cap = GetParam();
  const auto d = test::decompose_and_check(l_shaped_floor(), options);
  ASSERT_TRUE(d);
  ASSERT_GE(d->covering.hulls.size(), 2u) << "no seam to test";
  const auto world = build_hull_world(d->covering).value();
  // Spheres and lying capsules 0.05 deep in the floor, all over it (seams
  // included), clear of its outer edges.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> x(0.5, 3.5), z(0.5, 5.5);
  int contacts = 0;
  for (int i = 0; i < 2000; ++i) {
    const V p(x(rng), 0.25, z(rng));
    if (p.x() > 1.5 && p.z() > 1.5) continue; // off the L
    Eigen::Isometry3d lying = at(p);
    lying.linear() = Eigen::AngleAxisd(0.5 * M_PI, V::UnitY()).toRotationMatrix(); // axis (local z) along x
    for (const QueryShape& shape : {QueryShape::sphere(0.3), QueryShape::capsule(0.3, 0.4)}) {
      ContactResult result;
      ASSERT_TRUE(world->contacts({shape, shape.kind == ShapeKind::sphere ? at(p) : lying, 16}, result).ok());
      ASSERT_FALSE(result.contacts.empty()) << p.transpose();
      for (const Contact& c : result.contacts) {
        ++contacts;
        EXPECT_GT(c.normal.y(), std::cos(M_PI / 180.0)) << "hull " << c.hull << " at " << p.transpose();
        EXPECT_NEAR(c.depth, 0.05, 1e-9) << "hull " << c.hull << " at " << p.transpose();
      }
    }
  }
  EXPECT_GT(contacts, 1000);
}

// Two floor prisms meeting at x = 0, flagged as the decomposer flags a seam
// (the sides at x = 0 are not the surface's): a sphere sunk below the top
// at the seam, and a box across it, go out through the top of both, never
// through a seam side.
TEST(SeamFlags, SunkSpheresGoOutThroughTheTop) {
  std::vector<RuntimeHull> floor = {test::box_hull(V(-2, -0.5, -2), V(0, 0, 2)),
                                    test::box_hull(V(0, -0.5, -2), V(2, 0, 2))};
  for (int side = 0; side < 2; ++side) {
    RuntimeHull& h = floor[side];
    h.surface_planes.assign(h.shape.planes.size(), true);
    for (size_t p = 0; p < h.shape.planes.size(); ++p)
      if (std::abs(std::abs(h.shape.planes[p].normal.x()) - 1.0) < 1e-12 &&
          std::abs(h.shape.planes[p].signed_distance(V::Zero())) < 1e-12)
        h.surface_planes[p] = false; // the side at x = 0
  }
  const auto world = HullWorld::build(floor).value();
  for (const double x : {-0.2, -0.05, 0.0, 0.05, 0.2}) {
    ContactResult result;
    ASSERT_TRUE(world->contacts({QueryShape::sphere(0.3), at(V(x, -0.05, 0.3)), 8}, result).ok());
    ASSERT_EQ(result.contacts.size(), 2u) << x;
    for (const Contact& c : result.contacts) {
      EXPECT_GT(c.normal.y(), std::cos(M_PI / 180.0)) << "hull " << c.hull << " at x " << x;
      EXPECT_NEAR(c.depth, 0.35, 1e-9) << "hull " << c.hull << " at x " << x;
    }
  }
  // A box resting across the seam, 0.1 deep, overlapping the far hull by
  // only 0.05: out through the top of both.
  ContactResult boxed;
  ASSERT_TRUE(world->contacts({QueryShape::box(V(0.3, 0.3, 0.3)), at(V(-0.25, 0.2, 0.3)), 8}, boxed).ok());
  ASSERT_EQ(boxed.contacts.size(), 2u);
  for (const Contact& c : boxed.contacts) {
    EXPECT_GT(c.normal.y(), std::cos(M_PI / 180.0)) << "box, hull " << c.hull;
    EXPECT_NEAR(c.depth, 0.1, 1e-9) << "box, hull " << c.hull;
  }
  // Without the flags the hull on the far side pushes sideways: the ghost.
  const auto plain =
      HullWorld::build({test::box_hull(V(-2, -0.5, -2), V(0, 0, 2)), test::box_hull(V(0, -0.5, -2), V(2, 0, 2))})
          .value();
  ContactResult result;
  ASSERT_TRUE(plain->contacts({QueryShape::sphere(0.3), at(V(0.2, -0.05, 0.3)), 8}, result).ok());
  bool sideways = false;
  for (const Contact& c : result.contacts) sideways = sideways || std::abs(c.normal.x()) > 0.99;
  EXPECT_TRUE(sideways);
  ASSERT_TRUE(plain->contacts({QueryShape::box(V(0.3, 0.3, 0.3)), at(V(-0.25, 0.2, 0.3)), 8}, boxed).ok());
  sideways = false;
  for (const Contact& c : boxed.contacts) sideways = sideways || std::abs(c.normal.x()) > 0.99;
  EXPECT_TRUE(sideways);
}

TEST_P(FloorSeams, ALedgeWhereTheFloorEndsKeepsItsRoundedNormal) {
  DecomposeOptions options;
  options.prism_thickness_cap = GetParam();
  const auto d = test::decompose_and_check(l_shaped_floor(), options);
  ASSERT_TRUE(d);
  const auto world = build_hull_world(d->covering).value();
  // Beyond the outer edge x = 4, above and outside it at 45 degrees: a seam's
  // rule would turn this to the floor's normal.
  ContactResult result;
  const double gap = 0.2;
  ASSERT_TRUE(world->contacts({QueryShape::sphere(0.3), at(V(4 + gap, gap, 1))}, result).ok());
  ASSERT_EQ(result.contacts.size(), 1u);
  EXPECT_NEAR((result.contacts[0].normal - V(1, 1, 0).normalized()).norm(), 0.0, 1e-9);
  EXPECT_NEAR(result.contacts[0].depth, 0.3 - gap * std::sqrt(2.0), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(FlatAndPrism, FloorSeams, ::testing::Values(0.0, 0.25));

} // namespace
} // namespace hullcover::bvh

// region_outside_interior (convex_polytope.h) and the tree walk it prunes
// (AabbTree::any_overlapping_pruned): condition 1's vertex and edge walks
// skip whole nodes of the box trees with it, so its promise must hold to the
// last bit, and the pruned walk must answer as the full one does.

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/convex_polytope.h"

#include <gtest/gtest.h>

#include <random>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;

Aabb region_box(const V& min, const V& max) { return Aabb{min, max}; }

// The hull of the cube of side `side` with its lowest corner at `offset`.
ConvexPolytope cube(const V& offset, double side = 1.0) {
  std::vector<V> points;
  for (int i = 0; i < 8; ++i) points.push_back(offset + side * V(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  ConvexHullBuilder builder;
  Result<ConvexPolytope> hull = builder.build(points);
  EXPECT_TRUE(hull.ok());
  return std::move(hull).value();
}

TEST(RegionOutsideInterior, OnlyABoxClearOfTheShrunkHullWithRoomToSpare) {
  const ConvexPolytope hull = cube(V::Zero());
  const double tol = 1e-3;
  EXPECT_TRUE(region_outside_interior(hull.planes, region_box({2, 0, 0}, {3, 1, 1}), tol));   // beside it
  EXPECT_TRUE(region_outside_interior(hull.planes, region_box({-1, -1, 1}, {2, 2, 3}), tol)); // on top, touching
  EXPECT_TRUE(region_outside_interior(hull.planes, region_box({0, 0, 1 - 0.4 * tol}, {1, 1, 2}), tol)); // 0.4 tol in
  // Within tol of the top but with less than the slack to spare: not skipped.
  EXPECT_FALSE(region_outside_interior(hull.planes, region_box({0, 0, 1 - 0.6 * tol}, {1, 1, 2}), tol));
  EXPECT_FALSE(region_outside_interior(hull.planes, region_box({0.4, 0.4, 0.4}, {0.6, 0.6, 0.6}), tol)); // inside
  EXPECT_FALSE(region_outside_interior(hull.planes, region_box({-1, -1, -1}, {2, 2, 2}), tol));          // round it
  EXPECT_FALSE(region_outside_interior(hull.planes, Aabb{}, tol));
  EXPECT_FALSE(region_outside_interior({}, region_box({2, 0, 0}, {3, 1, 1}), tol));
  // A plane whose normal is not finite settles nothing.
  std::vector<Plane> broken = hull.planes;
  for (Plane& p : broken) p.normal = V::Constant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE(region_outside_interior(broken, region_box({2, 0, 0}, {3, 1, 1}), tol));
}

// Random boxes about a hull far from the origin: a box said to be outside
// holds no point the point test finds inside (its corners, centre and
// random points), and every box with such a point is said not to be.
TEST(RegionOutsideInterior, NoPointOfABoxSaidOutsideTestsInside) {
  const V offset(3.0e5, -1.0e5, 2.0e4);
  const ConvexPolytope hull = cube(offset);
  const double tol = 1e-4;
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> corner(-0.5, 1.5), extent(0.0, 0.6), unit(0.0, 1.0);
  int outside = 0, not_outside = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    V low, high;
    for (int k = 0; k < 3; ++k) {
      low[k] = offset[k] + corner(rng);
      high[k] = low[k] + extent(rng);
    }
    const Aabb region = region_box(low, high);
    const bool said_outside = region_outside_interior(hull.planes, region, tol);
    (said_outside ? outside : not_outside) += 1;
    if (!said_outside) continue;
    for (int i = 0; i < 16; ++i) {
      V p;
      for (int k = 0; k < 3; ++k)
        p[k] = i < 8 ? ((i >> k) & 1 ? high[k] : low[k]) : low[k] + unit(rng) * (high[k] - low[k]);
      ASSERT_GE(deepest_signed_distance(hull.planes, p), -tol) << "trial " << trial;
    }
  }
  EXPECT_GT(outside, 500); // both answers were put to the test
  EXPECT_GT(not_outside, 500);
}

// The walks' test asks only the largest facets' planes, and only of hulls
// that leave most of their box outside: a thin tilted slab is worth it, a
// cube is not; what it calls outside the full test calls outside too.
TEST(InteriorRegionTest, AsksTheLargestFacetsOfAHullThatFillsLittleOfItsBox) {
  const double tol = 1e-3;
  const ConvexPolytope block = cube(V::Zero());
  const Aabb block_box = region_box(V::Constant(-tol), V::Constant(1 + tol));
  EXPECT_FALSE(InteriorRegionTest(block, block_box, tol).worthwhile());
  // A slab 0.05 thick, tilted across the diagonal of a 10 x 10 x 10 box.
  std::vector<V> slab;
  for (const V& corner : {V(0, 0, 0), V(10, 0, 10), V(0, 10, 0), V(10, 10, 10)}) {
    slab.push_back(corner);
    slab.push_back(corner + V(0.05, 0, -0.05));
  }
  ConvexHullBuilder builder;
  const Result<ConvexPolytope> tilted = builder.build(slab);
  ASSERT_TRUE(tilted.ok());
  Aabb slab_box;
  for (const V& p : slab) slab_box.extend(p);
  const InteriorRegionTest test(tilted.value(), slab_box, tol);
  EXPECT_TRUE(test.worthwhile());
  // The box's far corners are off the slab: outside, by its big faces.
  EXPECT_TRUE(test.outside(region_box(V(0, 0, 6), V(3, 10, 10))));
  EXPECT_TRUE(test.outside(region_box(V(6, 0, 0), V(10, 10, 3))));
  EXPECT_FALSE(test.outside(region_box(V(4, 4, 4), V(6, 6, 6)))); // across the slab
  std::mt19937 rng(53);
  std::uniform_real_distribution<double> coordinate(0.0, 10.0), extent(0.0, 3.0);
  int outside = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const V low(coordinate(rng), coordinate(rng), coordinate(rng));
    const Aabb region = region_box(low, low + V(extent(rng), extent(rng), extent(rng)));
    if (!test.outside(region)) continue;
    ++outside;
    ASSERT_TRUE(region_outside_interior(tilted.value().planes, region, tol)) << "trial " << trial;
  }
  EXPECT_GT(outside, 1000);
}

// The pruned walk, told to skip nodes outside the hull, finds a point inside
// exactly when the full walk does, over points spread round the hull.
TEST(AabbTreePruned, AnswersAsTheFullWalkWhenThePromiseHolds) {
  const ConvexPolytope hull = cube(V(8, 8, 8), 5.0);
  const double tol = 1e-3;
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> coordinate(0.0, 21.0);
  std::vector<V> points(3000);
  std::vector<Aabb> boxes;
  for (V& p : points) {
    p = V(coordinate(rng), coordinate(rng), coordinate(rng));
    boxes.push_back(region_box(p, p));
  }
  const AabbTree tree(boxes);
  const auto inside = [&](int i) { return deepest_signed_distance(hull.planes, points[i]) < -tol; };
  const auto outside = [&](const Aabb& region) { return region_outside_interior(hull.planes, region, tol); };
  std::uniform_real_distribution<double> size(0.5, 12.0);
  int found = 0;
  for (int q = 0; q < 400; ++q) {
    const V low(coordinate(rng), coordinate(rng), coordinate(rng));
    const Aabb query = region_box(low, low + V::Constant(size(rng)));
    const bool full = tree.any_overlapping(query, inside);
    int asked = 0;
    const bool pruned = tree.any_overlapping_pruned(query, outside, [&](int i) {
      ++asked;
      return inside(i);
    });
    ASSERT_EQ(pruned, full) << "query " << q;
    found += full;
  }
  EXPECT_GT(found, 30);
  // A query round the hull's whole neighbourhood but wholly outside it asks
  // next to nothing: the nodes far off the hull are passed over whole.
  int asked = 0;
  const Aabb far_side = region_box(V(14, 0, 0), V(21, 21, 21));
  EXPECT_FALSE(tree.any_overlapping_pruned(far_side, outside, [&](int i) {
    ++asked;
    return inside(i);
  }));
  std::vector<int> listed;
  tree.overlapping(far_side, listed);
  EXPECT_LT(asked * 4, static_cast<int>(listed.size())) << asked << " of " << listed.size();
}

} // namespace
} // namespace hullcover

// The paper's cases (figures 2-5, 7, 8, 10), built in code, plus the closed and
// inward cubes. Every result is re-checked by the independent checker in
// decompose_and_check; the assertions here are the figures' own claims.

#include "covering_fixture.h"

#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hullcover {
namespace {

using test::add_quad_facing;
using test::decompose_and_check;
using V = Eigen::Vector3d;

TEST(PaperCases, ClosedOutwardCubeIsOneHull) {
  Mesh m;
  add_box(m, V(0, 0, 0), V(1, 1, 1), true);
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  ASSERT_EQ(d->covering.hulls.size(), 1u);
  EXPECT_NEAR(d->covering.hulls[0].volume, 1.0, 1e-9);
}

TEST(PaperCases, RoomSeenFromInsideIsSixPrismsAndKeepsItsSpace) {
  Mesh m;
  add_box(m, V(0, 0, 0), V(4, 3, 5), false);
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  ASSERT_EQ(d->covering.hulls.size(), 6u);
  for (const CoveringHull& h : d->covering.hulls) {
    EXPECT_TRUE(h.planar);
    EXPECT_GT(h.thickness, 0.0); // nothing behind the walls: full prisms
  }
  for (const V& p : {V(2, 1.5, 2.5), V(0.01, 0.01, 0.01), V(3.99, 2.99, 4.99)})
    EXPECT_FALSE(test::point_inside_covering(d->covering, p, d->tol())) << p.transpose();
}

// Figure 3(a): a ridge of terrain; its hull sits below the surface.
TEST(PaperCases, Figure3aRidgeIsOneHull) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(0, 0, 2), V(1, 0.5, 2), V(1, 0.5, 0), V(-0.5, 1, 0));
  add_quad_facing(m, V(1, 0.5, 0), V(1, 0.5, 2), V(2, 0, 2), V(2, 0, 0), V(0.5, 1, 0));
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->covering.hulls.size(), 1u);
  EXPECT_FALSE(d->covering.hulls[0].planar);
}

// Figure 3(b): the inverse, a valley: its hull would block the way down.
TEST(PaperCases, Figure3bValleyIsNotMerged) {
  Mesh m;
  add_quad_facing(m, V(0, 0.5, 0), V(0, 0.5, 2), V(1, 0, 2), V(1, 0, 0), V(0.5, 1, 0));
  add_quad_facing(m, V(1, 0, 0), V(1, 0, 2), V(2, 0.5, 2), V(2, 0.5, 0), V(-0.5, 1, 0));
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->covering.hulls.size(), 2u);
  EXPECT_FALSE(test::segment_hits_covering(d->covering, V(1, 1, 1), V(1, 0.01, 1), d->tol()));
}

// Figure 3(b), orange patches, and condition 4: a floor with a pit. One
// polygon over the whole floor would close the pit.
TEST(PaperCases, PitInAFloorStaysOpen) {
  Mesh m;
  const double xs[] = {0, 1, 3, 4};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (i == 1 && j == 1) continue; // the pit's mouth
      add_quad_facing(m, V(xs[i], 0, xs[j]), V(xs[i + 1], 0, xs[j]), V(xs[i + 1], 0, xs[j + 1]), V(xs[i], 0, xs[j + 1]),
                      V(0, 1, 0));
    }
  const double depth = -1.0;
  add_quad_facing(m, V(1, 0, 1), V(3, 0, 1), V(3, depth, 1), V(1, depth, 1), V(0, 0, 1));
  add_quad_facing(m, V(1, 0, 3), V(3, 0, 3), V(3, depth, 3), V(1, depth, 3), V(0, 0, -1));
  add_quad_facing(m, V(1, 0, 1), V(1, 0, 3), V(1, depth, 3), V(1, depth, 1), V(1, 0, 0));
  add_quad_facing(m, V(3, 0, 1), V(3, 0, 3), V(3, depth, 3), V(3, depth, 1), V(-1, 0, 0));
  add_quad_facing(m, V(1, depth, 1), V(3, depth, 1), V(3, depth, 3), V(1, depth, 3), V(0, 1, 0));
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  EXPECT_GT(d->covering.hulls.size(), 1u);
  EXPECT_FALSE(test::segment_hits_covering(d->covering, V(2, 0.5, 2), V(2, depth + 0.01, 2), d->tol()));
  EXPECT_FALSE(test::point_inside_covering(d->covering, V(2, -0.5, 2), d->tol()));
}

// Figure 4: a closed box with an opening in its top; the opening stays open
// thanks to the boundary bars.
TEST(PaperCases, Figure4OpeningStaysOpen) {
  Mesh m;
  const double xs[] = {0, 1, 2, 3};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!(i == 1 && j == 1))
        add_quad_facing(m, V(xs[i], 2, xs[j]), V(xs[i + 1], 2, xs[j]), V(xs[i + 1], 2, xs[j + 1]),
                        V(xs[i], 2, xs[j + 1]), V(0, 1, 0));
  // Walls and bottom, split at the same x/z so the top ring shares their edges.
  for (int i = 0; i < 3; ++i) {
    add_quad_facing(m, V(xs[i], 0, 0), V(xs[i + 1], 0, 0), V(xs[i + 1], 2, 0), V(xs[i], 2, 0), V(0, 0, -1));
    add_quad_facing(m, V(xs[i], 0, 3), V(xs[i + 1], 0, 3), V(xs[i + 1], 2, 3), V(xs[i], 2, 3), V(0, 0, 1));
    add_quad_facing(m, V(0, 0, xs[i]), V(0, 0, xs[i + 1]), V(0, 2, xs[i + 1]), V(0, 2, xs[i]), V(-1, 0, 0));
    add_quad_facing(m, V(3, 0, xs[i]), V(3, 0, xs[i + 1]), V(3, 2, xs[i + 1]), V(3, 2, xs[i]), V(1, 0, 0));
    for (int j = 0; j < 3; ++j)
      add_quad_facing(m, V(xs[i], 0, xs[j]), V(xs[i + 1], 0, xs[j]), V(xs[i + 1], 0, xs[j + 1]), V(xs[i], 0, xs[j + 1]),
                      V(0, -1, 0));
  }
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  EXPECT_GT(d->covering.hulls.size(), 1u);
  EXPECT_FALSE(test::segment_hits_covering(d->covering, V(1.5, 3, 1.5), V(1.5, 2.0, 1.5), d->tol()));
  EXPECT_FALSE(test::point_inside_covering(d->covering, V(1.5, 1.98, 1.5), d->tol()));
}

// Figure 5 / condition 1: the ridge of figure 3(a) with a small object
// standing where its hull would be: the two faces stay apart.
TEST(PaperCases, Figure5ObjectUnderTheRidgeKeepsItsHullsApart) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(0, 0, 2), V(1, 0.5, 2), V(1, 0.5, 0), V(-0.5, 1, 0));
  add_quad_facing(m, V(1, 0.5, 0), V(1, 0.5, 2), V(2, 0, 2), V(2, 0, 0), V(0.5, 1, 0));
  add_box(m, V(0.9, 0.05, 0.9), V(1.1, 0.25, 1.1)); // under the ridge, inside the would-be hull
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  EXPECT_NE(d->hull_of_face(0), d->hull_of_face(2));
}

// Figure 2(a)/(b): a convex patch (an upside-down frustum, open below)
// lies on its hull, but the hull adds a face across the opening, under
// which something could stand: not one hull. Figure 2(c): closed, the
// extra face is inside the object and one hull is right.
Mesh inverted_frustum(bool closed) {
  Mesh m;
  const double bottom = 0.6, top = 1.0, h = 1.0;
  const V b[4] = {V(-bottom, 0, -bottom), V(bottom, 0, -bottom), V(bottom, 0, bottom), V(-bottom, 0, bottom)};
  const V t[4] = {V(-top, h, -top), V(top, h, -top), V(top, h, top), V(-top, h, top)};
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const V out = (0.5 * (b[i] + b[j]) - V(0, 0, 0)).normalized() + V(0, -0.4, 0);
    add_quad_facing(m, b[i], b[j], t[j], t[i], out);
  }
  add_quad_facing(m, t[0], t[1], t[2], t[3], V(0, 1, 0));
  if (closed) add_quad_facing(m, b[0], b[1], b[2], b[3], V(0, -1, 0));
  return m;
}

TEST(PaperCases, Figure2OpenConvexPatchWithAnExtraFaceIsNotOneHull) {
  const auto d = decompose_and_check(inverted_frustum(false));
  ASSERT_TRUE(d);
  EXPECT_GT(d->covering.hulls.size(), 1u);
  EXPECT_FALSE(test::segment_hits_covering(d->covering, V(0, -0.5, 0), V(0, 0.05, 0), d->tol()));
}

TEST(PaperCases, Figure2cTheSameSolidClosedIsOneHull) {
  const auto d = decompose_and_check(inverted_frustum(true));
  ASSERT_TRUE(d);
  EXPECT_EQ(d->covering.hulls.size(), 1u);
}

// The paper's merging alone (its figures count what it makes), under the
// exact conditions.
DecomposeOptions paper_merging() {
  DecomposeOptions options;
  options.near_merge_distance = 0.0;
  return options;
}

// Figure 7: merge order matters. A plus-shaped floor of five cells (two
// triangles each) is ideally three rectangles; compactness finds them, while
// other orders can merge a jagged patch first and end with more.
Mesh plus_floor() {
  Mesh m;
  for (const auto& [x, z] : {std::pair{1, 0}, {0, 1}, {1, 1}, {2, 1}, {1, 2}})
    add_quad_facing(m, V(x, 0, z), V(x, 0, z + 1), V(x + 1, 0, z + 1), V(x + 1, 0, z), V(0, 1, 0));
  return m;
}

TEST(PaperCases, Figure7CompactOrderFindsTheThreeRectangles) {
  const Mesh m = plus_floor();
  const auto compact = decompose_and_check(m, paper_merging());
  ASSERT_TRUE(compact);
  EXPECT_EQ(compact->covering.hulls.size(), 3u);
  DecomposeOptions random = paper_merging();
  random.order = MergeOrder::random;
  size_t fewest = SIZE_MAX, most = 0;
  for (std::uint64_t seed = 1; seed <= 15; ++seed) {
    random.seed = seed;
    const auto d = decompose_and_check(m, random);
    ASSERT_TRUE(d);
    fewest = std::min(fewest, d->covering.hulls.size());
    most = std::max(most, d->covering.hulls.size());
  }
  EXPECT_EQ(fewest, 3u);
  EXPECT_GT(most, 3u);
}

// Beyond the paper: near merges (DecomposeOptions::near_merge_distance, here
// a cell wide) join the two side cells across the centre cell, which the
// other bar already covers: two overlapping bars, and still nothing over the
// plus's empty corners.
TEST(PaperCases, Figure7NearMergesCoverThePlusWithTwoOverlappingBars) {
  DecomposeOptions options;
  options.near_merge_distance = 1.0;
  const auto d = decompose_and_check(plus_floor(), options);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->covering.hulls.size(), 2u);
  EXPECT_GE(d->covering.statistics.near_merges, 1);
  for (const auto& [x, z] : {std::pair{0.5, 0.5}, {2.5, 0.5}, {0.5, 2.5}, {2.5, 2.5}})
    EXPECT_FALSE(test::segment_hits_covering(d->covering, V(x, -0.5, z), V(x, 0.5, z), d->tol())) << x << ", " << z;
}

// Figure 10: an extruded gear with 32 teeth; caps tessellated with each
// tooth's root as an edge, so hub + 32 teeth = 33 patches is reachable.
Mesh gear(int teeth) {
  Mesh m;
  const double pi = std::acos(-1.0), h = 0.3, root = 1.0, tip = 1.25;
  const double half_tooth = pi / (2.0 * teeth) * 0.9;
  std::vector<V> profile;      // counter-clockwise seen from +z
  std::vector<int> root_index; // positions of root vertices in `profile`
  for (int i = 0; i < teeth; ++i) {
    const double a = 2.0 * pi * i / teeth;
    const auto at = [](double r, double angle) { return V(r * std::cos(angle), r * std::sin(angle), 0); };
    root_index.push_back(static_cast<int>(profile.size()));
    profile.push_back(at(root, a - half_tooth));
    profile.push_back(at(tip, a - 0.6 * half_tooth));
    profile.push_back(at(tip, a + 0.6 * half_tooth));
    root_index.push_back(static_cast<int>(profile.size()));
    profile.push_back(at(root, a + half_tooth));
  }
  const int n = static_cast<int>(profile.size());
  for (int z = 0; z < 2; ++z)
    for (const V& p : profile) m.positions.push_back(p + V(0, 0, z * h));
  m.positions.push_back(V(0, 0, 0));
  m.positions.push_back(V(0, 0, h));
  const int centre[2] = {2 * n, 2 * n + 1};
  const auto tri = [&](int a, int b, int c) {
    m.triangles.emplace_back(a, b, c);
    m.material_ids.push_back(0);
  };
  for (int z = 0; z < 2; ++z) {
    const int o = z * n;
    const auto cap = [&](int a, int b, int c) { z ? tri(o + a, o + b, o + c) : tri(o + a, o + c, o + b); };
    for (size_t r = 0; r < root_index.size(); ++r) { // the hub, a fan over the root vertices
      const int a = root_index[r], b = root_index[(r + 1) % root_index.size()];
      z ? tri(centre[z], o + a, o + b) : tri(centre[z], o + b, o + a);
    }
    for (int t = 0; t < teeth; ++t) { // each tooth: root A, tip C, tip D, root B
      const int A = 4 * t, C = A + 1, D = A + 2, B = A + 3;
      cap(A, C, D);
      cap(A, D, B);
    }
  }
  for (int i = 0; i < n; ++i) { // side walls
    const int j = (i + 1) % n;
    tri(i, j, n + j);
    tri(i, n + j, n + i);
  }
  return m;
}

TEST(PaperCases, Figure10GearCompactOrderGivesHubAndTeeth) {
  const auto d = decompose_and_check(gear(32), paper_merging());
  ASSERT_TRUE(d);
  EXPECT_EQ(d->covering.hulls.size(), 33u);
}

// Beyond the paper: near merges pair hub wedges with teeth across the hub
// hull; fewer hulls, and the gaps between the teeth stay free.
TEST(PaperCases, Figure10NearMergesNeedFewerHullsAndKeepTheGaps) {
  const int teeth = 32;
  const auto d = decompose_and_check(gear(teeth));
  ASSERT_TRUE(d);
  EXPECT_LT(d->covering.hulls.size(), 33u);
  const double pi = std::acos(-1.0);
  for (int i = 0; i < teeth; ++i) {
    const double between = 2.0 * pi * (i + 0.5) / teeth; // the middle of a gap, just off the root
    const V p(1.05 * std::cos(between), 1.05 * std::sin(between), 0.15);
    EXPECT_FALSE(test::point_inside_covering(d->covering, p, d->tol())) << "gap " << i;
  }
}

TEST(PaperCases, Figure10GearRandomOrderGivesMore) {
  DecomposeOptions random = paper_merging();
  random.order = MergeOrder::random;
  size_t fewest = SIZE_MAX;
  for (std::uint64_t seed : {1, 2, 3}) {
    random.seed = seed;
    const auto d = decompose_and_check(gear(32), random);
    ASSERT_TRUE(d);
    fewest = std::min(fewest, d->covering.hulls.size());
  }
  EXPECT_GT(fewest, 33u);
}

// Figure 8: a single-sided fireplace; the burning chamber stays open.
TEST(PaperCases, Figure8FireplaceChamberStaysOpen) {
  Mesh m;
  const double xs[] = {0, 1, 3, 4}, ys[] = {0, 1.5, 3};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j)
      if (!(i == 1 && j == 0)) // the chamber's mouth
        add_quad_facing(m, V(xs[i], ys[j], 1), V(xs[i + 1], ys[j], 1), V(xs[i + 1], ys[j + 1], 1),
                        V(xs[i], ys[j + 1], 1), V(0, 0, 1));
  const double back = 0.3;
  add_quad_facing(m, V(1, 0, back), V(3, 0, back), V(3, 1.5, back), V(1, 1.5, back), V(0, 0, 1));
  add_quad_facing(m, V(1, 0, back), V(1, 0, 1), V(1, 1.5, 1), V(1, 1.5, back), V(1, 0, 0));
  add_quad_facing(m, V(3, 0, back), V(3, 0, 1), V(3, 1.5, 1), V(3, 1.5, back), V(-1, 0, 0));
  add_quad_facing(m, V(1, 1.5, back), V(3, 1.5, back), V(3, 1.5, 1), V(1, 1.5, 1), V(0, -1, 0));
  add_quad_facing(m, V(1, 0, back), V(3, 0, back), V(3, 0, 1), V(1, 0, 1), V(0, 1, 0));
  add_quad_facing(m, V(0, 3, 0), V(4, 3, 0), V(4, 3, 1), V(0, 3, 1), V(0, 1, 0)); // top panel
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  EXPECT_FALSE(test::segment_hits_covering(d->covering, V(2, 0.75, 2), V(2, 0.75, back + 0.01), d->tol()));
  EXPECT_FALSE(test::point_inside_covering(d->covering, V(2, 0.75, 0.65), d->tol()));
}

// A building with an interior wall and a doorway (the demo scene): the
// doorway, the passage past the interior wall and the rooms stay free.
TEST(PaperCases, BuildingKeepsItsDoorwayPassageAndRooms) {
  const auto d = decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  const double tol = d->tol();
  EXPECT_FALSE(test::segment_hits_covering(d->covering, V(0, 1, 3), V(0, 1, 5), tol));
  EXPECT_FALSE(test::segment_hits_covering(d->covering, V(-2, 1, 2.5), V(2, 1, 2.5), tol));
  for (const V& p : {V(-2.5, 1.5, -1), V(2.5, 2.5, 0), V(0, 1, 3.9)})
    EXPECT_FALSE(test::point_inside_covering(d->covering, p, tol)) << p.transpose();
  EXPECT_LT(d->covering.hulls.size(), d->prepared.mesh.triangles.size() / 2);
}

} // namespace
} // namespace hullcover

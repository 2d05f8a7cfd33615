// Dissolving (DecomposeOptions::dissolve, lib/covering/src/merging/patch_dissolving.cpp),
// built in code from the case it exists for: greedy merging unites the two
// middle strips of a ridge first, and then neither outer strip can join the
// pair; emptying the pair into the outer strips saves a hull.

#include "covering_fixture.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hullcover {
namespace {

using test::add_quad_facing;
using test::decompose_and_check;
using V = Eigen::Vector3d;

constexpr double kRadius = 5.0;
constexpr double kDepth = 6.0; // along y: long strips, so the wider middle pair is the most compact
constexpr double kDegrees = 3.14159265358979323846 / 180.0;

V on_arc(double degrees, double r = kRadius) {
  return V(r * std::cos(degrees * kDegrees), 0, r * std::sin(degrees * kDegrees));
}

// A ridge of four strips A B C D (arc points at 55, 70, 90, 110, 125 degrees,
// extruded along y, facing away from the arc's centre) and under it two thin
// triangles in the plane y = depth / 2, pointing up at the ridge. Strips
// A+B and C+D are valid hulls; A+B+C and B+C+D each swallow a triangle's tip,
// and so does A+D.
Mesh ridge_over_two_spikes() {
  Mesh m;
  const double angles[] = {55, 70, 90, 110, 125};
  for (int i = 0; i < 4; ++i) {
    const V a = on_arc(angles[i]), b = on_arc(angles[i + 1]);
    const V middle = on_arc(0.5 * (angles[i] + angles[i + 1]));
    add_quad_facing(m, a, b, b + V(0, kDepth, 0), a + V(0, kDepth, 0), middle);
  }
  const V mid_depth(0, 0.5 * kDepth, 0);
  for (const double spike : {82.5, 97.5}) {
    // The tip: between the chord of three strips and the chords of the pairs.
    const int first = static_cast<int>(m.positions.size());
    for (const V& p : {on_arc(spike, 4.55), on_arc(spike + 3, 3.0), on_arc(spike - 3, 3.0)})
      m.positions.push_back(p + mid_depth);
    m.triangles.emplace_back(first, first + 1, first + 2);
    m.material_ids.push_back(0);
  }
  return m;
}

DecomposeOptions with_dissolving(bool on) {
  DecomposeOptions options;
  options.dissolve = on;
  return options;
}

std::vector<std::vector<int>> faces_by_hull(const Covering& covering) {
  std::vector<std::vector<int>> out;
  for (const CoveringHull& h : covering.hulls) out.push_back(h.faces);
  return out;
}

const V kSpikeTips[] = {on_arc(82.5, 4.55) + V(0, 0.5 * kDepth, 0), on_arc(97.5, 4.55) + V(0, 0.5 * kDepth, 0)};

TEST(Dissolving, EmptiesTheMiddlePairOfARidgeIntoTheOuterStrips) {
  const Mesh m = ridge_over_two_spikes();
  // Faces: strips A = {0, 1}, B = {2, 3}, C = {4, 5}, D = {6, 7}; spikes 8, 9.
  const auto without = decompose_and_check(m, with_dissolving(false));
  ASSERT_TRUE(without);
  const std::vector<std::vector<int>> greedy = {{0, 1}, {2, 3, 4, 5}, {6, 7}, {8}, {9}};
  EXPECT_EQ(faces_by_hull(without->covering), greedy);

  const auto with = decompose_and_check(m, with_dissolving(true));
  ASSERT_TRUE(with);
  const std::vector<std::vector<int>> dissolved = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8}, {9}};
  EXPECT_EQ(faces_by_hull(with->covering), dissolved);
  EXPECT_EQ(with->covering.statistics.dissolved_patches, 1);
  for (const V& tip : kSpikeTips) EXPECT_FALSE(test::point_inside_covering(with->covering, tip, with->tol()));
}

TEST(Dissolving, IsOnInExactModeAndOffInPaperMode) {
  const Mesh m = ridge_over_two_spikes();
  const auto exact = decompose_and_check(m);
  ASSERT_TRUE(exact);
  EXPECT_TRUE(exact->covering.dissolve);
  EXPECT_EQ(exact->covering.hulls.size(), 4u);
  DecomposeOptions paper;
  paper.conditions = ValidityMode::paper;
  const auto d = decompose_and_check(m, paper);
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->covering.dissolve);
  EXPECT_EQ(d->covering.statistics.dissolved_patches, 0);
}

} // namespace
} // namespace hullcover

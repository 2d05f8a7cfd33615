#include "hullcover/mesh/tolerance.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hullcover {
namespace {

Mesh unit_box_at(const Eigen::Vector3d& offset) {
  Mesh m;
  add_box(m, offset, offset + Eigen::Vector3d(1, 2, 2));
  return m;
}

TEST(ChooseTolerance, DefaultIsAFixedFractionOfTheDiagonal) {
  const Result<Tolerance> t = choose_tolerance(unit_box_at({0, 0, 0}), std::nullopt);
  ASSERT_TRUE(t.ok());
  EXPECT_DOUBLE_EQ(t.value().diagonal, 3.0);
  EXPECT_DOUBLE_EQ(t.value().length, 3.0 * kDefaultRelativeTolerance);
  EXPECT_FALSE(t.value().user_given);
  EXPECT_FALSE(t.value().raised_to_floor);
}

TEST(ChooseTolerance, UserLengthWins) {
  const Result<Tolerance> t = choose_tolerance(unit_box_at({0, 0, 0}), 0.01);
  ASSERT_TRUE(t.ok());
  EXPECT_DOUBLE_EQ(t.value().length, 0.01);
  EXPECT_TRUE(t.value().user_given);
}

TEST(ChooseTolerance, RejectsNonPositiveOrNonFiniteUserLength) {
  const Mesh m = unit_box_at({0, 0, 0});
  for (double bad : {0.0, -1e-3, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_EQ(choose_tolerance(m, bad).status().code(), StatusCode::invalid_argument) << bad;
}

TEST(ChooseTolerance, RejectsASceneWithoutExtent) {
  Mesh m;
  m.positions = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  m.triangles = {{0, 1, 2}};
  m.material_ids = {0};
  EXPECT_EQ(choose_tolerance(m, std::nullopt).status().code(), StatusCode::degenerate_scene);
}

TEST(ChooseTolerance, FloorFollowsMagnitudeAndNeverLetsTheUserGoBelowIt) {
  // Far from the origin, double rounding alone is ~1e5 * 2.2e-16.
  const Mesh far = unit_box_at({1e5, 1e5, 1e5});
  const Result<Tolerance> t = choose_tolerance(far, 1e-20);
  ASSERT_TRUE(t.ok());
  EXPECT_GT(t.value().floor, 1e5 * std::numeric_limits<double>::epsilon());
  EXPECT_DOUBLE_EQ(t.value().length, t.value().floor);
  EXPECT_TRUE(t.value().raised_to_floor);
}

TEST(ChooseTolerance, InputRoundingErrorRaisesTheFloor) {
  Mesh m = unit_box_at({0, 0, 0});
  m.coordinate_error = 1e-3; // e.g. coordinates that went through float16
  const Result<Tolerance> t = choose_tolerance(m, std::nullopt);
  ASSERT_TRUE(t.ok());
  EXPECT_DOUBLE_EQ(t.value().floor, kRoundingErrorsPerPlaneTest * 1e-3);
  EXPECT_DOUBLE_EQ(t.value().length, t.value().floor);
  EXPECT_TRUE(t.value().raised_to_floor);
}

// Two boxes' meshes in one.
Mesh joined(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const int base = static_cast<int>(m.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  for (const Eigen::Vector3i& t : b.triangles) m.triangles.push_back(t + Eigen::Vector3i::Constant(base));
  m.material_ids.insert(m.material_ids.end(), b.material_ids.begin(), b.material_ids.end());
  return m;
}

Mesh box_from(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Mesh m;
  add_box(m, lo, hi);
  return m;
}

TEST(ChooseTolerance, EachIslandHasItsOwnAndTheSmallestRulesWhereZonesMeet) {
  // A 1 x 2 x 2 box and one ten times larger far away: each its own default.
  const Mesh far_apart = joined(box_from({0, 0, 0}, {1, 2, 2}), box_from({100, 0, 0}, {110, 20, 20}));
  const Result<Tolerance> t = choose_tolerance(far_apart, std::nullopt);
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t.value().island_lengths.size(), 2u);
  EXPECT_DOUBLE_EQ(t.value().island_lengths[0], 3.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(t.value().island_lengths[1], 30.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(t.value().length, 3.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(t.value().largest_length(), 30.0 * kDefaultRelativeTolerance);
  // A hull anywhere near the large box is judged at its tolerance; one
  // spanning both, or out in the open, at the smallest.
  const PlaceTolerance place(t.value());
  EXPECT_DOUBLE_EQ(place.at(bounding_box_of({{101, 1, 1}, {102, 2, 2}})), 30.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(place.at(bounding_box_of({{0.5, 1, 1}, {102, 2, 2}})), 3.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(place.at(bounding_box_of({{50, 50, 50}, {51, 51, 51}})), 3.0 * kDefaultRelativeTolerance);

  // A small island whose box meets the large one's (a prop inside an
  // L-shaped map of two interpenetrating pieces, touching neither) is one
  // place with it: both take the tolerance the place has as one island, the
  // default from the L's 10 x 20 x 20 box.
  const Mesh l_shape = joined(box_from({100, 0, 0}, {110, 2, 20}), box_from({100, 1, 0.5}, {102, 20, 19.5}));
  const Mesh prop = joined(box_from({105, 10, 5}, {106, 12, 7}), l_shape);
  const Result<Tolerance> s = choose_tolerance(prop, std::nullopt);
  ASSERT_TRUE(s.ok());
  ASSERT_EQ(s.value().island_lengths.size(), 2u);
  EXPECT_EQ(s.value().places, 1);
  EXPECT_DOUBLE_EQ(s.value().island_lengths[0], 30.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(s.value().island_lengths[1], 30.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(s.value().island_lengths[0], choose_tolerance(l_shape, std::nullopt).value().length);
}

TEST(ChooseTolerance, MapsLaidCloseKeepTheirOwnTolerance) {
  // Two maps as a world lays them: 5,000 and 1,000 units across, 64 units
  // apart (1.3% of the larger, less than their 1% reaches added up). Each
  // keeps the tolerance it has alone, and their zones stop short of each
  // other: no hull of one is judged at the other's tolerance.
  const Mesh large = box_from({0, 0, 0}, {5000, 500, 3000});
  const Mesh small = box_from({5064, 0, 0}, {6064, 200, 600});
  const Result<Tolerance> t = choose_tolerance(joined(large, small), std::nullopt);
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t.value().island_lengths.size(), 2u);
  EXPECT_EQ(t.value().places, 2);
  EXPECT_DOUBLE_EQ(t.value().island_lengths[0], choose_tolerance(large, std::nullopt).value().length);
  EXPECT_DOUBLE_EQ(t.value().island_lengths[1], choose_tolerance(small, std::nullopt).value().length);
  EXPECT_FALSE(boxes_overlap(t.value().island_zones[0], t.value().island_zones[1]));
  EXPECT_LE(t.value().island_zones[0].max.x(), 5000 + kZoneShareOfGap * 64 + 1e-9);
  // Alone, a zone reaches kIslandZoneRelative of the diagonal.
  const Tolerance alone = choose_tolerance(large, std::nullopt).value();
  EXPECT_DOUBLE_EQ(alone.island_zones[0].max.x(), 5000 + kIslandZoneRelative * alone.diagonal);
}

TEST(ChooseTolerance, IslandsWhoseBoxesMeetAlongAChainAreOnePlace) {
  // Two L-shaped islands (each of two interpenetrating pieces) whose boxes
  // meet, though no piece of one touches the other, and a small box inside
  // the second's box alone: one place, with the tolerance of the box of all
  // three, 30 x 30 x 10, as if they were one island.
  const Mesh a = joined(box_from({0, 0, 0}, {10, 1, 10}), box_from({0, 0.5, 0.5}, {1, 10, 9.5}));
  const Mesh b = joined(box_from({5, 5, 0}, {30, 6, 10}), box_from({29, 5.5, 0.5}, {30, 30, 9.5}));
  const Mesh chain = joined(joined(a, b), box_from({20, 20, 4}, {21, 22, 6}));
  const Result<Tolerance> t = choose_tolerance(chain, std::nullopt);
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t.value().island_lengths.size(), 3u);
  EXPECT_EQ(t.value().places, 1);
  for (int i = 0; i < 3; ++i)
    EXPECT_DOUBLE_EQ(t.value().island_lengths[i], std::sqrt(1900.0) * kDefaultRelativeTolerance) << i;
  // Moved apart (a gap of 1 along x), B and its box are a place of their own.
  Mesh apart = b;
  for (Eigen::Vector3d& p : apart.positions) p.x() += 6.0;
  const Result<Tolerance> two = choose_tolerance(joined(a, apart), std::nullopt);
  ASSERT_TRUE(two.ok());
  EXPECT_EQ(two.value().places, 2);
  EXPECT_DOUBLE_EQ(two.value().island_lengths[0], choose_tolerance(a, std::nullopt).value().length);
  EXPECT_DOUBLE_EQ(two.value().island_lengths[1], choose_tolerance(apart, std::nullopt).value().length);
}

TEST(ChooseTolerance, AFloat32IslandFarFromTheOriginGetsTheFloorOfItsOwnMagnitude) {
  // float32 rounding is relative: the box at the origin keeps its default,
  // the copy at 1e6 is raised to the rounding of coordinates near 1e6.
  Mesh m = joined(box_from({0, 0, 0}, {1, 2, 2}), box_from({1e6, 0, 0}, {1e6 + 1, 2, 2}));
  const double relative = std::numeric_limits<float>::epsilon() / 2.0;
  m.coordinate_relative_error = relative;
  m.coordinate_error = relative * (1e6 + 1);
  const Result<Tolerance> t = choose_tolerance(m, std::nullopt);
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t.value().island_lengths.size(), 2u);
  EXPECT_DOUBLE_EQ(t.value().island_lengths[0], 3.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(t.value().island_lengths[1], kRoundingErrorsPerPlaneTest * relative * (1e6 + 1));
  EXPECT_DOUBLE_EQ(t.value().floor, kRoundingErrorsPerPlaneTest * relative * (1e6 + 1));
  EXPECT_TRUE(t.value().raised_to_floor);
}

} // namespace
} // namespace hullcover

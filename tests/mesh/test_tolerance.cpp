#include "hullcover/mesh/tolerance.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

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
  m.coordinate_error = 1e-3;  // e.g. coordinates that went through float16
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

  // Zones meet where an island of several pieces reaches farther than its
  // pieces: two 10 x 20 x 20 boxes 0.2 apart are one island (each reaches
  // 0.3 beyond itself), whose zone reaches 1% of its 34.7 diagonal. The
  // small box 0.05 beyond the second one's reach is an island of its own,
  // inside that zone: the large island takes the small one's tolerance.
  const Mesh pair = joined(box_from({100, 0, 0}, {110, 20, 20}), box_from({110.2, 0, 0}, {120.2, 20, 20}));
  const Mesh near = joined(box_from({120.55, 0, 0}, {121.55, 2, 2}), pair);
  const Result<Tolerance> n = choose_tolerance(near, std::nullopt);
  ASSERT_TRUE(n.ok());
  ASSERT_EQ(n.value().island_lengths.size(), 2u);
  EXPECT_DOUBLE_EQ(n.value().island_lengths[0], 3.0 * kDefaultRelativeTolerance);
  EXPECT_DOUBLE_EQ(n.value().island_lengths[1], 3.0 * kDefaultRelativeTolerance);
  // Moved farther, the large island keeps its own.
  const Mesh apart = joined(box_from({121.55, 0, 0}, {122.55, 2, 2}), pair);
  const Result<Tolerance> a = choose_tolerance(apart, std::nullopt);
  ASSERT_TRUE(a.ok());
  ASSERT_EQ(a.value().island_lengths.size(), 2u);
  EXPECT_GT(a.value().island_lengths[1], 10.0 * kDefaultRelativeTolerance);
}

TEST(ChooseTolerance, ZonesMeetingAlongAChainShareTheirSmallest) {
  // Islands A and B (pairs of 10 x 20 x 20 boxes, as above) 0.65 apart:
  // apart as pieces, their zones meet. C, a small box just beyond B's
  // pieces' reach, meets B's zone but not A's. A takes C's tolerance through
  // B: a hull of A reaching B's zone is judged there at C's.
  const auto pair_at = [](double x) {
    return joined(box_from({x, 0, 0}, {x + 10, 20, 20}), box_from({x + 10.2, 0, 0}, {x + 20.2, 20, 20}));
  };
  const Mesh a_and_b = joined(pair_at(100.0), pair_at(120.85));
  const Mesh chain = joined(a_and_b, box_from({141.4, 0, 0}, {142.4, 2, 2}));
  const Result<Tolerance> t = choose_tolerance(chain, std::nullopt);
  ASSERT_TRUE(t.ok());
  ASSERT_EQ(t.value().island_lengths.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(t.value().island_lengths[i], 3.0 * kDefaultRelativeTolerance) << i;
  // Without C, A and B keep their own.
  const Result<Tolerance> two = choose_tolerance(a_and_b, std::nullopt);
  ASSERT_TRUE(two.ok());
  ASSERT_EQ(two.value().island_lengths.size(), 2u);
  EXPECT_GT(two.value().island_lengths[0], 30.0 * kDefaultRelativeTolerance);
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

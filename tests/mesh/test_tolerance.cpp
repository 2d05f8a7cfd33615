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

} // namespace
} // namespace hullcover

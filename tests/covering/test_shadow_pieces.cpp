// Cutting a region of rays along a triangle's shadow (shadow_pieces.h): the
// quick miss test that lets the exact judges pass over faces whose shadow
// does not reach a piece must never pass over one that does.

#include "shadow_pieces.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

namespace hullcover::detail {
namespace {

using V = Eigen::Vector3d;

TEST(ShadowColumn, MissesOnlyPiecesItsSplitLeavesNothingInside) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_vector = [&] { return V(unit(rng), unit(rng), unit(rng)); };
  const double tol = 1e-3;
  int missed = 0, shadowed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const V dir = random_vector().normalized();
    // A piece: a quad across the rays, a triangle somewhere along them.
    const V u = dir.unitOrthogonal(), v = dir.cross(u);
    const V centre = 0.5 * random_vector();
    const std::vector<V> piece = {centre - 0.3 * u - 0.2 * v, centre + 0.3 * u - 0.2 * v,
                                  centre + 0.3 * u + 0.2 * v, centre - 0.3 * u + 0.2 * v};
    const V at = 2.0 * dir + 1.2 * random_vector();
    std::vector<V> triangle = {at + 0.4 * random_vector(), at + 0.4 * random_vector(), at + 0.4 * random_vector()};
    if ((triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).norm() < 1e-3) continue;
    const ShadowColumn column = shadow_column(triangle, dir, tol);
    const ShadowSplit split = split_by_shadow(piece, column, tol);
    // The column made once gives the split the triangle gives.
    const ShadowSplit again = split_by_shadow(piece, triangle, dir, tol);
    ASSERT_EQ(split.inside.size(), again.inside.size());
    for (size_t i = 0; i < split.inside.size(); ++i) EXPECT_TRUE(split.inside[i] == again.inside[i]);
    ASSERT_EQ(split.beside.size(), again.beside.size());
    if (column.misses(piece)) {
      ++missed;
      EXPECT_TRUE(split.inside.empty()) << "trial " << trial << ": a piece in the shadow was called missed";
    } else {
      shadowed += !split.inside.empty();
    }
  }
  // Both answers occur, so the property above was put to the test.
  EXPECT_GT(missed, 300);
  EXPECT_GT(shadowed, 300);
}

} // namespace
} // namespace hullcover::detail

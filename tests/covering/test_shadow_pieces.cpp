// Cutting a region of rays along a triangle's shadow (shadow_pieces.h): the
// quick miss test that lets the exact judges pass over faces whose shadow
// does not reach a piece must never pass over one that does.

#include "validity/shadow_pieces.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace hullcover::detail {
namespace {

using V = Eigen::Vector3d;

// A piece of a sweep along `dir`: a quad across the rays about `centre`.
std::vector<V> piece_across(const V& dir, const V& centre) {
  const V u = dir.unitOrthogonal(), v = dir.cross(u);
  return {centre - 0.3 * u - 0.2 * v, centre + 0.3 * u - 0.2 * v, centre + 0.3 * u + 0.2 * v,
          centre - 0.3 * u + 0.2 * v};
}

TEST(ShadowColumn, MissesOnlyPiecesItsSplitLeavesNothingInside) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_vector = [&] { return V(unit(rng), unit(rng), unit(rng)); };
  const double tol = 1e-3;
  int missed = 0, shadowed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const V dir = random_vector().normalized();
    // A piece: a quad across the rays, a triangle somewhere along them.
    const std::vector<V> piece = piece_across(dir, 0.5 * random_vector());
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

TEST(ShadowSplit, ASplitReusedFromCallToCallGivesWhatAFreshOneGives) {
  // As the judges use them: one split and one pair of buffers for many
  // pieces and columns, each giving bit for bit what a fresh split and
  // clip_polygon_to_planes with column_planes give.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto random_vector = [&] { return V(unit(rng), unit(rng), unit(rng)); };
  const double tol = 1e-3;
  ShadowSplit reused;
  std::vector<V> clipped, spare;
  int cut = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const V dir = random_vector().normalized();
    const std::vector<V> piece = piece_across(dir, 0.5 * random_vector());
    const V at = 2.0 * dir + 0.6 * random_vector();
    const std::vector<V> triangle = {at + 0.5 * random_vector(), at + 0.5 * random_vector(),
                                     at + 0.5 * random_vector()};
    if ((triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).norm() < 1e-3) continue;
    const ShadowColumn column = shadow_column(triangle, dir, tol);
    const ShadowSplit fresh = split_by_shadow(piece, column, tol);
    split_by_shadow(piece, column, tol, reused);
    ASSERT_TRUE(reused.inside == fresh.inside) << "trial " << trial;
    ASSERT_EQ(reused.beside.size(), fresh.beside.size()) << "trial " << trial;
    for (size_t i = 0; i < fresh.beside.size(); ++i) EXPECT_TRUE(reused.beside[i] == fresh.beside[i]);
    cut += !fresh.inside.empty() && !fresh.beside.empty();

    clip_to_column(piece, triangle, dir, clipped, spare);
    EXPECT_TRUE(clipped == clip_polygon_to_planes(piece, column_planes(triangle, dir), 0.0)) << "trial " << trial;
  }
  EXPECT_GT(cut, 300); // pieces were cut, not only passed whole
}

// The narrowest width of convex polygon `polygon` over its edges'
// directions, measured plainly: what negligible() compares with its
// threshold.
double least_width(const std::vector<V>& polygon) {
  V normal = V::Zero();
  for (size_t i = 1; i + 1 < polygon.size(); ++i)
    normal += (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]);
  double least = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < polygon.size(); ++i) {
    const V across = normal.cross(polygon[(i + 1) % polygon.size()] - polygon[i]).normalized();
    double widest = 0.0;
    for (const V& p : polygon) widest = std::max(widest, std::abs(across.dot(p - polygon[i])));
    least = std::min(least, widest);
  }
  return least;
}

TEST(Negligible, AgreesWithThePolygonsWidthFarFromItsOrigin) {
  // Slivers and fat pieces alike, far from the origin (where an area taken
  // about the origin would be lost to cancellation): the quick bound for
  // fat pieces must never call a sliver fat, nor the other way round.
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double tol = 1e-3;
  const double threshold = kNegligibleWidthInTolerances * tol;
  int slivers = 0, fat = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const V centre = V(1e3, -2e3, 5e2) + 100.0 * V(unit(rng), unit(rng), unit(rng));
    const V u = V(unit(rng), unit(rng), unit(rng)).normalized();
    const V v = u.cross(V(unit(rng), unit(rng), unit(rng))).normalized();
    // Widths from a hundredth to a hundred times the threshold.
    const double width = threshold * std::pow(10.0, -2.0 + 4.0 * (0.5 + 0.5 * unit(rng)));
    const double length = 0.01 + std::abs(unit(rng));
    const int n = 3 + trial % 4;
    std::vector<V> polygon;
    for (int i = 0; i < n; ++i) {
      const double angle = 2.0 * 3.141592653589793 * i / n;
      polygon.push_back(centre + 0.5 * length * std::cos(angle) * u + 0.5 * width * std::sin(angle) * v);
    }
    const double measured = least_width(polygon);
    // Away from the threshold (rounding at these coordinates is far below
    // a tenth of it), the verdict follows the width.
    if (measured < 0.9 * threshold) {
      ++slivers;
      EXPECT_TRUE(negligible(polygon, tol)) << "trial " << trial << ": width " << measured;
    } else if (measured > 1.1 * threshold) {
      ++fat;
      EXPECT_FALSE(negligible(polygon, tol)) << "trial " << trial << ": width " << measured;
    }
  }
  EXPECT_GT(slivers, 1000);
  EXPECT_GT(fat, 1000);
}

} // namespace
} // namespace hullcover::detail

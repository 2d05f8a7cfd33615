// triangle_distance and segment_distance: exact on cases whose answer is
// known by construction, never above a dense sampling of point pairs, and
// the same under a rotation (what near merges rely on).

#include "hullcover/geometry/triangle_distance.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;

// Rounding allowed in a distance computed from unit-sized coordinates.
constexpr double kUnitRounding = 1e-12;

TEST(SegmentDistance, SkewParallelAndPointCases) {
  // Skew: x axis and a line along z one unit above it.
  EXPECT_NEAR(segment_distance(V(-1, 0, 0), V(1, 0, 0), V(0, 1, -1), V(0, 1, 1)), 1.0, kUnitRounding);
  // Parallel and overlapping, 2 apart.
  EXPECT_NEAR(segment_distance(V(0, 0, 0), V(2, 0, 0), V(1, 2, 0), V(3, 2, 0)), 2.0, kUnitRounding);
  // Collinear with a gap of 1.
  EXPECT_NEAR(segment_distance(V(0, 0, 0), V(1, 0, 0), V(2, 0, 0), V(3, 0, 0)), 1.0, kUnitRounding);
  // A point against a segment, and two points.
  EXPECT_NEAR(segment_distance(V(0.5, 3, 0), V(0.5, 3, 0), V(0, 0, 0), V(1, 0, 0)), 3.0, kUnitRounding);
  EXPECT_NEAR(segment_distance(V(0, 0, 0), V(0, 0, 0), V(0, 0, 4), V(0, 0, 4)), 4.0, kUnitRounding);
}

TEST(TriangleDistance, KnownConfigurations) {
  const V floor[3] = {V(0, 0, 0), V(2, 0, 0), V(0, 0, 2)};
  const V above[3] = {V(0, 1, 0), V(2, 1, 0), V(0, 1, 2)};                // parallel, 1 above
  const V crossing[3] = {V(0.5, -1, 0.5), V(0.5, 1, 0.5), V(0.6, 0, -3)}; // pierces the floor
  const V edge_to_edge[3] = {V(3, 0, -1), V(3, 0, 3), V(5, 0, 1)};        // side x = 3 faces the floor's hypotenuse end
  const V touching[3] = {V(2, 0, 0), V(3, 1, 0), V(3, -1, 0)};            // shares the floor's corner
  EXPECT_NEAR(triangle_distance(floor, above), 1.0, kUnitRounding);
  EXPECT_NEAR(triangle_distance(floor, crossing), 0.0, kUnitRounding);
  EXPECT_NEAR(triangle_distance(floor, edge_to_edge), 1.0, kUnitRounding);
  EXPECT_NEAR(triangle_distance(floor, touching), 0.0, kUnitRounding);
  // Two crossing sides, neither triangle's corner near the other (edge-edge).
  const V bar_a[3] = {V(-1, 0, 0), V(1, 0, 0), V(0, -0.001, -5)};
  const V bar_b[3] = {V(0, 0.5, -1), V(0, 0.5, 1), V(5, 0.501, 0)};
  EXPECT_NEAR(triangle_distance(bar_a, bar_b), 0.5, kUnitRounding);
}

constexpr int kPairs = 200, kSamplesPerSide = 30;
// A sampled pair's distance exceeds the true one by at most the sample
// spacing on both triangles (their sides are under 2 sqrt(3) long).
constexpr double kSamplingSlack = 2.0 * 3.5 / kSamplesPerSide;

// Random pairs: never above the nearest of many sampled point pairs, not far
// below it (sampling resolution), and the same once both are turned.
TEST(TriangleDistance, AgreesWithSamplingAndIgnoresRotation) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  const auto random_point = [&] { return V(coordinate(rng), coordinate(rng), coordinate(rng)); };
  const auto samples = [](const V(&t)[3]) {
    std::vector<V> out;
    for (int i = 0; i <= kSamplesPerSide; ++i)
      for (int j = 0; i + j <= kSamplesPerSide; ++j)
        out.push_back(t[0] + (t[1] - t[0]) * i / kSamplesPerSide + (t[2] - t[0]) * j / kSamplesPerSide);
    return out;
  };
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, V(1, 2, 3).normalized()).toRotationMatrix();
  for (int k = 0; k < kPairs; ++k) {
    const V offset = 1.5 * random_point();
    const V s[3] = {random_point(), random_point(), random_point()};
    const V t[3] = {random_point() + offset, random_point() + offset, random_point() + offset};
    const double d = triangle_distance(s, t);
    double sampled = std::numeric_limits<double>::infinity();
    for (const V& p : samples(s))
      for (const V& q : samples(t)) sampled = std::min(sampled, (p - q).norm());
    EXPECT_LE(d, sampled + kUnitRounding) << "pair " << k;
    EXPECT_GE(d, sampled - kSamplingSlack) << "pair " << k;
    const V s_turned[3] = {turn * s[0], turn * s[1], turn * s[2]};
    const V t_turned[3] = {turn * t[0], turn * t[1], turn * t[2]};
    EXPECT_NEAR(triangle_distance(s_turned, t_turned), d, kUnitRounding) << "pair " << k;
  }
}

TEST(TrianglesWithin, AnswersAsTheDistanceComparedAtEveryThreshold) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  const auto random_point = [&] { return V(coordinate(rng), coordinate(rng), coordinate(rng)); };
  int apart = 0;
  for (int k = 0; k < 2000; ++k) {
    const V offset = 2.0 * random_point();
    const V s[3] = {random_point(), random_point(), random_point()};
    const V t[3] = {random_point() + offset, random_point() + offset, random_point() + offset};
    const double d = triangle_distance(s, t);
    apart += d > 0.0;
    // At the distance itself and one rounding step either side: the
    // bounded test stops early, yet must agree to the last bit.
    for (const double threshold : {0.0, std::nextafter(d, 0.0), d, std::nextafter(d, 10.0), 0.5 * d, 2.0 * d + 0.1})
      EXPECT_EQ(triangles_within(s, t, threshold), d <= threshold) << "pair " << k << " at " << threshold;
  }
  EXPECT_GT(apart, 1000); // most pairs are apart, so the thresholds below d are asked
  // Corners that are no numbers: the distance is infinity, met only by it.
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const V s[3] = {V(nan, nan, nan), V(nan, nan, nan), V(nan, nan, nan)};
  const V t[3] = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
  EXPECT_EQ(triangle_distance(s, t), inf);
  for (const double threshold : {0.0, 1e300, inf, nan})
    EXPECT_EQ(triangles_within(s, t, threshold), triangle_distance(s, t) <= threshold) << threshold;
}

// Ericson's closest points of two segments with the re-clamp of s written
// as branches: what closest_points_of_segments computes with masks. `side`
// says which re-clamp ran (-1: t below 0, 1: t above 1, 0: none).
std::pair<Eigen::Vector3d, Eigen::Vector3d> branching_closest_points(const Eigen::Vector3d& p0,
                                                                     const Eigen::Vector3d& p1,
                                                                     const Eigen::Vector3d& q0,
                                                                     const Eigen::Vector3d& q1, int& side) {
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2);
  const double denominator = a * e - b * b;
  double s = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  side = 0;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
    side = -1;
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
    side = 1;
  }
  return {p0 + s * d1, q0 + t * d2};
}

// Segments of every length and direction, parallel ones included: the
// same points, bit for bit, as the branching form, with t past either end
// met many times.
TEST(SegmentDistance, ClosestPointsEqualTheBranchingForm) {
  std::mt19937 rng(20261206);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  int past[3] = {0, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d p0(u(rng), u(rng), u(rng)), q0(u(rng), u(rng), u(rng));
    Eigen::Vector3d p1(u(rng), u(rng), u(rng)), q1(u(rng), u(rng), u(rng));
    if (i % 10 == 0) q1 = q0 + 0.5 * (p1 - p0); // parallel
    int side = 0;
    const auto expected = branching_closest_points(p0, p1, q0, q1, side);
    const auto got = closest_points_of_segments(p0, p1, q0, q1);
    ASSERT_EQ(got.first, expected.first) << i;
    ASSERT_EQ(got.second, expected.second) << i;
    ++past[side + 1];
  }
  EXPECT_GT(std::min({past[0], past[1], past[2]}), 2000);
}

// The branch-free clamp of the closest-point parameters equals
// std::clamp's on every kind of double: either side of 0 and 1, both
// zeros, the ends themselves, subnormals and infinities.
TEST(UnitClamp, EqualsStdClamp) {
  std::mt19937_64 rng(20261206);
  std::vector<double> xs = {0.0,
                            -0.0,
                            1.0,
                            std::nextafter(1.0, 2.0),
                            std::nextafter(1.0, 0.0),
                            std::numeric_limits<double>::denorm_min(),
                            -std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::max(),
                            std::numeric_limits<double>::lowest()};
  std::uniform_real_distribution<double> u(-2.0, 3.0);
  for (int i = 0; i < 10000; ++i) xs.push_back(u(rng));
  int below = 0, inside = 0, above = 0;
  for (double x : xs) {
    EXPECT_EQ(unit_clamp(x), std::clamp(x, 0.0, 1.0)) << x;
    below += x < 0.0;
    inside += x > 0.0 && x < 1.0;
    above += x > 1.0;
  }
  EXPECT_GT(std::min({below, inside, above}), 1000);
}

} // namespace
} // namespace hullcover

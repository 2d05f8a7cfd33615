// The ray clip two planes at a time (bvh/src/planes_ray_hit.h) against the
// clip one plane at a time: the same hit, bit for bit, on random hulls'
// planes with odd and even counts, repeated planes (ties for the entering
// plane), planes parallel to the ray, and origins inside and outside. This
// file is built twice: with the SSE2 pairs where the compiler offers them,
// and with the plain loop (HULLCOVER_PLANE_PAIRS_SSE2=0).

#include "planes_ray_hit.h" // private to bvh

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace hullcover::bvh::detail {
namespace {

std::vector<PlanePair> pairs_of(const std::vector<Plane>& planes) {
  std::vector<PlanePair> pairs((planes.size() + 1) / 2);
  for (size_t i = 0; i < 2 * pairs.size(); ++i) {
    PlanePair& q = pairs[i / 2];
    const size_t l = i % 2;
    if (i < planes.size()) {
      q.nx[l] = planes[i].normal.x();
      q.ny[l] = planes[i].normal.y();
      q.nz[l] = planes[i].normal.z();
      q.offset[l] = planes[i].offset;
    } else {
      q.nx[l] = q.ny[l] = q.nz[l] = 0.0;
      q.offset[l] = std::numeric_limits<double>::max();
    }
  }
  return pairs;
}

TEST(PlanePairs, TwoPlanesAtATimeHitWhereOneAtATimeDoes) {
  std::mt19937 rng(20261206);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0, from_inside = 0, misses = 0, ties = 0;
  for (int trial = 0; trial < 50000; ++trial) {
    const int count = 1 + static_cast<int>(rng() % 13), facets = 1 + static_cast<int>(rng() % count);
    std::vector<Plane> planes(count);
    for (int i = 0; i < count; ++i) {
      Eigen::Vector3d n(u(rng), u(rng), u(rng));
      if (rng() % 5 == 0) n.z() = 0.0; // parallel to the rays made level below
      if (rng() % 7 == 0) n = Eigen::Vector3d(0.0, 0.0, rng() % 2 ? 1.0 : -1.0);
      planes[i] = {n.normalized(), 0.3 + 0.5 * std::abs(u(rng))};
      if (i > 0 && rng() % 11 == 0) {
        planes[i] = planes[rng() % i]; // equal entries: the lower plane wins
        ++ties;
      }
    }
    Eigen::Vector3d origin(2.0 * u(rng), 2.0 * u(rng), 2.0 * u(rng)), dir(u(rng), u(rng), u(rng));
    if (rng() % 6 == 0) dir.z() = 0.0;
    if (rng() % 9 == 0) origin *= 0.1;
    dir.normalize();
    const double reach = 4.0 * std::abs(u(rng));
    const std::vector<PlanePair> pairs = pairs_of(planes);
    const auto one = first_hit_on_planes(planes.data(), count, facets, origin, dir, reach);
    const auto two = first_hit_on_plane_pairs(pairs.data(), count, facets, origin, dir, reach);
    ASSERT_EQ(one.has_value(), two.has_value()) << "trial " << trial;
    if (!one) {
      ++misses;
      continue;
    }
    ++hits;
    from_inside += one->t == 0.0;
    EXPECT_EQ(one->t, two->t) << "trial " << trial;
    EXPECT_EQ(one->point, two->point) << "trial " << trial;
    EXPECT_EQ(one->normal, two->normal) << "trial " << trial;
  }
  // Every case is met many times.
  EXPECT_GT(hits - from_inside, 2000);
  EXPECT_GT(from_inside, 2000);
  EXPECT_GT(misses, 2000);
  EXPECT_GT(ties, 2000);
}

// Rays aimed at a cube's edges and corners along its diagonals enter
// through two or three faces at the same t, to the bit: the hit takes the
// lowest-numbered of them, however the faces are numbered.
TEST(PlanePairs, ARayThroughAnEdgeEntersByTheLowestNumberedFace) {
  std::mt19937 rng(7);
  std::vector<Plane> cube;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) cube.push_back({side * Eigen::Vector3d::Unit(axis), 1.0});
  int tied = 0;
  for (int order = 0; order < 200; ++order) {
    std::shuffle(cube.begin(), cube.end(), rng);
    const std::vector<PlanePair> pairs = pairs_of(cube);
    for (int sx = -1; sx <= 1; ++sx)
      for (int sy = -1; sy <= 1; ++sy)
        for (int sz = -1; sz <= 1; ++sz) {
          const Eigen::Vector3d s(sx, sy, sz);
          if (s.cwiseAbs().sum() < 2.0) continue; // a face's middle: no tie
          const Eigen::Vector3d origin = 3.0 * s, dir = -s.normalized();
          const auto one = first_hit_on_planes(cube.data(), 6, 6, origin, dir, 10.0);
          const auto two = first_hit_on_plane_pairs(pairs.data(), 6, 6, origin, dir, 10.0);
          ASSERT_TRUE(one && two);
          int lowest = -1;
          for (int i = 0; i < 6 && lowest < 0; ++i)
            if (cube[i].normal.dot(s) > 0.0) lowest = i;
          EXPECT_EQ(one->normal, cube[lowest].normal);
          EXPECT_EQ(two->normal, cube[lowest].normal);
          EXPECT_EQ(one->t, two->t);
          ++tied;
        }
  }
  EXPECT_EQ(tied, 200 * 20);
}

} // namespace
} // namespace hullcover::bvh::detail

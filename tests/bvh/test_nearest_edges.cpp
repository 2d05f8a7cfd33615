// The nearest edge to a segment two edges at a time (bvh/src/nearest_edges.h)
// against a scan of the edges one at a time with closest_points_of_segments:
// the same edge, squared distance and points, bit for bit, on random hulls'
// edges with odd and even counts, repeated edges (ties, where the first
// must win), edges of no length, edges parallel to the segment and bounds
// that no edge beats. This file is built twice: with the SSE2 pairs where
// the compiler offers them, and with the plain loop
// (HULLCOVER_PLANE_PAIRS_SSE2=0).

#include "nearest_edges.h" // private to bvh

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

namespace hullcover::bvh::detail {
namespace {

using V = Eigen::Vector3d;

// The scan one edge at a time, as a capsule's contact made it.
NearestEdge scan(const SegmentTerms& axis, const std::vector<V>& vertices,
                 const std::vector<std::pair<int, int>>& edges, double bound) {
  NearestEdge best;
  best.squared = bound;
  for (int i = 0; i < static_cast<int>(edges.size()); ++i) {
    const auto [on_segment, on_edge] =
        closest_points_of_segments(axis, vertices[edges[i].first], vertices[edges[i].second]);
    const double d2 = (on_segment - on_edge).squaredNorm();
    if (d2 < best.squared) {
      best = {i, d2, on_segment, on_edge};
    }
  }
  return best;
}

void expect_same(const NearestEdge& x, const NearestEdge& y) {
  EXPECT_EQ(x.edge, y.edge);
  EXPECT_EQ(x.squared, y.squared); // bit for bit, not within a tolerance
  if (x.edge >= 0 && y.edge >= 0) {
    EXPECT_EQ(x.on_segment, y.on_segment);
    EXPECT_EQ(x.on_edge, y.on_edge);
  }
}

TEST(NearestEdges, TwoEdgesAtATimeFindTheEdgeAndPointsOneAtATimeDoes) {
  std::mt19937 rng(20261207);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  std::uniform_int_distribution<int> count_of(1, 13);
  const auto random_point = [&] { return V(coordinate(rng), coordinate(rng), coordinate(rng)); };
  int found = 0, ties = 0, degenerate = 0, parallel = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<V> vertices;
    for (int i = 0, n = count_of(rng) + 1; i < n; ++i) vertices.push_back(random_point());
    std::uniform_int_distribution<int> vertex(0, static_cast<int>(vertices.size()) - 1);
    std::vector<std::pair<int, int>> edges;
    for (int i = 0, n = count_of(rng); i < n; ++i) edges.emplace_back(vertex(rng), vertex(rng));
    const V a = random_point();
    const V b = trial % 7 == 0 ? a + V(1e-3, 0.0, 0.0) : random_point();
    // Now and then an edge repeated (a tie), of no length, or parallel to
    // the segment.
    if (trial % 5 == 0) {
      edges.push_back(edges.front());
      ++ties;
    }
    if (trial % 6 == 0) {
      edges.insert(edges.begin() + static_cast<long>(edges.size() / 2), {edges.back().first, edges.back().first});
      ++degenerate;
    }
    if (trial % 4 == 0) {
      vertices.push_back(vertices[0] + (b - a));
      edges.emplace_back(0, static_cast<int>(vertices.size()) - 1);
      ++parallel;
    }
    const SegmentTerms axis(a, b);
    const double bound = trial % 3 == 0 ? std::numeric_limits<double>::infinity() : coordinate(rng) * coordinate(rng);
    const NearestEdge fast = nearest_edge_to_segment(axis, vertices, edges, bound);
    const NearestEdge slow = scan(axis, vertices, edges, bound);
    expect_same(fast, slow);
    found += slow.edge >= 0;
  }
  // The cases were reached: most trials find an edge, some none.
  EXPECT_GT(found, 2000);
  EXPECT_LT(found, 4000);
  EXPECT_GT(ties + degenerate + parallel, 2000);
}

TEST(NearestEdges, TheFirstOfTwoEqualEdgesWins) {
  // Two copies of one edge in lanes 0 and 1, then in lanes 1 and 0 of the
  // next pair: the lower number wins both times.
  const std::vector<V> vertices = {V(0, 0, 1), V(1, 0, 1), V(5, 5, 5), V(6, 5, 5)};
  const SegmentTerms axis(V(0, 0, 0), V(1, 0, 0));
  EXPECT_EQ(nearest_edge_to_segment(axis, vertices, {{0, 1}, {0, 1}}, 1e9).edge, 0);
  EXPECT_EQ(nearest_edge_to_segment(axis, vertices, {{2, 3}, {0, 1}, {0, 1}}, 1e9).edge, 1);
  const NearestEdge far = nearest_edge_to_segment(axis, vertices, {{2, 3}, {0, 1}}, 0.5); // 1 away: not below 0.5
  EXPECT_EQ(far.edge, -1);
  EXPECT_EQ(far.squared, 0.5);
}

} // namespace
} // namespace hullcover::bvh::detail

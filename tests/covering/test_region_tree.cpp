// The regions a movement covering merges in (lib/covering/src/movement/
// region_tree.h): how faces are split, and the order the joins of their
// groups run in on any number of threads.

#include "movement/region_tree.h"

#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace hullcover::detail {
namespace {

// A strip of `n` small triangles along x, one unit apart.
Mesh strip(int n) {
  Mesh mesh;
  for (int i = 0; i < n; ++i) {
    const int v = static_cast<int>(mesh.positions.size());
    mesh.positions.emplace_back(i, 0, 0);
    mesh.positions.emplace_back(i + 0.5, 0, 0);
    mesh.positions.emplace_back(i, 0.5, 0);
    mesh.triangles.emplace_back(v, v + 1, v + 2);
  }
  return mesh;
}

std::vector<int> all_faces(const Mesh& mesh) {
  std::vector<int> faces(mesh.triangles.size());
  std::iota(faces.begin(), faces.end(), 0);
  return faces;
}

TEST(RegionTree, RegionsHoldAtMostTheLimitAndJoinsPairNeighbouringRanges) {
  const Mesh mesh = strip(100);
  const RegionTree tree = split_into_regions(mesh, all_faces(mesh), 8);
  std::vector<int> size(tree.regions, 0);
  for (int r : tree.region_of) ++size[r];
  for (int s : size) {
    EXPECT_GE(s, 1);
    EXPECT_LE(s, 8);
  }
  // Halving 100 faces until at most 8: 16 regions of 6 or 7, 15 joins.
  EXPECT_EQ(tree.regions, 16);
  ASSERT_EQ(tree.joins.size(), 15u);
  // Depth first along the strip: each region's faces are consecutive.
  for (size_t f = 1; f < tree.region_of.size(); ++f) EXPECT_GE(tree.region_of[f], tree.region_of[f - 1]);
  // Every join's halves are a region or a lower join; the last spans all.
  std::map<std::pair<int, int>, int> height;
  for (int r = 0; r < tree.regions; ++r) height[{r, r + 1}] = 0;
  for (const RegionJoin& j : tree.joins) {
    ASSERT_LT(j.first, j.split);
    ASSERT_LT(j.split, j.end);
    ASSERT_TRUE(height.count({j.first, j.split}));
    ASSERT_TRUE(height.count({j.split, j.end}));
    EXPECT_EQ(j.height, 1 + std::max(height[{j.first, j.split}], height[{j.split, j.end}]));
    height[{j.first, j.end}] = j.height;
  }
  EXPECT_EQ(tree.joins.back().first, 0);
  EXPECT_EQ(tree.joins.back().end, tree.regions);
}

TEST(RegionTree, FewFacesAreOneRegionWithoutJoins) {
  const Mesh mesh = strip(5);
  const RegionTree tree = split_into_regions(mesh, all_faces(mesh), 512);
  EXPECT_EQ(tree.regions, 1);
  EXPECT_TRUE(tree.joins.empty());
  const RegionTree none = split_into_regions(mesh, {}, 512);
  EXPECT_EQ(none.regions, 0);
}

TEST(RegionTree, EveryJoinRunsOnceAfterBothItsHalvesOnAnyThreadCount) {
  const Mesh mesh = strip(300);
  const RegionTree tree = split_into_regions(mesh, all_faces(mesh), 4);
  for (int threads : {1, 2, 4}) {
    SCOPED_TRACE(threads);
    std::mutex mutex;
    std::map<std::pair<int, int>, int> done; // range -> times run
    int order = 0;
    std::vector<int> finished_at(tree.regions + tree.joins.size(), -1);
    run_regions_and_joins(
        tree, threads,
        [&](int r) {
      const std::lock_guard<std::mutex> lock(mutex);
      ++done[{r, r + 1}];
      finished_at[r] = order++;
        },
        [&](int j) {
      const RegionJoin& join = tree.joins[j];
      const std::lock_guard<std::mutex> lock(mutex);
      EXPECT_EQ((done[{join.first, join.split}]), 1);
      EXPECT_EQ((done[{join.split, join.end}]), 1);
      ++done[{join.first, join.end}];
      finished_at[tree.regions + j] = order++;
    });
    for (int r = 0; r < tree.regions; ++r) EXPECT_EQ((done[{r, r + 1}]), 1);
    for (const RegionJoin& j : tree.joins) EXPECT_EQ((done[{j.first, j.end}]), 1);
    for (int f : finished_at) EXPECT_GE(f, 0);
  }
}

TEST(RegionTree, AFailingCallStopsTheRestAndIsRethrown) {
  const Mesh mesh = strip(64);
  const RegionTree tree = split_into_regions(mesh, all_faces(mesh), 4);
  for (int threads : {1, 2}) {
    std::atomic<int> joins_run{0};
    EXPECT_THROW(run_regions_and_joins(
                     tree, threads,
                     [&](int r) {
      if (r == 3) throw std::runtime_error("region 3");
                     },
                     [&](int) { ++joins_run; }),
                 std::runtime_error);
    // The joins above region 3, the last one among them, never ran.
    EXPECT_LT(joins_run.load(), static_cast<int>(tree.joins.size()));
  }
}

} // namespace
} // namespace hullcover::detail

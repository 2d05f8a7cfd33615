// The thread helpers of hullcover/geometry/parallel_for.h: every job runs
// once on any thread count, an ordered commit sees indices in order, and a
// reporting run tells its fraction from the calling thread, rising to 1.

#include "hullcover/geometry/parallel_for.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <thread>
#include <vector>

namespace hullcover {
namespace {

TEST(ParallelFor, RunsEveryJobOnceOnAnyThreadCount) {
  for (int threads : {1, 2, 5}) {
    std::vector<int> runs(1000, 0);
    parallel_for(static_cast<int>(runs.size()), threads, [&](int i) { ++runs[i]; });
    EXPECT_EQ(std::count(runs.begin(), runs.end(), 1), 1000) << threads << " threads";
  }
}

TEST(ParallelFor, RethrowsAJobsExceptionOnceEveryThreadHasStopped) {
  EXPECT_THROW(parallel_for(
                   100, 3,
                   [](int i) {
    if (i == 17) throw std::runtime_error("job 17");
                   }),
               std::runtime_error);
}

TEST(ParallelFor, OrderedCommitsSeeIndicesInOrder) {
  std::vector<int> committed;
  parallel_for_ordered(
      250, 3, 16, [](int) {}, [&](int i) { committed.push_back(i); });
  ASSERT_EQ(committed.size(), 250u);
  for (int i = 0; i < 250; ++i) EXPECT_EQ(committed[i], i);
}

TEST(ParallelFor, AReportingRunTellsItsRisingFractionFromTheCallingThread) {
  const std::thread::id caller = std::this_thread::get_id();
  for (int count : {1, 63, 64, 1000}) {
    std::vector<int> runs(count, 0);
    std::vector<double> told;
    parallel_for_reporting(
        count, 3, 64, [&](int i) { ++runs[i]; },
        [&](double fraction) {
      EXPECT_EQ(std::this_thread::get_id(), caller);
      told.push_back(fraction);
        });
    EXPECT_EQ(std::count(runs.begin(), runs.end(), 1), count);
    ASSERT_FALSE(told.empty());
    EXPECT_LE(told.size(), 64u) << count << " jobs";
    EXPECT_TRUE(std::is_sorted(told.begin(), told.end()));
    EXPECT_GT(told.front(), 0.0);
    EXPECT_EQ(told.back(), 1.0);
  }
  // Without a report it is parallel_for: every job, no batches to tell.
  std::vector<int> runs(10, 0);
  parallel_for_reporting(10, 2, 64, [&](int i) { ++runs[i]; }, {});
  EXPECT_EQ(std::count(runs.begin(), runs.end(), 1), 10);
}

} // namespace
} // namespace hullcover

// StreamedWorld's threading contract (streamed_world.h): queries from
// several threads while another thread loads and unloads a section give, at
// every call, the answer with that section or the answer without it, never
// a mixture of the two; a ray batch answers every ray on one snapshot. Run under
// ThreadSanitizer by preset tsan (docs/design.md, "Streaming cells").

#include "streamed_world_fixture.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <thread>

namespace hullcover::bvh {
namespace {

using test::Answers;
using test::ask;
using test::same_answers;

TEST(StreamedWorld, QueriesDuringLoadsSeeTheSectionWhollyOrNotAtAll) {
  const test::SectionedWorld w = test::make_sectioned_world(31, 300);
  StreamedWorld streamed;
  // The section toggled: an inner cell, so poses around it cross its borders.
  const SectionHulls& toggled = w.sections[5];
  for (const SectionHulls& s : w.sections)
    if (s.id != toggled.id) {
      ASSERT_TRUE(streamed.add_section(s).ok());
    }
  // The two valid answers of every pose: with the section, and without it.
  const std::vector<test::Pose> poses = test::seeded_poses(13, 160);
  std::vector<Answers> with, without;
  for (const test::Pose& p : poses) without.push_back(ask(streamed, p));
  ASSERT_TRUE(streamed.add_section(toggled).ok());
  for (const test::Pose& p : poses) with.push_back(ask(streamed, p));
  int differing = 0;
  for (size_t i = 0; i < poses.size(); ++i) differing += !same_answers(with[i], without[i]);
  ASSERT_GT(differing, 10) << "the toggled section matters to some poses";
  // A batch of the rays whose answer the section changes.
  std::vector<RayRequest> batch;
  std::vector<RayResult> batch_with, batch_without;
  for (size_t i = 0; i < poses.size(); ++i)
    if (with[i].ray.hit != without[i].ray.hit || with[i].ray.first.hull != without[i].ray.first.hull) {
      batch.push_back(poses[i].ray);
      batch_with.push_back(with[i].ray);
      batch_without.push_back(without[i].ray);
    }
  ASSERT_GE(batch.size(), 3u);
  const auto same_rays = [](const std::vector<RayResult>& x, const std::vector<RayResult>& y) {
    for (size_t k = 0; k < x.size(); ++k)
      if (x[k].hit != y[k].hit || x[k].first.hull != y[k].first.hull || x[k].first.t != y[k].first.t) return false;
    return true;
  };

  std::atomic<bool> done{false};
  std::atomic<int> failures{0}, seen_with{0}, seen_without{0}, batches{0};
  std::vector<std::thread> readers;
  for (int t = 0; t < 3; ++t)
    readers.emplace_back([&, t] {
      for (size_t i = t; !done.load(); i = (i + 1) % poses.size()) {
        const Answers a = ask(streamed, poses[i]);
        // Each call answers on its own snapshot: `a` may mix the two worlds
        // from one query to the next, never within one.
        failures += !test::each_query_as_one_of(a, with[i], without[i]);
        const bool is_with = same_answers(a, with[i]), is_without = same_answers(a, without[i]);
        if (is_with != is_without) ++(is_with ? seen_with : seen_without);
        if (i % 16 == 0) {
          std::vector<RayResult> results;
          if (!streamed.ray_cast_batch(batch, results).ok()) ++failures;
          failures += !same_rays(results, batch_with) && !same_rays(results, batch_without);
          ++batches;
        }
      }
    });
  // The loader: unload and load the section again and again, as a server
  // does when players cross the cell's border.
  std::thread loader([&] {
    for (int round = 0; round < 40; ++round) {
      if (!streamed.remove_section(toggled.id).ok()) ++failures;
      std::this_thread::yield();
      if (!streamed.add_section(toggled).ok()) ++failures;
      std::this_thread::yield();
    }
    done = true;
  });
  loader.join();
  for (std::thread& r : readers) r.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_GT(batches.load(), 0);
  std::printf("answers with the section %d, without it %d, ray batches %d\n", seen_with.load(), seen_without.load(),
              batches.load());
  // After the last load, the answers with the section.
  for (size_t i = 0; i < poses.size(); ++i) EXPECT_TRUE(same_answers(ask(streamed, poses[i]), with[i])) << i;
  test::remove_sectioned_world(w);
}

// Sections loaded from several threads at once (each build off the lock,
// publishing in turn) end as the same world as loaded one by one.
TEST(StreamedWorld, ConcurrentLoadsEndAsTheWholeWorld) {
  const test::SectionedWorld w = test::make_sectioned_world(37, 240);
  StreamedWorld streamed;
  std::atomic<int> failures{0};
  std::vector<std::thread> loaders;
  for (int t = 0; t < 4; ++t)
    loaders.emplace_back([&, t] {
      for (size_t s = t; s < w.sections.size(); s += 4)
        if (!streamed.add_section(w.sections[s]).ok()) ++failures;
    });
  for (std::thread& l : loaders) l.join();
  EXPECT_EQ(failures.load(), 0);
  for (const test::Pose& p : test::seeded_poses(17, 120)) {
    std::string why;
    EXPECT_TRUE(same_answers(ask(*w.full, p), ask(streamed, p), &why)) << why;
  }
  test::remove_sectioned_world(w);
}

} // namespace
} // namespace hullcover::bvh

// Batches on QueryThreads: the same answers as the plain calls on any
// thread count, and the same lowest bad index. It links the runtime alone,
// so the ThreadSanitizer build (preset tsan) runs it.

#include "box_field.h"
#include "hullcover/bvh/hull_world.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;
using ::hullcover::test::at;
using ::hullcover::test::box_field;
using ::hullcover::test::Probe;
using ::hullcover::test::probes;
using ::hullcover::test::same_contacts;

TEST(QueryThreads, BatchesAnswerAlikeOnAnyThreadCount) {
  const auto world = box_field();
  std::vector<ContactRequest> contacts;
  std::vector<OverlapRequest> touches;
  std::vector<RayRequest> rays;
  for (const Probe& p : probes(1000)) {
    contacts.push_back(p.shape);
    touches.push_back({p.shape.shape, p.shape.pose});
    rays.push_back(p.ray);
  }
  std::vector<ContactResult> c1, cn;
  std::vector<TouchResult> t1, tn;
  std::vector<RayResult> r1, rn, b1, bn;
  ASSERT_TRUE(world->contacts_batch(contacts, c1).ok());
  ASSERT_TRUE(world->touches_batch(touches, t1).ok());
  ASSERT_TRUE(world->ray_cast_batch(rays, r1).ok());
  ASSERT_TRUE(world->ray_blocked_batch(rays, b1).ok());
  for (size_t i = 0; i < rays.size(); ++i) {
    RayResult one;
    ASSERT_TRUE(world->ray_blocked(rays[i], one).ok());
    EXPECT_EQ(one.hit, b1[i].hit) << i;
    EXPECT_EQ(one.first.hull, b1[i].first.hull) << i;
    EXPECT_EQ(one.first.t, b1[i].first.t) << i;
  }
  for (size_t i = 0; i < contacts.size(); ++i) {
    ContactResult one;
    ASSERT_TRUE(world->contacts(contacts[i], one).ok());
    ASSERT_TRUE(same_contacts(one.contacts, c1[i].contacts)) << i;
  }
  for (int threads : {1, 2, 3, 8}) {
    auto pool = QueryThreads::start(threads);
    ASSERT_TRUE(pool.ok()) << pool.status().message();
    ASSERT_EQ(pool.value()->size(), threads);
    ASSERT_TRUE(world->contacts_batch(contacts, cn, pool.value().get()).ok());
    ASSERT_TRUE(world->touches_batch(touches, tn, pool.value().get()).ok());
    ASSERT_TRUE(world->ray_cast_batch(rays, rn, pool.value().get()).ok());
    ASSERT_TRUE(world->ray_blocked_batch(rays, bn, pool.value().get()).ok());
    ASSERT_EQ(cn.size(), contacts.size());
    for (size_t i = 0; i < contacts.size(); ++i) {
      EXPECT_TRUE(same_contacts(cn[i].contacts, c1[i].contacts)) << threads << " threads, request " << i;
      EXPECT_EQ(tn[i].touching, t1[i].touching) << i;
      EXPECT_EQ(tn[i].hull, t1[i].hull) << i;
      EXPECT_EQ(rn[i].hit, r1[i].hit) << i;
      EXPECT_EQ(rn[i].first.hull, r1[i].first.hull) << i;
      EXPECT_EQ(rn[i].first.t, r1[i].first.t) << i;
    }
    for (size_t i = 0; i < rays.size(); ++i) {
      EXPECT_EQ(bn[i].hit, b1[i].hit) << threads << " threads, ray " << i;
      EXPECT_EQ(bn[i].first.hull, b1[i].first.hull) << i;
      EXPECT_EQ(bn[i].first.t, b1[i].first.t) << i;
    }
  }
}

TEST(QueryThreads, ABatchNamesItsLowestBadRequestOnAnyThreadCount) {
  const auto world = box_field();
  std::vector<RayRequest> rays(500);
  rays[317].direction = V::Zero();
  rays[401].max_distance = -1.0;
  std::vector<ContactRequest> contacts(500, ContactRequest{QueryShape::sphere(1.0), at(V(1, 1, 1)), 8});
  contacts[250].shape.radius = -1.0;
  contacts[260].max_contacts = 0;
  for (int threads : {1, 2, 4}) {
    auto pool = QueryThreads::start(threads).value();
    std::vector<RayResult> ray_results;
    const Status r = world->ray_cast_batch(rays, ray_results, pool.get());
    EXPECT_EQ(r.code(), StatusCode::invalid_argument);
    EXPECT_NE(r.message().find("ray 317 of the batch"), std::string::npos) << r.message();
    EXPECT_TRUE(ray_results.empty());
    std::vector<ContactResult> contact_results;
    const Status c = world->contacts_batch(contacts, contact_results, pool.get());
    EXPECT_EQ(c.code(), StatusCode::invalid_argument);
    EXPECT_NE(c.message().find("request 250 of the batch"), std::string::npos) << c.message();
  }
  EXPECT_EQ(QueryThreads::start(-1).status().code(), StatusCode::invalid_argument);
  EXPECT_EQ(QueryThreads::start(QueryThreads::kMostThreads + 1).status().code(), StatusCode::invalid_argument);
  const Status negative = QueryThreads::start(2, std::chrono::microseconds(-1)).status();
  EXPECT_EQ(negative.code(), StatusCode::invalid_argument);
  EXPECT_NE(negative.message().find("watch of -1 microseconds"), std::string::npos) << negative.message();
  EXPECT_EQ(QueryThreads::start(2, QueryThreads::kLongestWatch + std::chrono::microseconds(1)).status().code(),
            StatusCode::invalid_argument);
}

// Threads that sleep at once between batches, and threads that watch for
// the longest time, answer alike, batches asked back to back or after the
// threads have slept.
TEST(QueryThreads, AnyWatchGivesTheSameAnswers) {
  const auto world = box_field();
  std::vector<RayRequest> rays;
  for (const Probe& p : probes(300)) rays.push_back(p.ray);
  std::vector<RayResult> alone;
  ASSERT_TRUE(world->ray_cast_batch(rays, alone).ok());
  for (const auto watch : {std::chrono::microseconds(0), QueryThreads::kLongestWatch}) {
    auto pool = QueryThreads::start(2, watch);
    ASSERT_TRUE(pool.ok()) << pool.status().message();
    for (int round = 0; round < 3; ++round) {
      if (round == 2) std::this_thread::sleep_for(std::chrono::milliseconds(2));
      std::vector<RayResult> pooled;
      ASSERT_TRUE(world->ray_cast_batch(rays, pooled, pool.value().get()).ok());
      ASSERT_EQ(pooled.size(), alone.size());
      for (size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(pooled[i].hit, alone[i].hit) << watch.count() << " us watch, round " << round << ", ray " << i;
        EXPECT_EQ(pooled[i].first.hull, alone[i].first.hull) << i;
        EXPECT_EQ(pooled[i].first.t, alone[i].first.t) << i;
      }
    }
  }
}

} // namespace
} // namespace hullcover::bvh

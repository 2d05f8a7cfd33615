// No allocation per query: once a server's results and collectors have
// grown, HullWorld's queries allocate nothing. This executable replaces the
// global allocation functions with counting ones (so it is a test of its
// own), warms each query up once, then counts.

#include "box_hulls.h"
#include "hullcover/bvh/hull_world.h"

#include "poses.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

namespace {
std::atomic<long> g_allocations{0};
} // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;

TEST(QueryAllocation, NoQueryAllocatesOnceItsResultHasGrown) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> where(0.0, 30.0), size(0.2, 3.0);
  std::vector<RuntimeHull> hulls;
  for (int i = 0; i < 300; ++i) {
    const V lo(where(rng), where(rng), where(rng));
    hulls.push_back(test::box_hull(lo, lo + V(size(rng), size(rng), size(rng))));
  }
  const auto world = HullWorld::build(std::move(hulls)).value();
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 500; ++i) {
    Eigen::Isometry3d pose = test::at(V(where(rng), where(rng), where(rng)));
    pose.linear() = Eigen::Quaterniond(Eigen::Vector4d::Random().normalized()).toRotationMatrix();
    poses.push_back(pose);
  }
  const QueryShape shapes[] = {QueryShape::sphere(1.0), QueryShape::capsule(0.6, 1.0),
                               QueryShape::box(V(0.8, 0.5, 1.2))};
  ContactResult contacts;
  TouchResult touch;
  RayResult ray;
  AllHitsCollector<Contact> all_contacts;
  AllHitsCollector<RayHit> all_rays;
  long touching = 0;
  auto ask_everything = [&] {
    for (const Eigen::Isometry3d& pose : poses)
      for (const QueryShape& shape : shapes) {
        ASSERT_TRUE(world->contacts({shape, pose, 1 << 20}, contacts).ok());
        ASSERT_TRUE(world->touches({shape, pose}, touch).ok());
        ASSERT_TRUE(world->collide({shape, pose}, HullFilter{}, all_contacts).ok());
        ASSERT_TRUE(world->ray_cast({pose.translation(), pose.linear().col(2), 20.0}, ray).ok());
        ASSERT_TRUE(world->ray_blocked({pose.translation(), pose.linear().col(2), 20.0}, ray).ok());
        ASSERT_TRUE(world->cast_ray({pose.translation(), pose.linear().col(2), 20.0}, HullFilter{}, all_rays).ok());
        touching += touch.touching;
      }
  };
  ask_everything(); // the results and collectors grow to their largest
  // (QueryShape is passed by value inside the requests above: a sphere,
  // capsule or box holds no heap memory, so copying it allocates nothing.)
  const long before = g_allocations.load();
  ask_everything();
  const long during = g_allocations.load() - before;
  EXPECT_EQ(during, 0) << "allocations in " << 6 * 3 * poses.size() << " queries";
  EXPECT_GT(touching, 100); // the queries did find hulls
  // The counter counts: a vector that must grow allocates.
  const long check = g_allocations.load();
  std::vector<int> grows(1000);
  EXPECT_GT(g_allocations.load(), check);
  EXPECT_EQ(grows.size(), 1000u);
}

} // namespace
} // namespace hullcover::bvh

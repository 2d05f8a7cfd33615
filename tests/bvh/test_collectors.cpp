// The collector and filter forms of the queries (collectors.h): the same
// answers as the plain calls, filters that skip exactly what they say, and
// collectors that stop the walk.

#include "box_hulls.h"
#include "hullcover/bvh/hull_world.h"

#include "box_field.h"
#include "poses.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;
using test::at;
using test::box_field;
using test::Probe;
using test::probes;
using test::same_contacts;

void sort_deepest_first(std::vector<Contact>& contacts) {
  std::sort(contacts.begin(), contacts.end(), [](const Contact& x, const Contact& y) {
    return x.depth > y.depth || (x.depth == y.depth && x.hull < y.hull);
  });
}

TEST(Collectors, EveryCollectorAgreesWithThePlainCalls) {
  const auto world = box_field();
  AllHitsCollector<Contact> all_contacts;
  AllHitsCollector<int> all_hulls;
  AnyHitCollector<int> any_hull;
  AllHitsCollector<RayHit> all_ray_hits;
  int touching = 0, hit = 0;
  for (const Probe& p : probes(300)) {
    const OverlapRequest overlap{p.shape.shape, p.shape.pose};
    ContactResult contacts;
    OverlapResult hulls;
    TouchResult touch;
    RayResult ray;
    ASSERT_TRUE(world->contacts(p.shape, contacts).ok());
    ASSERT_TRUE(world->overlap(overlap, hulls).ok());
    ASSERT_TRUE(world->touches(overlap, touch).ok());
    ASSERT_TRUE(world->ray_cast(p.ray, ray).ok());
    ASSERT_TRUE(world->collide(overlap, HullFilter{}, all_contacts).ok());
    ASSERT_TRUE(world->overlapping(overlap, HullFilter{}, all_hulls).ok());
    ASSERT_TRUE(world->overlapping(overlap, HullFilter{}, any_hull).ok());
    ASSERT_TRUE(world->cast_ray(p.ray, HullFilter{}, all_ray_hits).ok());
    sort_deepest_first(all_contacts.hits());
    EXPECT_TRUE(same_contacts(all_contacts.hits(), contacts.contacts));
    std::vector<int> sorted = all_hulls.hits();
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, hulls.hulls);
    EXPECT_EQ(any_hull.found(), touch.touching);
    if (any_hull.found()) {
      EXPECT_TRUE(std::binary_search(sorted.begin(), sorted.end(), any_hull.hit()));
    }
    // Every hull's first hit, when all are kept: the nearest is ray_cast's.
    EXPECT_EQ(all_ray_hits.hits().empty(), !ray.hit);
    if (ray.hit) {
      const RayHit& nearest = *std::min_element(
          all_ray_hits.hits().begin(), all_ray_hits.hits().end(),
          [](const RayHit& a, const RayHit& b) { return a.t < b.t || (a.t == b.t && a.hull < b.hull); });
      EXPECT_EQ(nearest.hull, ray.first.hull);
      EXPECT_EQ(nearest.t, ray.first.t);
    }
    touching += touch.touching;
    hit += ray.hit;
  }
  EXPECT_GT(touching, 30);
  EXPECT_GT(hit, 30);
}

// ray_blocked: blocked exactly when ray_cast hits, by a hull the ray really
// hits there (that hull's own first hit, never nearer than ray_cast's).
TEST(Collectors, ABlockedRayIsOneRayCastHitsAndNamesAHullItHits) {
  const auto world = box_field();
  const std::vector<RuntimeHull>& hulls = world->hulls();
  int blocked = 0;
  for (const Probe& p : probes(300)) {
    RayResult nearest, any;
    ASSERT_TRUE(world->ray_cast(p.ray, nearest).ok());
    ASSERT_TRUE(world->ray_blocked(p.ray, any).ok());
    ASSERT_EQ(any.hit, nearest.hit);
    if (!any.hit) continue;
    ++blocked;
    const std::optional<RayHit> own =
        ray_hit(hulls[any.first.hull], p.ray.origin, p.ray.direction.normalized(), p.ray.max_distance);
    ASSERT_TRUE(own.has_value());
    EXPECT_EQ(own->t, any.first.t);
    EXPECT_EQ(own->point, any.first.point);
    EXPECT_EQ(own->normal, any.first.normal);
    EXPECT_GE(any.first.t, nearest.first.t);
  }
  EXPECT_GT(blocked, 30);
}

// Hulls of one material are skipped by the mask, and hulls a predicate
// refuses by it: the answers are those of a world without those hulls.
TEST(Collectors, FiltersSkipExactlyTheHullsTheyRefuse) {
  const auto world = box_field();
  std::vector<RuntimeHull> kept;
  std::vector<int> kept_index;
  for (size_t i = 0; i < world->hulls().size(); ++i)
    if (world->hulls()[i].material != 2 && i % 5 != 0) {
      kept.push_back(world->hulls()[i]);
      kept_index.push_back(static_cast<int>(i));
    }
  const auto smaller = HullWorld::build(kept).value();
  HullFilter filter;
  filter.material_mask = ~(std::uint64_t{1} << 2);
  filter.accept = [](const void*, int hull) { return hull % 5 != 0; };
  AllHitsCollector<Contact> filtered;
  AllHitsCollector<RayHit> filtered_rays;
  int compared = 0;
  for (const Probe& p : probes(300)) {
    const OverlapRequest overlap{p.shape.shape, p.shape.pose};
    ContactResult expected;
    ASSERT_TRUE(smaller->contacts(p.shape, expected).ok());
    for (Contact& c : expected.contacts) c.hull = kept_index[c.hull];
    sort_deepest_first(expected.contacts);
    ASSERT_TRUE(world->collide(overlap, filter, filtered).ok());
    sort_deepest_first(filtered.hits());
    EXPECT_TRUE(same_contacts(filtered.hits(), expected.contacts));
    RayResult ray;
    ASSERT_TRUE(smaller->ray_cast(p.ray, ray).ok());
    ASSERT_TRUE(world->cast_ray(p.ray, filter, filtered_rays).ok());
    bool found = false;
    for (const RayHit& h : filtered_rays.hits()) {
      EXPECT_NE(world->hulls()[h.hull].material, 2);
      EXPECT_NE(h.hull % 5, 0);
      found = found || (ray.hit && h.hull == kept_index[ray.first.hull] && h.t == ray.first.t);
    }
    EXPECT_EQ(found, ray.hit);
    compared += !expected.contacts.empty();
  }
  EXPECT_GT(compared, 20);
  // A mask with no material admitted finds nothing.
  HullFilter none;
  none.material_mask = 0;
  AnyHitCollector<int> any;
  for (const Probe& p : probes(50)) {
    ASSERT_TRUE(world->overlapping({p.shape.shape, p.shape.pose}, none, any).ok());
    EXPECT_FALSE(any.found());
  }
}

// A callback collector that stops after its second hit gets two, where
// there are more.
class StopAfterTwo final : public HitCollector<int> {
public:
  void add(const int&) override {
    if (++count == 2) stop();
  }
  int count = 0;

private:
  void on_reset() override { count = 0; }
};

TEST(Collectors, ACallbackStopsTheWalk) {
  const auto world = box_field();
  StopAfterTwo two;
  int many = 0;
  for (const Probe& p : probes(300)) {
    const OverlapRequest overlap{QueryShape::sphere(5.0), p.shape.pose}; // large: often many hulls
    OverlapResult all;
    ASSERT_TRUE(world->overlap(overlap, all).ok());
    ASSERT_TRUE(world->overlapping(overlap, HullFilter{}, two).ok());
    EXPECT_EQ(two.count, std::min<int>(2, static_cast<int>(all.hulls.size())));
    many += all.hulls.size() > 2;
  }
  EXPECT_GT(many, 5);
}

} // namespace
} // namespace hullcover::bvh

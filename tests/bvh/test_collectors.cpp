// The collector and filter forms of the queries (collectors.h) and the
// batches on QueryThreads: the same answers as the plain calls, filters
// that skip exactly what they say, collectors that stop the walk, and
// batches that answer alike on any thread count.

#include "box_hulls.h"
#include "hullcover/bvh/hull_world.h"

#include "poses.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;
using test::at;
using test::box_hull;

// 400 boxes of random sizes in a 40 m cube, materials 0-3 in turn: many
// overlapping candidates per query.
std::shared_ptr<const HullWorld> box_field() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> where(0.0, 40.0), size(0.2, 3.0);
  std::vector<RuntimeHull> hulls;
  for (int i = 0; i < 400; ++i) {
    const V lo(where(rng), where(rng), where(rng));
    hulls.push_back(box_hull(lo, lo + V(size(rng), size(rng), size(rng))));
    hulls.back().material = i % 4;
  }
  auto world = HullWorld::build(std::move(hulls));
  EXPECT_TRUE(world.ok()) << world.status().message();
  return world.value();
}

struct Probe {
  ContactRequest shape;
  RayRequest ray;
};

std::vector<Probe> probes(int count) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> where(0.0, 40.0);
  std::vector<Probe> out;
  for (int i = 0; i < count; ++i) {
    const QueryShape shape = i % 3 == 0 ? QueryShape::sphere(1.0)
                             : i % 3 == 1 ? QueryShape::capsule(0.6, 1.0)
                                          : QueryShape::box(V(0.8, 0.5, 1.2));
    Eigen::Isometry3d pose = at(V(where(rng), where(rng), where(rng)));
    pose.linear() = Eigen::Quaterniond(Eigen::Vector4d::Random().normalized()).toRotationMatrix();
    out.push_back({{shape, pose, 1 << 20}, {pose.translation(), pose.linear().col(0), 15.0}});
  }
  return out;
}

bool same_contacts(const std::vector<Contact>& a, const std::vector<Contact>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].hull != b[i].hull || a[i].depth != b[i].depth || a[i].normal != b[i].normal || a[i].point != b[i].point)
      return false;
  return true;
}

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
  void reset() override {
    HitCollector<int>::reset();
    count = 0;
  }
  int count = 0;
};

TEST(Collectors, ACallbackStopsTheWalk) {
  const auto world = box_field();
  StopAfterTwo two;
  int many = 0;
  for (const Probe& p : probes(300)) {
    const OverlapRequest overlap{QueryShape::sphere(5.0), p.shape.pose};  // large: often many hulls
    OverlapResult all;
    ASSERT_TRUE(world->overlap(overlap, all).ok());
    ASSERT_TRUE(world->overlapping(overlap, HullFilter{}, two).ok());
    EXPECT_EQ(two.count, std::min<int>(2, static_cast<int>(all.hulls.size())));
    many += all.hulls.size() > 2;
  }
  EXPECT_GT(many, 5);
}

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
  std::vector<RayResult> r1, rn;
  ASSERT_TRUE(world->contacts_batch(contacts, c1).ok());
  ASSERT_TRUE(world->touches_batch(touches, t1).ok());
  ASSERT_TRUE(world->ray_cast_batch(rays, r1).ok());
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
    ASSERT_EQ(cn.size(), contacts.size());
    for (size_t i = 0; i < contacts.size(); ++i) {
      EXPECT_TRUE(same_contacts(cn[i].contacts, c1[i].contacts)) << threads << " threads, request " << i;
      EXPECT_EQ(tn[i].touching, t1[i].touching) << i;
      EXPECT_EQ(tn[i].hull, t1[i].hull) << i;
      EXPECT_EQ(rn[i].hit, r1[i].hit) << i;
      EXPECT_EQ(rn[i].first.hull, r1[i].first.hull) << i;
      EXPECT_EQ(rn[i].first.t, r1[i].first.t) << i;
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
}

} // namespace
} // namespace hullcover::bvh

// The yes/no queries (HullWorld::touches, overlap; hull_contact.h's
// *_touches) and the direct walks of the broad-phase tree (rays nearest box
// first, batches), checked against independent answers: the contacts of
// every hull one by one, and rays cast at every hull without the tree.

#include "box_hulls.h"
#include "concurrent_queries.h"
#include "covering_fixture.h"
#include "poses.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <random>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;

using test::at;

// The demo building's covering as a world (about a hundred hulls).
std::shared_ptr<const HullWorld> demo_world() {
  const auto d = test::decompose_and_check(demo_building());
  EXPECT_TRUE(d);
  if (!d) return nullptr;
  return build_hull_world(d->covering).value();
}

// Random poses of all four shape kinds around the demo building.
std::vector<OverlapRequest> random_requests(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-15, 5), y(-0.5, 3.5), z(-6, 6);
  std::vector<OverlapRequest> requests;
  for (int i = 0; i < count; ++i) {
    QueryShape shape = i % 4 == 0   ? QueryShape::sphere(0.4)
                       : i % 4 == 1 ? QueryShape::capsule(0.3, 0.6)
                       : i % 4 == 2 ? QueryShape::box(V(0.3, 0.5, 0.2))
                                    : QueryShape{};
    if (i % 4 == 3) {
      shape.kind = ShapeKind::convex;
      shape.points = {V(0, 0, 0), V(0.6, 0, 0), V(0, 0.5, 0), V(0, 0, 0.4), V(0.3, 0.3, 0.3)};
    }
    Eigen::Isometry3d pose = at(V(x(rng), y(rng), z(rng)));
    pose.linear() = Eigen::Quaterniond(Eigen::Vector4d::Random().normalized()).toRotationMatrix();
    requests.push_back({shape, pose});
  }
  return requests;
}

// The contact of `request`'s shape with one hull, by the free functions
// alone (no broad phase).
std::optional<Contact> contact_of(const RuntimeHull& hull, const OverlapRequest& request) {
  const QueryShape& s = request.shape;
  const Eigen::Vector3d axis = request.pose.linear().col(2) * s.half_height;
  switch (s.kind) {
    case ShapeKind::sphere: return sphere_contact(hull, request.pose.translation(), s.radius);
    case ShapeKind::capsule:
      return capsule_contact(hull, request.pose.translation() - axis, request.pose.translation() + axis, s.radius);
    case ShapeKind::box: return box_contact(hull, request.pose, s.half_extents);
    case ShapeKind::convex: return convex_contact(hull, *placed_convex(s, request.pose));
  }
  return std::nullopt;
}

TEST(HullTouch, YesNoAgreesWithContactsOnEveryHull) {
  const auto world = demo_world();
  ASSERT_TRUE(world);
  int touching = 0, apart = 0;
  for (const OverlapRequest& request : random_requests(800, 11)) {
    // Independent answer: every hull's contact, one by one, without the tree.
    std::vector<int> expected;
    for (int h = 0; h < static_cast<int>(world->hulls().size()); ++h)
      if (contact_of(world->hulls()[h], request)) expected.push_back(h);
    OverlapResult overlap;
    ASSERT_TRUE(world->overlap(request, overlap).ok());
    EXPECT_EQ(overlap.hulls, expected);
    TouchResult yes_no;
    ASSERT_TRUE(world->touches(request, yes_no).ok());
    EXPECT_EQ(yes_no.touching, !expected.empty());
    if (yes_no.touching) {
      EXPECT_TRUE(std::binary_search(expected.begin(), expected.end(), yes_no.hull)) << yes_no.hull;
      ++touching;
    } else {
      EXPECT_EQ(yes_no.hull, -1);
      ++apart;
    }
  }
  // Both answers were exercised.
  EXPECT_GT(touching, 100);
  EXPECT_GT(apart, 100);
}

// A capsule passing a box's edge diagonally: no single facet plane has both
// ends beyond the radius, so only the clip against the grown planes, or the
// exact distance, can tell.
TEST(HullTouch, CapsuleAcrossABoxEdge) {
  const RuntimeHull block = test::box_hull(V(0, 0, 0), V(1, 1, 1));
  // The axis runs from (2, 0.5, 0.5) to (0.5, 2, 0.5), along x + y = 2.5:
  // 0.25 * sqrt(2) from the edge x = y = 1, nearest at (1.25, 1.25, 0.5).
  const V a(2, 0.5, 0.5), b(0.5, 2, 0.5);
  const double gap = 0.25 * std::sqrt(2.0);
  // No facet plane has both ends in front of it by the gap.
  for (const Plane& p : block.shape.planes) EXPECT_FALSE(p.signed_distance(a) > gap && p.signed_distance(b) > gap);
  EXPECT_FALSE(capsule_touches(block, a, b, gap - 1e-9));
  EXPECT_FALSE(capsule_contact(block, a, b, gap - 1e-9));
  EXPECT_TRUE(capsule_touches(block, a, b, gap + 1e-9));
  const std::optional<Contact> c = capsule_contact(block, a, b, gap + 1e-9);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->depth, 1e-9, 1e-12);
  EXPECT_NEAR((c->normal - V(1, 1, 0).normalized()).norm(), 0.0, 1e-9);
}

TEST(HullTouch, TouchingAtDepthZeroCounts) {
  auto world = HullWorld::build({test::box_hull(V(-5, -1, -5), V(5, 0, 5))}).value();
  TouchResult r;
  ASSERT_TRUE(world->touches({QueryShape::sphere(0.5), at(V(1, 0.5, 1))}, r).ok()); // resting on it exactly
  EXPECT_TRUE(r.touching);
  EXPECT_EQ(r.hull, 0);
  ASSERT_TRUE(world->touches({QueryShape::sphere(0.5), at(V(1, 0.5 + 1e-9, 1))}, r).ok());
  EXPECT_FALSE(r.touching);
  EXPECT_EQ(r.hull, -1);
  // Beyond the floor's corner, diagonally: apart though each plane alone
  // would let it through.
  ASSERT_TRUE(world->touches({QueryShape::sphere(0.5), at(V(5.4, 0.4, 5.4))}, r).ok());
  EXPECT_FALSE(r.touching);
  QueryShape bad = QueryShape::sphere(-1.0);
  EXPECT_EQ(world->touches({bad, at(V(0, 0, 0))}, r).code(), StatusCode::invalid_argument);
}

// The ray walk visits nearer boxes first and prunes at the best hit: compare
// with casting at every hull.
TEST(HullTouch, RaysMatchEveryHullCastOneByOne) {
  const auto world = demo_world();
  ASSERT_TRUE(world);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(-15, 5), y(-0.5, 3.5), z(-6, 6), d(-1, 1);
  std::vector<RayRequest> rays;
  for (int i = 0; i < 600; ++i) {
    V dir(d(rng), d(rng), d(rng));
    V origin(x(rng), y(rng), z(rng));
    if (i % 10 == 0) dir = V(0, -1, 0); // straight down, parallel to most boxes' sides
    if (i % 20 == 0) {
      // Starting exactly on a hull's box face, running along it: the slab
      // test's 0 * infinity case.
      const Aabb& box = world->hulls()[i % world->hulls().size()].box;
      origin.x() = box.min.x();
      dir = V(0, d(rng), d(rng));
    }
    rays.push_back({origin, dir, i % 3 == 0 ? 2.0 : 1e30});
  }
  std::vector<RayResult> batch;
  ASSERT_TRUE(world->ray_cast_batch(rays, batch).ok());
  ASSERT_EQ(batch.size(), rays.size());
  int hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const V dir = rays[i].direction.normalized();
    std::optional<RayHit> best;
    for (int h = 0; h < static_cast<int>(world->hulls().size()); ++h) {
      std::optional<RayHit> hit = ray_hit(world->hulls()[h], rays[i].origin, dir, rays[i].max_distance);
      if (hit && (!best || hit->t < best->t)) {
        best = hit;
        best->hull = h;
      }
    }
    RayResult single;
    ASSERT_TRUE(world->ray_cast(rays[i], single).ok());
    ASSERT_EQ(single.hit, best.has_value()) << i;
    EXPECT_EQ(batch[i].hit, single.hit) << i;
    if (!best) continue;
    ++hits;
    EXPECT_EQ(single.first.t, best->t) << i;
    // Two hulls met at the same distance (touching boxes) may come in either
    // order; another hull must be met exactly as near.
    if (single.first.hull != best->hull) {
      const std::optional<RayHit> tie =
          ray_hit(world->hulls()[single.first.hull], rays[i].origin, dir, rays[i].max_distance);
      EXPECT_TRUE(tie && tie->t == best->t) << i << ": hull " << single.first.hull << " instead of " << best->hull;
    }
    EXPECT_EQ(batch[i].first.hull, single.first.hull) << i;
    EXPECT_EQ(batch[i].first.t, single.first.t) << i;
  }
  EXPECT_GT(hits, 200);
}

TEST(HullTouch, ABadRayFailsTheBatchByIndex) {
  auto world = HullWorld::build({test::box_hull(V(0, 0, 0), V(1, 1, 1))}).value();
  std::vector<RayResult> results;
  std::vector<RayRequest> rays = {{V(-1, 0.5, 0.5), V(1, 0, 0), 10.0}, {V(-1, 0.5, 0.5), V(0, 0, 0), 10.0}};
  const Status s = world->ray_cast_batch(rays, results);
  EXPECT_EQ(s.code(), StatusCode::invalid_argument);
  EXPECT_NE(s.message().find("ray 1"), std::string::npos) << s.message();
  EXPECT_TRUE(results.empty());
  rays.pop_back();
  ASSERT_TRUE(world->ray_cast_batch(rays, results).ok());
  ASSERT_EQ(results.size(), 1u);
  EXPECT_TRUE(results[0].hit);
  EXPECT_DOUBLE_EQ(results[0].first.t, 1.0);
}

TEST(HullTouch, EightThreadsGetExactlyWhatOneThreadGets) {
  const auto world = demo_world();
  ASSERT_TRUE(world);
  const std::vector<OverlapRequest> requests = random_requests(400, 7);
  std::vector<TouchResult> expected(requests.size());
  for (size_t i = 0; i < requests.size(); ++i) ASSERT_TRUE(world->touches(requests[i], expected[i]).ok());
  const auto got = test::answers_from_threads<TouchResult>(
      8, requests.size(), [&](size_t k, TouchResult& answer) { (void)world->touches(requests[k], answer); });
  for (size_t i = 0; i < requests.size(); ++i)
    for (int t = 0; t < 8; ++t) {
      EXPECT_EQ(got[t][i].touching, expected[i].touching) << "thread " << t << " request " << i;
      EXPECT_EQ(got[t][i].hull, expected[i].hull) << "thread " << t << " request " << i;
    }
}

} // namespace
} // namespace hullcover::bvh

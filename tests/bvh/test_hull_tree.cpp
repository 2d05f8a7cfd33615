// The broad phase's walks (bvh/src/hull_tree.h) against every hull tested
// one by one: a walk may hand over more hulls than touch, never fewer.

#include "box_hulls.h"
#include "hull_tree.h" // private to bvh
#include "hullcover/bvh/hull_contact.h"
#include "hullcover/bvh/hull_world.h"
#include "hullcover/bvh/runtime_hull.h"

#include "poses.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;

// Boxes of random sizes in a cube of side `extent` about `centre`, and
// flat triangles along the axis planes (floor and wall tiles).
std::vector<RuntimeHull> boxes_about(const V& centre, double extent, std::mt19937& rng) {
  std::uniform_real_distribution<double> where(-0.5 * extent, 0.5 * extent), size(0.05, 0.1 * extent);
  std::vector<RuntimeHull> hulls;
  for (int i = 0; i < 300; ++i) {
    const V lo = centre + V(where(rng), where(rng), where(rng));
    const V side(size(rng), size(rng), size(rng));
    if (i % 5 == 0) {
      const int k = i % 3, u = (k + 1) % 3, w = (k + 2) % 3;
      hulls.push_back(flat_triangle_hull(lo, lo + side[u] * V::Unit(u), lo + side[w] * V::Unit(w)));
    } else {
      hulls.push_back(test::box_hull(lo, lo + side));
    }
  }
  return hulls;
}

// Capsule axes through the field: slanted, along an axis, of no length,
// and 0.3 over a hull's top face.
std::vector<std::pair<V, V>> axes_through(const std::vector<RuntimeHull>& hulls, const V& centre, double extent,
                                          std::mt19937& rng) {
  std::uniform_real_distribution<double> where(-0.5 * extent, 0.5 * extent), unit(-1.0, 1.0);
  std::vector<std::pair<V, V>> axes;
  for (int i = 0; i < 400; ++i) {
    const V a = centre + V(where(rng), where(rng), where(rng));
    V d(unit(rng), unit(rng), unit(rng));
    if (i % 4 == 1) d = V::Unit(i % 3) * unit(rng);
    if (i % 4 == 2) d.setZero();
    if (i % 4 == 3) { // 0.3 over a hull's top face, across it: a capsule of radius 0.3 rests on it
      const RuntimeHull& h = hulls[static_cast<size_t>(i) % hulls.size()];
      const double over = h.box.max.y() + 0.3;
      axes.emplace_back(V(h.box.min.x(), over, h.box.min.z()), V(h.box.max.x(), over, h.box.max.z()));
      continue;
    }
    axes.emplace_back(a, a + 0.2 * extent * d);
  }
  return axes;
}

TEST(HullTree, ACapsuleWalkMissesNoHullACapsuleTouches) {
  std::mt19937 rng(23);
  int touching = 0, tangent = 0;
  for (const double far : {0.0, 1e5, 1e7}) {
    const V centre = V::Constant(far);
    const double extent = 40.0;
    const std::vector<RuntimeHull> hulls = boxes_about(centre, extent, rng);
    const detail::HullTree tree(hulls);
    for (const auto& [a, b] : axes_through(hulls, centre, extent, rng))
      for (const double radius : {0.0, 0.3, 2.0}) {
        std::set<int> walked;
        EXPECT_FALSE(tree.find_near_segment(a, b, radius, [&](int h) {
          EXPECT_TRUE(walked.insert(h).second) << "hull " << h << " handed over twice";
          return false;
        }));
        for (size_t h = 0; h < hulls.size(); ++h)
          if (capsule_touches(hulls[h], a, b, radius)) {
            ++touching;
            // Resting on it: apart by the radius to the rounding of the coordinates.
            tangent += std::abs(closest_to_segment(hulls[h], a, b).distance - radius) <= 4e-15 * (1.0 + far);
            EXPECT_TRUE(walked.count(static_cast<int>(h)))
                << "hull " << h << " touches the capsule but the walk missed it, at " << far << ", radius " << radius;
          }
      }
  }
  EXPECT_GT(touching, 1000);
  EXPECT_GT(tangent, 20); // capsules resting exactly on a face were tested
}

TEST(HullTree, ACapsuleWalkStopsWhenAVisitAsks) {
  const std::vector<RuntimeHull> hulls = {test::box_hull(V(0, 0, 0), V(1, 1, 1)),
                                          test::box_hull(V(3, 0, 0), V(4, 1, 1)),
                                          test::box_hull(V(6, 0, 0), V(7, 1, 1))};
  const detail::HullTree tree(hulls);
  std::vector<int> order;
  EXPECT_TRUE(tree.find_near_segment(V(-1, 0.5, 0.5), V(8, 0.5, 0.5), 0.1, [&](int h) {
    order.push_back(h);
    return order.size() == 2;
  }));
  // Along the axis from its first end, and no further once stopped.
  EXPECT_EQ(order, (std::vector<int>{0, 1}));
}

// HullWorld's capsule contacts (found along the axis) are the hulls' own
// contacts, each tested alone.
TEST(HullTree, CapsuleContactsOfAWorldAreEveryHullsOwn) {
  std::mt19937 rng(29);
  const V centre(10, -20, 30);
  std::vector<RuntimeHull> hulls = boxes_about(centre, 40.0, rng);
  const auto world = HullWorld::build(hulls);
  ASSERT_TRUE(world.ok());
  int contacts = 0;
  for (const auto& [a, b] : axes_through(hulls, centre, 40.0, rng)) {
    const V mid = 0.5 * (a + b);
    const double half = 0.5 * (b - a).norm();
    if (!(half > 0.0)) continue;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = mid;
    pose.linear() = Eigen::Quaterniond::FromTwoVectors(V::UnitZ(), b - a).toRotationMatrix();
    ContactRequest request{QueryShape::capsule(0.5, half), pose, 1 << 20};
    ContactResult result;
    ASSERT_TRUE(world.value()->contacts(request, result).ok());
    // The query's own axis ends, as the world places them.
    const V axis = pose.linear().col(2) * half, qa = mid - axis, qb = mid + axis;
    std::set<int> expected;
    for (size_t h = 0; h < hulls.size(); ++h)
      if (capsule_contact(hulls[h], qa, qb, 0.5)) expected.insert(static_cast<int>(h));
    std::set<int> got;
    for (const Contact& c : result.contacts) got.insert(c.hull);
    EXPECT_EQ(got, expected);
    contacts += static_cast<int>(got.size());
  }
  EXPECT_GT(contacts, 100);
}

} // namespace
} // namespace hullcover::bvh

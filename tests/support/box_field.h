#pragma once
// A field of random boxes and random probes in it: many overlapping
// candidates per query, for the runtime's collector and thread tests.

#include "box_hulls.h"
#include "hullcover/bvh/hull_world.h"

#include "poses.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace hullcover::test {

using V = Eigen::Vector3d;

// 400 boxes of random sizes in a 40 m cube, materials 0-3 in turn: many
// overlapping candidates per query.
inline std::shared_ptr<const bvh::HullWorld> box_field() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> where(0.0, 40.0), size(0.2, 3.0);
  std::vector<bvh::RuntimeHull> hulls;
  for (int i = 0; i < 400; ++i) {
    const V lo(where(rng), where(rng), where(rng));
    hulls.push_back(box_hull(lo, lo + V(size(rng), size(rng), size(rng))));
    hulls.back().material = i % 4;
  }
  auto world = bvh::HullWorld::build(std::move(hulls));
  EXPECT_TRUE(world.ok()) << world.status().message();
  return world.value();
}

struct Probe {
  bvh::ContactRequest shape;
  bvh::RayRequest ray;
};

inline std::vector<Probe> probes(int count) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> where(0.0, 40.0);
  std::vector<Probe> out;
  for (int i = 0; i < count; ++i) {
    const bvh::QueryShape shape = i % 3 == 0   ? bvh::QueryShape::sphere(1.0)
                                  : i % 3 == 1 ? bvh::QueryShape::capsule(0.6, 1.0)
                                               : bvh::QueryShape::box(V(0.8, 0.5, 1.2));
    Eigen::Isometry3d pose = at(V(where(rng), where(rng), where(rng)));
    pose.linear() = Eigen::Quaterniond(Eigen::Vector4d::Random().normalized()).toRotationMatrix();
    out.push_back({{shape, pose, 1 << 20}, {pose.translation(), pose.linear().col(0), 15.0}});
  }
  return out;
}

/// Whether two contact lists are the same, bit for bit.
inline bool same_contacts(const std::vector<bvh::Contact>& a, const std::vector<bvh::Contact>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].hull != b[i].hull || a[i].depth != b[i].depth || a[i].normal != b[i].normal || a[i].point != b[i].point)
      return false;
  return true;
}

} // namespace hullcover::test

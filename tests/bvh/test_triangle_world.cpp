// The triangle baseline against the hull world on scenes where both must
// agree, and the case where they must not (stuck in the wall).

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/triangle_world.h"

#include "covering_fixture.h"
#include "poses.h"

#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;

using test::at;

struct Worlds {
  std::shared_ptr<const HullWorld> hulls;
  std::shared_ptr<const TriangleWorld> triangles;
};

Worlds worlds_of(const Mesh& mesh) {
  const auto d = test::decompose_and_check(mesh);
  EXPECT_TRUE(d);
  Worlds w;
  w.hulls = build_hull_world(d->covering).value();
  w.triangles = TriangleWorld::build(d->prepared.mesh, d->tol()).value();
  return w;
}

TEST(TriangleWorld, StuckInTheWallGetsOpposingNormals) {
  Mesh wall;
  add_box(wall, V(0, 0, 0), V(0.3, 3, 4));
  const Worlds w = worlds_of(wall);
  ContactResult triangles, hulls;
  const ContactRequest deep{QueryShape::sphere(0.25), at(V(0.12, 1.5, 2)), 16};
  ASSERT_TRUE(w.triangles->contacts(deep, triangles).ok());
  ASSERT_TRUE(w.hulls->contacts(deep, hulls).ok());
  bool plus = false, minus = false;
  for (const Contact& c : triangles.contacts) {
    plus |= c.normal.x() > 0.99;
    minus |= c.normal.x() < -0.99;
  }
  EXPECT_TRUE(plus && minus) << "triangles should push both ways";
  ASSERT_EQ(hulls.contacts.size(), 1u);
  EXPECT_LT(hulls.contacts[0].normal.x(), -0.99);
}

// On a closed convex block touched from outside, every query agrees.
TEST(TriangleWorld, AgreesWithTheHullWorldOutsideAClosedBlock) {
  Mesh block;
  add_box(block, V(0, 0, 0), V(2, 1, 3));
  const Worlds w = worlds_of(block);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.5, 3.5);
  int compared = 0;
  for (int i = 0; i < 400; ++i) {
    const V c(u(rng), u(rng), u(rng));
    if (c.x() > -0.01 && c.x() < 2.01 && c.y() > -0.01 && c.y() < 1.01 && c.z() > -0.01 && c.z() < 3.01) continue;
    const ContactRequest request{QueryShape::sphere(0.6), at(c), 16};
    ContactResult t, h;
    ASSERT_TRUE(w.triangles->contacts(request, t).ok());
    ASSERT_TRUE(w.hulls->contacts(request, h).ok());
    ASSERT_EQ(t.contacts.empty(), h.contacts.empty()) << c.transpose();
    if (!h.contacts.empty()) {
      ++compared;
      EXPECT_NEAR(t.contacts[0].depth, h.contacts[0].depth, 1e-9) << c.transpose();
      EXPECT_NEAR((t.contacts[0].normal - h.contacts[0].normal).norm(), 0.0, 1e-6) << c.transpose();
    } else {
      DistanceResult dt, dh;
      ASSERT_TRUE(w.triangles->distance({QueryShape::sphere(0.6), at(c)}, dt).ok());
      ASSERT_TRUE(w.hulls->distance({QueryShape::sphere(0.6), at(c)}, dh).ok());
      EXPECT_NEAR(dt.distance, dh.distance, 1e-6) << c.transpose();
    }
    RayResult rt, rh;
    const RayRequest ray{c, V(1, 0.5, 1.5) - c, 100};
    ASSERT_TRUE(w.triangles->ray_cast(ray, rt).ok());
    ASSERT_TRUE(w.hulls->ray_cast(ray, rh).ok());
    ASSERT_TRUE(rt.hit && rh.hit);
    EXPECT_NEAR(rt.first.t, rh.first.t, 1e-9);
  }
  EXPECT_GT(compared, 50);
}

// A ray down a row of separate triangles (scattered debris, one island
// each) first meets the nearest; it is found by visiting the tree nearest
// first. Where two triangles coincide the lower face wins, and every hit up
// to a reach is listed, however the tree is walked.
TEST(TriangleWorld, ARayDownARowOfTrianglesMeetsTheNearestAndListsEveryHit) {
  constexpr int kRow = 2000;
  Mesh mesh;
  for (int i = 0; i < kRow; ++i) {
    const int base = static_cast<int>(mesh.positions.size());
    mesh.positions.push_back(V(i, -1, -1));
    mesh.positions.push_back(V(i, 2, -1));
    mesh.positions.push_back(V(i, -1, 2));
    mesh.triangles.emplace_back(base, base + 1, base + 2);
  }
  // A second triangle on the first's plane, added last.
  mesh.positions.push_back(V(0, -1, -1));
  mesh.positions.push_back(V(0, 2, -1));
  mesh.positions.push_back(V(0, -1, 2));
  mesh.triangles.emplace_back(3 * kRow, 3 * kRow + 1, 3 * kRow + 2);
  mesh.material_ids.assign(mesh.triangles.size(), 0);
  const auto built = TriangleWorld::build(mesh, 1e-6);
  ASSERT_TRUE(built.ok()) << built.status().message();
  const auto& world = built.value();
  for (const double start : {-0.5, 10.5, 1234.5}) {
    RayResult hit;
    ASSERT_TRUE(world->ray_cast({V(start, 0.1, 0.2), V(1, 0, 0), 1e9}, hit).ok());
    ASSERT_TRUE(hit.hit);
    EXPECT_DOUBLE_EQ(hit.first.t, std::ceil(start) - start);
    EXPECT_EQ(hit.first.hull, static_cast<int>(std::ceil(start)));
  }
  std::vector<RayHit> hits;
  ASSERT_TRUE(world->ray_hits({V(-0.5, 0.1, 0.2), V(1, 0, 0), 100.0}, hits).ok());
  ASSERT_EQ(hits.size(), 101u); // faces 0 to 99, and the copy of face 0
  EXPECT_EQ(hits[0].hull, 0);
  EXPECT_EQ(hits[1].hull, kRow);
  for (size_t k = 2; k < hits.size(); ++k) EXPECT_EQ(hits[k].hull, static_cast<int>(k - 1));
}

} // namespace
} // namespace hullcover::bvh

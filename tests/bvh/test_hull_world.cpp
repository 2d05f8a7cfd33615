// HullWorld: known geometry through the whole query path (FCL broad phase,
// exact narrow phase), a world built from a real covering, and concurrent
// queries.

#include "box_hulls.h"
#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/hull_world.h"

#include "concurrent_queries.h"
#include "covering_fixture.h"
#include "poses.h"
#include "query_guard.h" // private to bvh: no public input makes a query throw

#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <new>
#include <random>
#include <stdexcept>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;

using test::box_hull;

std::shared_ptr<const HullWorld> floor_and_block() {
  auto world = HullWorld::build({box_hull(V(-5, -1, -5), V(5, 0, 5)), box_hull(V(0, 0, 0), V(1, 1, 1))});
  EXPECT_TRUE(world.ok()) << world.status().message();
  return world.value();
}

using test::at;

TEST(HullWorld, SphereRestingOnTheFloor) {
  const auto world = floor_and_block();
  ContactResult result;
  ASSERT_TRUE(world->contacts({QueryShape::sphere(0.5), at(V(-2, 0.4, 2))}, result).ok());
  ASSERT_EQ(result.contacts.size(), 1u);
  const Contact& c = result.contacts[0];
  EXPECT_EQ(c.hull, 0);
  EXPECT_NEAR(c.depth, 0.1, 1e-12);
  EXPECT_NEAR((c.normal - V(0, 1, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((c.point - V(-2, 0, 2)).norm(), 0.0, 1e-12);
  OverlapResult overlap;
  ASSERT_TRUE(world->overlap({QueryShape::sphere(0.5), at(V(-2, 0.4, 2))}, overlap).ok());
  EXPECT_EQ(overlap.hulls, std::vector<int>{0});
}

TEST(HullWorld, CapsuleAgainstABlockEdge) {
  const auto world = floor_and_block();
  // Lying along z, its axis 0.2 * sqrt(2) from the block's top-right edge.
  Eigen::Isometry3d pose = at(V(1.2, 1.2, 0.5));
  ContactResult result;
  ASSERT_TRUE(world->contacts({QueryShape::capsule(0.4, 1.0), pose}, result).ok());
  ASSERT_EQ(result.contacts.size(), 1u);
  EXPECT_EQ(result.contacts[0].hull, 1);
  EXPECT_NEAR(result.contacts[0].depth, 0.4 - 0.2 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR((result.contacts[0].normal - V(1, 1, 0).normalized()).norm(), 0.0, 1e-12);
}

// A capsule against the edge of a prism made from a planar patch: a floor
// quad decomposed into one prism of thickness 0.25 below it.
TEST(HullWorld, CapsuleAgainstAPrismEdge) {
  Mesh floor;
  test::add_quad_facing(floor, V(0, 0, 0), V(0, 0, 2), V(2, 0, 2), V(2, 0, 0), V(0, 1, 0));
  DecomposeOptions options;
  options.prism_thickness_cap = 0.25;
  const auto d = test::decompose_and_check(floor, options);
  ASSERT_TRUE(d);
  ASSERT_EQ(d->covering.hulls.size(), 1u);
  ASSERT_DOUBLE_EQ(d->covering.hulls[0].thickness, 0.25);
  const auto world = build_hull_world(d->covering).value();
  // Lying along z beyond the prism's edge x = 2, level with its middle.
  ContactResult result;
  ASSERT_TRUE(world->contacts({QueryShape::capsule(0.3, 0.5), at(V(2.2, -0.125, 1))}, result).ok());
  ASSERT_EQ(result.contacts.size(), 1u);
  EXPECT_NEAR(result.contacts[0].depth, 0.1, 1e-12);
  EXPECT_NEAR((result.contacts[0].normal - V(1, 0, 0)).norm(), 0.0, 1e-12);
  // Beyond its top edge, diagonally: 0.2 * sqrt(2) from the edge.
  ASSERT_TRUE(world->contacts({QueryShape::capsule(0.3, 0.5), at(V(2.2, 0.2, 1))}, result).ok());
  ASSERT_EQ(result.contacts.size(), 1u);
  EXPECT_NEAR(result.contacts[0].depth, 0.3 - 0.2 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR((result.contacts[0].normal - V(1, 1, 0).normalized()).norm(), 0.0, 1e-12);
}

TEST(HullWorld, DistanceBetweenSeparatedShapes) {
  const auto world = floor_and_block();
  DistanceResult d;
  ASSERT_TRUE(world->distance({QueryShape::sphere(0.5), at(V(3, 0.5 + 1.0, 0.5))}, d).ok());
  // Nearest: the floor top (y = 0) is 1.5 - 0.5 = 1.0 away, the block 2 - 0.5.
  EXPECT_FALSE(d.touching);
  EXPECT_NEAR(d.distance, 1.0, 1e-12);
  EXPECT_EQ(d.hull, 0);
  ASSERT_TRUE(world->distance({QueryShape::capsule(0.25, 0.5), at(V(0.5, 3.0, 0.5))}, d).ok());
  EXPECT_NEAR(d.distance, 3.0 - 0.25 - 1.0, 1e-12); // axis along z at y = 3: lowest point y = 2.75
  EXPECT_EQ(d.hull, 1);
  EXPECT_NEAR(d.on_world.y(), 1.0, 1e-12);
  // A box: the floor 1.5 below it, the block's corner edge sqrt(1.5^2 + 0.5^2) away.
  ASSERT_TRUE(world->distance({QueryShape::box(V(0.5, 0.5, 0.5)), at(V(3, 2, 0.5))}, d).ok());
  EXPECT_NEAR(d.distance, 1.5, 1e-12);
  EXPECT_EQ(d.hull, 0);
  EXPECT_NEAR(d.on_world.y(), 0.0, 1e-12);
  ASSERT_TRUE(world->distance({QueryShape::box(V(0.5, 0.5, 0.5)), at(V(3, 0.4, 0.5))}, d).ok());
  EXPECT_TRUE(d.touching);
}

// Regression: FCL 0.7's GJK distance between this box and this thin hull
// came out 5.397 (and 3.678 at x = -3), which would let a sweep tunnel.
TEST(HullWorld, BoxDistanceToAThinWallIsExact) {
  auto world = HullWorld::build({box_hull(V(0, 0, 0), V(0.01, 3, 3))}).value();
  for (double x : {-5.0, -3.0, -2.0}) {
    DistanceResult d;
    ASSERT_TRUE(world->distance({QueryShape::box(V(0.1, 0.1, 0.1)), at(V(x, 1.5, 1.5))}, d).ok());
    EXPECT_NEAR(d.distance, -x - 0.1, 1e-12) << x;
  }
}

TEST(HullWorld, RaysFindTheFirstHull) {
  const auto world = floor_and_block();
  RayResult r;
  ASSERT_TRUE(world->ray_cast({V(-3, 0.5, 0.5), V(1, 0, 0), 100}, r).ok());
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.first.hull, 1);
  EXPECT_NEAR(r.first.t, 3.0, 1e-12);
  ASSERT_TRUE(world->ray_cast({V(0.5, 5, 0.5), V(0, -2, 0), 100}, r).ok()); // unnormalised direction
  EXPECT_EQ(r.first.hull, 1);
  EXPECT_NEAR(r.first.t, 4.0, 1e-12);
  ASSERT_TRUE(world->ray_cast({V(3, 5, 3), V(0, -1, 0), 100}, r).ok());
  EXPECT_EQ(r.first.hull, 0);
  EXPECT_NEAR(r.first.t, 5.0, 1e-12);
  ASSERT_TRUE(world->ray_cast({V(3, 5, 3), V(0, 1, 0), 100}, r).ok());
  EXPECT_FALSE(r.hit);
  EXPECT_EQ(world->ray_cast({V(3, 5, 3), V(0, 0, 0), 100}, r).code(), StatusCode::invalid_argument);
}

TEST(HullWorld, BadRequestsAreRefusedNotCrashed) {
  const auto world = floor_and_block();
  ContactResult result;
  EXPECT_EQ(world->contacts({QueryShape::sphere(-1), at(V(0, 0, 0))}, result).code(), StatusCode::invalid_argument);
  EXPECT_EQ(world->contacts({QueryShape::sphere(1), at(V(NAN, 0, 0))}, result).code(), StatusCode::invalid_argument);
  EXPECT_FALSE(HullWorld::build(std::vector<RuntimeHull>{}).ok());
}

// The paper's "stuck in the wall": a sphere deep inside a thin closed wall.
// The wall's triangles push it out of both sides at once; its one hull
// pushes it out of one side.
TEST(HullWorld, StuckInTheWallGetsOneConsistentNormal) {
  Mesh wall;
  add_box(wall, V(0, 0, 0), V(0.3, 3, 4));
  const auto d = test::decompose_and_check(wall);
  ASSERT_TRUE(d);
  ASSERT_EQ(d->covering.hulls.size(), 1u);
  const auto world = build_hull_world(d->covering);
  ASSERT_TRUE(world.ok());
  ContactResult result;
  ASSERT_TRUE(world.value()->contacts({QueryShape::sphere(0.25), at(V(0.12, 1.5, 2))}, result).ok());
  ASSERT_EQ(result.contacts.size(), 1u);
  EXPECT_NEAR((result.contacts[0].normal - V(-1, 0, 0)).norm(), 0.0, 1e-12); // nearest side: x = 0
  EXPECT_NEAR(result.contacts[0].depth, 0.25 + 0.12, 1e-12);
  // Against the triangles, each face facing the sphere's centre pushes
  // along its own normal: the two big sides give opposing normals.
  int towards_minus_x = 0, towards_plus_x = 0;
  for (int t = 0; t < static_cast<int>(wall.triangles.size()); ++t) {
    const V n = triangle_area_vector(wall, t).normalized();
    const V a = wall.positions[wall.triangles[t][0]];
    const double behind = n.dot(V(0.12, 1.5, 2) - a);
    if (behind < 0 && behind > -0.25) {
      towards_minus_x += n.x() < -0.9;
      towards_plus_x += n.x() > 0.9;
    }
  }
  EXPECT_GT(towards_minus_x, 0);
  EXPECT_GT(towards_plus_x, 0);
}

TEST(HullWorld, CoveringOfTheDemoBuilding) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  const auto world = build_hull_world(d->covering);
  ASSERT_TRUE(world.ok());
  ContactResult result;
  // Standing upright in the doorway, 5 cm into the floor: touches only the
  // floor, pushed up.
  Eigen::Isometry3d upright = at(V(0, 0.85, 3.9));
  upright.linear() = Eigen::AngleAxisd(-M_PI / 2, V::UnitX()).toRotationMatrix(); // local z -> world y
  ASSERT_TRUE(world.value()->contacts({QueryShape::capsule(0.3, 0.6), upright}, result).ok());
  ASSERT_FALSE(result.contacts.empty());
  for (const Contact& c : result.contacts) {
    EXPECT_GT(c.normal.y(), 0.99) << c.hull;
    EXPECT_NEAR(c.depth, 0.05, 1e-9) << c.hull;
  }
  // Walking into the back wall from the room.
  ASSERT_TRUE(world.value()->contacts({QueryShape::sphere(0.3), at(V(-2, 1.5, -3.6))}, result).ok());
  ASSERT_FALSE(result.contacts.empty());
  EXPECT_NEAR(result.contacts[0].depth, 0.1, 1e-9);
  EXPECT_NEAR(result.contacts[0].normal.z(), 1.0, 1e-9);
}

bool same(const ContactResult& a, const ContactResult& b) {
  if (a.contacts.size() != b.contacts.size()) return false;
  for (size_t i = 0; i < a.contacts.size(); ++i)
    if (a.contacts[i].hull != b.contacts[i].hull || a.contacts[i].depth != b.contacts[i].depth ||
        a.contacts[i].normal != b.contacts[i].normal || a.contacts[i].point != b.contacts[i].point)
      return false;
  return true;
}

TEST(HullWorld, EightThreadsGetExactlyWhatOneThreadGets) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  const auto world = build_hull_world(d->covering).value();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(-15, 5), y(-0.5, 3.5), z(-6, 6);
  std::vector<ContactRequest> requests;
  for (int i = 0; i < 400; ++i) {
    const QueryShape shape = i % 3 == 0   ? QueryShape::sphere(0.4)
                             : i % 3 == 1 ? QueryShape::capsule(0.3, 0.6)
                                          : QueryShape::box(V(0.3, 0.5, 0.2));
    Eigen::Isometry3d pose = at(V(x(rng), y(rng), z(rng)));
    pose.linear() = Eigen::Quaterniond(Eigen::Vector4d::Random().normalized()).toRotationMatrix();
    requests.push_back({shape, pose, 8});
  }
  std::vector<ContactResult> expected(requests.size());
  for (size_t i = 0; i < requests.size(); ++i) ASSERT_TRUE(world->contacts(requests[i], expected[i]).ok());
  const auto got = test::answers_from_threads<ContactResult>(
      8, requests.size(), [&](size_t k, ContactResult& answer) { (void)world->contacts(requests[k], answer); });
  int touching = 0;
  for (size_t i = 0; i < requests.size(); ++i) {
    touching += !expected[i].contacts.empty();
    for (int t = 0; t < 8; ++t) EXPECT_TRUE(same(got[t][i], expected[i])) << "thread " << t << " request " << i;
  }
  EXPECT_GT(touching, 40);
}

} // namespace
} // namespace hullcover::bvh

namespace hullcover::bvh {
namespace {

TEST(HullWorld, SweepNeverTunnelsThroughAThinWall) {
  auto built = HullWorld::build({box_hull(V(0, 0, 0), V(0.01, 3, 3))});
  ASSERT_TRUE(built.ok());
  const auto& world = built.value();
  SweepResult r;
  // A 0.1 sphere crossing 10 m in one step, straight through a 1 cm wall.
  ASSERT_TRUE(world->sweep({QueryShape::sphere(0.1), at(V(-5, 1.5, 1.5)), at(V(5, 1.5, 1.5))}, r, 1e-9).ok());
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.fraction, (5.0 - 0.1) / 10.0, 1e-8);
  EXPECT_NEAR(r.normal.x(), -1.0, 1e-6);
  // Missing the wall (passing above it), and stopping short of it.
  ASSERT_TRUE(world->sweep({QueryShape::sphere(0.1), at(V(-5, 3.2, 1.5)), at(V(5, 3.2, 1.5))}, r, 1e-9).ok());
  EXPECT_FALSE(r.hit);
  ASSERT_TRUE(world->sweep({QueryShape::sphere(0.1), at(V(-5, 1.5, 1.5)), at(V(-1, 1.5, 1.5))}, r, 1e-9).ok());
  EXPECT_FALSE(r.hit);
  // A capsule swept sideways into the wall's edge, and one touching at start.
  Eigen::Isometry3d upright = at(V(-2, 1.5, 1.5));
  upright.linear() = Eigen::AngleAxisd(-M_PI / 2, V::UnitX()).toRotationMatrix();
  Eigen::Isometry3d moved = upright;
  moved.translation() = V(2, 1.5, 1.5);
  ASSERT_TRUE(world->sweep({QueryShape::capsule(0.2, 0.5), upright, moved}, r, 1e-9).ok());
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.fraction, (2.0 - 0.2) / 4.0, 1e-8);
  ASSERT_TRUE(world->sweep({QueryShape::sphere(0.1), at(V(0.05, 1, 1)), at(V(1, 1, 1))}, r, 1e-9).ok());
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.fraction, 0.0);
  // A box, stepping on the exact closest-feature distance.
  ASSERT_TRUE(world->sweep({QueryShape::box(V(0.1, 0.1, 0.1)), at(V(-5, 1.5, 1.5)), at(V(5, 1.5, 1.5))}, r, 1e-7).ok());
  ASSERT_TRUE(r.hit);
  EXPECT_NEAR(r.fraction, (5.0 - 0.1) / 10.0, 1e-6);
}

// A plank turning in place about z: at angle a its half extent along y is
// sin(a) + 0.05 cos(a) = R sin(a + b), R = sqrt(1 + 0.05^2), b = atan(0.05),
// so it reaches the wall's face y = 0.5 at a = asin(0.5 / R) - b.
TEST(HullWorld, ATurningSweepStopsWhereThePlankMeetsTheWall) {
  auto world = HullWorld::build({box_hull(V(-2, 0.5, -1), V(2, 0.6, 1))}).value();
  const QueryShape plank = QueryShape::box(V(1, 0.05, 0.05));
  Eigen::Isometry3d start = at(V(0, 0, 0)), end = start;
  end.linear() = Eigen::AngleAxisd(M_PI / 2, V::UnitZ()).toRotationMatrix();
  SweepResult r;
  ASSERT_TRUE(world->sweep({plank, start, end}, r, 1e-9).ok());
  ASSERT_TRUE(r.hit);
  const double meet = std::asin(0.5 / std::sqrt(1.0 + 0.05 * 0.05)) - std::atan(0.05);
  EXPECT_NEAR(r.fraction, meet / (M_PI / 2), 1e-7);
  EXPECT_NEAR(r.normal.y(), -1.0, 1e-6); // pushed back out of the wall's face
  // Apart where it stopped, by at most the touch (and rounding).
  Eigen::Isometry3d stopped = start;
  stopped.linear() = Eigen::AngleAxisd(r.fraction * M_PI / 2, V::UnitZ()).toRotationMatrix();
  DistanceResult gap;
  ASSERT_TRUE(world->distance({plank, stopped}, gap).ok());
  EXPECT_LE(gap.distance, 1e-8);
  TouchResult overlapping;
  ASSERT_TRUE(world->touches({QueryShape::box(V(1, 0.05, 0.05) - V::Constant(1e-7)), stopped}, overlapping).ok());
  EXPECT_FALSE(overlapping.touching) << "stopped inside the wall";
  // Turning 20 degrees (either way: the plank is symmetric) it stops short.
  end.linear() = Eigen::AngleAxisd(-20.0 * M_PI / 180.0, V::UnitZ()).toRotationMatrix();
  ASSERT_TRUE(world->sweep({plank, start, end}, r, 1e-9).ok());
  EXPECT_FALSE(r.hit);
}

// A long plank swinging a half turn while it moves, across a 1 cm wall: a
// sweep that only checked its ends, or stepped by the origin's travel
// alone, would pass straight through.
TEST(HullWorld, ATurningSweepDoesNotTunnelThroughAThinWall) {
  auto world = HullWorld::build({box_hull(V(1.5, -3, -3), V(1.51, 3, 3))}).value();
  const QueryShape plank = QueryShape::box(V(2, 0.05, 0.05));
  Eigen::Isometry3d start = at(V(0, 0, 0)), end = at(V(0.2, 0, 0));
  start.linear() = Eigen::AngleAxisd(M_PI / 2, V::UnitZ()).toRotationMatrix();       // along y: clear of the wall
  end.linear() = Eigen::AngleAxisd(-M_PI / 2 + 1e-3, V::UnitZ()).toRotationMatrix(); // along y again, the other way
  for (const Eigen::Isometry3d* pose : {&start, &end}) {
    TouchResult t;
    ASSERT_TRUE(world->touches({plank, *pose}, t).ok());
    ASSERT_FALSE(t.touching) << "the ends are clear; only the swing meets the wall";
  }
  SweepResult r;
  ASSERT_TRUE(world->sweep({plank, start, end}, r, 1e-9).ok());
  EXPECT_TRUE(r.hit);
  EXPECT_GT(r.fraction, 0.0);
  EXPECT_LT(r.fraction, 0.5); // halfway it lies along x, through the wall
}

// Out of steps, a sweep reports a hit where the shape stands (still apart):
// at once with one step, and on a path grazing the wall's top edge 1e-6
// away, where advancement slows to 1e-6 a step.
TEST(HullWorld, SweepOutOfStepsStopsWhereItStands) {
  auto built = HullWorld::build({box_hull(V(0, 0, 0), V(0.01, 3, 3))});
  ASSERT_TRUE(built.ok());
  const auto& world = built.value();
  SweepRequest request{QueryShape::sphere(0.1), at(V(-5, 1.5, 1.5)), at(V(5, 1.5, 1.5))};
  SweepResult r;
  for (int bad : {0, -3}) {
    request.max_steps = bad;
    EXPECT_EQ(world->sweep(request, r, 1e-9).code(), StatusCode::invalid_argument) << bad;
  }
  request.max_steps = 1;
  ASSERT_TRUE(world->sweep(request, r, 1e-9).ok());
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.fraction, 0.0);
  EXPECT_EQ(r.hull, 0);
  EXPECT_EQ(r.normal, V(-1, 0, 0)); // no contact a touch further on: against the travel

  const double over = 3.0 + (0.1 + 1e-6) / std::sqrt(2.0); // off the edge y = z = 3, diagonally
  request = {QueryShape::sphere(0.1), at(V(-5, over, over)), at(V(5, over, over))};
  ASSERT_TRUE(world->sweep(request, r, 1e-9).ok()); // the default 200 steps
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.hull, 0);
  EXPECT_LT(r.fraction, 0.5);
  DistanceResult d;
  ASSERT_TRUE(world->distance({request.shape, at(V(-5 + 10 * r.fraction, over, over))}, d).ok());
  EXPECT_GT(d.distance, 1e-9);
  request.max_steps = 1000000;
  ASSERT_TRUE(world->sweep(request, r, 1e-9).ok());
  EXPECT_FALSE(r.hit);
}

TEST(HullWorld, QueryShapeCheckNamesTheProblem) {
  const Eigen::Isometry3d pose = at(V(1, 2, 3));
  EXPECT_TRUE(check_query_shape(QueryShape::capsule(0.4, 0.0), pose).ok());
  const Status negative = check_query_shape(QueryShape::sphere(-1), pose);
  EXPECT_EQ(negative.code(), StatusCode::invalid_argument);
  EXPECT_EQ(negative.message(), "sphere radius must be positive");
  QueryShape flat;
  flat.kind = ShapeKind::convex;
  flat.points = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
  EXPECT_EQ(check_query_shape(flat, pose).code(), StatusCode::invalid_argument);
  EXPECT_EQ(check_query_shape(QueryShape::box(V(1, 1, 1)), at(V(0, INFINITY, 0))).code(), StatusCode::invalid_argument);
}

// The barrier every public query runs in: nothing thrown gets out.
TEST(HullWorld, ExceptionsComeBackAsInternalErrors) {
  const Status no_memory = detail::guarded("overlap query", []() -> Status { throw std::bad_alloc(); });
  EXPECT_EQ(no_memory.code(), StatusCode::internal_error);
  EXPECT_EQ(no_memory.message(), "overlap query failed: out of memory");
  const Result<int> thrown = detail::guarded("building", []() -> Result<int> { throw std::runtime_error("boom"); });
  EXPECT_EQ(thrown.status().code(), StatusCode::internal_error);
  EXPECT_EQ(thrown.status().message(), "building failed: boom");
  EXPECT_EQ(detail::guarded("x", []() -> Status { throw 7; }).code(), StatusCode::internal_error);
  EXPECT_EQ(detail::guarded("x", [] { return Result<int>(3); }).value(), 3);
}

} // namespace
} // namespace hullcover::bvh

namespace hullcover::bvh {
namespace {

// The trees file each hull under its box: a box that misses a vertex, or
// an empty one, would hide the hull, so building refuses it.
TEST(HullWorld, RefusesAHullWhoseBoxMissesItsVertices) {
  RuntimeHull shifted = box_hull(V(0, 0, 0), V(1, 1, 1));
  shifted.box.max.x() = 0.5;
  RuntimeHull empty = box_hull(V(2, 0, 0), V(3, 1, 1));
  empty.box = Aabb{};
  for (const RuntimeHull& bad : {shifted, empty}) {
    auto world = HullWorld::build({box_hull(V(-5, -1, -5), V(5, 0, 5)), bad});
    ASSERT_FALSE(world.ok());
    EXPECT_EQ(world.status().code(), StatusCode::invalid_argument);
    EXPECT_NE(world.status().message().find("hull 1"), std::string::npos) << world.status().message();
  }
}

} // namespace
} // namespace hullcover::bvh

namespace hullcover::bvh {
namespace {

// The narrow phase reads a hull's vertices through its facets' and edges'
// indices unchecked, and takes a facet for a polygon: a hull made by hand
// that names a vertex it does not have, or has a facet of two corners, is
// refused at build, naming the hull, not read out of bounds or misjudged.
TEST(HullWorld, RefusesAHullWhoseFacetOrEdgeNamesAMissingVertex) {
  RuntimeHull bad_facet = box_hull(V(0, 0, 0), V(1, 1, 1));
  bad_facet.shape.facets[2][1] = static_cast<int>(bad_facet.shape.vertices.size());
  RuntimeHull bad_edge = box_hull(V(0, 0, 0), V(1, 1, 1));
  bad_edge.edges.back().second = -1;
  RuntimeHull short_facet = box_hull(V(0, 0, 0), V(1, 1, 1));
  short_facet.shape.facets[3].resize(2);
  for (const RuntimeHull& bad : {bad_facet, bad_edge, short_facet}) {
    auto world = HullWorld::build({box_hull(V(-5, -1, -5), V(5, 0, 5)), bad});
    ASSERT_FALSE(world.ok());
    EXPECT_EQ(world.status().code(), StatusCode::invalid_argument);
    EXPECT_NE(world.status().message().find("hull 1"), std::string::npos) << world.status().message();
    EXPECT_NE(world.status().message().find("vertex it does not have"), std::string::npos);
  }
  EXPECT_TRUE(HullWorld::build({box_hull(V(0, 0, 0), V(1, 1, 1))}).ok());
}

} // namespace
} // namespace hullcover::bvh

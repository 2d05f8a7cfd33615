// The covering as FCL objects (fcl_covering.h): FCL's own yes/no and
// distance on those objects, asked through its broadphase manager, against
// HullWorld's exact answers on the same hulls, at random sphere and capsule
// poses in a real covering (the demo building) with rotated hulls added.

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/fcl_covering.h"
#include "hullcover/bvh/hull_world.h"

#include "box_hulls.h"
#include "covering_fixture.h"
#include "poses.h"

#include "hullcover/mesh/scene_builder.h"

#include <fcl/broadphase/default_broadphase_callbacks.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/sphere.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <string>

namespace hullcover::bvh {
namespace {

using V = Eigen::Vector3d;

/// FCL decides touches by GJK (libccd), an iteration that stops at a
/// tolerance (the request's gjk_tolerance, 1e-6 by default), so its yes/no
/// is held to the exact answer only where the exact gap or overlap exceeds
/// this fraction of the scene's size (its bounding diagonal, about 26.7
/// units here: a margin of about 2.7e-5 units).
constexpr double kYesNoMarginPerSceneSize = 1e-6;

/// Random poses of each shape kind (spheres, capsules), the same on every
/// run (a fixed seed), drawn up to an overhang (scene units) past the
/// scene's bounding box so some are apart from everything.
constexpr int kPosesPerShapeKind = 300;
constexpr unsigned kPoseSeed = 20240611;
constexpr double kPoseOverhang = 1.0;

/// Query shape sizes (scene units): a character's scale in the demo
/// building (metres), always well above the yes/no margin.
constexpr double kSmallestRadius = 0.1;
constexpr double kLargestRadius = 0.6;
constexpr double kLargestHalfHeight = 0.8;

/// Rounding in coordinates of the scene's size: FCL's boxes of unrotated
/// objects, and GJK's distance estimate, which is the length of a point of
/// the shapes' Minkowski difference and so never below the true distance
/// but by rounding.
constexpr double kRoundingPerSceneSize = 1e-12;

/// The hulls, HullWorld's world of them and their FCL form.
struct Scene {
  std::vector<RuntimeHull> hulls;
  std::shared_ptr<const HullWorld> world;
  FclCovering fcl;
  Aabb bounds;
  double margin = 0.0; ///< the yes/no margin for this scene's size
};

/// The box around every hull.
Aabb bounds_of(const std::vector<RuntimeHull>& hulls) {
  Aabb box;
  for (const RuntimeHull& h : hulls) {
    box.extend(h.box.min);
    box.extend(h.box.max);
  }
  return box;
}

/// The demo building's covering, then two turned hulls beside it (a box and
/// an octahedron), so FCL also meets hulls whose faces are not axis-aligned.
/// Built once, for every test here.
const Scene& demo_scene() {
  static const Scene scene = [] {
    Scene s;
    const auto d = test::decompose_and_check(demo_building());
    EXPECT_TRUE(d);
    if (!d) return s;
    s.hulls = runtime_hulls(d->covering);
    const Aabb building = bounds_of(s.hulls);
    const V beside(building.max.x() + 1.5, 0.5 * (building.min.y() + building.max.y()), building.min.z() + 1.5);
    Eigen::Isometry3d turned = test::at(beside);
    turned.linear() = Eigen::AngleAxisd(0.6, V(1, 2, 3).normalized()).toRotationMatrix();
    s.hulls.push_back(placed_box(turned, V(0.8, 0.5, 0.3)));
    turned.translation().z() += 3.0;
    QueryShape octahedron;
    octahedron.kind = ShapeKind::convex;
    octahedron.points = {V(1, 0, 0), V(-1, 0, 0), V(0, 1, 0), V(0, -1, 0), V(0, 0, 1), V(0, 0, -1)};
    const std::optional<RuntimeHull> turned_octahedron = placed_convex(octahedron, turned);
    EXPECT_TRUE(turned_octahedron);
    if (turned_octahedron) s.hulls.push_back(*turned_octahedron);
    s.bounds = bounds_of(s.hulls);
    s.margin = kYesNoMarginPerSceneSize * s.bounds.diagonal();
    auto world = HullWorld::build(s.hulls);
    EXPECT_TRUE(world.ok()) << world.status().message();
    auto fcl = make_fcl_covering(s.hulls);
    EXPECT_TRUE(fcl.ok()) << fcl.status().message();
    if (!world.ok() || !fcl.ok()) return s;
    s.world = world.value();
    s.fcl = std::move(fcl).value();
    return s;
  }();
  return scene;
}

/// A query shape at a pose.
struct Pose {
  QueryShape shape;
  Eigen::Isometry3d pose;
};
/// A random sphere or capsule (alternately) at a random pose in and around
/// the scene.
Pose random_pose(int i, const Scene& scene, std::mt19937& rng) {
  std::uniform_real_distribution<double> radius(kSmallestRadius, kLargestRadius);
  std::uniform_real_distribution<double> half_height(0.0, kLargestHalfHeight);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const QueryShape shape =
      i % 2 == 0 ? QueryShape::sphere(radius(rng)) : QueryShape::capsule(radius(rng), half_height(rng));
  const V lo = scene.bounds.min.array() - kPoseOverhang;
  const V span = (scene.bounds.max - scene.bounds.min).array() + 2.0 * kPoseOverhang;
  Eigen::Isometry3d pose = test::at(lo + V(unit(rng), unit(rng), unit(rng)).cwiseProduct(span));
  pose.linear() = Eigen::AngleAxisd(angle(rng), test::random_unit(rng)).toRotationMatrix();
  return {shape, pose};
}

/// A sphere or capsule grown (or shrunk) by `by` all round.
QueryShape grown(QueryShape shape, double by) {
  shape.radius += by;
  return shape;
}

/// The same shape as an FCL collision object at the pose (an FCL capsule's
/// length is its axis segment's, along local z as QueryShape's).
fcl::CollisionObjectd fcl_object(const Pose& p) {
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
  if (p.shape.kind == ShapeKind::sphere)
    geometry = std::make_shared<fcl::Sphered>(p.shape.radius);
  else
    geometry = std::make_shared<fcl::Capsuled>(p.shape.radius, 2.0 * p.shape.half_height);
  return fcl::CollisionObjectd(geometry, p.pose);
}

/// The hull an FCL callback's pair is about: the manager's object carries
/// its index, the query object none.
int hull_of_pair(const fcl::CollisionObjectd& a, const fcl::CollisionObjectd& b) {
  const int index = fcl_hull_index(a);
  return index >= 0 ? index : fcl_hull_index(b);
}

/// Collects every hull FCL's collide says the query object touches.
struct AllCollisions {
  fcl::CollisionRequestd request;
  std::set<int> hulls;
};
bool collect_collision(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data) {
  auto& all = *static_cast<AllCollisions*>(data);
  fcl::CollisionResultd result;
  fcl::collide(a, b, all.request, result);
  if (result.isCollision()) all.hulls.insert(hull_of_pair(*a, *b));
  return false; // keep walking: every colliding hull is wanted
}

/// The least of FCL's distances over the manager's objects and the hull it
/// was found to, by the object's user data.
struct Nearest {
  fcl::DistanceRequestd request;
  double distance = std::numeric_limits<double>::infinity();
  int hull = -1;
};
bool nearer_object(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data, double& least_so_far) {
  auto& nearest = *static_cast<Nearest*>(data);
  fcl::DistanceResultd result;
  fcl::distance(a, b, nearest.request, result);
  if (result.min_distance < nearest.distance) {
    nearest.distance = result.min_distance;
    nearest.hull = hull_of_pair(*a, *b);
  }
  // The manager prunes boxes farther than this; in touch, nothing is nearer.
  least_so_far = nearest.distance;
  return least_so_far <= 0.0;
}

/// Every hull HullWorld says `shape` touches at the pose.
std::set<int> exact_overlap(const HullWorld& world, const QueryShape& shape, const Eigen::Isometry3d& pose) {
  OverlapResult result;
  EXPECT_TRUE(world.overlap({shape, pose}, result).ok());
  return {result.hulls.begin(), result.hulls.end()};
}

bool includes(const std::set<int>& outer, const std::set<int>& inner) {
  return std::includes(outer.begin(), outer.end(), inner.begin(), inner.end());
}

TEST(FclCovering, EveryObjectIsItsHullAndCarriesItsIndex) {
  const Scene& scene = demo_scene();
  ASSERT_TRUE(scene.world && scene.fcl.manager);
  ASSERT_EQ(scene.fcl.objects.size(), scene.hulls.size());
  EXPECT_EQ(scene.fcl.manager->size(), scene.hulls.size());
  // Unrotated objects' boxes are their geometry's own: the hull's box.
  const double rounding = kRoundingPerSceneSize * scene.bounds.diagonal();
  for (size_t i = 0; i < scene.hulls.size(); ++i) {
    const fcl::CollisionObjectd& object = *scene.fcl.objects[i];
    EXPECT_EQ(fcl_hull_index(object), static_cast<int>(i));
    EXPECT_EQ(object.getNodeType(), fcl::GEOM_CONVEX) << i;
    EXPECT_LE((object.getAABB().min_ - scene.hulls[i].box.min).norm(), rounding) << i;
    EXPECT_LE((object.getAABB().max_ - scene.hulls[i].box.max).norm(), rounding) << i;
  }
}

/// What the yes/no comparisons found, summed over poses.
struct YesNoCounts {
  int clearly_touching = 0, clearly_apart = 0, within_margin = 0;
  void print(const char* poses, double margin) const {
    std::printf("%s: %d clearly touching, %d clearly apart, %d within the margin %.3g\n", poses, clearly_touching,
                clearly_apart, within_margin, margin);
  }
};

/// (a) FCL's yes/no through the manager agrees with HullWorld::touches
/// wherever the exact answer is clear by the margin: HullWorld finds the
/// shape shrunk by the margin still touching, or the exact distance beyond
/// it. And, at every pose, the hulls FCL finds touching (by the objects'
/// user data) are among those HullWorld finds touching the shape grown by
/// the margin, and include every hull it finds touching the shrunk shape.
void check_yes_no(const Scene& scene, const Pose& p, YesNoCounts& counts) {
  TouchResult exact;
  ASSERT_TRUE(scene.world->touches({p.shape, p.pose}, exact).ok());
  DistanceResult gap;
  ASSERT_TRUE(scene.world->distance({p.shape, p.pose}, gap).ok());
  TouchResult shrunk;
  ASSERT_TRUE(scene.world->touches({grown(p.shape, -scene.margin), p.pose}, shrunk).ok());
  EXPECT_EQ(exact.touching, gap.touching);

  fcl::CollisionObjectd query = fcl_object(p);
  fcl::DefaultCollisionData<double> yes_no;
  scene.fcl.manager->collide(&query, &yes_no, fcl::DefaultCollisionFunction<double>);
  AllCollisions all;
  scene.fcl.manager->collide(&query, &all, collect_collision);
  EXPECT_EQ(yes_no.result.isCollision(), !all.hulls.empty());
  EXPECT_TRUE(includes(exact_overlap(*scene.world, grown(p.shape, scene.margin), p.pose), all.hulls));
  EXPECT_TRUE(includes(all.hulls, exact_overlap(*scene.world, grown(p.shape, -scene.margin), p.pose)));

  if (shrunk.touching) {
    ++counts.clearly_touching;
    EXPECT_TRUE(exact.touching);
    EXPECT_TRUE(yes_no.result.isCollision());
  } else if (!gap.touching && gap.distance > scene.margin) {
    ++counts.clearly_apart;
    EXPECT_FALSE(yes_no.result.isCollision()) << "exact distance " << gap.distance;
  } else {
    ++counts.within_margin;
  }
}

TEST(FclCovering, YesNoAgreesWithTheHullWorldOutsideTheMargin) {
  const Scene& scene = demo_scene();
  ASSERT_TRUE(scene.world && scene.fcl.manager);
  std::mt19937 rng(kPoseSeed);
  YesNoCounts counts;
  for (int i = 0; i < 2 * kPosesPerShapeKind; ++i) {
    SCOPED_TRACE("pose " + std::to_string(i));
    check_yes_no(scene, random_pose(i, scene, rng), counts);
  }
  counts.print("random poses", scene.margin);
  // Random poses land on both sides; each side must have been compared.
  EXPECT_GT(counts.clearly_touching, kPosesPerShapeKind / 10);
  EXPECT_GT(counts.clearly_apart, kPosesPerShapeKind / 10);
}

/// How many margins from touching the grazing poses are put, either side:
/// just outside the band where FCL is excused.
constexpr double kGrazeInMargins = 2.0;

// The same comparison where FCL's iteration is hardest: each apart random
// pose moved straight at its nearest hull until its gap is kGrazeInMargins
// margins, and on until it overlaps by as much.
TEST(FclCovering, YesNoAgreesWithTheHullWorldJustOutsideTheMargin) {
  const Scene& scene = demo_scene();
  ASSERT_TRUE(scene.world && scene.fcl.manager);
  std::mt19937 rng(kPoseSeed);
  YesNoCounts counts;
  for (int i = 0; i < 2 * kPosesPerShapeKind; ++i) {
    const Pose p = random_pose(i, scene, rng);
    DistanceResult gap;
    ASSERT_TRUE(scene.world->distance({p.shape, p.pose}, gap).ok());
    if (gap.touching || gap.hull < 0) continue;
    // Along the closest points' line the gap shrinks by exactly the travel
    // (another hull can only come nearer): the exact queries in
    // check_yes_no classify the moved pose.
    const V toward = (gap.on_world - gap.on_shape).normalized();
    for (const double gap_left : {kGrazeInMargins * scene.margin, -kGrazeInMargins * scene.margin}) {
      SCOPED_TRACE("pose " + std::to_string(i) + ", gap " + std::to_string(gap_left));
      Pose moved = p;
      moved.pose.translation() += (gap.distance - gap_left) * toward;
      check_yes_no(scene, moved, counts);
    }
  }
  counts.print("grazing poses", scene.margin);
  EXPECT_GT(counts.clearly_touching, kPosesPerShapeKind / 10);
  EXPECT_GT(counts.clearly_apart, kPosesPerShapeKind / 10);
}

/// FCL's GJK distance (libccd) stops once a step gains less than the
/// request's distance_tolerance: at its default (1e-6) it was found up to
/// 1.4e-4 units high on these poses, a bound that depends on the geometry
/// and the poses, so the default request is held only to never being below
/// the exact distance. A 1e-9 request compares the geometry itself
/// (measured 1.4e-7 units high at most; the bound, this fraction of the
/// scene's size, 2.7e-6 units).
constexpr double kTightGjkTolerance = 1e-9;
constexpr double kTightDistanceTolerancePerSceneSize = 1e-7;

/// HullWorld's exact distance from the shape to hull `h` alone.
double exact_distance_to_hull(const Scene& scene, const Pose& p, int h) {
  auto alone = HullWorld::build({scene.hulls[h]});
  EXPECT_TRUE(alone.ok());
  DistanceResult result;
  EXPECT_TRUE(alone.ok() && alone.value()->distance({p.shape, p.pose}, result).ok());
  return result.distance;
}

// (b) FCL's least distance through the manager (FCL's default request)
// agrees with HullWorld's exact distance at every pose clear of the hulls;
// (c) the object it finds nearest carries HullWorld's nearest hull's index,
// or that of a hull the exact distance puts as near within the tolerance;
// and objects[i] is hull i: FCL's distance (tight request) to the object at
// HullWorld's nearest hull's index is HullWorld's distance.
TEST(FclCovering, DistanceAgreesWithTheHullWorldWhenApart) {
  const Scene& scene = demo_scene();
  ASSERT_TRUE(scene.world && scene.fcl.manager);
  const double size = scene.bounds.diagonal();
  const double tolerance = kTightDistanceTolerancePerSceneSize * size;
  fcl::DistanceRequestd tight;
  tight.distance_tolerance = kTightGjkTolerance;
  std::mt19937 rng(kPoseSeed);
  int apart = 0, same_nearest = 0, tied_nearest = 0;
  for (int i = 0; i < 2 * kPosesPerShapeKind; ++i) {
    const Pose p = random_pose(i, scene, rng);
    SCOPED_TRACE("pose " + std::to_string(i));
    DistanceResult exact;
    ASSERT_TRUE(scene.world->distance({p.shape, p.pose}, exact).ok());
    if (exact.touching || !(exact.distance > scene.margin)) continue;
    ++apart;
    ASSERT_GE(exact.hull, 0);

    fcl::CollisionObjectd query = fcl_object(p);
    Nearest loose; // FCL's default request: never below the exact distance
    scene.fcl.manager->distance(&query, &loose, nearer_object);
    EXPECT_GE(loose.distance, exact.distance - kRoundingPerSceneSize * size);
    Nearest nearest;
    nearest.request = tight;
    scene.fcl.manager->distance(&query, &nearest, nearer_object);
    EXPECT_GE(nearest.distance, exact.distance - kRoundingPerSceneSize * size);
    EXPECT_LE(nearest.distance, exact.distance + tolerance);

    fcl::DistanceResultd to_that_object;
    fcl::distance(scene.fcl.objects[exact.hull].get(), &query, tight, to_that_object);
    EXPECT_NEAR(to_that_object.min_distance, exact.distance, tolerance);

    ASSERT_GE(nearest.hull, 0);
    if (nearest.hull == exact.hull) {
      ++same_nearest;
    } else {
      // Hulls meeting at a seam are often equally near.
      ++tied_nearest;
      EXPECT_NEAR(exact_distance_to_hull(scene, p, nearest.hull), exact.distance, tolerance)
          << "FCL's nearest " << nearest.hull << ", exact nearest " << exact.hull;
    }
  }
  EXPECT_GT(apart, kPosesPerShapeKind / 10);
  // Ties need a seam nearest: most poses have one nearest hull.
  EXPECT_GT(same_nearest, apart / 2);
  std::printf("apart %d: FCL's nearest hull the exact one %d, a tied one %d\n", apart, same_nearest, tied_nearest);
}

// (d) What HullWorld::build refuses, make_fcl_covering refuses, and so do
// facets FCL would read out of bounds; the message names the hull.
TEST(FclCovering, RefusesBadHulls) {
  const RuntimeHull good = test::box_hull(V(0, 0, 0), V(1, 1, 1));
  ASSERT_TRUE(make_fcl_covering({good}).ok());
  EXPECT_EQ(make_fcl_covering({}).status().code(), StatusCode::invalid_argument);
  // The code for a good hull then `spoil`ed copy; `world_too`: HullWorld's.
  const auto refusal = [&](void (*spoil)(RuntimeHull&), bool world_too) {
    RuntimeHull bad = good;
    spoil(bad);
    const Result<FclCovering> built = make_fcl_covering({good, bad});
    EXPECT_NE(built.status().message().find("hull 1"), std::string::npos) << built.status().message();
    if (world_too) {
      EXPECT_EQ(HullWorld::build({good, bad}).status().code(), built.status().code());
    }
    return built.status().code();
  };
  const StatusCode refused = StatusCode::invalid_argument;
  EXPECT_EQ(refusal([](RuntimeHull& h) { h.shape.facets.clear(); }, true), refused);
  EXPECT_EQ(refusal([](RuntimeHull& h) { h.shape.vertices[0].x() = std::nan(""); }, true), refused);
  EXPECT_EQ(refusal([](RuntimeHull& h) { h.shape.facets[0][0] = static_cast<int>(h.shape.vertices.size()); }, false),
            refused);
  EXPECT_EQ(refusal([](RuntimeHull& h) { h.shape.facets[0].resize(2); }, false), refused);
}

// Every pointer an FclCovering hands out holds the whole: a manager or an
// object kept after the FclCovering is gone still answers, with its user
// data.
TEST(FclCovering, APointerKeptAloneStaysValid) {
  std::shared_ptr<fcl::DynamicAABBTreeCollisionManagerd> manager;
  std::shared_ptr<fcl::CollisionObjectd> second;
  {
    Result<FclCovering> built =
        make_fcl_covering({test::box_hull(V(0, 0, 0), V(1, 1, 1)), test::box_hull(V(3, 0, 0), V(4, 1, 1))});
    ASSERT_TRUE(built.ok()) << built.status().message();
    manager = built.value().manager;
    second = built.value().objects[1];
  }
  EXPECT_EQ(fcl_hull_index(*second), 1);
  AllCollisions all;
  fcl::CollisionObjectd query = fcl_object({QueryShape::sphere(0.5), test::at(V(3.5, 0.5, 1.2))});
  manager->collide(&query, &all, collect_collision);
  EXPECT_EQ(all.hulls, std::set<int>{1});
  manager.reset();
  EXPECT_EQ(fcl_hull_index(*second), 1);
}

} // namespace
} // namespace hullcover::bvh

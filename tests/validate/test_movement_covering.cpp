// Movement coverings (hullcover/covering/movement_covering.h) on a level
// built for them, checked against the definition: points the level's parts
// name, the faces each hull holds, and the movement audit's own lattice of
// agent centres (hullcover/validate/movement_audit.h), which shares no
// code with the decomposer's reach grid or proofs but the geometry
// library's block store and its flood (block_bytes.h).

#include "box_hulls.h"
#include "movement_scene.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/covering/movement_covering.h"
#include "hullcover/mesh/prepared_mesh.h"
#include "hullcover/validate/movement_audit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;

constexpr double kRadius = 0.3;
// The audit's lattice here: a sixth of the radius.
constexpr double kDenseSpacing = 0.05;

struct Made {
  PreparedMesh prepared;
  MovementCovering movement;
};

MovementOptions walking_from(const test::MovementLevel& level) {
  MovementOptions options;
  options.radius = kRadius;
  options.height = 1.8;
  options.climb = 0.4;
  options.seeds = {level.spawn};
  return options;
}

Made make(const Mesh& mesh, const MovementOptions& options) {
  Result<PreparedMesh> prepared = prepare_mesh(mesh, std::nullopt);
  EXPECT_TRUE(prepared.ok()) << prepared.status().message();
  Result<MovementCovering> made = decompose_for_movement(prepared.value(), options);
  EXPECT_TRUE(made.ok()) << made.status().message();
  return {std::move(prepared).value(), std::move(made).value()};
}

bool inside_some_hull(const Covering& covering, const V& p) {
  return std::any_of(covering.hulls.begin(), covering.hulls.end(),
                     [&](const CoveringHull& h) { return deepest_signed_distance(h.polytope.planes, p) < 0.0; });
}

// The hulls holding any of faces [first, first + count).
std::set<int> hulls_holding(const Covering& covering, int first, int count) {
  std::set<int> holding;
  for (size_t h = 0; h < covering.hulls.size(); ++h)
    for (int f : covering.hulls[h].faces)
      if (f >= first && f < first + count) holding.insert(static_cast<int>(h));
  return holding;
}

validate::MovementAuditReport audited(const Made& made, const std::vector<bvh::RuntimeHull>& hulls,
                                      const MovementOptions& options) {
  validate::MovementAuditOptions audit;
  audit.agent = options;
  audit.spacing = kDenseSpacing;
  Result<validate::MovementAuditReport> report = validate::audit_movement(made.prepared, hulls, audit, 2);
  EXPECT_TRUE(report.ok()) << report.status().message();
  return report.value();
}

TEST(MovementCovering, WalkingFillsTheVoidAndTheGapDropsTheBalconyAndKeepsEveryAgentWithinTheSlop) {
  const test::MovementLevel level = test::movement_level();
  const MovementOptions options = walking_from(level);
  const Made made = make(level.mesh, options);
  const Covering& covering = made.movement.covering;
  EXPECT_TRUE(inside_some_hull(covering, level.in_void));
  EXPECT_TRUE(inside_some_hull(covering, level.in_gap));
  // The balcony's slab is out of reach: no hull holds its faces.
  EXPECT_TRUE(hulls_holding(covering, level.first_balcony_face, 12).empty());
  const validate::MovementAuditReport report = audited(made, bvh::runtime_hulls(covering), options);
  EXPECT_GT(report.reachable_points, 10000);
  EXPECT_GT(report.touching_poses, 1000);
  EXPECT_EQ(report.sinking, 0) << "deepest " << report.deepest << " at " << report.deepest_at.transpose();
  EXPECT_EQ(report.contacts_lost, 0) << "first at " << report.first_lost_at.transpose();
}

TEST(MovementCovering, TheStairsBecomeOneHullAtASlopOfSixCentimetres) {
  const test::MovementLevel level = test::movement_level();
  MovementOptions options = walking_from(level);
  options.slop = 0.06;
  const Made made = make(level.mesh, options);
  const std::set<int> holding = hulls_holding(made.movement.covering, level.first_stair_face, level.stair_faces);
  EXPECT_EQ(holding.size(), 1u);
  const validate::MovementAuditReport report = audited(made, bvh::runtime_hulls(made.movement.covering), options);
  EXPECT_EQ(report.sinking, 0) << "deepest " << report.deepest << " at " << report.deepest_at.transpose();
  EXPECT_EQ(report.contacts_lost, 0);
  // At 2 cm the steps' nosings stand too far out of the ramp between them.
  options.slop = 0.02;
  const Made tight = make(level.mesh, options);
  EXPECT_GT(hulls_holding(tight.movement.covering, level.first_stair_face, level.stair_faces).size(), 1u);
}

TEST(MovementCovering, FlyingAgentsReachTheBalcony) {
  const test::MovementLevel level = test::movement_level();
  MovementOptions options = walking_from(level);
  options.reach = AgentReach::fly;
  const Made made = make(level.mesh, options);
  EXPECT_FALSE(hulls_holding(made.movement.covering, level.first_balcony_face, 12).empty());
  EXPECT_TRUE(inside_some_hull(made.movement.covering, level.in_void));
  const validate::MovementAuditReport report = audited(made, bvh::runtime_hulls(made.movement.covering), options);
  EXPECT_EQ(report.sinking, 0) << "deepest " << report.deepest << " at " << report.deepest_at.transpose();
  EXPECT_EQ(report.contacts_lost, 0);
}

// With the default regions (one, on this level) and with regions of 8
// faces, merged at once on two threads and then across regions.
TEST(MovementCovering, TheSameHullsForAnyThreadCount) {
  const test::MovementLevel level = test::movement_level();
  for (int faces_per_region : {512, 8}) {
    SCOPED_TRACE(faces_per_region);
    MovementOptions options = walking_from(level);
    options.faces_per_region = faces_per_region;
    options.threads = 1;
    const Made one = make(level.mesh, options);
    options.threads = 2;
    const Made two = make(level.mesh, options);
    ASSERT_EQ(one.movement.covering.hulls.size(), two.movement.covering.hulls.size());
    for (size_t h = 0; h < one.movement.covering.hulls.size(); ++h) {
      EXPECT_EQ(one.movement.covering.hulls[h].faces, two.movement.covering.hulls[h].faces);
      EXPECT_EQ(one.movement.covering.hulls[h].polytope.vertices, two.movement.covering.hulls[h].polytope.vertices);
    }
    if (faces_per_region == 8) {
      // Small regions keep the promise too, and still merge across them:
      // the void and the gap are filled.
      EXPECT_TRUE(inside_some_hull(two.movement.covering, level.in_void));
      EXPECT_TRUE(inside_some_hull(two.movement.covering, level.in_gap));
      const validate::MovementAuditReport report = audited(two, bvh::runtime_hulls(two.movement.covering), options);
      EXPECT_EQ(report.sinking, 0) << "deepest " << report.deepest << " at " << report.deepest_at.transpose();
      EXPECT_EQ(report.contacts_lost, 0);
    }
  }
}

TEST(MovementCovering, OptionsOutOfRangeAndSeedsInsideTheSceneAreRefusedWithAMessage) {
  const test::MovementLevel level = test::movement_level();
  Result<PreparedMesh> prepared = prepare_mesh(level.mesh, std::nullopt);
  ASSERT_TRUE(prepared.ok());
  const auto refused = [&](const MovementOptions& options, const std::string& says) {
    const Result<MovementCovering> made = decompose_for_movement(prepared.value(), options);
    ASSERT_FALSE(made.ok());
    EXPECT_EQ(made.status().code(), StatusCode::invalid_argument);
    EXPECT_NE(made.status().message().find(says), std::string::npos) << made.status().message();
  };
  MovementOptions options = walking_from(level);
  options.radius = 0.0;
  refused(options, "radius");
  options = walking_from(level);
  options.slop = 0.3;
  refused(options, "slop");
  options = walking_from(level);
  options.height = 0.5;
  refused(options, "height");
  options = walking_from(level);
  options.up = V(0, 0.6, 0.8);
  refused(options, "up");
  options = walking_from(level);
  options.faces_per_region = 0;
  refused(options, "faces per region");
  options = walking_from(level);
  options.seeds = {V(9, 0.75, 2)}; // in the crate's cavity: clear, but where no walker stands
  refused(options, "walking agent");
  options.seeds = {V(2, 0.1, 2)}; // 0.1 above the floor
  refused(options, "nearest triangle");
}

// The audit's reach holds every centre of a walker on a level floor, far
// from the floor's triangle edges too (where the lowest point a walker
// rests on lies inside the face): a block hung over the middle of one of
// its two triangles, 1.1 m from every edge, is found sinking, and the
// floor's own covering is clean.
TEST(MovementAudit, ReachesEveryCentreOfAWalkerOnALevelFloor) {
  Mesh floor;
  floor.positions = {V(0, 0, 0), V(0, 0, 4), V(4, 0, 4), V(4, 0, 0)};
  floor.triangles = {Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(0, 2, 3)}; // split along x = z
  floor.material_ids = {0, 0};
  MovementOptions options;
  options.radius = kRadius;
  options.height = 1.8;
  options.climb = 0.4;
  options.seeds = {V(2, 0.5, 2)};
  const Made made = make(floor, options);
  std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(made.movement.covering);
  const validate::MovementAuditReport clean = audited(made, hulls, options);
  EXPECT_EQ(clean.sinking, 0);
  EXPECT_EQ(clean.contacts_lost, 0);
  hulls.push_back(test::box_hull(V(2.9, 0.9, 0.9), V(3.1, 1.1, 1.1)));
  const validate::MovementAuditReport blocked = audited(made, hulls, options);
  EXPECT_GT(blocked.sinking, 0);
  EXPECT_GT(blocked.deepest, 0.2);
}

// The audit can fail: a block hung in reachable space, and a covering
// without the floor's hull.
TEST(MovementAudit, FindsAHullInReachableSpaceAndAFloorWithoutItsHull) {
  const test::MovementLevel level = test::movement_level();
  const MovementOptions options = walking_from(level);
  const Made made = make(level.mesh, options);
  std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(made.movement.covering);
  std::vector<bvh::RuntimeHull> with_block = hulls;
  with_block.push_back(test::box_hull(V(3, 0.8, 3), V(3.5, 1.0, 3.5)));
  const validate::MovementAuditReport blocked = audited(made, with_block, options);
  EXPECT_GT(blocked.sinking, 0);
  EXPECT_GT(blocked.deepest, 0.2);
  EXPECT_NEAR(blocked.deepest_at.y(), 0.9, 0.4);
  // The floor's top is covered by the hull holding face 6 (the slab's +y side).
  std::vector<bvh::RuntimeHull> without_floor;
  for (size_t h = 0; h < hulls.size(); ++h) {
    const std::vector<int>& faces = made.movement.covering.hulls[h].faces;
    if (std::find(faces.begin(), faces.end(), 6) == faces.end()) without_floor.push_back(hulls[h]);
  }
  ASSERT_LT(without_floor.size(), hulls.size());
  const validate::MovementAuditReport bare = audited(made, without_floor, options);
  EXPECT_GT(bare.contacts_lost, 0);
}

// A closed room of 4 x 3 x 4 whose wall at x = 4 has no hull. The audit's
// lattice (origin r below the room's corner, spacing r / 2 = 0.15) has no
// point between 3.6 and 3.75 across x: a walker touching that wall stands
// at x = 3.7, whose nearest lattice point (3.75) lies nearer than r to the
// wall. Judged by that point alone, no pose of the wall was judged and the
// lost contacts went unseen; the 4 points above it include x = 3.6.
TEST(MovementAudit, FindsAWallWithoutItsHullWhateverTheLatticesOffsetFromIt) {
  Mesh room;
  test::add_level_box(room, V(0, 0, 0), V(4, 3, 4), true);
  room.material_ids.assign(room.triangles.size(), 0);
  Result<PreparedMesh> prepared = prepare_mesh(room, std::nullopt);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();
  validate::MovementAuditOptions audit;
  audit.agent.radius = kRadius;
  audit.agent.height = 1.8;
  audit.agent.climb = 0.4;
  audit.agent.seeds = {V(2, 0.5, 2)};
  audit.spacing = 0.5 * kRadius;
  std::vector<bvh::RuntimeHull> walls = {
      test::box_hull(V(-1, -1, -1), V(5, 0, 5)), test::box_hull(V(-1, 3, -1), V(5, 4, 5)),
      test::box_hull(V(-1, -1, -1), V(0, 4, 5)), test::box_hull(V(-1, -1, -1), V(5, 4, 0)),
      test::box_hull(V(-1, -1, 4), V(5, 4, 5))};
  Result<validate::MovementAuditReport> open = validate::audit_movement(prepared.value(), walls, audit, 2);
  ASSERT_TRUE(open.ok()) << open.status().message();
  EXPECT_GT(open.value().contacts_lost, 0);
  EXPECT_NEAR(open.value().first_lost_at.x(), 4.0 - kRadius, 0.01);
  walls.push_back(test::box_hull(V(4, -1, -1), V(5, 4, 5)));
  Result<validate::MovementAuditReport> closed = validate::audit_movement(prepared.value(), walls, audit, 2);
  ASSERT_TRUE(closed.ok()) << closed.status().message();
  EXPECT_TRUE(closed.value().clean()) << closed.value().contacts_lost << " lost, " << closed.value().sinking
                                      << " sinking";
}

// Two copies of the level 256 m apart, as two maps of a world: the audit's
// lattice spans hundreds of millions of points but examines only the
// blocks near walkable faces. From a spawn in either copy it reaches about
// as many centres (the far copy's coordinates round differently, and a
// point exactly r from a face may fall either side), from both the sum of
// the two, and it finds a block hung in the far copy's reachable space.
TEST(MovementAudit, TwoLevelsFarApartAreAuditedAlike) {
  const test::MovementLevel level = test::movement_level();
  const V apart(256, 0, 256);
  const Mesh world = test::with_a_copy(level.mesh, apart);
  MovementOptions options = walking_from(level);
  options.seeds.push_back(level.spawn + apart);
  const Made both = make(world, options);
  std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(both.movement.covering);

  validate::MovementAuditOptions audit;
  audit.agent = options;
  audit.spacing = 0.125; // the copies' points are 2,048 spacings apart
  const auto audit_from = [&](const std::vector<V>& seeds, const std::vector<bvh::RuntimeHull>& with) {
    audit.agent.seeds = seeds;
    Result<validate::MovementAuditReport> report = validate::audit_movement(both.prepared, with, audit, 2);
    EXPECT_TRUE(report.ok()) << report.status().message();
    return report.ok() ? report.value() : validate::MovementAuditReport{};
  };
  const validate::MovementAuditReport near = audit_from({level.spawn}, hulls);
  const validate::MovementAuditReport far = audit_from({level.spawn + apart}, hulls);
  const validate::MovementAuditReport twice = audit_from(options.seeds, hulls);
  EXPECT_GT(twice.lattice_points, 1LL << 27); // past what the audit held a byte each before

  EXPECT_GT(near.reachable_points, 10000);
  EXPECT_NEAR(far.reachable_points, near.reachable_points, 0.05 * near.reachable_points);
  EXPECT_EQ(twice.reachable_points, near.reachable_points + far.reachable_points);
  EXPECT_EQ(twice.touching_poses, near.touching_poses + far.touching_poses);
  EXPECT_TRUE(twice.clean());

  hulls.push_back(test::box_hull(V(3, 0.8, 3) + apart, V(3.5, 1.0, 3.5) + apart));
  EXPECT_EQ(audit_from({level.spawn}, hulls).sinking, 0);
  const validate::MovementAuditReport blocked = audit_from({level.spawn + apart}, hulls);
  EXPECT_GT(blocked.sinking, 0);
  EXPECT_GT(blocked.deepest_at.x(), 250.0);
}

} // namespace
} // namespace hullcover

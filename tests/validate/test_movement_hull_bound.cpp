// The lower bound on a movement covering's hulls
// (hullcover/validate/movement_audit.h, movement_hull_bound): a room whose
// fewest hulls are known, and the movement level, whose clean coverings
// must give each of the bound's points a hull of its own.

#include "movement_scene.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/covering/movement_covering.h"
#include "hullcover/mesh/prepared_mesh.h"
#include "hullcover/validate/movement_audit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <thread>

namespace hullcover {
namespace {

// A room of 4 x 3 x 4 (y up) with a spawn point inside. Each of its six
// walls is a plane of two triangles; a hull spanning two walls cuts across
// the room's corner, where a flyer reaches, so a flyer needs six hulls. A
// walker (1.8 tall, climbing 0.4, radius 0.3) reaches no higher than 2.2:
// the ceiling is not touched, and five are needed.
Mesh closed_room() {
  Mesh mesh;
  test::add_level_box(mesh, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 3, 4), true);
  mesh.material_ids.assign(mesh.triangles.size(), 0);
  return mesh;
}

MovementOptions room_agent(AgentReach reach) {
  MovementOptions options;
  options.radius = 0.3;
  options.height = 1.8;
  options.climb = 0.4;
  options.reach = reach;
  options.seeds = {Eigen::Vector3d(2.0, 0.5, 2.0)};
  return options;
}

validate::MovementHullBound bound_for(const PreparedMesh& prepared, const MovementOptions& agent, int threads = 2) {
  validate::MovementAuditOptions options;
  options.agent = agent;
  Result<validate::MovementHullBound> bound = validate::movement_hull_bound(prepared, options, threads);
  EXPECT_TRUE(bound.ok()) << bound.status().message();
  return bound.ok() ? bound.value() : validate::MovementHullBound{};
}

TEST(MovementHullBound, AClosedRoomNeedsAHullForEachWallItsAgentsTouch) {
  Result<PreparedMesh> prepared = prepare_mesh(closed_room(), std::nullopt);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();
  EXPECT_EQ(bound_for(prepared.value(), room_agent(AgentReach::fly)).hulls_needed, 6);
  const validate::MovementHullBound walking = bound_for(prepared.value(), room_agent(AgentReach::walk));
  EXPECT_EQ(walking.hulls_needed, 5);
  for (const Eigen::Vector3d& p : walking.points) EXPECT_LT(p.y(), 2.9) << "a point on the ceiling, at 3";
}

TEST(MovementHullBound, ASlopLeavingNoRoomToPartTwoPointsIsRefusedBeforeTheWork) {
  Result<PreparedMesh> prepared = prepare_mesh(closed_room(), std::nullopt);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();
  const double tol = prepared.value().tolerance.largest_length();
  validate::MovementAuditOptions options;
  options.agent = room_agent(AgentReach::fly);
  options.agent.slop = options.agent.radius - tol; // r - E - 2 tol < 0: no centre parts two points
  const Result<validate::MovementHullBound> alone = validate::movement_hull_bound(prepared.value(), options, 2);
  ASSERT_FALSE(alone.ok());
  EXPECT_EQ(alone.status().code(), StatusCode::invalid_argument);
  EXPECT_NE(alone.status().message().find("slop"), std::string::npos) << alone.status().message();
  // With the audit, refused before its hulls are indexed: none are given.
  options.hull_bound = true;
  const Result<validate::MovementAuditReport> audited = validate::audit_movement(prepared.value(), {}, options, 2);
  ASSERT_FALSE(audited.ok());
  EXPECT_EQ(audited.status().message(), alone.status().message());
}

TEST(MovementHullBound, TheAuditWithTheBoundReportsItsProgressAndFindsTheSameWithIt) {
  Result<PreparedMesh> prepared = prepare_mesh(closed_room(), std::nullopt);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();
  const MovementOptions agent = room_agent(AgentReach::fly);
  Result<MovementCovering> made = decompose_for_movement(prepared.value(), agent);
  ASSERT_TRUE(made.ok()) << made.status().message();
  const std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(made.value().covering);
  validate::MovementAuditOptions options;
  options.agent = agent;
  options.hull_bound = true;
  const Result<validate::MovementAuditReport> quiet = validate::audit_movement(prepared.value(), hulls, options, 2);
  ASSERT_TRUE(quiet.ok()) << quiet.status().message();
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<double> reported;
  options.progress = [&](double fraction) {
    EXPECT_EQ(std::this_thread::get_id(), caller) << "reported from another thread";
    reported.push_back(fraction);
  };
  const Result<validate::MovementAuditReport> told = validate::audit_movement(prepared.value(), hulls, options, 2);
  ASSERT_TRUE(told.ok()) << told.status().message();
  ASSERT_GE(reported.size(), 4u); // the reach, the centres, the touching poses, the bound
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  EXPECT_GT(reported.front(), 0.0);
  EXPECT_EQ(reported.back(), 1.0);
  EXPECT_EQ(told.value().touching_poses, quiet.value().touching_poses);
  EXPECT_EQ(told.value().reachable_points, quiet.value().reachable_points);
  ASSERT_TRUE(told.value().hull_bound && quiet.value().hull_bound);
  EXPECT_EQ(told.value().hull_bound->points, quiet.value().hull_bound->points);
}

// An open sheet of 10 x 10, rippled 0.4 up and down every 2.5 along both
// axes: a flyer reaches both sides, so every ripple keeps hulls apart.
Mesh rippled_sheet() {
  Mesh mesh;
  constexpr int kSide = 14;
  for (int j = 0; j <= kSide; ++j)
    for (int i = 0; i <= kSide; ++i) {
      const double x = 10.0 * i / kSide, z = 10.0 * j / kSide;
      mesh.positions.emplace_back(x, 0.4 * std::sin(x * 2.5) * std::sin(z * 2.5), z);
    }
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      const int v = j * (kSide + 1) + i;
      mesh.triangles.emplace_back(v, v + kSide + 1, v + 1);
      mesh.triangles.emplace_back(v + 1, v + kSide + 1, v + kSide + 2);
    }
  mesh.material_ids.assign(mesh.triangles.size(), 0);
  return mesh;
}

// The decomposer's covering of `mesh` for `agent`, clean by the audit, must
// give each of the bound's points a hull (its face is touched), and no hull
// two of them.
void expect_a_hull_for_each_point(const Mesh& mesh, const MovementOptions& agent, int fewest_points) {
  Result<PreparedMesh> prepared = prepare_mesh(mesh, std::nullopt);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();
  const double tol = prepared.value().tolerance.largest_length();
  Result<MovementCovering> made = decompose_for_movement(prepared.value(), agent);
  ASSERT_TRUE(made.ok()) << made.status().message();
  const Covering& covering = made.value().covering;
  validate::MovementAuditOptions audit;
  audit.agent = agent;
  audit.hull_bound = true;
  Result<validate::MovementAuditReport> report =
      validate::audit_movement(prepared.value(), bvh::runtime_hulls(covering), audit, 2);
  ASSERT_TRUE(report.ok()) << report.status().message();
  ASSERT_TRUE(report.value().clean());

  // The audit's bound, on its own reach, is the bound found alone.
  const validate::MovementHullBound bound = bound_for(prepared.value(), agent);
  ASSERT_TRUE(report.value().hull_bound.has_value());
  EXPECT_EQ(report.value().hull_bound->points, bound.points);
  EXPECT_GE(bound.hulls_needed, fewest_points);
  std::set<int> taken;
  for (const Eigen::Vector3d& p : bound.points) {
    int holding = 0;
    for (size_t h = 0; h < covering.hulls.size(); ++h) {
      if (deepest_signed_distance(covering.hulls[h].polytope.planes, p) > tol) continue;
      ++holding;
      EXPECT_TRUE(taken.insert(static_cast<int>(h)).second)
          << "hull " << h << " holds two of the bound's points, one at " << p.transpose();
    }
    EXPECT_GT(holding, 0) << "no hull holds " << p.transpose();
  }
}

TEST(MovementHullBound, EachPointHasAHullOfItsOwnInACleanCovering) {
  const test::MovementLevel level = test::movement_level();
  for (AgentReach reach : {AgentReach::walk, AgentReach::fly}) {
    SCOPED_TRACE(reach == AgentReach::walk ? "walking" : "flying");
    MovementOptions agent = room_agent(reach);
    agent.seeds = {level.spawn};
    expect_a_hull_for_each_point(level.mesh, agent, 2);
  }
  SCOPED_TRACE("the rippled sheet, flying");
  MovementOptions flyer = room_agent(AgentReach::fly);
  flyer.seeds.clear(); // over every walkable face
  expect_a_hull_for_each_point(rippled_sheet(), flyer, 129);
}

TEST(MovementHullBound, TheSamePointsOnAnyThreadCount) {
  Result<PreparedMesh> prepared = prepare_mesh(rippled_sheet(), std::nullopt);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();
  MovementOptions agent = room_agent(AgentReach::fly);
  agent.seeds.clear(); // over every walkable face
  const validate::MovementHullBound one = bound_for(prepared.value(), agent, 1);
  const validate::MovementHullBound three = bound_for(prepared.value(), agent, 3);
  // More points than one task of the threads asks (64), so they share them.
  EXPECT_GT(one.hulls_needed, 128) << one.hulls_needed;
  EXPECT_EQ(one.points, three.points);
}

} // namespace
} // namespace hullcover

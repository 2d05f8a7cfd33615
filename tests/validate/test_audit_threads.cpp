// The audit on many threads (AuditOptions::threads, `audit --threads`):
// the report is the one-thread report to the last bit, every figure, example
// and located place, in the same order; progress comes from the caller's
// thread, never going back; a negative count is refused.

#include "box_hulls.h"
#include "covering_fixture.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/geometry/parallel_for.h"
#include "hullcover/mesh/scene_builder.h"
#include "hullcover/validate/audit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace hullcover::validate {
namespace {

using V = Eigen::Vector3d;

// Doubles compared with ==: the same operations in the same order give the
// same bits, and anything less would hide an order that depends on threads.
void expect_same(const LostPlace& a, const LostPlace& b, const char* what) {
  EXPECT_EQ(a.point, b.point) << what;
  EXPECT_EQ(a.face, b.face) << what;
  EXPECT_EQ(a.hull, b.hull) << what;
  EXPECT_EQ(a.depth, b.depth) << what;
  EXPECT_EQ(a.opening, b.opening) << what;
}

void expect_same(const RayTally& a, const RayTally& b, const char* what) {
  EXPECT_EQ(a.rays, b.rays) << what;
  EXPECT_EQ(a.enclosed, b.enclosed) << what;
  EXPECT_EQ(a.lost, b.lost) << what;
  EXPECT_EQ(a.lost_length, b.lost_length) << what;
  expect_same(a.deepest, b.deepest, what);
}

void expect_same(const AllowanceReport& a, const AllowanceReport& b) {
  EXPECT_EQ(a.options.agent_radius, b.options.agent_radius);
  EXPECT_EQ(a.options.max_deviation, b.options.max_deviation);
  EXPECT_EQ(a.max_lost_deviation, b.max_lost_deviation);
  EXPECT_EQ(a.farthest_point, b.farthest_point);
  EXPECT_EQ(a.farthest_face, b.farthest_face);
  EXPECT_EQ(a.farthest_hull, b.farthest_hull);
  EXPECT_EQ(a.lost_stretches, b.lost_stretches);
  EXPECT_EQ(a.beyond_deviation, b.beyond_deviation);
  EXPECT_EQ(a.centre_rays, b.centre_rays);
  EXPECT_EQ(a.reach_lost, b.reach_lost);
  EXPECT_EQ(a.deepest_reach.centre, b.deepest_reach.centre);
  EXPECT_EQ(a.deepest_reach.face, b.deepest_reach.face);
  EXPECT_EQ(a.deepest_reach.hull, b.deepest_reach.hull);
  EXPECT_EQ(a.deepest_reach.depth, b.deepest_reach.depth);
  EXPECT_EQ(a.deepest_reach.clearance, b.deepest_reach.clearance);
  EXPECT_EQ(a.deepest_reach.opening, b.deepest_reach.opening);
  EXPECT_EQ(a.enclosed_balls, b.enclosed_balls);
  EXPECT_EQ(a.undecided, b.undecided);
  EXPECT_EQ(a.first_undecided.point, b.first_undecided.point);
  EXPECT_EQ(a.first_undecided.face, b.first_undecided.face);
}

void expect_same(const CheckReport& a, const CheckReport& b) {
  EXPECT_EQ(a.vertices_inside, b.vertices_inside);
  EXPECT_EQ(a.edges_inside, b.edges_inside);
  EXPECT_EQ(a.faces_off_hull, b.faces_off_hull);
  EXPECT_EQ(a.bars_inside, b.bars_inside);
  EXPECT_EQ(a.faces_below_polygon, b.faces_below_polygon);
  EXPECT_EQ(a.faces_uncovered, b.faces_uncovered);
  EXPECT_EQ(a.faces_inside, b.faces_inside);
  EXPECT_EQ(a.uncovered_area, b.uncovered_area);
  EXPECT_EQ(a.total_area, b.total_area);
  EXPECT_EQ(a.hulls_not_convex, b.hulls_not_convex);
  EXPECT_EQ(a.examples, b.examples);
  EXPECT_EQ(a.inside_allowed, b.inside_allowed);
}

void expect_same(const BehaviourReport& a, const BehaviourReport& b) {
  EXPECT_EQ(a.size, b.size);
  EXPECT_EQ(a.poses, b.poses);
  EXPECT_EQ(a.both_touch, b.both_touch);
  EXPECT_EQ(a.neither_touches, b.neither_touches);
  EXPECT_EQ(a.missed, b.missed);
  EXPECT_EQ(a.false_contacts, b.false_contacts);
  EXPECT_EQ(a.deep_false_contacts, b.deep_false_contacts);
  EXPECT_EQ(a.deep_false_boxes, b.deep_false_boxes);
  EXPECT_EQ(a.enclosed_false_contacts, b.enclosed_false_contacts);
  EXPECT_EQ(a.max_false_depth, b.max_false_depth);
  EXPECT_EQ(a.deepest_false.hull, b.deepest_false.hull);
  EXPECT_EQ(a.deepest_false.face, b.deepest_false.face);
  EXPECT_EQ(a.deepest_false.centre, b.deepest_false.centre);
  EXPECT_EQ(a.deepest_false.point, b.deepest_false.point);
  EXPECT_EQ(a.deepest_false.depth, b.deepest_false.depth);
  EXPECT_EQ(a.max_normal_angle, b.max_normal_angle);
  EXPECT_EQ(a.mean_normal_angle, b.mean_normal_angle);
}

// Every field of the two reports (an audit report has no timing).
void expect_same(const AuditReport& a, const AuditReport& b) {
  EXPECT_EQ(a.findings, b.findings);
  EXPECT_EQ(a.hull_count, b.hull_count);
  EXPECT_EQ(a.groups_without_area, b.groups_without_area);
  const ProbeReport &p = a.probe, &q = b.probe;
  EXPECT_EQ(p.probe_distance, q.probe_distance);
  EXPECT_EQ(p.resolution, q.resolution);
  expect_same(p.front, q.front, "front");
  expect_same(p.opening, q.opening, "openings");
  EXPECT_EQ(p.lost_cells, q.lost_cells);
  EXPECT_EQ(p.max_lost_depth, q.max_lost_depth);
  EXPECT_EQ(p.octree_origin, q.octree_origin);
  ASSERT_EQ(p.worst.size(), q.worst.size());
  for (size_t i = 0; i < p.worst.size(); ++i) expect_same(p.worst[i], q.worst[i], "worst");
  expect_same(p.allowance, q.allowance);
  expect_same(a.recheck, b.recheck);
  expect_same(a.behaviour, b.behaviour);
}

AuditReport audit_on(const test::Decomposed& d, const HullSet& set, AuditOptions options, int threads) {
  options.threads = threads;
  Result<AuditReport> r = run_audit(d.prepared, set, options);
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? std::move(r).value() : AuditReport{};
}

// The demo building's hulls, spoiled three ways: the first hull dropped (its
// faces on no hull: re-check examples), a box closing the doorway (front
// space lost) and one round the interior wall's end (mesh edges inside it,
// space lost on either side).
TEST(AuditThreads, AViolatingCoveringGivesTheSameReportOnOneTwoThreeAndEightThreads) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  set.hulls.erase(set.hulls.begin());
  set.hulls.push_back(test::box_hull(V(-0.6, 0.0, 3.8), V(0.6, 2.1, 4.0)));
  set.hulls.push_back(test::box_hull(V(-0.4, 0.5, 1.0), V(0.4, 1.5, 2.0)));
  AuditOptions options;
  options.probe.resolution = 0.15;
  options.behaviour.proxies = 600;
  const AuditReport one = audit_on(*d, set, options, 1);
  // The comparison means something only when every part found something.
  EXPECT_GT(one.probe.front.lost, 0);
  EXPECT_GT(one.probe.lost_cells, 1);
  EXPECT_GE(one.probe.worst.size(), 2u);
  EXPECT_GT(one.recheck.edges_inside, 0);
  EXPECT_GT(one.recheck.faces_uncovered, 0);
  EXPECT_FALSE(one.recheck.examples.empty());
  for (int threads : {2, 3, 8}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    expect_same(one, audit_on(*d, set, options, threads));
  }
  // 0 is every core, whatever their number.
  expect_same(one, audit_on(*d, set, options, 0));
}

// The allowance judge's figures (farthest lost point, balls of the agent
// radius) are added up per face and edge too: the same on any count.
TEST(AuditThreads, AnAllowanceAuditGivesTheSameReportOnAnyThreadCount) {
  DecomposeOptions decompose;
  decompose.max_deviation = 2.0 * test::kGrooveDepth;
  const auto d = test::decompose_and_check(test::grooved_floor(), decompose);
  ASSERT_TRUE(d);
  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  AuditOptions options;
  options.probe.allowance = {4.0 * test::kGrooveDepth, 0.25 * test::kGrooveDepth};
  // Rays 0.04 apart, not the default 0.006: the groove (0.2 wide) still
  // holds several, and the sanitizer builds stay quick.
  options.probe.resolution = 0.04;
  options.behaviour.proxies = 300;
  const AuditReport one = audit_on(*d, set, options, 1);
  EXPECT_GT(one.probe.allowance.beyond_deviation, 0);
  EXPECT_GT(one.probe.allowance.centre_rays, 0);
  for (int threads : {2, 3, 8}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    expect_same(one, audit_on(*d, set, options, threads));
  }
  // Held to 4 evaluations a ray, many run out: the first one named is the
  // first in ray order, whichever thread met it.
  options.probe.allowance.max_evaluations_per_ray = 4;
  const AuditReport bounded = audit_on(*d, set, options, 1);
  EXPECT_GT(bounded.probe.allowance.undecided, 1);
  EXPECT_GE(bounded.probe.allowance.first_undecided.face, 0);
  for (int threads : {2, 8}) {
    SCOPED_TRACE(testing::Message() << threads << " threads, bounded");
    expect_same(bounded, audit_on(*d, set, options, threads));
  }
}

// Progress is reported from the thread that called run_audit, in order,
// ending at 1, however many threads work.
TEST(AuditThreads, ProgressComesFromTheCallerAndNeverGoesBack) {
  Mesh room;
  add_box(room, V(0, 0, 0), V(4, 3, 5), false);
  const auto d = test::decompose_and_check(room);
  ASSERT_TRUE(d);
  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  std::vector<double> fractions;
  std::vector<std::thread::id> callers;
  AuditOptions options;
  options.probe.resolution = 0.1;
  options.behaviour.proxies = 300;
  options.threads = 4;
  options.progress = [&](double fraction) {
    fractions.push_back(fraction);
    callers.push_back(std::this_thread::get_id());
  };
  ASSERT_TRUE(run_audit(d->prepared, set, options).ok());
  ASSERT_GT(fractions.size(), 3u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_GE(fractions.front(), 0.0);
  for (const std::thread::id& id : callers) EXPECT_EQ(id, std::this_thread::get_id());
}

TEST(AuditThreads, ANegativeThreadCountIsRefused) {
  Mesh room;
  add_box(room, V(0, 0, 0), V(4, 3, 5), false);
  const auto d = test::decompose_and_check(room);
  ASSERT_TRUE(d);
  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  AuditOptions options;
  options.threads = -1;
  const Result<AuditReport> refused = run_audit(d->prepared, set, options);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), StatusCode::invalid_argument);
  EXPECT_NE(refused.status().message().find("thread"), std::string::npos) << refused.status().message();
  options.threads = -8;
  EXPECT_EQ(run_audit(d->prepared, set, options).status().code(), StatusCode::invalid_argument);
}

// What the audit's split rests on: every job runs once, commits come on the
// caller's thread in index order batch by batch, and a job's exception comes
// back to the caller after the threads stop.
TEST(AuditThreads, ParallelForOrderedCommitsEveryIndexInOrderOnTheCaller) {
  constexpr int kCount = 1000, kBatch = 64;
  std::vector<std::atomic<int>> runs(kCount);
  std::vector<int> committed;
  bool on_caller = true;
  const std::thread::id caller = std::this_thread::get_id();
  parallel_for_ordered(
      kCount, 4, kBatch, [&](int i) { ++runs[i]; },
      [&](int i) {
    EXPECT_EQ(runs[i].load(), 1) << i; // its batch is done before it is committed
    committed.push_back(i);
    on_caller = on_caller && std::this_thread::get_id() == caller;
      });
  std::vector<int> expected(kCount);
  for (int i = 0; i < kCount; ++i) expected[i] = i;
  EXPECT_EQ(committed, expected);
  EXPECT_TRUE(on_caller);
  EXPECT_THROW(parallel_for(
                   kCount, 4,
                   [](int i) {
    if (i == 500) throw std::runtime_error("job 500");
                   }),
               std::runtime_error);
  EXPECT_EQ(threads_to_use(3), 3);
  EXPECT_GE(threads_to_use(0), 1);
}

} // namespace
} // namespace hullcover::validate

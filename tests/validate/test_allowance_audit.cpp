// The allowance audit (allowance_audit.h, `hullcover audit --agent-radius /
// --max-deviation`) passes the decomposer's allowance coverings and catches
// hulls that take more than the allowance, at the place they take it.

#include "box_hulls.h"
#include "covering_fixture.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/tolerances.h"
#include "hullcover/validate/audit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace hullcover::validate {
namespace {

using V = Eigen::Vector3d;

using test::grooved_floor;
using test::kGrooveDepth;

AuditReport audit(const test::Decomposed& d, std::vector<bvh::RuntimeHull> hulls, const AllowanceOptions& allowance) {
  HullSet set;
  set.hulls = std::move(hulls);
  AuditOptions options;
  options.probe.allowance = allowance;
  options.behaviour.proxies = 600;
  Result<AuditReport> r = run_audit(d.prepared, set, options);
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? r.value() : AuditReport{};
}

TEST(AllowanceAudit, MaxDeviationFindsTheFarthestLostPointAndJudgesIt) {
  DecomposeOptions options;
  options.max_deviation = 2.0 * kGrooveDepth;
  const auto d = test::decompose_and_check(grooved_floor(), options);
  ASSERT_TRUE(d);
  const std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(d->covering);
  const AuditReport allowed = audit(*d, hulls, {std::nullopt, options.max_deviation});
  // The groove is spanned: exact mode's rays see it lost, the allowance
  // finds the farthest lost point inside E and passes it.
  EXPECT_GT(allowed.probe.front.lost, 0);
  EXPECT_GT(allowed.probe.allowance.max_lost_deviation, 0.5 * kGrooveDepth);
  EXPECT_LE(allowed.probe.allowance.max_lost_deviation, *options.max_deviation + d->tol());
  EXPECT_TRUE(allowed.clean()) << allowed.recheck.summary();
  // Held to a quarter of the groove's depth, the same hulls take too much,
  // and the farthest point found lies in the groove.
  const AuditReport tight = audit(*d, hulls, {std::nullopt, 0.25 * kGrooveDepth});
  EXPECT_TRUE(test::has_finding(tight, AuditFinding::deviation_exceeded));
  EXPECT_GT(tight.probe.allowance.beyond_deviation, 0);
  EXPECT_NEAR(tight.probe.allowance.farthest_point.x(), 1.1, 0.1);
  EXPECT_LT(tight.probe.allowance.farthest_point.y(), 0.0);
  // And exact mode calls it lost space.
  EXPECT_TRUE(test::has_finding(audit(*d, hulls, {}), AuditFinding::front_space_lost));
}

TEST(AllowanceAudit, AgentRadiusPassesTheAgentCoveringAndCatchesAFloatingHull) {
  DecomposeOptions options;
  options.agent_radius = 0.3;
  const auto d = test::decompose_and_check(grooved_floor(), options);
  ASSERT_TRUE(d);
  std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(d->covering);
  const AuditReport agent = audit(*d, hulls, {options.agent_radius, std::nullopt});
  EXPECT_GT(agent.probe.allowance.centre_rays, 100);
  EXPECT_EQ(agent.probe.allowance.reach_lost, 0);
  EXPECT_EQ(agent.probe.allowance.undecided, 0);
  EXPECT_EQ(agent.behaviour.missed, 0);
  EXPECT_DOUBLE_EQ(agent.behaviour.size, *options.agent_radius); // proxies of the agent's size
  EXPECT_TRUE(agent.clean()) << agent.recheck.summary();

  // A block hanging 0.4 above the floor: balls of radius 0.3 fit beside and
  // above it, so it takes reachable space; the audit says where.
  hulls.push_back(test::box_hull(V(0.3, 0.4, 0.3), V(0.6, 0.7, 0.6)));
  const AuditReport caught = audit(*d, hulls, {options.agent_radius, std::nullopt});
  EXPECT_TRUE(test::has_finding(caught, AuditFinding::reachable_space_lost));
  EXPECT_EQ(caught.probe.allowance.deepest_reach.hull, static_cast<int>(hulls.size()) - 1);
  EXPECT_GT(caught.probe.allowance.deepest_reach.clearance, *options.agent_radius - d->tol());
}

TEST(AllowanceAudit, ASlotNarrowerThanTheAgentMayBeFilledAWiderOneMayNot) {
  // A floor with a closed-ended slot 0.4 wide and 1 deep; the slot is
  // filled by one box up to 0.15 under the floor (a ball of radius 0.3 dips
  // 0.08 into the slot's mouth), the floors covered by boxes behind them,
  // the end walls' upper strips by their own triangles (flat hulls).
  Mesh m;
  test::add_quad_facing(m, V(0, 0, 0), V(1, 0, 0), V(1, 0, 1), V(0, 0, 1), V(0, 1, 0));
  test::add_quad_facing(m, V(1.4, 0, 0), V(2.4, 0, 0), V(2.4, 0, 1), V(1.4, 0, 1), V(0, 1, 0));
  test::add_quad_facing(m, V(1, -1, 0), V(1.4, -1, 0), V(1.4, -1, 1), V(1, -1, 1), V(0, 1, 0));
  for (const double y0 : {-1.0, -0.15}) {
    const double y1 = y0 < -0.5 ? -0.15 : 0.0;
    test::add_quad_facing(m, V(1, y0, 0), V(1, y1, 0), V(1, y1, 1), V(1, y0, 1), V(1, 0, 0));
    test::add_quad_facing(m, V(1.4, y0, 0), V(1.4, y1, 0), V(1.4, y1, 1), V(1.4, y0, 1), V(-1, 0, 0));
    test::add_quad_facing(m, V(1, y0, 0), V(1.4, y0, 0), V(1.4, y1, 0), V(1, y1, 0), V(0, 0, 1));
    test::add_quad_facing(m, V(1, y0, 1), V(1.4, y0, 1), V(1.4, y1, 1), V(1, y1, 1), V(0, 0, -1));
  }
  const auto d = test::decompose_and_check(m);
  ASSERT_TRUE(d);
  std::vector<bvh::RuntimeHull> hulls = {test::box_hull(V(0, -0.15, 0), V(1, 0, 1)),
                                         test::box_hull(V(1.4, -0.15, 0), V(2.4, 0, 1)),
                                         test::box_hull(V(1, -1, 0), V(1.4, -0.15, 1))};
  for (const Eigen::Vector3i& t : m.triangles) {
    const V &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    const bool end_wall = a.z() == b.z() && b.z() == c.z();
    if (end_wall && std::min({a.y(), b.y(), c.y()}) >= -0.15) hulls.push_back(bvh::flat_triangle_hull(a, b, c));
  }
  ASSERT_EQ(hulls.size(), 7u);
  const AuditReport exact = audit(*d, hulls, {});
  EXPECT_TRUE(test::has_finding(exact, AuditFinding::front_space_lost));
  const AuditReport wide_agent = audit(*d, hulls, {0.3, std::nullopt});
  EXPECT_EQ(wide_agent.probe.allowance.reach_lost, 0);
  EXPECT_FALSE(test::has_finding(wide_agent, AuditFinding::reachable_space_lost));
  const AuditReport thin_agent = audit(*d, hulls, {0.15, std::nullopt});
  EXPECT_TRUE(test::has_finding(thin_agent, AuditFinding::reachable_space_lost));
  EXPECT_EQ(thin_agent.probe.allowance.deepest_reach.hull, 2);
}

// A sheet (y up): a triangle sloping 4 tol over 4 units down to a level
// strip 0.2 wide, above a wall hanging from the strip's outer edge and
// facing in; so placed, the sheet's hull comes out a flat polygon (checked
// below). The sheet's corners fit a slab of tol, so an allowance
// makes one planar patch of it (exact mode's condition 2 refuses: the
// slope's top corner lies 4 tol above the strip's plane). Every point of
// the strip lies on that polygon within tol; the re-check once called the
// strip uncovered because the polygon's far corner rises more than 2 tol
// above the strip's own plane (recast-dungeon in the agent-radius world:
// 3 faces).
TEST(AllowanceAudit, AFlatHullRisingAboveAFacesPlaneFarAwayStillCoversTheFace) {
  // The scene's tolerance, given: a round length, so the rise is 4 of it.
  constexpr double kSceneTolerance = 1e-3;
  constexpr double kRiseInTolerances = 4.0;
  const double tol = kSceneTolerance, rise = kRiseInTolerances * tol;
  Mesh m;
  const V up(0, 1, 0), top(0, rise, 0), near(4, 0, 0), far(4, 0, 6);
  test::add_triangle(m, top, far, near);
  test::add_quad_facing(m, near, V(4.2, 0, 0), V(4.2, 0, 6), far, up);
  test::add_quad_facing(m, V(4.2, 0, 0), V(4.2, -1, 0), V(4.2, -1, 6), V(4.2, 0, 6), V(-1, 0, 0));
  DecomposeOptions options;
  options.agent_radius = 0.3;
  const auto d = test::decompose_and_check(m, options, tol); // re-checks coverage of claimed faces
  ASSERT_TRUE(d);
  // The case at hand: the slope and the strip in one flat hull, rising above
  // the strip's plane (y = 0) by more than the re-check's on-hull distance.
  const int upper = d->hull_of_face(0);
  ASSERT_GE(upper, 0);
  const CoveringHull& hull = d->covering.hulls[upper];
  EXPECT_TRUE(hull.planar && hull.thickness == 0.0);
  EXPECT_EQ(hull.faces, (std::vector<int>{0, 1, 2}));
  double highest = 0.0;
  for (const V& p : hull.polytope.vertices) highest = std::max(highest, p.y());
  EXPECT_GT(highest, kOnHullInTolerances * tol);
  // Read as an audit reads hulls from a file (no faces claimed), every face
  // is covered and the covering audits clean at the agent's radius.
  const AuditReport agent = audit(*d, bvh::runtime_hulls(d->covering), {options.agent_radius, std::nullopt});
  EXPECT_EQ(agent.recheck.faces_uncovered, 0) << agent.recheck.summary();
  EXPECT_TRUE(agent.clean()) << agent.recheck.summary();
}

// Cut from sauerbraten-pandora (its coordinates and its island's tolerance):
// a ceiling (z = -144, facing down) over a wall at x = 496 facing -x, which
// stands on a bevel rising from (494, z -304) to (496, z -302); a wall
// panel far off whose open edge sends a ray along x at z = -304.125, under
// everything, escaping. Hull 4916 of pandora's r = 0.3 covering fills the
// space behind the bevel and under the wall (x >= 494, z in [-304, -302]),
// space on no open front ray. Balls on that ray, centred 0.125 under the
// hull's floor, reach into it; where the nearest point of its interior lay
// 0.0124-0.0175 behind the wall, the ceiling's column grown by tol held it,
// and the ray through it (not a ray of the ceiling: off its edge) slid along
// the wall and past the bevel's edge, outside the casts' tolerance, and
// escaped: the audit called the ball's reach free space (10 balls here, the
// one pandora finding at 0.175). The ceiling's own rays at its edge end on
// the bevel.
TEST(AllowanceAudit, APointBesideAColumnIsJudgedOnTheFacesOwnRaysNotOneSlippingPastAnEdge) {
  constexpr double kPandoraTolerance = 0.017492032471957054;
  const std::vector<std::array<V, 3>> faces = {
      {{V(416, 416, -306), V(416, 416, -304), V(408, 416, -320)}}, // 52657: the far panel
      {{V(464, 416, -144), V(496, 432, -144), V(496, 416, -144)}}, // 38452: the ceiling
      {{V(464, 416, -144), V(464, 432, -144), V(496, 432, -144)}}, // 38453
      {{V(496, 432, -256), V(496, 416, -302), V(496, 416, -256)}}, // 54441: the wall
      {{V(496, 432, -256), V(496, 432, -302), V(496, 416, -302)}}, // 54442
      {{V(496, 432, -192), V(496, 416, -256), V(496, 416, -192)}}, // 54498
      {{V(496, 432, -192), V(496, 432, -256), V(496, 416, -256)}}, // 54499
      {{V(496, 432, -144), V(496, 416, -192), V(496, 416, -144)}}, // 54506
      {{V(496, 432, -144), V(496, 432, -192), V(496, 416, -192)}}, // 54507
      {{V(496, 416, -302), V(496, 432, -302), V(494, 432, -304)}}, // 44546: the bevel
      {{V(494, 432, -304), V(496, 400, -302), V(496, 416, -302)}}, // 44547
      {{V(494, 432, -304), V(494, 416, -304), V(496, 400, -302)}}, // 44551
  };
  Mesh m;
  for (const auto& f : faces) test::add_triangle(m, f[0], f[1], f[2]);
  Result<PreparedMesh> prepared = prepare_mesh(m, kPandoraTolerance);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();
  ConvexHullBuilder builder;
  Result<ConvexPolytope> behind_bevel =
      builder.build({V(496, 400, -302), V(494, 400, -304), V(528, 400, -304), V(528, 416, -302), V(494, 432, -304),
                     V(528, 400, -302), V(496, 432, -302)});
  ASSERT_TRUE(behind_bevel.ok()) << behind_bevel.status().message();
  HullSet set;
  set.hulls.push_back(bvh::make_runtime_hull(std::move(behind_bevel).value(), 0));
  for (const auto& f : faces) set.hulls.push_back(bvh::flat_triangle_hull(f[0], f[1], f[2])); // coverage
  AuditOptions options;
  options.probe.allowance = {0.3, std::nullopt};
  options.behaviour.proxies = 100;
  Result<AuditReport> r = run_audit(prepared.value(), set, options);
  ASSERT_TRUE(r.ok()) << r.status().message();
  const AllowanceReport& agent = r.value().probe.allowance;
  // Balls do reach into the hull (the cut's own open edges also send rays
  // into it: the strict figures are not the point here), in enclosed space.
  EXPECT_GT(agent.enclosed_balls, 0);
  EXPECT_EQ(agent.undecided, 0);
  EXPECT_EQ(agent.reach_lost, 0) << "ball at " << agent.deepest_reach.centre.transpose() << " reaches "
                                 << agent.deepest_reach.depth << " into hull " << agent.deepest_reach.hull;
  EXPECT_FALSE(test::has_finding(r.value(), AuditFinding::reachable_space_lost));
}

// A one-sided wall 20 high (facing away), a hull filling the void behind it
// 0.15 deep, and a strip of floor 0.3-0.44 behind the wall whose rays rise
// beside the hull for 18 units: every ball of 0.3 on them reaches into the
// hull, always where no face's ray passes (enclosed, allowed). Halving to
// tol takes about 37,000 evaluations per ray; the audit decides them all.
// A small face inside the hull, facing up, opens its column through it:
// the balls above it now take free space, and the audit says so.
TEST(AllowanceAudit, ALongRayBesideAFilledVoidIsDecidedAndAnOpeningAboveItIsCaught) {
  constexpr double kHeight = 20.0;
  Mesh m;
  test::add_quad_facing(m, V(0, 0, 0), V(0.4, 0, 0), V(0.4, kHeight, 0), V(0, kHeight, 0), V(0, 0, 1));
  test::add_quad_facing(m, V(0, 0, -0.44), V(0.4, 0, -0.44), V(0.4, 0, -0.2), V(0, 0, -0.2), V(0, 1, 0));
  const auto d = test::decompose_and_check(m, {}, 1e-3);
  ASSERT_TRUE(d);
  const std::vector<bvh::RuntimeHull> hulls = {test::box_hull(V(0, 1, -0.15), V(0.4, kHeight - 1, 0))};
  const auto agent_audit = [](const test::Decomposed& scene, const std::vector<bvh::RuntimeHull>& h,
                              int max_evaluations = kMaxEvaluationsPerRay) {
    HullSet set;
    set.hulls = h;
    AuditOptions options;
    options.probe.allowance = {0.3, std::nullopt, max_evaluations};
    options.probe.resolution = 0.2; // a few rays: each is long work
    options.behaviour.proxies = 30;
    Result<AuditReport> r = run_audit(scene.prepared, set, options);
    EXPECT_TRUE(r.ok()) << r.status().message();
    return r.ok() ? r.value().probe.allowance : AllowanceReport{};
  };
  const AllowanceReport enclosed = agent_audit(*d, hulls);
  EXPECT_GT(enclosed.centre_rays, 0);
  EXPECT_GT(enclosed.enclosed_balls, 1000);
  EXPECT_EQ(enclosed.reach_lost, 0);
  EXPECT_EQ(enclosed.undecided, 0) << "first given up at " << enclosed.first_undecided.point.transpose();
  EXPECT_EQ(enclosed.first_undecided.face, -1);
  // Bound to 16,384 evaluations, the same rays run out, and the report says
  // where: on the floor strip's rays, beside the hull.
  const AllowanceReport bounded = agent_audit(*d, hulls, 16384);
  EXPECT_GT(bounded.undecided, 0);
  EXPECT_EQ(bounded.reach_lost, 0);
  const RayPoint& given_up = bounded.first_undecided;
  EXPECT_TRUE(given_up.face == 2 || given_up.face == 3) << given_up.face; // the floor strip's two triangles
  EXPECT_FALSE(given_up.opening);
  EXPECT_GE(given_up.point.x(), 0.0);
  EXPECT_LE(given_up.point.x(), 0.4);
  EXPECT_GT(given_up.point.y(), 0.5);
  EXPECT_LT(given_up.point.y(), kHeight - 0.5);
  EXPECT_NEAR(given_up.point.z(), -0.37, 0.08);

  Mesh opened = m;
  test::add_quad_facing(opened, V(0.1, 10, -0.15), V(0.3, 10, -0.15), V(0.3, 10, -0.05), V(0.1, 10, -0.05), V(0, 1, 0));
  const auto o = test::decompose_and_check(opened, {}, 1e-3);
  ASSERT_TRUE(o);
  const AllowanceReport caught = agent_audit(*o, hulls);
  EXPECT_GT(caught.reach_lost, 0);
  EXPECT_EQ(caught.deepest_reach.hull, 0);
  EXPECT_GT(caught.deepest_reach.centre.y(), 10.0);
}

TEST(AllowanceAudit, ABoundBelowARaysTwoEndsIsRefused) {
  const auto d = test::decompose_and_check(grooved_floor());
  ASSERT_TRUE(d);
  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  AuditOptions options;
  options.probe.allowance = {0.3, std::nullopt, 1};
  const Result<AuditReport> r = run_audit(d->prepared, set, options);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::invalid_argument);
  EXPECT_NE(r.status().message().find("at least 2 evaluations"), std::string::npos) << r.status().message();
}

} // namespace
} // namespace hullcover::validate

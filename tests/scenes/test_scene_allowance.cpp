// The agent covering of a real scene, decomposed and audited at the radius
// it was made for. Regression from `hullcover bench`: collision-world at
// r = 0.3 (1 unit per metre) was reported losing reachable space; the balls
// met a wedge-shaped hull only within the audit's margin of its thin edge,
// and the point judged lay under a wall's edge by less than the ray casts'
// tolerance. Balls now count only where they reach a hull's interior, and
// the audit of that covering is clean, with the wedge's balls seen.

#include "covering_fixture.h"
#include "shared_data.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/mesh/mesh_import.h"
#include "hullcover/validate/audit.h"

#include <gtest/gtest.h>

namespace hullcover::validate {
namespace {

TEST(AgentCovering, CollisionWorldAtACharactersRadiusAuditsClean) {
  HULLCOVER_REQUIRE_SHARED_SCENES(dir);
  const Result<ImportedMesh> imported = import_mesh(dir + "/threejs-collision-world.glb");
  ASSERT_TRUE(imported.ok()) << imported.status().message();
  DecomposeOptions options;
  options.agent_radius = 0.3;
  const auto d = test::decompose_and_check(imported.value().mesh, options);
  ASSERT_TRUE(d);
  const auto exact = test::decompose_and_check(imported.value().mesh);
  ASSERT_TRUE(exact);
  EXPECT_LT(d->covering.hulls.size(), exact->covering.hulls.size());

  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  AuditOptions audit_options;
  audit_options.probe.allowance = {options.agent_radius, std::nullopt};
  const Result<AuditReport> report = run_audit(d->prepared, set, audit_options);
  ASSERT_TRUE(report.ok()) << report.status().message();
  const AllowanceReport& a = report.value().probe.allowance;
  EXPECT_GT(a.centre_rays, 100000);
  EXPECT_GT(a.enclosed_balls, 0); // balls under the floors' open edges meet hulls in enclosed space
  EXPECT_EQ(a.reach_lost, 0) << "ball at " << a.deepest_reach.centre.transpose() << " into hull "
                             << a.deepest_reach.hull;
  EXPECT_EQ(a.undecided, 0);
  EXPECT_EQ(report.value().behaviour.missed, 0);
  EXPECT_TRUE(report.value().clean());
}

} // namespace
} // namespace hullcover::validate

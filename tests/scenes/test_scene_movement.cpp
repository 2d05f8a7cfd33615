// Movement coverings of real levels, made and audited by the movement audit
// (its own lattice of agent centres). Regressions on recast-dungeon: a
// group whose faces another group's hull held was dropped, and then that
// hull's group too, leaving a wall bare; and a hull a hair thick held a
// wall by its planes alone (a plane test with slack passes points far past
// a thin hull's rim): agents touching the wall lost their contact.

#include "covering_fixture.h"
#include "shared_data.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/covering/covering.h"
#include "hullcover/covering/movement_covering.h"
#include "hullcover/mesh/mesh_import.h"
#include "hullcover/mesh/prepared_mesh.h"
#include "hullcover/validate/movement_audit.h"

#include <gtest/gtest.h>

namespace hullcover::validate {
namespace {

void expect_walking_covering_audits_clean(const std::string& path) {
  const Result<ImportedMesh> imported = import_mesh(path);
  ASSERT_TRUE(imported.ok()) << imported.status().message();
  const Result<PreparedMesh> prepared = prepare_mesh(imported.value().mesh, std::nullopt);
  ASSERT_TRUE(prepared.ok()) << prepared.status().message();
  MovementOptions options;
  options.radius = 0.3; // metres: a character
  const Result<MovementCovering> made = decompose_for_movement(prepared.value(), options);
  ASSERT_TRUE(made.ok()) << made.status().message();
  const Result<Covering> exact = decompose(prepared.value(), {});
  ASSERT_TRUE(exact.ok()) << exact.status().message();
  EXPECT_LT(made.value().covering.hulls.size(), exact.value().hulls.size());

  MovementAuditOptions audit;
  audit.agent = options;
  const Result<MovementAuditReport> report =
      audit_movement(prepared.value(), bvh::runtime_hulls(made.value().covering), audit, 0);
  ASSERT_TRUE(report.ok()) << report.status().message();
  const MovementAuditReport& r = report.value();
  EXPECT_GT(r.reachable_points, 100000);
  EXPECT_GT(r.touching_poses, 100000);
  EXPECT_EQ(r.sinking, 0) << "deepest " << r.deepest << " at " << r.deepest_at.transpose() << " into hull "
                          << r.deepest_hull;
  EXPECT_EQ(r.contacts_lost, 0) << "first at " << r.first_lost_at.transpose();
}

TEST(MovementCoveringScene, DungeonForWalkingAuditsClean) {
  HULLCOVER_REQUIRE_SHARED_SCENES(dir);
  expect_walking_covering_audits_clean(dir + "/recast-dungeon.obj");
}

TEST(MovementCoveringScene, CollisionWorldForWalkingAuditsClean) {
  HULLCOVER_REQUIRE_SHARED_SCENES(dir);
  expect_walking_covering_audits_clean(dir + "/threejs-collision-world.glb");
}

} // namespace
} // namespace hullcover::validate

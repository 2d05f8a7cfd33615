// The metamorphic suite on shared scenes (tests/validate/test_metamorphic.cpp
// has the scenes built in code): nav_test and collision-world moved by 1e5
// and 1e7, turned, scaled by 1e-3 and 1e3 (the default tolerance is
// relative, so it scales with them) and mirrored with the winding flipped
// still decompose to hulls the re-check passes, audit clean under the strict
// definition at the audit's defaults, and need the same number of hulls
// within 2% (5% at 1e7: mesh_transforms.h says why). The transforms are
// applied to the imported mesh in double; the float32 import's own limit at
// 1e7 is the unit test's.

#include "covering_fixture.h"
#include "mesh_transforms.h"
#include "shared_data.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/mesh/mesh_import.h"
#include "hullcover/validate/audit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace hullcover::validate {
namespace {

class SceneMetamorphic : public ::testing::TestWithParam<const char*> {};

// Decomposes and audits `mesh` at the audit's defaults; returns the hull
// count (-1 on failure, recorded as a test failure naming `what`).
long clean_hull_count(const Mesh& mesh, const std::string& what) {
  const auto d = test::decompose_and_check(mesh);
  EXPECT_TRUE(d) << what;
  if (!d) return -1;
  HullSet set;
  set.hulls = bvh::runtime_hulls(d->covering);
  const Result<AuditReport> audit = run_audit(d->prepared, set, AuditOptions{});
  EXPECT_TRUE(audit.ok()) << what << ": " << audit.status().message();
  if (!audit.ok()) return -1;
  const AuditReport& a = audit.value();
  EXPECT_TRUE(a.clean()) << what << ": first finding " << audit_finding_name(a.findings.front());
  EXPECT_GT(a.probe.front.rays, 10000) << what;
  return static_cast<long>(d->covering.hulls.size());
}

TEST_P(SceneMetamorphic, TransformedSceneAuditsCleanWithTheSameHullCount) {
  HULLCOVER_REQUIRE_SHARED_SCENES(dir);
  const Result<ImportedMesh> imported = import_mesh(dir + "/" + GetParam());
  ASSERT_TRUE(imported.ok()) << imported.status().message();
  const Mesh& mesh = imported.value().mesh;
  const long reference = clean_hull_count(mesh, "untransformed");
  ASSERT_GT(reference, 0);
  std::printf("%s untransformed: %ld hulls\n", GetParam(), reference);
  for (const test::MeshTransform& t : test::metamorphic_transforms()) {
    const long count = clean_hull_count(test::transformed(mesh, t.map), t.name);
    std::printf("%s %s: %ld hulls\n", GetParam(), t.name.c_str(), count); // the figures docs/results/covering.md quotes
    EXPECT_LE(std::abs(count - reference), std::floor(t.hull_count_spread * reference))
        << t.name << ": " << count << " hulls, " << reference << " untransformed";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneMetamorphic,
                         ::testing::Values("recast-nav_test.obj", "threejs-collision-world.glb"),
                         [](const ::testing::TestParamInfo<const char*>& param_info) {
  return test::file_test_name(param_info.param);
});

} // namespace
} // namespace hullcover::validate

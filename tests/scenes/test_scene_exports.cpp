// Engine exports of every shared scene: the .glb passes
// the Khronos validator and reads back in Assimp with every hull; the Unreal
// and Godot OBJs read back as the hulls alone; and the audit of the .glb,
// allowed the stated flat-hull thickness, finds nothing farther from the
// mesh than that thickness and no face uncovered. Run on the covering
// test_scene_coverings.cpp makes of each scene, so that each is decomposed
// once.

#include "scene_export_checks.h"
#include "temp_dir.h"

#include "export/collider_export.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/validate/audit.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>

namespace hullcover {

void check_engine_exports(const std::string& scene, const PreparedMesh& prepared, const Covering& covering) {
  const std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(covering);
  const double tol = prepared.tolerance.length;
  const test::TempDir out;

  app::ColliderExportOptions glb_options;
  glb_options.with_scene = true;
  const Result<app::ColliderExportReport> glb =
      app::export_colliders(hulls, tol, &prepared.mesh, glb_options, out.path("hulls.glb"));
  ASSERT_TRUE(glb.ok()) << glb.status().message();
  std::printf("%s: %zu hulls, %d flat given thickness %.6g (%d split), tol %.6g\n", scene.c_str(), hulls.size(),
              glb.value().flat_thickened, glb.value().thickness, glb.value().split, tol);

  // Assimp reads every hull and the render mesh.
  Assimp::Importer importer;
  const aiScene* read = importer.ReadFile(out.path("hulls.glb"), 0);
  ASSERT_NE(read, nullptr) << importer.GetErrorString();
  EXPECT_EQ(read->mNumMeshes, hulls.size() + 1);

  // The Khronos validator, where scripts/setup.sh installed it.
  const std::filesystem::path tools = std::filesystem::path(HULLCOVER_SOURCE_DIR) / "tests/tools/gltf-validator";
  if (std::filesystem::exists(tools / "node_modules/gltf-validator")) {
    const std::string command =
        "node " + (tools / "validate_glb.mjs").string() + " " + out.path("hulls.glb") + " >" + out.path("report.json");
    ASSERT_EQ(std::system(command.c_str()), 0);
    const auto report = nlohmann::json::parse(test::slurp(out.path("report.json")));
    EXPECT_EQ(report["issues"]["numErrors"].get<int>(), 0) << scene;
    EXPECT_EQ(report["issues"]["numWarnings"].get<int>(), 0) << scene;
  } else {
    std::printf("glTF validator not installed (scripts/setup.sh): checked by Assimp and the audit only\n");
  }

  // Unreal's and Godot's names read back as the hulls alone.
  for (const bool unreal : {true, false}) {
    app::ColliderExportOptions names;
    names.with_scene = true;
    if (unreal)
      names.ucx_name = "Level";
    else
      names.godot_names = true;
    const std::string path = out.path(unreal ? "ucx.obj" : "godot.obj");
    ASSERT_TRUE(app::export_colliders(hulls, tol, &prepared.mesh, names, path).ok());
    const Result<validate::HullSet> set = validate::load_hull_set(path);
    ASSERT_TRUE(set.ok()) << set.status().message();
    EXPECT_EQ(set.value().hulls.size(), hulls.size()) << path;
  }

  // The audit of the .glb with the thickness as its max deviation.
  const Result<validate::HullSet> set = validate::load_hull_set(out.path("hulls.glb"));
  ASSERT_TRUE(set.ok()) << set.status().message();
  ASSERT_EQ(set.value().hulls.size(), hulls.size());
  validate::AuditOptions audit;
  audit.probe.allowance.max_deviation = glb.value().thickness;
  const Result<validate::AuditReport> report = validate::run_audit(prepared, set.value(), audit);
  ASSERT_TRUE(report.ok()) << report.status().message();
  const validate::AllowanceReport& a = report.value().probe.allowance;
  std::printf(
      "%s: audit of the .glb: farthest lost point %.6g from the mesh (thickness %.6g), %ld strict lost rays, "
      "%s\n",
      scene.c_str(), a.max_lost_deviation, glb.value().thickness, report.value().probe.lost_rays(),
      report.value().clean() ? "CLEAN" : "not clean");
  EXPECT_LE(a.max_lost_deviation, glb.value().thickness + tol);
  EXPECT_EQ(a.beyond_deviation, 0);
  EXPECT_EQ(report.value().recheck.faces_uncovered, 0);
  EXPECT_TRUE(report.value().clean());
}

} // namespace hullcover

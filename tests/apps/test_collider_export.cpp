// Engine exports (`hullcover export`, `decompose --format`): what engines
// read back and what the audit reads back must be the covering's hulls,
// flat hulls thickened within the stated thickness, every hull within the
// engine's limits; the Khronos validator must accept every .glb.

#include "command_run.h"
#include "temp_dir.h"

#include "export/engine_limits.h"
#include "export/flat_hull_thickening.h"

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/covering/decompose_options.h"
#include "hullcover/geometry/planar_hull.h"
#include "hullcover/validate/hull_set.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

using hullcover::test::CommandRun;
using hullcover::test::run_hullcover;
using hullcover::test::slurp;
using hullcover::test::TempDir;

// A floor, a crate on it, and a wall modelled as a double-sided sheet (two
// coincident quads wound opposite ways): exact mode must cover the sheet
// with flat hulls, one per side.
std::string sheet_room_obj() {
  std::ostringstream obj;
  int base = 1;
  const auto quad = [&](std::initializer_list<double> xyz) {
    const std::vector<double> c(xyz);
    for (int k = 0; k < 4; ++k) obj << "v " << c[3 * k] << ' ' << c[3 * k + 1] << ' ' << c[3 * k + 2] << '\n';
    obj << "f " << base << ' ' << base + 1 << ' ' << base + 2 << ' ' << base + 3 << '\n';
    base += 4;
  };
  quad({0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0}); // floor, up
  quad({2, 0, 0, 2, 4, 0, 2, 4, 2, 2, 0, 2}); // sheet, facing -x ... (winding decides)
  quad({2, 0, 0, 2, 0, 2, 2, 4, 2, 2, 4, 0}); // the same sheet, the other way
  // A crate: five faces looking out (its bottom sits on the floor).
  quad({0.5, 0.5, 1, 1.5, 0.5, 1, 1.5, 1.5, 1, 0.5, 1.5, 1});
  quad({0.5, 0.5, 0, 1.5, 0.5, 0, 1.5, 0.5, 1, 0.5, 0.5, 1});
  quad({1.5, 1.5, 0, 0.5, 1.5, 0, 0.5, 1.5, 1, 1.5, 1.5, 1});
  quad({0.5, 1.5, 0, 0.5, 0.5, 0, 0.5, 0.5, 1, 0.5, 1.5, 1});
  quad({1.5, 0.5, 0, 1.5, 1.5, 0, 1.5, 1.5, 1, 1.5, 0.5, 1});
  return obj.str();
}

struct Decomposed {
  TempDir dir;
  nlohmann::json json;
  int hulls = 0;
  int flat = 0;
};

// Decomposes the sheet room with `extra` decompose options.
void decompose_room(Decomposed& d, const std::string& extra = "") {
  std::ofstream(d.dir.path("room.obj")) << sheet_room_obj();
  const CommandRun run = run_hullcover(d.dir, "decompose " + d.dir.path("room.obj") + " -o " + d.dir.path("hulls.obj") +
                                                  " --json " + d.dir.path("hulls.json") + " -q " + extra);
  ASSERT_EQ(run.status, 0) << run.err;
  d.json = nlohmann::json::parse(slurp(d.dir.path("hulls.json")));
  d.hulls = static_cast<int>(d.json["hulls"].size());
  for (const auto& h : d.json["hulls"]) d.flat += h["planar"].get<bool>() && h["prism_thickness"].get<double>() == 0.0;
}

// Every vertex of every hull, rounded to float as a .glb stores them.
std::multiset<std::array<float, 3>> float_vertices(const std::vector<hullcover::bvh::RuntimeHull>& hulls) {
  std::multiset<std::array<float, 3>> out;
  for (const auto& h : hulls)
    for (const Eigen::Vector3d& v : h.shape.vertices)
      out.insert({static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())});
  return out;
}

// The thickness the export states ("given thickness T").
double stated_thickness(const std::string& out) {
  const size_t at = out.find("given thickness ");
  return at == std::string::npos ? -1.0 : std::stod(out.substr(at + 16));
}

TEST(ColliderExport, GlbHoldsEveryHullSolidAndTheAuditReadsTheSameHulls) {
  Decomposed d;
  decompose_room(d);
  ASSERT_GE(d.flat, 2) << "the double-sided sheet should give flat hulls";
  const CommandRun run = run_hullcover(d.dir, "export " + d.dir.path("hulls.obj") + " -o " + d.dir.path("out.glb") +
                                                  " --scene " + d.dir.path("room.obj") + " --with-scene");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find(std::to_string(d.flat) + " flat hulls"), std::string::npos) << run.out;
  const double thickness = stated_thickness(run.out);
  ASSERT_GT(thickness, 0.0) << run.out;

  const auto glb = hullcover::validate::load_hull_set(d.dir.path("out.glb"));
  ASSERT_TRUE(glb.ok()) << glb.status().message();
  ASSERT_EQ(static_cast<int>(glb.value().hulls.size()), d.hulls) << "the render mesh must not count as a hull";
  for (const auto& h : glb.value().hulls) EXPECT_FALSE(hullcover::app::is_flat_polygon(h.shape));
  // The solid hulls are the covering's own, vertex for vertex (to float).
  const auto obj = hullcover::validate::load_hull_set(d.dir.path("hulls.obj"));
  ASSERT_TRUE(obj.ok());
  std::vector<hullcover::bvh::RuntimeHull> solid_obj;
  for (const auto& h : obj.value().hulls)
    if (!hullcover::app::is_flat_polygon(h.shape)) solid_obj.push_back(h);
  const auto all_glb = float_vertices(glb.value().hulls);
  for (const auto& v : float_vertices(solid_obj)) EXPECT_TRUE(all_glb.count(v)) << v[0] << ' ' << v[1] << ' ' << v[2];

  // Assimp (what many engines' importers are built on) reads the same.
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(d.dir.path("out.glb"), 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  EXPECT_EQ(static_cast<int>(scene->mNumMeshes), d.hulls + 1);
  std::multiset<std::array<float, 3>> assimp_vertices;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    if (std::string(mesh->mName.C_Str()) == "scene") continue;
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
      assimp_vertices.insert({mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z});
  }
  EXPECT_EQ(assimp_vertices, all_glb);

  // The audit of the export: its loss lies within the thickness of the mesh.
  const CommandRun audit =
      run_hullcover(d.dir, "audit " + d.dir.path("room.obj") + " " + d.dir.path("out.glb") + " --max-deviation " +
                               std::to_string(thickness) + " --json " + d.dir.path("audit.json"));
  EXPECT_EQ(audit.status, 0) << audit.out << audit.err;
  const auto report = nlohmann::json::parse(slurp(d.dir.path("audit.json")));
  EXPECT_LE(report["allowance"]["max_lost_deviation"].get<double>(), thickness + report["tolerance"].get<double>());
  EXPECT_EQ(report["recheck"]["faces_uncovered"].get<int>(), 0);
  // And the strict audit sees the thickened sheet take space: the test
  // would pass vacuously if the export lost nothing.
  const CommandRun strict = run_hullcover(d.dir, "audit " + d.dir.path("room.obj") + " " + d.dir.path("out.glb"));
  EXPECT_EQ(strict.status, 1) << strict.out;
}

TEST(ColliderExport, KhronosValidatorReportsNoErrorAndPhysicsExtensionsOnlyAsInformation) {
  const std::filesystem::path tools = std::filesystem::path(HULLCOVER_SOURCE_DIR) / "tests/tools/gltf-validator";
  if (!std::filesystem::exists(tools / "node_modules/gltf-validator"))
    GTEST_SKIP() << "the glTF validator is not installed (scripts/setup.sh runs npm ci in " << tools << ")";
  Decomposed d;
  decompose_room(d);
  for (const std::string& extra : std::vector<std::string>{"", " --with-scene --scene " + d.dir.path("room.obj")}) {
    ASSERT_EQ(run_hullcover(d.dir, "export " + d.dir.path("hulls.obj") + " -o " + d.dir.path("v.glb") + extra).status,
              0);
    const std::string command = "node " + (tools / "validate_glb.mjs").string() + " " + d.dir.path("v.glb") + " >" +
                                d.dir.path("report.json") + " 2>" + d.dir.path("node.err");
    ASSERT_EQ(std::system(command.c_str()), 0) << slurp(d.dir.path("node.err"));
    const auto report = nlohmann::json::parse(slurp(d.dir.path("report.json")));
    EXPECT_EQ(report["issues"]["numErrors"].get<int>(), 0) << report.dump(1);
    EXPECT_EQ(report["issues"]["numWarnings"].get<int>(), 0) << report.dump(1);
    std::set<std::string> unknown;
    for (const auto& m : report["issues"]["messages"]) {
      if (m["code"] == "UNSUPPORTED_EXTENSION") {
        EXPECT_EQ(m["severity"].get<int>(), 2) << m.dump(); // 2: information
        unknown.insert(m["message"].get<std::string>());
      }
    }
    std::string all;
    for (const std::string& u : unknown) all += u + "\n";
    for (const char* extension : {"KHR_physics_rigid_bodies", "OMI_physics_body", "OMI_physics_shape"})
      EXPECT_NE(all.find(extension), std::string::npos) << extension << " not reported: " << all;
  }
}

TEST(ColliderExport, UnrealAndGodotNamesAreReadBackAsTheHullsOnly) {
  Decomposed d;
  decompose_room(d);
  const std::string common =
      "export " + d.dir.path("hulls.obj") + " --scene " + d.dir.path("room.obj") + " --with-scene ";
  ASSERT_EQ(run_hullcover(d.dir, common + "-o " + d.dir.path("ucx.obj") + " --ucx Room").status, 0);
  ASSERT_EQ(run_hullcover(d.dir, common + "-o " + d.dir.path("godot.obj") + " --godot").status, 0);
  const std::string ucx = slurp(d.dir.path("ucx.obj"));
  EXPECT_NE(ucx.find("\no Room\n"), std::string::npos);
  EXPECT_NE(ucx.find("\no UCX_Room_00\n"), std::string::npos);
  EXPECT_NE(slurp(d.dir.path("godot.obj")).find("\no hull_000-convcolonly\n"), std::string::npos);
  for (const char* file : {"ucx.obj", "godot.obj"}) {
    const auto set = hullcover::validate::load_hull_set(d.dir.path(file));
    ASSERT_TRUE(set.ok()) << set.status().message();
    EXPECT_EQ(static_cast<int>(set.value().hulls.size()), d.hulls) << file;
  }
  EXPECT_NE(run_hullcover(d.dir, common + "-o " + d.dir.path("both.obj") + " --ucx Room --godot").status, 0);
  // A name that would split an OBJ line (or an Unreal asset name) is refused.
  const CommandRun spaced = run_hullcover(d.dir, common + "-o " + d.dir.path("bad.obj") + " --ucx 'My Room'");
  EXPECT_EQ(spaced.status, 2);
  EXPECT_NE(spaced.err.find("--ucx NAME"), std::string::npos) << spaced.err;
}

TEST(ColliderExport, TriangleLimitHoldsForEveryHullAndItsExport) {
  Decomposed d;
  decompose_room(d, "--max-hull-triangles 12");
  const auto set = hullcover::validate::load_hull_set(d.dir.path("hulls.obj"));
  ASSERT_TRUE(set.ok());
  for (const auto& h : set.value().hulls) {
    const int triangles = hullcover::app::is_flat_polygon(h.shape)
                              ? hullcover::triangles_of_prism(static_cast<int>(h.shape.facets[0].size()))
                              : hullcover::triangles_of_facets(h.shape.facets);
    EXPECT_LE(triangles, 12);
  }
  EXPECT_EQ(run_hullcover(d.dir, "export " + d.dir.path("hulls.obj") + " -o " + d.dir.path("u.glb") + " --engine unity")
                .status,
            0);
}

TEST(ColliderExport, HullOverAnEnginesLimitIsRefusedNamingTheOption) {
  TempDir dir;
  // One hull of 100 points on a sphere.
  std::ofstream obj(dir.path("round.obj"));
  obj << "o hull_0\n";
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < 100; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / 100.0, r = std::sqrt(1.0 - z * z);
    obj << "v " << r * std::cos(golden * i) << ' ' << r * std::sin(golden * i) << ' ' << z << '\n';
  }
  obj << "f";
  for (int i = 1; i <= 100; ++i) obj << ' ' << i; // a group's hull is its points' hull
  obj << '\n';
  obj.close();
  const CommandRun gpu =
      run_hullcover(dir, "export " + dir.path("round.obj") + " -o " + dir.path("r.glb") + " --engine physx-gpu");
  EXPECT_EQ(gpu.status, 2);
  EXPECT_NE(gpu.err.find("over PhysX GPU's 64"), std::string::npos) << gpu.err;
  EXPECT_NE(gpu.err.find("--max-hull-vertices 64"), std::string::npos) << gpu.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path("r.glb")));
  EXPECT_EQ(
      run_hullcover(dir, "export " + dir.path("round.obj") + " -o " + dir.path("r.glb") + " --engine jolt").status, 0);
}

TEST(FlatHullThickening, OneSidedPolygonGrowsBehindItsFrontAndASheetSplitsAcrossBoth) {
  using hullcover::FlatPolygon;
  const std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const auto flat = [&](const Eigen::Vector3d& normal) {
    const FlatPolygon polygon = hullcover::make_flat_polygon(square, {0, 1, 2, 3}, normal, 1e-9);
    return hullcover::bvh::make_runtime_hull(hullcover::flat_polytope(polygon, true), 0);
  };
  const double t = 0.01, tol = 1e-6;
  const auto extent_along_z = [](const hullcover::ConvexPolytope& p) {
    double low = 1e9, high = -1e9;
    for (const Eigen::Vector3d& v : p.vertices) low = std::min(low, v.z()), high = std::max(high, v.z());
    return std::pair{low, high};
  };
  const auto one = hullcover::app::thicken_flat_hulls({flat(Eigen::Vector3d::UnitZ())}, t, tol);
  ASSERT_EQ(one.flat, 1);
  EXPECT_EQ(one.split, 0);
  EXPECT_EQ(extent_along_z(one.hulls[0]), (std::pair{-t, 0.0}));
  // Every vertex lies on or behind every plane: the planes face out.
  for (const auto& plane : one.hulls[0].planes)
    for (const Eigen::Vector3d& v : one.hulls[0].vertices) EXPECT_LE(plane.signed_distance(v), 1e-12);
  EXPECT_NEAR(hullcover::polytope_volume(one.hulls[0]), t, 1e-12);

  const auto sheet =
      hullcover::app::thicken_flat_hulls({flat(Eigen::Vector3d::UnitZ()), flat(-Eigen::Vector3d::UnitZ())}, t, tol);
  EXPECT_EQ(sheet.split, 2);
  for (const auto& hull : sheet.hulls) EXPECT_EQ(extent_along_z(hull), (std::pair{-t / 2, t / 2}));
}

TEST(EngineLimits, BoxFitsEveryEngineAndTheNamesAreKnown) {
  hullcover::ConvexPolytope box;
  for (int i = 0; i < 8; ++i) box.vertices.push_back(Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  box.facets = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const std::string& name : hullcover::app::engine_names()) {
    const auto engine = hullcover::app::engine_named(name);
    ASSERT_TRUE(engine) << name;
    EXPECT_TRUE(hullcover::app::engine_limit_breaches({box}, hullcover::app::engine_limits(*engine)).empty()) << name;
  }
  EXPECT_FALSE(hullcover::app::engine_named("havok"));
}

} // namespace

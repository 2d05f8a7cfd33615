// The limits an import enforces beyond the file's own consistency: the
// triangle limit that scales with the bytes read (instancing), and the OBJ
// pre-check (material names, material libraries outside the folder).

#include "hostile_corpus.h"
#include "temp_dir.h"

#include "hullcover/mesh/mesh_import.h"

#include <gtest/gtest.h>

#include <string>

namespace hullcover {
namespace {

using test::TempDir;

// A glTF whose one mesh of `triangles` triangles is placed by `placements`
// nodes, its buffer inline (a data URI): the file's size grows with the
// mesh, not with the placements.
std::string instanced_gltf(int triangles, int placements) {
  std::string nodes = "[", roots = "[";
  for (int i = 0; i < placements; ++i) {
    nodes += (i ? "," : "") + std::string(R"({"mesh":0,"translation":[0,)") + std::to_string(2 * i) + ",0]}";
    roots += (i ? "," : "") + std::to_string(i);
  }
  test::GltfParts parts;
  parts.uri = test::data_uri(test::HostileCorpus::triangle_bytes(triangles));
  parts.buffer_bytes = 36u * static_cast<unsigned>(triangles);
  parts.nodes = nodes + "]";
  parts.roots = roots + "]";
  parts.count = std::to_string(3 * triangles);
  return test::gltf_json(parts);
}

TEST(ImportLimits, InstancingPastOneTrianglePerEightBytesIsRefusedUnlessRaised) {
  const TempDir dir;
  // 500 triangles placed 200 times: 100,000 triangles from a file of about
  // 30 kB, whose default limit is the floor, 65,536.
  const std::string path = dir.write("forest.gltf", instanced_gltf(500, 200));
  ASSERT_LT(test::file_bytes(path) / kInputBytesPerDefaultTriangle, kDefaultTriangleLimitFloor);
  const Result<ImportedMesh> refused = import_mesh(path);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), StatusCode::limit_exceeded);
  EXPECT_NE(refused.status().message().find("--max-triangles"), std::string::npos) << refused.status().message();
  ImportLimits raised;
  raised.max_triangles = 100000;
  const Result<ImportedMesh> allowed = import_mesh(path, raised);
  ASSERT_TRUE(allowed.ok()) << allowed.status().message();
  EXPECT_EQ(allowed.value().mesh.triangles.size(), 100000u);
  // Placed fewer times it fits the default.
  const Result<ImportedMesh> few = import_mesh(dir.write("grove.gltf", instanced_gltf(500, 100)));
  ASSERT_TRUE(few.ok()) << few.status().message();
  EXPECT_EQ(few.value().mesh.triangles.size(), 50000u);
}

TEST(ImportLimits, TheDefaultTriangleLimitScalesWithTheBytesBetweenItsBounds) {
  EXPECT_EQ(default_triangle_limit(0), kDefaultTriangleLimitFloor);
  EXPECT_EQ(default_triangle_limit(kInputBytesPerDefaultTriangle * kDefaultTriangleLimitFloor * 3),
            3 * kDefaultTriangleLimitFloor);
  EXPECT_EQ(default_triangle_limit(std::uint64_t{1} << 40), kDefaultTriangleLimitCeiling);
}

const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(ImportLimits, AnObjNamingTooManyMaterialsIsRefusedUnlessRaised) {
  const TempDir dir;
  std::string obj = kTriangle;
  constexpr int kNames = 4097;
  for (int i = 0; i < kNames; ++i) obj += "usemtl m" + std::to_string(i) + "\nf 1 2 3\n";
  const std::string path = dir.write("many.obj", obj);
  const Result<ImportedMesh> refused = import_mesh(path);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), StatusCode::limit_exceeded);
  EXPECT_NE(refused.status().message().find("--max-materials"), std::string::npos) << refused.status().message();
  ImportLimits raised;
  raised.max_materials = kNames;
  const Result<ImportedMesh> allowed = import_mesh(path, raised);
  ASSERT_TRUE(allowed.ok()) << allowed.status().message();
  EXPECT_EQ(allowed.value().mesh.triangles.size(), static_cast<size_t>(kNames));
}

// Assimp ends an OBJ line at '\r' too: names split only by it are as many
// materials to Assimp, and must be to the check.
TEST(ImportLimits, MaterialNamesOnCarriageReturnOnlyLinesCountToo) {
  const TempDir dir;
  std::string obj = "v 0 0 0\rv 1 0 0\rv 0 1 0\r";
  constexpr int kNames = 4097;
  for (int i = 0; i < kNames; ++i) obj += "usemtl m" + std::to_string(i) + "\rf 1 2 3\r";
  const Result<ImportedMesh> refused = import_mesh(dir.write("cr.obj", obj));
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), StatusCode::limit_exceeded) << refused.status().message();
}

TEST(ImportLimits, AnObjMaterialLibraryOutsideTheFolderIsRefusedByItsText) {
  const TempDir dir;
  for (const std::string name : {"/etc/passwd", "../outside.mtl", "sub/../../x.mtl", "http://host/x.mtl",
                                 "file:///etc/passwd", "a\\..\\x.mtl"}) {
    const Result<ImportedMesh> r =
        import_mesh(dir.write("s.obj", "mtllib ok.mtl " + name + "\n" + kTriangle + "f 1 2 3\n"));
    ASSERT_FALSE(r.ok()) << name;
    EXPECT_EQ(r.status().code(), StatusCode::reference_outside_folder) << name;
    EXPECT_NE(r.status().message().find(name), std::string::npos) << r.status().message();
  }
  // Inside the folder (present or not) is fine.
  dir.write("inside.mtl", "newmtl stone\n");
  const Result<ImportedMesh> inside =
      import_mesh(dir.write("s.obj", std::string("mtllib inside.mtl sub/missing.mtl\n") + kTriangle + "f 1 2 3\n"));
  EXPECT_TRUE(inside.ok()) << inside.status().message();
}

} // namespace
} // namespace hullcover

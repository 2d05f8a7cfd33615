// Import of files from anyone (mesh_import.h): references stay inside the
// scene's folder, declared sizes are checked against the bytes present, and
// deep or cyclic hierarchies end as a clear error, never a crash or a hang.
// Each case here is one of the shapes a hostile-input probe used.

#include "hullcover/mesh/mesh_import.h"

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

namespace hullcover {
namespace {

using test::TempDir;

// One triangle, 36 bytes of float32 positions.
constexpr const char* kTriangleBase64 = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

std::string gltf_with(const std::string& buffer_uri, const std::string& nodes = R"([{"mesh":0}])") {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" + nodes +
         R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
         R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":")" +
         buffer_uri + R"("}]})";
}

std::string triangle_bytes() {
  std::string bytes(36, '\0');
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::memcpy(bytes.data(), corners, sizeof corners);
  return bytes;
}

Result<ImportedMesh> import_in(const TempDir& dir, const std::string& name, const std::string& content,
                               const ImportLimits& limits = {}) {
  std::filesystem::create_directories(dir.path("scene"));
  return import_mesh(dir.write("scene/" + name, content), limits);
}

void expect_failure(const Result<ImportedMesh>& r, StatusCode code, const std::string& mentions) {
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), code) << r.status().message();
  EXPECT_NE(r.status().message().find(mentions), std::string::npos) << r.status().message();
  EXPECT_EQ(r.status().message().find('\n'), std::string::npos);
}

TEST(HostileImport, DataUriAndABufferBesideTheSceneAreRead) {
  TempDir dir;
  const Result<ImportedMesh> inline_data = import_in(dir, "a.gltf", gltf_with(std::string("data:application/octet-stream;base64,") + kTriangleBase64));
  ASSERT_TRUE(inline_data.ok()) << inline_data.status().message();
  EXPECT_EQ(inline_data.value().mesh.triangles.size(), 1u);
  std::filesystem::create_directories(dir.path("scene/bin"));
  dir.write("scene/bin/t.bin", triangle_bytes());
  const Result<ImportedMesh> beside = import_in(dir, "b.gltf", gltf_with("bin/t.bin"));
  ASSERT_TRUE(beside.ok()) << beside.status().message();
  EXPECT_EQ(beside.value().mesh.triangles.size(), 1u);
}

TEST(HostileImport, ABufferOutsideTheFolderIsNotRead) {
  TempDir dir;
  const std::string secret = dir.write("secret.bin", triangle_bytes());  // beside the folder, readable
  expect_failure(import_in(dir, "up.gltf", gltf_with("../secret.bin")), StatusCode::reference_outside_folder,
                 "secret.bin");
  expect_failure(import_in(dir, "absolute.gltf", gltf_with(secret)), StatusCode::reference_outside_folder,
                 "secret.bin");
  expect_failure(import_in(dir, "proc.gltf", gltf_with("/proc/self/environ")), StatusCode::reference_outside_folder,
                 "/proc/self/environ");
  expect_failure(import_in(dir, "net.gltf", gltf_with("http://example.com/t.bin")),
                 StatusCode::reference_outside_folder, "example.com");
  std::filesystem::create_symlink(secret, dir.path("scene/link.bin"));
  expect_failure(import_in(dir, "link.gltf", gltf_with("link.bin")), StatusCode::reference_outside_folder,
                 "link.bin");
}

TEST(HostileImport, AnObjMaterialLibraryOutsideTheFolderIsNotRead) {
  TempDir dir;
  dir.write("secret.mtl", "newmtl stolen\nKd 1 0 0\n");
  expect_failure(import_in(dir, "m.obj", "mtllib ../secret.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl stolen\nf 1 2 3\n"),
                 StatusCode::reference_outside_folder, "secret.mtl");
}

TEST(HostileImport, ADeepOrCyclicNodeHierarchyIsAClearError) {
  TempDir dir;
  std::string chain = "[";
  const int depth = 100000;
  for (int i = 0; i < depth; ++i)
    chain += i + 1 < depth ? R"({"children":[)" + std::to_string(i + 1) + "]}," : R"({"mesh":0}])";
  const std::string data = std::string("data:application/octet-stream;base64,") + kTriangleBase64;
  expect_failure(import_in(dir, "deep.gltf", gltf_with(data, chain)), StatusCode::limit_exceeded, "--max-node-depth");
  expect_failure(import_in(dir, "cycle.gltf", gltf_with(data, R"([{"children":[1],"mesh":0},{"children":[0]}])")),
                 StatusCode::unreadable_file, "cycle");
  expect_failure(import_in(dir, "nested.gltf", std::string(50000, '[') + std::string(50000, ']')),
                 StatusCode::limit_exceeded, "nested");
}

TEST(HostileImport, DeclaredCountsMustFitTheBytesPresent) {
  TempDir dir;
  expect_failure(import_in(dir, "cut.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nprop"),
                 StatusCode::unreadable_file, "end_header");
  expect_failure(import_in(dir, "huge.ply",
                           "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                           "property float y\nproperty float z\nend_header\n0123456789"),
                 StatusCode::unreadable_file, "4000000000");
  expect_failure(import_in(dir, "empty_element.ply",
                           "ply\nformat ascii 1.0\nelement nothing 999999999999\nend_header\n"),
                 StatusCode::unreadable_file, "no properties");
  std::string stl(84, '\0');
  stl[80] = '\xff';
  stl[81] = '\xff';
  stl[82] = '\xff';
  stl[83] = '\x7f';
  expect_failure(import_in(dir, "count.stl", stl), StatusCode::unreadable_file, "binary STL declares");
  std::string accessor = gltf_with(std::string("data:application/octet-stream;base64,") + kTriangleBase64);
  accessor.replace(accessor.find("\"count\":3"), 9, "\"count\":3000000000");
  expect_failure(import_in(dir, "accessor.gltf", accessor), StatusCode::unreadable_file, "3000000000");
  std::string buffer = gltf_with("bin.bin");
  dir.write("scene/bin.bin", std::string(8, '\0'));
  expect_failure(import_in(dir, "short_buffer.gltf", buffer), StatusCode::unreadable_file, "holds 8");
}

TEST(HostileImport, LimitsAreEnforcedAndNamed) {
  TempDir dir;
  const std::string two = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
  ImportLimits one_triangle;
  one_triangle.max_triangles = 1;
  expect_failure(import_in(dir, "two.obj", two, one_triangle), StatusCode::limit_exceeded, "--max-triangles");
  ImportLimits tiny;
  tiny.max_file_bytes = 10;
  expect_failure(import_in(dir, "big.obj", two, tiny), StatusCode::limit_exceeded, "--max-file-size");
  ASSERT_TRUE(import_in(dir, "fine.obj", two).ok());
}

} // namespace
} // namespace hullcover

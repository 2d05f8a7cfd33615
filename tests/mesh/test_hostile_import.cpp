// Import of files from anyone (mesh_import.h): references stay inside the
// scene's folder, declared sizes are checked against the bytes present, and
// deep or cyclic hierarchies end as a clear error, never a crash or a hang.
// Each case here is one of the shapes a hostile-input probe used.

#include "hullcover/mesh/mesh_import.h"

#include "ply_value_bytes.h"
#include "shared_data.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>

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
  const Result<ImportedMesh> inline_data =
      import_in(dir, "a.gltf", gltf_with(std::string("data:application/octet-stream;base64,") + kTriangleBase64));
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
  const std::string secret = dir.write("secret.bin", triangle_bytes()); // beside the folder, readable
  expect_failure(import_in(dir, "up.gltf", gltf_with("../secret.bin")), StatusCode::reference_outside_folder,
                 "secret.bin");
  expect_failure(import_in(dir, "absolute.gltf", gltf_with(secret)), StatusCode::reference_outside_folder,
                 "secret.bin");
  expect_failure(import_in(dir, "proc.gltf", gltf_with("/proc/self/environ")), StatusCode::reference_outside_folder,
                 "/proc/self/environ");
  expect_failure(import_in(dir, "net.gltf", gltf_with("http://example.com/t.bin")),
                 StatusCode::reference_outside_folder, "example.com");
  std::filesystem::create_symlink(secret, dir.path("scene/link.bin"));
  expect_failure(import_in(dir, "link.gltf", gltf_with("link.bin")), StatusCode::reference_outside_folder, "link.bin");
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
  expect_failure(
      import_in(dir, "empty_element.ply", "ply\nformat ascii 1.0\nelement nothing 999999999999\nend_header\n"),
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

// A PLY header: three float coordinates a vertex, one list a face.
std::string ply_header(const std::string& format, int vertices, int faces,
                       const std::string& list_types = "uchar int") {
  return "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
         "\nproperty list " + list_types + " vertex_indices\nend_header\n";
}

// A tetrahedron (four triangles) as a binary PLY.
std::string binary_tetrahedron(bool big_endian) {
  std::string ply = ply_header(big_endian ? "binary_big_endian" : "binary_little_endian", 4, 4);
  for (float coordinate : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f})
    ply += test::ply_value_bytes(coordinate, big_endian);
  for (const auto& face : {std::array<int, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
    ply += test::ply_value_bytes(std::uint8_t{3}, big_endian);
    for (int index : face) ply += test::ply_value_bytes(index, big_endian);
  }
  return ply;
}

// One triangle whose face list declares `length` items of which only three
// follow.
std::string binary_face_declaring(std::uint32_t length, bool big_endian) {
  std::string ply = ply_header(big_endian ? "binary_big_endian" : "binary_little_endian", 3, 1, "uint int");
  for (float coordinate : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
    ply += test::ply_value_bytes(coordinate, big_endian);
  ply += test::ply_value_bytes(length, big_endian);
  for (int index : {0, 1, 2}) ply += test::ply_value_bytes(index, big_endian);
  return ply;
}

void expect_refused(const Result<ImportedMesh>& r, const std::string& mentions, const std::string& also) {
  expect_failure(r, StatusCode::unreadable_file, mentions);
  if (!r.ok()) {
    EXPECT_NE(r.status().message().find(also), std::string::npos) << r.status().message();
  }
}

TEST(HostileImport, PlyListLengthsMustFitTheBytesLeft) {
  TempDir dir;
  constexpr std::uint32_t kBinaryLength = std::uint32_t{1} << 27; // Assimp sized this list at 1 GiB
  for (bool big_endian : {false, true}) {
    const std::string ply = binary_face_declaring(kBinaryLength, big_endian);
    ASSERT_LT(ply.size(), 256u);
    expect_refused(import_in(dir, big_endian ? "be.ply" : "le.ply", ply), std::to_string(kBinaryLength), "bytes left");
  }
  std::string negative = ply_header("binary_little_endian", 3, 1, "char int");
  for (float coordinate : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
    negative += test::ply_value_bytes(coordinate, false);
  negative += test::ply_value_bytes(std::int8_t{-1}, false) + test::ply_value_bytes(0, false);
  expect_refused(import_in(dir, "negative.ply", negative), "-1", "negative");

  constexpr std::uint32_t kAsciiLength = std::uint32_t{1} << 26; // 1 GiB in Assimp
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  const std::string ascii = ply_header("ascii", 3, 1) + vertices + std::to_string(kAsciiLength) + " 0 1 2\n";
  expect_refused(import_in(dir, "ascii.ply", ascii), std::to_string(kAsciiLength), "bytes left");
  expect_refused(import_in(dir, "word.ply", ply_header("ascii", 3, 1) + vertices + "three 0 1 2\n"), "'three'",
                 "not a whole number");
  // The second face's length fits the bytes (blank lines) but its last item is missing.
  expect_refused(import_in(dir, "short.ply", ply_header("ascii", 3, 2) + vertices + "3 0 1 2\n3 0 1\n\n\n\n"),
                 "face #1", "ends inside");
}

// Assimp reads an ASCII PLY one element a line and stops a number at the
// first character it does not take, so a file that is sound token by token
// can still hand it a huge list length; the header too must mean to the
// check what it means to Assimp.
TEST(HostileImport, PlyIsCheckedAsAssimpReadsIt) {
  TempDir dir;
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  // Token by token: a list of one item (67108864), then an empty one.
  expect_refused(import_in(dir, "lines.ply", ply_header("ascii", 3, 2) + vertices + "1\n67108864\n0\n"), "67108864",
                 "one element a line");
  const std::string flagged =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty int flags\n"
      "property list int int vertex_indices\nend_header\n";
  expect_refused(import_in(dir, "plus.ply", flagged + vertices + "5+67108864 3 0 1 2\n"), "'5+67108864'",
                 "reads whole");
  std::string camera = binary_tetrahedron(false);
  camera.replace(camera.find("element vertex"), 0, "element camera 1\nproperty float a\n");
  camera.replace(camera.find("end_header\n") + 11, 0, test::ply_value_bytes(1.f, false));
  expect_refused(import_in(dir, "camera.ply", camera), "'camera'", "wrong place");
  std::string dropped = binary_tetrahedron(false);
  dropped.replace(dropped.find("property list"), 0, "obj_info scanner\n");
  expect_refused(import_in(dir, "dropped.ply", dropped), "property list", "drop");
  // A first data byte of 0x0A after the header's '\n' is data, not a line end.
  std::string newline_first = binary_tetrahedron(false);
  newline_first.replace(newline_first.find("end_header\n") + 11, 1, "\n"); // first byte of x = 0x0A
  const Result<ImportedMesh> newline = import_in(dir, "newline.ply", newline_first);
  ASSERT_TRUE(newline.ok()) << newline.status().message();
  const std::uint32_t x_bits = 0x0A;
  float x = 0.0f;
  std::memcpy(&x, &x_bits, sizeof x);
  ASSERT_EQ(newline.value().mesh.positions.size(), 4u);
  EXPECT_EQ(newline.value().mesh.positions[0].x(), static_cast<double>(x));
  EXPECT_EQ(newline.value().mesh.positions[1], Eigen::Vector3d(1, 0, 0));
  std::string crlf = binary_tetrahedron(true);
  crlf.replace(crlf.find("end_header\n"), 11, "end_header\r\n");
  const Result<ImportedMesh> windows = import_in(dir, "crlf.ply", crlf);
  ASSERT_TRUE(windows.ok()) << windows.status().message();
  EXPECT_EQ(windows.value().mesh.positions[3], Eigen::Vector3d(0, 0, 1));
}

TEST(HostileImport, SoundPlyFilesStillImport) {
  TempDir dir;
  for (bool big_endian : {false, true}) {
    const Result<ImportedMesh> r =
        import_in(dir, big_endian ? "tetra_be.ply" : "tetra_le.ply", binary_tetrahedron(big_endian));
    ASSERT_TRUE(r.ok()) << r.status().message();
    EXPECT_EQ(r.value().mesh.triangles.size(), 4u);
  }
  const std::string quad = ply_header("ascii", 4, 1) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  const Result<ImportedMesh> ascii = import_in(dir, "quad.ply", quad);
  ASSERT_TRUE(ascii.ok()) << ascii.status().message();
  EXPECT_EQ(ascii.value().mesh.triangles.size(), 2u);
  std::string crlf = quad; // Windows line ends, and a comment naming the header's end
  for (std::size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2))
    crlf.replace(at, 1, "\r\n");
  crlf.replace(crlf.find("element"), 0, "comment end_header\r\n");
  const Result<ImportedMesh> windows = import_in(dir, "crlf.ply", crlf);
  ASSERT_TRUE(windows.ok()) << windows.status().message();
  EXPECT_EQ(windows.value().mesh.triangles.size(), 2u);
}

TEST(HostileImport, TheStanfordBunnyStillImports) {
  HULLCOVER_REQUIRE_SHARED_SCENES(scenes);
  const Result<ImportedMesh> r = import_mesh(scenes + "/stanford-bunny-res2.ply");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r.value().mesh.triangles.size(), 16301u);
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

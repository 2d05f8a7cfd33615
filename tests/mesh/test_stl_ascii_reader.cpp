// The project's ASCII STL reader (lib/mesh/src/stl_ascii_reader.h), through
// import_mesh as every command reaches it: coordinates in double, corners
// joined where they coincide, binary STL still Assimp's, and a clear
// failure naming the line for every malformed statement.

#include "hullcover/mesh/mesh_import.h"

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace hullcover {
namespace {

using test::TempDir;

std::string facet(const char* a, const char* b, const char* c) {
  return std::string("  facet normal 0 0 1\n    outer loop\n      vertex ") + a + "\n      vertex " + b +
         "\n      vertex " + c + "\n    endloop\n  endfacet\n";
}

// Two triangles of a unit square 1e5 out, written with 17 digits.
std::string far_square() {
  return "solid square\n" +
         facet("100000.12345678901 100000 -100000", "100001.12345678901 100000 -100000",
               "100001.12345678901 100001 -100000") +
         facet("100000.12345678901 100000 -100000", "100001.12345678901 100001 -100000",
               "100000.12345678901 100001 -100000") +
         "endsolid square\n";
}

TEST(StlAsciiReader, CoordinatesKeepTheirDigitsAndSharedCornersAreJoined) {
  TempDir dir;
  const Result<ImportedMesh> read = import_mesh(dir.write("square.stl", far_square()));
  ASSERT_TRUE(read.ok()) << read.status().message();
  const Mesh& mesh = read.value().mesh;
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.positions.size(), 4u);                 // six corners, four places
  EXPECT_EQ(mesh.positions[0].x(), 100000.12345678901); // float32 would give 100000.125
  // The rounding the data carries is double's, not float32's 0.0078 at 1e5.
  EXPECT_LT(mesh.coordinate_error, 1e-10);
}

// The file must start "solid" (how an ASCII STL is told from a binary one);
// after that keywords may be in any case.
TEST(StlAsciiReader, KeywordsInAnyCaseAndSeveralSolidsRead) {
  TempDir dir;
  const std::string text =
      "solid a\n  FACET NORMAL 0 0 1\n    OUTER LOOP\n      VERTEX 0 0 0\n      VERTEX 1 0 0\n"
      "      VERTEX 0 1 0\n    ENDLOOP\n  ENDFACET\nENDSOLID a\nSolid b\n" +
      facet("0 0 1", "1 0 1", "0 1 1") + "endsolid b\n";
  const Result<ImportedMesh> read = import_mesh(dir.write("two.stl", text));
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read.value().mesh.triangles.size(), 2u);
}

TEST(StlAsciiReader, MalformedTextFailsNamingTheLine) {
  TempDir dir;
  const struct {
    std::string text;
    StatusCode code;
    const char* says;
  } cases[] = {
      {"solid x\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n    endloop\n"
       "  endfacet\nendsolid x\n",
       StatusCode::unreadable_file, "line 7: a facet ends without three vertices"},
      {"solid x\n" + facet("0 0 0", "1 0 0", "nan 1 0") + "endsolid x\n", StatusCode::non_finite_coordinate,
       "line 6: coordinate 'nan'"},
      {"solid x\n" + facet("0 0 0", "1 0 0", "0 1e400 0") + "endsolid x\n", StatusCode::non_finite_coordinate,
       "line 6: coordinate '1e400'"},
      {"solid x\n" + facet("0 0 0", "1 0 0", "0 one 0") + "endsolid x\n", StatusCode::unreadable_file,
       "line 6: coordinate 'one' is not a number"},
      {"solid x\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n", StatusCode::unreadable_file,
       "the text ends inside a facet"},
      {"solid x\n  triangle 0 0 0\nendsolid x\n", StatusCode::unreadable_file,
       "line 2: 'triangle' is no ASCII STL statement"},
      {"solid x\nendsolid x\n", StatusCode::empty_scene, "no facet"},
  };
  for (const auto& c : cases) {
    const Result<ImportedMesh> read = import_mesh(dir.write("bad.stl", c.text));
    ASSERT_FALSE(read.ok()) << c.text;
    EXPECT_EQ(read.status().code(), c.code) << read.status().message();
    EXPECT_NE(read.status().message().find(c.says), std::string::npos) << read.status().message();
  }
}

TEST(StlAsciiReader, MoreFacetsThanTheLimitAreRefused) {
  TempDir dir;
  std::string text = "solid x\n";
  for (int i = 0; i < 3; ++i) text += facet("0 0 0", "1 0 0", "0 1 0");
  ImportLimits limits;
  limits.max_triangles = 2;
  const Result<ImportedMesh> read = import_mesh(dir.write("many.stl", text + "endsolid x\n"), limits);
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.status().code(), StatusCode::limit_exceeded);
}

// A binary STL whose header starts with "solid" is still binary when its
// size is the one its count declares: Assimp reads it, in float32.
TEST(StlAsciiReader, ABinaryFileWhoseHeaderSaysSolidIsStillBinary) {
  TempDir dir;
  std::string bytes(84 + 50, '\0');
  std::memcpy(&bytes[0], "solid but binary", 16);
  bytes[80] = 1;                                                  // one triangle
  const float corners[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}; // normal, then three corners
  std::memcpy(&bytes[84], corners, sizeof corners);
  const Result<ImportedMesh> read = import_mesh(dir.write("binary.stl", bytes));
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read.value().mesh.triangles.size(), 1u);
  EXPECT_GT(read.value().mesh.coordinate_error, 0.0); // float32's rounding is recorded
}

} // namespace
} // namespace hullcover

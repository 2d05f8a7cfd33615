// The project's PLY reader (lib/mesh/src/ply_reader.h), ASCII and binary,
// through import_mesh as every command reaches it: coordinates in double,
// extra elements and properties read past, polygons triangulated, and a
// clear failure naming the element for every malformed value.

#include "ply_reader.h"

#include "hullcover/mesh/mesh_import.h"

#include "ply_value_bytes.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace hullcover {
namespace {

using test::TempDir;

// A unit square 1e5 out as one quad, with properties and an element the
// reader reads past (as the Stanford scans have).
std::string far_ply_square(const std::string& faces = "4 0 1 2 3\n") {
  return "ply\nformat ascii 1.0\ncomment far out\nelement vertex 4\nproperty float x\nproperty float y\n"
         "property float z\nproperty float confidence\nelement face 1\nproperty list uchar int vertex_indices\n"
         "element camera 1\nproperty float view_px\nend_header\n"
         "100000.12345678901 100000 -100000 0.5\n100001.12345678901 100000 -100000 0.5\n"
         "100001.12345678901 100001 -100000 0.5\n100000.12345678901 100001 -100000 0.5\n" +
         faces + "7\n";
}

TEST(PlyAsciiReader, CoordinatesKeepTheirDigitsAndPolygonsAreTriangulated) {
  TempDir dir;
  const Result<ImportedMesh> read = import_mesh(dir.write("square.ply", far_ply_square()));
  ASSERT_TRUE(read.ok()) << read.status().message();
  const Mesh& mesh = read.value().mesh;
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[0].x(), 100000.12345678901); // float32 would give 100000.125
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_LT(mesh.coordinate_error, 1e-10); // double's rounding, not float32's 0.0078 at 1e5
}

TEST(PlyAsciiReader, FacesOfFewerThanThreeCornersAreSkippedAndCounted) {
  TempDir dir;
  std::string text = far_ply_square("2 0 1\n");
  text.replace(text.find("element face 1"), 14, "element face 2");
  text.replace(text.find("2 0 1\n"), 6, "2 0 1\n3 0 1 2\n");
  const Result<ImportedMesh> read = import_mesh(dir.write("skip.ply", text));
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read.value().mesh.triangles.size(), 1u);
  EXPECT_EQ(read.value().report.skipped_non_triangle_primitives, 1);
}

TEST(PlyAsciiReader, MalformedValuesFailNamingTheElement) {
  TempDir dir;
  const struct {
    std::string faces;
    StatusCode code;
    const char* says;
  } cases[] = {
      {"4 0 1 2 9\n", StatusCode::index_out_of_range, "face #0: corner 9 names no vertex"},
      // Refused by the PLY check before the reader, in the same words' spirit.
      {"4 0 1 2 x\n", StatusCode::unreadable_file, "face #0"},
  };
  for (const auto& c : cases) {
    const Result<ImportedMesh> read = import_mesh(dir.write("bad.ply", far_ply_square(c.faces)));
    ASSERT_FALSE(read.ok()) << c.faces;
    EXPECT_EQ(read.status().code(), c.code) << read.status().message();
    EXPECT_NE(read.status().message().find(c.says), std::string::npos) << read.status().message();
  }
  std::string nan_vertex = far_ply_square();
  nan_vertex.replace(nan_vertex.find("100001.12345678901 100001"), 18, "nan");
  const Result<ImportedMesh> read = import_mesh(dir.write("nan.ply", nan_vertex));
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.status().code(), StatusCode::non_finite_coordinate) << read.status().message();
  EXPECT_NE(read.status().message().find("vertex #2"), std::string::npos) << read.status().message();
}

// The format lets the face element come first; corners are judged once
// every vertex is read, and a strip's triangles turn their winding each
// step (-1 starts a new strip).
TEST(PlyAsciiReader, FacesBeforeVerticesAndTriangleStripsRead) {
  TempDir dir;
  const std::string text =
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element tristrips 1\nproperty list int int vertex_indices\nelement vertex 5\nproperty double x\n"
      "property double y\nproperty double z\nend_header\n3 0 1 2\n7 0 1 2 3 -1 1 4\n"
      "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 0 0\n";
  const Result<ImportedMesh> read = import_mesh(dir.write("order.ply", text));
  ASSERT_TRUE(read.ok()) << read.status().message();
  const Mesh& mesh = read.value().mesh;
  ASSERT_EQ(mesh.triangles.size(), 3u); // the face, then the strip's two (the restart leaves "1 4" short)
  EXPECT_EQ(mesh.triangles[1], Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(mesh.triangles[2], Eigen::Vector3i(2, 1, 3)); // the second of a strip turns back
}

TEST(PlyAsciiReader, NegativeCornersAndVerticesWithoutCoordinatesAreRefused) {
  TempDir dir;
  const Result<ImportedMesh> negative = import_mesh(dir.write("negative.ply", far_ply_square("4 0 1 2 -3\n")));
  ASSERT_FALSE(negative.ok());
  EXPECT_EQ(negative.status().code(), StatusCode::index_out_of_range) << negative.status().message();
  std::string no_z = far_ply_square();
  no_z.replace(no_z.find("property float z\n"), 17, "property float w\n");
  const Result<ImportedMesh> flat = import_mesh(dir.write("no_z.ply", no_z));
  ASSERT_FALSE(flat.ok());
  EXPECT_NE(flat.status().message().find("no x, y and z"), std::string::npos) << flat.status().message();
}

// A unit square 1e5 out as two triangles, its coordinates binary doubles, a
// signed 16-bit `confidence` read past, corner lists of uchar length and
// uint corners, and a last element the reader reads past.
std::string binary_far_square(bool big_endian) {
  std::string ply = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
                    "property short confidence\nelement face 2\nproperty list uchar uint vertex_indices\n"
                    "element camera 1\nproperty float view_px\nend_header\n";
  const double corners[4][3] = {{100000.12345678901, 100000, -100000},
                                {100001.12345678901, 100000, -100000},
                                {100001.12345678901, 100001, -100000},
                                {100000.12345678901, 100001, -100000}};
  for (const auto& corner : corners) {
    for (double c : corner) ply += test::ply_value_bytes(c, big_endian);
    ply += test::ply_value_bytes(std::int16_t{-2}, big_endian);
  }
  for (const auto& face : {std::array<std::uint32_t, 3>{0, 1, 2}, {0, 2, 3}}) {
    ply += test::ply_value_bytes(std::uint8_t{3}, big_endian);
    for (std::uint32_t corner : face) ply += test::ply_value_bytes(corner, big_endian);
  }
  return ply + test::ply_value_bytes(0.5f, big_endian);
}

TEST(PlyBinaryReader, DoublesKeepTheirDigitsInEitherByteOrder) {
  TempDir dir;
  for (bool big_endian : {false, true}) {
    SCOPED_TRACE(big_endian ? "big-endian" : "little-endian");
    const Result<ImportedMesh> read = import_mesh(dir.write("square.ply", binary_far_square(big_endian)));
    ASSERT_TRUE(read.ok()) << read.status().message();
    const Mesh& mesh = read.value().mesh;
    ASSERT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.positions[1], Eigen::Vector3d(100001.12345678901, 100000, -100000)); // float32: 100001.125
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[1], Eigen::Vector3i(0, 2, 3));
    EXPECT_LT(mesh.coordinate_error, 1e-10);
  }
}

TEST(PlyBinaryReader, DamagedBodiesAreRefusedNamingTheElement) {
  TempDir dir;
  std::string cut = binary_far_square(false);
  cut.resize(cut.size() - 4 - 3); // inside face #1's corners
  const Result<ImportedMesh> short_body = import_mesh(dir.write("cut.ply", cut));
  ASSERT_FALSE(short_body.ok());
  EXPECT_EQ(short_body.status().code(), StatusCode::unreadable_file);
  EXPECT_NE(short_body.status().message().find("face #1"), std::string::npos) << short_body.status().message();

  std::string far_corner = binary_far_square(true);
  const std::size_t last_corner = far_corner.size() - 4 - 4;
  far_corner.replace(last_corner, 4, test::ply_value_bytes(std::uint32_t{7}, true));
  const Result<ImportedMesh> out_of_range = import_mesh(dir.write("corner.ply", far_corner));
  ASSERT_FALSE(out_of_range.ok());
  EXPECT_EQ(out_of_range.status().code(), StatusCode::index_out_of_range) << out_of_range.status().message();
  EXPECT_NE(out_of_range.status().message().find("face #1: corner 7 names no vertex"), std::string::npos)
      << out_of_range.status().message();

  std::string infinite = binary_far_square(false);
  const std::size_t second_y = infinite.find("end_header\n") + 11 + 26 + 8;
  infinite.replace(second_y, 8, test::ply_value_bytes(std::numeric_limits<double>::infinity(), false));
  const Result<ImportedMesh> not_finite = import_mesh(dir.write("inf.ply", infinite));
  ASSERT_FALSE(not_finite.ok());
  EXPECT_EQ(not_finite.status().code(), StatusCode::non_finite_coordinate) << not_finite.status().message();
  EXPECT_NE(not_finite.status().message().find("vertex #1"), std::string::npos) << not_finite.status().message();
}

// The reader's own checks, asked directly: the pre-check import_mesh runs
// first refuses these files already.
Result<Mesh> read_body_of(const std::string& path, std::uint64_t triangle_limit, int& skipped) {
  std::ifstream in(path, std::ios::binary);
  const std::uint64_t bytes = static_cast<std::uint64_t>(std::filesystem::file_size(path));
  detail::PlyHeader header;
  if (Status read = detail::read_ply_header(in, bytes, header); !read.ok()) return read;
  return detail::read_ply_body(in, header, bytes, triangle_limit, skipped);
}

TEST(PlyBinaryReader, ItsOwnCheckRefusesABodyEndingInsideAList) {
  TempDir dir;
  int skipped = 0;
  std::string cut = binary_far_square(false);
  cut.resize(cut.size() - 4 - 3); // inside face #1's corners
  const Result<Mesh> short_body = read_body_of(dir.write("cut.ply", cut), 100, skipped);
  ASSERT_FALSE(short_body.ok());
  EXPECT_EQ(short_body.status().code(), StatusCode::unreadable_file);
  EXPECT_NE(short_body.status().message().find("face #1: the data ends inside a list"), std::string::npos)
      << short_body.status().message();
}

TEST(PlyAsciiReader, FacesTooShortForATriangleAreCountedNotKept) {
  TempDir dir;
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1003\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n";
  for (int i = 0; i < 1000; ++i) text += i % 2 ? "2 0 1\n" : "0\n";
  text += "3 0 1 2\n1 2\n3 2 1 0\n";
  int skipped = 0;
  const Result<Mesh> read = read_body_of(dir.write("short_faces.ply", text), 2, skipped);
  ASSERT_TRUE(read.ok()) << read.status().message(); // two triangles, within a limit of 2
  EXPECT_EQ(read.value().triangles.size(), 2u);
  EXPECT_EQ(skipped, 1001);
  // One triangle allowed: the last face, the second triangle, is refused.
  const Result<Mesh> limited = read_body_of(dir.write("short_faces.ply", text), 1, skipped);
  ASSERT_FALSE(limited.ok());
  EXPECT_EQ(limited.status().code(), StatusCode::limit_exceeded);
  EXPECT_NE(limited.status().message().find("face #1002: more than 1 triangles"), std::string::npos)
      << limited.status().message();
}

} // namespace
} // namespace hullcover

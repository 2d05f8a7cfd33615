// The project's OBJ reader (lib/mesh/src/obj_reader.h), through import_mesh
// as every command reaches it: coordinates in double, polygons cut into
// triangles that cover exactly the polygon, materials, and a clear failure
// for every malformed statement.

#include "hullcover/mesh/mesh_import.h"

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace hullcover {
namespace {

using test::TempDir;

Result<ImportedMesh> read(const TempDir& dir, const std::string& text) {
  return import_mesh(dir.write("scene.obj", text));
}

// Twice the area of triangle t of `m`, as a vector.
Eigen::Vector3d area_vector(const Mesh& m, int t) {
  const Eigen::Vector3i& f = m.triangles[t];
  return (m.positions[f[1]] - m.positions[f[0]]).cross(m.positions[f[2]] - m.positions[f[0]]);
}

TEST(ObjReader, KeepsEverySeventeenDigitCoordinateFarFromTheOrigin) {
  TempDir dir;
  const char* coordinates[] = {"100000.12345678901", "-99999.987654321012", "1000000.0000000001",
                               "123456.78901234567", "0.10000000000000001", "-1234567.8901234567"};
  const std::string text = std::string("v ") + coordinates[0] + " " + coordinates[1] + " " + coordinates[2] + "\nv " +
                           coordinates[3] + " " + coordinates[4] + " " + coordinates[5] + "\nv 1 2 3\nf 1 2 3\n";
  const Result<ImportedMesh> r = read(dir, text);
  ASSERT_TRUE(r.ok()) << r.status().message();
  const Mesh& m = r.value().mesh;
  ASSERT_EQ(m.positions.size(), 3u);
  // Each coordinate is the double nearest its text, as strtod gives it.
  for (int i = 0; i < 6; ++i) EXPECT_EQ(m.positions[i / 3][i % 3], std::strtod(coordinates[i], nullptr)) << i;
  // A float32 reader moves 100000.12345678901 by about 0.0016; a double one
  // carries only the decimal's rounding to double.
  EXPECT_LT(m.coordinate_error, 1e-9);
  EXPECT_GT(m.coordinate_error, 0.0);
}

TEST(ObjReader, ReadsCornerFormsAndCountsBackFromNegativeIndices) {
  TempDir dir;
  const Result<ImportedMesh> r = read(dir,
                                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                                      "f 1/1 2/1/1 3//1\nf -4 -2 -1\n");
  ASSERT_TRUE(r.ok()) << r.status().message();
  const Mesh& m = r.value().mesh;
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[0], Eigen::Vector3i(0, 1, 2));
  EXPECT_EQ(m.triangles[1], Eigen::Vector3i(0, 2, 3));
}

TEST(ObjReader, CutsAConcavePolygonIntoTrianglesThatCoverItExactly) {
  TempDir dir;
  // An L-shaped hexagon, counter-clockwise seen from +z, concave at (1, 1):
  // a fan from its first corner would cover the notch.
  const Result<ImportedMesh> r = read(dir, "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 1 2 3 4 5 6\n");
  ASSERT_TRUE(r.ok()) << r.status().message();
  const Mesh& m = r.value().mesh;
  ASSERT_EQ(m.triangles.size(), 4u);
  double area = 0.0;
  for (int t = 0; t < 4; ++t) {
    const Eigen::Vector3d a = area_vector(m, t);
    EXPECT_GT(a.z(), 0.0) << "triangle " << t << " keeps the polygon's winding";
    area += 0.5 * a.z();
    const Eigen::Vector3d centre =
        (m.positions[m.triangles[t][0]] + m.positions[m.triangles[t][1]] + m.positions[m.triangles[t][2]]) / 3.0;
    EXPECT_FALSE(centre.x() > 1.0 && centre.y() > 1.0) << "triangle " << t << " lies in the notch";
  }
  EXPECT_DOUBLE_EQ(area, 3.0); // the L's area, nothing more
}

TEST(ObjReader, CutsAPentagramIntoTrianglesInsideItsOutline) {
  TempDir dir;
  // A pentagram (corners of a pentagon taken every other one) turns one
  // way at every corner but goes round twice: not convex, so no fan,
  // which would cover the pentagon's whole inside between the points.
  std::string text;
  for (int i = 0; i < 5; ++i)
    text += "v " + std::to_string(std::cos(2.0 * M_PI * i / 5.0)) + " " +
            std::to_string(std::sin(2.0 * M_PI * i / 5.0)) + " 0\n";
  const Result<ImportedMesh> r = read(dir, text + "f 1 3 5 2 4\n");
  ASSERT_TRUE(r.ok()) << r.status().message();
  const Mesh& m = r.value().mesh;
  ASSERT_EQ(m.triangles.size(), 3u);
  // A fan from corner 1 would hold the triangle 1, 3, 5 whole; clipping
  // takes ears at the points instead.
  EXPECT_NE(m.triangles[0], Eigen::Vector3i(0, 2, 4));
}

TEST(ObjReader, TakesAStraightPolygonWrittenWithFewDigitsAsConvex) {
  TempDir dir;
  // 300 corners round a turned square, its sides stitched with points
  // written with 6 decimals: their turns are rounding, either sign; the
  // polygon is convex, whatever its corner count.
  std::string text;
  const double turn = 0.3;
  const auto corner = [&](double x, double y) {
    char line[96];
    std::snprintf(line, sizeof line, "v %.6f %.6f 0\n", std::cos(turn) * x - std::sin(turn) * y,
                  std::sin(turn) * x + std::cos(turn) * y);
    text += line;
  };
  for (int i = 0; i < 75; ++i) corner(i / 75.0, 0.0);
  for (int i = 0; i < 75; ++i) corner(1.0, i / 75.0);
  for (int i = 0; i < 75; ++i) corner(1.0 - i / 75.0, 1.0);
  for (int i = 0; i < 75; ++i) corner(0.0, 1.0 - i / 75.0);
  text += "f";
  for (int i = 1; i <= 300; ++i) text += " " + std::to_string(i);
  const Result<ImportedMesh> r = read(dir, text + "\n");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r.value().mesh.triangles.size(), 298u);
}

TEST(ObjReader, ReadsACoordinateBelowDoublesRangeAsZero) {
  TempDir dir;
  const Result<ImportedMesh> r = read(dir, "v 1e-400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r.value().mesh.positions[0].x(), 0.0);
}

TEST(ObjReader, NumbersMaterialsInOrderOfFirstUse) {
  TempDir dir;
  const std::string corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const Result<ImportedMesh> named = read(
      dir, "mtllib missing.mtl\n" + corners + "usemtl stone\nf 1 2 3\nusemtl wood\nf 1 2 3\nusemtl stone\nf 1 2 3\n");
  ASSERT_TRUE(named.ok()) << named.status().message(); // the library is never opened
  EXPECT_EQ(named.value().mesh.material_names, (std::vector<std::string>{"stone", "wood"}));
  EXPECT_EQ(named.value().mesh.material_ids, (std::vector<int>{0, 1, 0}));
  const Result<ImportedMesh> mixed = read(dir, corners + "f 1 2 3\nusemtl wood\nf 1 2 3\n");
  ASSERT_TRUE(mixed.ok());
  EXPECT_EQ(mixed.value().mesh.material_names, (std::vector<std::string>{"default", "wood"}));
  EXPECT_EQ(mixed.value().mesh.material_ids, (std::vector<int>{0, 1}));
  // A material named "default" is the one faces before any usemtl have.
  const Result<ImportedMesh> named_default = read(dir, corners + "f 1 2 3\nusemtl default\nf 1 2 3\n");
  ASSERT_TRUE(named_default.ok());
  EXPECT_EQ(named_default.value().mesh.material_names, (std::vector<std::string>{"default"}));
  EXPECT_EQ(named_default.value().mesh.material_ids, (std::vector<int>{0, 0}));
}

TEST(ObjReader, SkipsLinesAndPointsAndCountsThem) {
  TempDir dir;
  const Result<ImportedMesh> r = read(dir, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\np 3\nf 1 2\nf 1 2 3\n");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r.value().mesh.triangles.size(), 1u);
  EXPECT_EQ(r.value().report.skipped_non_triangle_primitives, 3);
}

TEST(ObjReader, RefusesEveryMalformedStatementNamingItsLine) {
  TempDir dir;
  const std::string corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  struct Case {
    std::string text;
    StatusCode code;
    std::string says;
  };
  const Case cases[] = {
      {"v nan 0 0\n" + corners + "f 2 3 4\n", StatusCode::non_finite_coordinate, "line 1: coordinate 'nan'"},
      {"v 1e999 0 0\n" + corners + "f 2 3 4\n", StatusCode::non_finite_coordinate, "line 1: coordinate '1e999'"},
      {"v 0 zero 0\n", StatusCode::unreadable_file, "line 1: 'zero' is not a number"},
      {"v 0 0\n", StatusCode::unreadable_file, "line 1: a position needs three coordinates"},
      {corners + "f 1 2 4\n", StatusCode::index_out_of_range, "line 4: face corner '4' names no position"},
      {corners + "f 0 1 2\n", StatusCode::index_out_of_range, "line 4: face corner '0'"},
      {corners + "f -4 1 2\n", StatusCode::index_out_of_range, "line 4: face corner '-4'"},
      {corners + "f 1 2 x\n", StatusCode::unreadable_file, "line 4: face corner 'x'"},
      {corners + "f 99999999999999999999 1 2\n", StatusCode::index_out_of_range, "line 4: face corner"},
      {corners, StatusCode::empty_scene, "no triangles"},
  };
  for (const Case& c : cases) {
    const Result<ImportedMesh> r = read(dir, c.text);
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.status().code(), c.code) << c.text << " -> " << r.status().message();
    EXPECT_NE(r.status().message().find(c.says), std::string::npos) << r.status().message();
  }
}

TEST(ObjReader, BoundsTheWorkOfOnePolygonAndOfTheFile) {
  TempDir dir;
  // A comb: a concave polygon of 300 corners, beyond what the ear clipping takes.
  std::string comb;
  for (int i = 0; i < 150; ++i) comb += "v " + std::to_string(i) + " 0 0\n";
  for (int i = 149; i >= 0; --i) comb += "v " + std::to_string(i) + " " + (i % 2 ? "1" : "3") + " 0\n";
  comb += "f";
  for (int i = 1; i <= 300; ++i) comb += " " + std::to_string(i);
  const Result<ImportedMesh> r = read(dir, comb + "\n");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::limit_exceeded);
  EXPECT_NE(r.status().message().find("a concave polygon of 300 corners"), std::string::npos) << r.status().message();
  // The triangle limit holds before the triangles are stored.
  ImportLimits limits;
  limits.max_triangles = 2;
  const Result<ImportedMesh> many =
      import_mesh(dir.write("many.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\nf 1 2 3\n"), limits);
  ASSERT_FALSE(many.ok());
  EXPECT_EQ(many.status().code(), StatusCode::limit_exceeded);
  EXPECT_NE(many.status().message().find("line 6"), std::string::npos) << many.status().message();
}

} // namespace
} // namespace hullcover

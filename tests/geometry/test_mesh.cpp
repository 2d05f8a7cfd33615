#include "hullcover/geometry/mesh.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <limits>

namespace hullcover {
namespace {

Mesh one_triangle() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  m.material_ids = {0};
  return m;
}

TEST(ValidateMesh, AcceptsAWellFormedTriangle) { EXPECT_TRUE(validate_mesh(one_triangle()).ok()); }

TEST(ValidateMesh, RejectsAnEmptyMesh) { EXPECT_EQ(validate_mesh(Mesh{}).code(), StatusCode::empty_scene); }

TEST(ValidateMesh, RejectsIndicesOutOfRangeNamingTheTriangle) {
  Mesh m = one_triangle();
  m.triangles[0][2] = 3;
  const Status s = validate_mesh(m);
  EXPECT_EQ(s.code(), StatusCode::index_out_of_range);
  EXPECT_NE(s.message().find("triangle 0"), std::string::npos) << s.message();
  m.triangles[0][2] = -1;
  EXPECT_EQ(validate_mesh(m).code(), StatusCode::index_out_of_range);
}

TEST(ValidateMesh, RejectsNanAndInfinityInReferencedVertices) {
  Mesh m = one_triangle();
  m.positions[1].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validate_mesh(m).code(), StatusCode::non_finite_coordinate);
  m.positions[1].y() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validate_mesh(m).code(), StatusCode::non_finite_coordinate);
}

TEST(ValidateMesh, IgnoresNonFiniteUnreferencedVertices) {
  Mesh m = one_triangle();
  m.positions.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_TRUE(validate_mesh(m).ok());
  const Aabb box = referenced_bounding_box(m);
  EXPECT_TRUE(box.min.allFinite() && box.max.allFinite());
  EXPECT_DOUBLE_EQ(box.diagonal(), std::sqrt(2.0));
}

TEST(ValidateMesh, RejectsMaterialIdsOfTheWrongLength) {
  Mesh m = one_triangle();
  m.material_ids.clear();
  EXPECT_EQ(validate_mesh(m).code(), StatusCode::invalid_argument);
}

TEST(TriangleAreaVector, PointsToTheCounterClockwiseFront) {
  const Mesh m = one_triangle();
  const Eigen::Vector3d n = triangle_area_vector(m, 0);
  EXPECT_DOUBLE_EQ(n.z(), 1.0); // twice the area 0.5, towards +z
  EXPECT_FALSE(triangle_has_repeated_vertex(m, 0));
}

} // namespace
} // namespace hullcover

#include "hullcover/mesh/scene_builder.h"
#include "hullcover/mesh/mesh_connectivity.h"
#include "hullcover/mesh/vertex_welding.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace hullcover {
namespace {

// Signed volume enclosed by a closed mesh (positive when normals point out).
double signed_volume(const Mesh& m) {
  double six_v = 0;
  for (const Eigen::Vector3i& t : m.triangles)
    six_v += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]]));
  return six_v / 6.0;
}

// Does the segment p-q cross any triangle's interior? (Moller-Trumbore.)
bool segment_hits_mesh(const Mesh& m, const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  const Eigen::Vector3d d = q - p;
  for (const Eigen::Vector3i& t : m.triangles) {
    const Eigen::Vector3d a = m.positions[t[0]], e1 = m.positions[t[1]] - a, e2 = m.positions[t[2]] - a;
    const Eigen::Vector3d h = d.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-14) continue;
    const Eigen::Vector3d s = p - a;
    const double u = s.dot(h) / det;
    const Eigen::Vector3d qv = s.cross(e1);
    const double v = d.dot(qv) / det;
    const double s_param = e2.dot(qv) / det;
    if (u >= 0 && v >= 0 && u + v <= 1 && s_param >= 0 && s_param <= 1) return true;
  }
  return false;
}

TEST(AddBox, OutwardAndInwardBoxesEncloseTheirVolumeWithTheRightSign) {
  Mesh out, in;
  add_box(out, {0, 0, 0}, {1, 2, 3}, true);
  add_box(in, {0, 0, 0}, {1, 2, 3}, false);
  EXPECT_NEAR(signed_volume(out), 6.0, 1e-12);
  EXPECT_NEAR(signed_volume(in), -6.0, 1e-12);
}

TEST(AddHeightField, IsOneOpenUpwardSheetWithOneBoundaryLoop) {
  Mesh m;
  const std::vector<double> xs = {0, 0.1, 0.5, 2}, zs = {0, 1, 1.2};
  add_height_field(m, xs, zs, [](double x, double z) { return 0.1 * x * z; });
  const MeshConnectivity c = build_connectivity(m, 1e-9);
  EXPECT_EQ(m.triangles.size(), 2u * 3u * 2u);
  EXPECT_EQ(count_edges(c, EdgeKind::boundary), 2 * (3 + 2));
  EXPECT_EQ(count_edges(c, EdgeKind::boundary) + count_edges(c, EdgeKind::manifold), static_cast<int>(c.edges.size()));
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) EXPECT_GT(triangle_area_vector(m, t).y(), 0.0);
}

TEST(DemoBuilding, HasADoorwayAnInteriorWallStairsAndTerrain) {
  const Mesh m = demo_building();
  ASSERT_TRUE(validate_mesh(m).ok());
  // Through the doorway at chest height: nothing. Through the wall beside it: the wall.
  EXPECT_FALSE(segment_hits_mesh(m, {0, 1, 3}, {0, 1, 5}));
  EXPECT_TRUE(segment_hits_mesh(m, {-2, 1, 3}, {-2, 1, 5}));
  // The interior wall splits the back of the room but leaves a passage at the front.
  EXPECT_TRUE(segment_hits_mesh(m, {-2, 1, 0}, {2, 1, 0}));
  EXPECT_FALSE(segment_hits_mesh(m, {-2, 1, 2.5}, {2, 1, 2.5}));
  // Climbing the stairs: the top step is 1.5 m up.
  EXPECT_TRUE(segment_hits_mesh(m, {3.75, 2, -3.3}, {3.75, 1.4, -3.3}));
  // Terrain beside the building.
  EXPECT_TRUE(segment_hits_mesh(m, {-10, 5, 0}, {-10, -5, 0}));
  int terrain = 0;
  for (int id : m.material_ids) terrain += id == demo_terrain;
  EXPECT_GT(terrain, 100);
}

} // namespace
} // namespace hullcover

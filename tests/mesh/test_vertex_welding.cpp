#include "hullcover/mesh/vertex_welding.h"

#include <gtest/gtest.h>

#include <random>

namespace hullcover {
namespace {

Mesh soup(const std::vector<Eigen::Vector3d>& corners) {
  Mesh m;
  m.positions = corners;
  for (int t = 0; t + 2 < static_cast<int>(corners.size()); t += 3) {
    m.triangles.emplace_back(t, t + 1, t + 2);
    m.material_ids.push_back(0);
  }
  return m;
}

TEST(WeldVertices, JoinsCornersStoredPerFace) {
  // Two triangles of a unit square, glTF style: six corner records.
  const Mesh m = soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const WeldResult w = weld_vertices(m, 1e-6);
  EXPECT_EQ(w.mesh.positions.size(), 4u);
  ASSERT_EQ(w.mesh.triangles.size(), 2u);
  EXPECT_EQ(w.mesh.triangles[0][0], w.mesh.triangles[1][0]);
  EXPECT_EQ(w.mesh.triangles[0][2], w.mesh.triangles[1][1]);
}

TEST(WeldVertices, MergesWithinTheRadiusOnlyAcrossCellBorders) {
  const double r = 1e-3;
  // Pairs straddling a hash-cell border (0) at 0.9 r, and one pair at 1.1 r.
  const Mesh m =
      soup({{-0.45 * r, 0, 0}, {0.45 * r, 0, 0}, {5, 0, 0}, {10, -0.55 * r, 0}, {10, 0.55 * r, 0}, {5, 5, 0}});
  const WeldResult w = weld_vertices(m, r);
  EXPECT_EQ(w.new_index_of_input_vertex[0], w.new_index_of_input_vertex[1]);
  EXPECT_NE(w.new_index_of_input_vertex[3], w.new_index_of_input_vertex[4]);
  EXPECT_EQ(w.mesh.positions.size(), 5u);
}

TEST(WeldVertices, KeepsCollapsedTrianglesAndFaceOrder) {
  const Mesh m = soup({{0, 0, 0}, {1e-9, 0, 0}, {0, 1, 0}, {3, 0, 0}, {4, 0, 0}, {3, 1, 0}});
  const WeldResult w = weld_vertices(m, 1e-6);
  ASSERT_EQ(w.mesh.triangles.size(), 2u);
  EXPECT_EQ(w.mesh.triangles[0][0], w.mesh.triangles[0][1]);
  EXPECT_EQ(w.mesh.material_ids, m.material_ids);
}

TEST(WeldVertices, DropsUnreferencedVerticesEvenWhenNotFinite) {
  Mesh m = soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  m.positions.emplace_back(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  const WeldResult w = weld_vertices(m, 1e-6);
  EXPECT_EQ(w.unreferenced_dropped, 1);
  EXPECT_EQ(w.new_index_of_input_vertex[3], -1);
  EXPECT_EQ(w.mesh.positions.size(), 3u);
}

TEST(WeldVertices, IsNotTransitiveSoNoVertexMovesFartherThanTheRadius) {
  const double r = 1.0;
  const Mesh m = soup({{0, 0, 0}, {0.6, 0, 0}, {1.2, 0, 0}});
  const WeldResult w = weld_vertices(m, r);
  EXPECT_EQ(w.new_index_of_input_vertex[0], w.new_index_of_input_vertex[1]);
  EXPECT_NE(w.new_index_of_input_vertex[0], w.new_index_of_input_vertex[2]);
}

// Property test against brute force on clustered random points far from the
// origin: every vertex stays within the radius of where it was, and no two
// kept vertices are within the radius of each other.
TEST(WeldVertices, RandomClustersMatchBruteForceGuarantees) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> centre(-5.0, 5.0);
  std::normal_distribution<double> jitter(0.0, 4e-4);
  const double r = 1e-3;
  const Eigen::Vector3d offset(1e5, -2e4, 3e3);
  std::vector<Eigen::Vector3d> points;
  for (int cluster = 0; cluster < 300; ++cluster) {
    const Eigen::Vector3d c = offset + Eigen::Vector3d(centre(rng), centre(rng), centre(rng));
    for (int k = 0; k < 6; ++k) points.push_back(c + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)));
  }
  const Mesh m = soup(points);
  const WeldResult w = weld_vertices(m, r);

  for (size_t v = 0; v < points.size(); ++v)
    EXPECT_LE((w.mesh.positions[w.new_index_of_input_vertex[v]] - points[v]).norm(), r) << v;
  for (size_t a = 0; a < w.mesh.positions.size(); ++a)
    for (size_t b = a + 1; b < w.mesh.positions.size(); ++b)
      ASSERT_GT((w.mesh.positions[a] - w.mesh.positions[b]).squaredNorm(), r * r) << a << " " << b;
  EXPECT_LT(w.mesh.positions.size(), points.size()); // the clusters did weld

  const WeldResult again = weld_vertices(m, r); // deterministic
  EXPECT_EQ(again.new_index_of_input_vertex, w.new_index_of_input_vertex);
}

} // namespace
} // namespace hullcover

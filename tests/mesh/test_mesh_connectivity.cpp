#include "hullcover/mesh/mesh_connectivity.h"
#include "hullcover/mesh/scene_builder.h"
#include "hullcover/mesh/vertex_welding.h"

#include <gtest/gtest.h>

namespace hullcover {
namespace {

constexpr double kTol = 1e-6;

Mesh quad() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.material_ids = {0, 0};
  return m;
}

TEST(Connectivity, ClosedBoxIsAManifoldOfGenusZero) {
  Mesh m;
  add_box(m, {0, 0, 0}, {1, 2, 3});
  const MeshConnectivity c = build_connectivity(m, kTol);
  EXPECT_EQ(c.edges.size(), 18u);
  EXPECT_EQ(count_edges(c, EdgeKind::manifold), 18);
  EXPECT_EQ(
      static_cast<int>(m.positions.size()) - static_cast<int>(c.edges.size()) + static_cast<int>(m.triangles.size()),
      2); // Euler characteristic of a sphere
  EXPECT_EQ(c.component_count, 1);
  for (const Eigen::Vector3i& n : c.face_neighbours) EXPECT_TRUE((n.array() >= 0).all());
}

TEST(Connectivity, OpenQuadHasFourBoundaryEdges) {
  const MeshConnectivity c = build_connectivity(quad(), kTol);
  EXPECT_EQ(count_edges(c, EdgeKind::boundary), 4);
  EXPECT_EQ(count_edges(c, EdgeKind::manifold), 1);
  EXPECT_EQ(c.face_neighbours[0][2], 1); // corner 2 of face 0 runs 2 -> 0
  EXPECT_EQ(c.face_neighbours[1][0], 0); // corner 0 of face 1 runs 0 -> 2
}

TEST(Connectivity, FlippedFaceIsAnOrientationConflictAndNoNeighbour) {
  Mesh m = quad();
  m.triangles[1] = {2, 0, 3}; // uses 2 -> 0, the same direction as face 0 does
  const MeshConnectivity c = build_connectivity(m, kTol);
  EXPECT_EQ(count_edges(c, EdgeKind::orientation_conflict), 1);
  EXPECT_EQ(count_edges(c, EdgeKind::manifold), 0);
  for (const Eigen::Vector3i& n : c.face_neighbours) EXPECT_TRUE((n.array() < 0).all());
}

TEST(Connectivity, ThreeFacesOnOneEdgeAreNonManifold) {
  Mesh m = quad();
  m.positions.emplace_back(0.5, 0.5, 1.0);
  m.triangles.emplace_back(0, 4, 2); // a fin standing on the diagonal
  m.material_ids.push_back(0);
  const MeshConnectivity c = build_connectivity(m, kTol);
  EXPECT_EQ(count_edges(c, EdgeKind::non_manifold), 1);
  EXPECT_EQ(c.face_neighbours[0][2], -1);
}

TEST(Connectivity, ComponentsJoinFacesThatShareOnlyAVertex) {
  Mesh m;
  add_box(m, {0, 0, 0}, {1, 1, 1});
  add_box(m, {5, 0, 0}, {6, 1, 1});
  add_box(m, {1, 1, 1}, {2, 2, 2}); // touches the first box at one corner
  const WeldResult w = weld_vertices(m, kTol);
  const MeshConnectivity c = build_connectivity(w.mesh, kTol);
  EXPECT_EQ(c.component_count, 2);
  EXPECT_EQ(c.face_component.front(), c.face_component.back());
  EXPECT_NE(c.face_component[0], c.face_component[12]);
}

TEST(Connectivity, ZeroAreaUsesTheSmallestAltitudeAgainstTheTolerance) {
  Mesh m;
  m.positions = {{0, 0, 0}, {10, 0, 0}, {5, 0.5e-6, 0}, {0, 0, 1}, {10, 0, 1}, {5, 2e-6, 1}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {0, 0, 1}};
  m.material_ids = {0, 0, 0};
  const MeshConnectivity c = build_connectivity(m, kTol);
  EXPECT_EQ(c.zero_area[0], 1); // altitude 0.5e-6 < tol
  EXPECT_EQ(c.zero_area[1], 0); // altitude 2e-6 > tol
  EXPECT_EQ(c.zero_area[2], 1); // collapsed
  EXPECT_TRUE((c.face_edges[2].array() < 0).all());
  EXPECT_EQ(count_zero_area_faces(c), 2);
}

// On a real, messy mesh: adjacency is symmetric and every neighbour pair
// really shares the edge in opposite directions.
TEST(Connectivity, NeighboursAreSymmetricOnTheDemoBuilding) {
  const WeldResult w = weld_vertices(demo_building(), 1e-6);
  const Mesh& m = w.mesh;
  const MeshConnectivity c = build_connectivity(m, kTol);
  int pairs = 0;
  for (int f = 0; f < static_cast<int>(m.triangles.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = c.face_neighbours[f][k];
      if (g < 0) continue;
      ++pairs;
      const int a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
      bool found = false;
      for (int j = 0; j < 3; ++j)
        found |= m.triangles[g][j] == b && m.triangles[g][(j + 1) % 3] == a && c.face_neighbours[g][j] == f;
      EXPECT_TRUE(found) << "face " << f << " corner " << k;
    }
  EXPECT_EQ(pairs, 2 * count_edges(c, EdgeKind::manifold));
}

} // namespace
} // namespace hullcover

// A world of real maps laid close together, as a studio lays its levels side
// by side: four shared scenes in a row, each 0.5% of the largest one's
// diagonal from the next (a world of 7,000-unit maps 35 units apart), closer
// than their 1% reaches added up. (recast-undulating, 5,000 units from its
// origin, is left out: its float32 import's rounding, bounded at its own
// magnitude, would have to be bounded for the whole world.) The world's covering audits clean, and
// each map's hulls from the world, moved back, audit clean against the map
// alone: a map keeps its tolerance, its prisms stay short of its
// neighbours, and no other map's back encloses its rays
// (docs/definitions-and-proofs.md, "The tolerance").

#include "covering_fixture.h"
#include "shared_data.h"

#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/mesh/mesh_import.h"
#include "hullcover/mesh/prepared_mesh.h"
#include "hullcover/validate/audit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace hullcover::validate {
namespace {

// A map of the world: where its faces are and how far it was moved.
struct PlacedMap {
  std::string file;
  Mesh mesh;
  int first_face = 0;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

// `hull` moved by `by`.
bvh::RuntimeHull moved(bvh::RuntimeHull hull, const Eigen::Vector3d& by) {
  for (Eigen::Vector3d& v : hull.shape.vertices) v += by;
  for (Plane& p : hull.shape.planes) p.offset += p.normal.dot(by);
  hull.box.min += by;
  hull.box.max += by;
  return hull;
}

// Audits `hulls` against `mesh` at the defaults; records a failure naming
// `what` unless the audit is clean.
void expect_clean(const Mesh& mesh, std::vector<bvh::RuntimeHull> hulls, const std::string& what) {
  const Result<PreparedMesh> prepared = prepare_mesh(mesh, std::nullopt);
  ASSERT_TRUE(prepared.ok()) << what << ": " << prepared.status().message();
  HullSet set;
  set.hulls = std::move(hulls);
  const Result<AuditReport> audit = run_audit(prepared.value(), set, AuditOptions{});
  ASSERT_TRUE(audit.ok()) << what << ": " << audit.status().message();
  const AuditReport& a = audit.value();
  EXPECT_TRUE(a.clean()) << what << ": " << test::finding_names(a.findings) << "; lost front rays "
                         << a.probe.front.lost << ", lost opening rays " << a.probe.opening.lost;
  EXPECT_GT(a.probe.front.rays, 1000) << what;
}

TEST(WorldOfMaps, EachMapsWorldHullsAuditCleanAgainstTheMapAlone) {
  HULLCOVER_REQUIRE_SHARED_SCENES(dir);
  std::vector<PlacedMap> maps;
  for (const char* file :
       {"recast-nav_test.obj", "threejs-collision-world.glb", "recast-dungeon.obj", "sauerbraten-fdm6.obj"}) {
    const Result<ImportedMesh> imported = import_mesh(dir + "/" + file);
    ASSERT_TRUE(imported.ok()) << file << ": " << imported.status().message();
    maps.push_back({file, imported.value().mesh});
  }
  double largest = 0.0;
  for (const PlacedMap& m : maps) largest = std::max(largest, referenced_bounding_box(m.mesh).diagonal());
  const double gap = 0.005 * largest;
  // In a row along x, the lowest corners level, `gap` apart.
  Mesh world;
  double x = 0.0;
  for (PlacedMap& m : maps) {
    const Aabb box = referenced_bounding_box(m.mesh);
    m.offset = Eigen::Vector3d(x, 0.0, 0.0) - box.min;
    m.first_face = static_cast<int>(world.triangles.size());
    const int base = static_cast<int>(world.positions.size());
    for (const Eigen::Vector3d& p : m.mesh.positions) world.positions.push_back(p + m.offset);
    for (const Eigen::Vector3i& t : m.mesh.triangles) world.triangles.push_back(t + Eigen::Vector3i::Constant(base));
    world.material_ids.insert(world.material_ids.end(), m.mesh.triangles.size(), 0);
    // Moved in double, each vertex keeps its import's rounding: the
    // largest of the maps' bounds holds for every vertex.
    world.coordinate_error = std::max(world.coordinate_error, m.mesh.coordinate_error);
    x += box.max.x() - box.min.x() + gap;
  }
  const auto decomposed = test::decompose_and_check(world);
  ASSERT_TRUE(decomposed);
  // Each map alone keeps its tolerance in the world.
  for (const PlacedMap& m : maps)
    EXPECT_DOUBLE_EQ(decomposed->prepared.face_tolerance(m.first_face),
                     choose_tolerance(m.mesh, std::nullopt).value().length)
        << m.file;
  const std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(decomposed->covering);
  expect_clean(world, hulls, "the world");
  for (size_t i = 0; i < maps.size(); ++i) {
    const int end = i + 1 < maps.size() ? maps[i + 1].first_face : static_cast<int>(world.triangles.size());
    std::vector<bvh::RuntimeHull> own;
    for (size_t h = 0; h < hulls.size(); ++h) {
      const int face = decomposed->covering.hulls[h].faces.front();
      if (face >= maps[i].first_face && face < end) own.push_back(moved(hulls[h], -maps[i].offset));
    }
    ASSERT_FALSE(own.empty()) << maps[i].file;
    expect_clean(maps[i].mesh, std::move(own), maps[i].file + "'s world hulls, alone");
  }
}

} // namespace
} // namespace hullcover::validate

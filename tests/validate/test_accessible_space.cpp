// The accessible-space probe catches hulls that take free space, and passes
// the decomposer's hulls on scenes where the paper's conditions suffice.

#include "box_hulls.h"
#include "hullcover/bvh/covering_hulls.h"
#include "hullcover/validate/accessible_space.h"
#include "hullcover/validate/behaviour_equivalence.h"
#include "hullcover/validate/hull_set.h"
#include "hullcover/validate/validity_recheck.h"

#include "covering_fixture.h"
#include "temp_dir.h"

#include "hullcover/geometry/planar_hull.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

namespace hullcover::validate {
namespace {

using V = Eigen::Vector3d;

using test::box_hull;

ProbeReport probe(const test::Decomposed& d, std::vector<bvh::RuntimeHull> hulls, ProbeOptions options = {}) {
  const auto world = bvh::HullWorld::build(std::move(hulls)).value();
  const auto triangles = bvh::TriangleWorld::build(d.prepared.mesh, d.tol()).value();
  Result<ProbeReport> r = probe_accessible_space(d.prepared, *triangles, *world, options);
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.value();
}

TEST(AccessibleSpace, DecomposedBuildingIsCleanAndAClosedDoorwayIsCaught) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  const ProbeReport clean = probe(*d, bvh::runtime_hulls(d->covering));
  EXPECT_GT(clean.front.rays, 1000);
  EXPECT_GT(clean.opening.rays, 100);
  EXPECT_EQ(clean.front.lost, 0);
  EXPECT_EQ(clean.opening.lost, 0);
  EXPECT_EQ(clean.lost_cells, 0);
  EXPECT_GT(clean.front.enclosed, 0); // inside the wall boxes and stairs

  // The same hulls plus one that fills the doorway.
  std::vector<bvh::RuntimeHull> closed = bvh::runtime_hulls(d->covering);
  closed.push_back(box_hull(V(-0.6, 0.0, 3.8), V(0.6, 2.1, 4.0)));
  const ProbeReport caught = probe(*d, closed);
  EXPECT_GT(caught.lost_rays(), 0);
  EXPECT_GT(caught.lost_cells, 0);
  ASSERT_FALSE(caught.worst.empty());
  EXPECT_EQ(caught.worst[0].hull, static_cast<int>(closed.size()) - 1);
}

TEST(AccessibleSpace, AHullAboveTheTerrainIsCaught) {
  Mesh terrain;
  add_height_field(terrain, {0, 1, 2, 3, 4, 5, 6}, {0, 1, 2, 3, 4, 5, 6},
                   [](double x, double z) { return 0.2 * std::sin(x) * std::cos(z); });
  const auto d = test::decompose_and_check(terrain);
  ASSERT_TRUE(d);
  ProbeOptions metre; // capped at a metre: the cap an agent's reach would give
  metre.probe_distance = 1.0;
  metre.resolution = 0.1;
  EXPECT_EQ(probe(*d, bvh::runtime_hulls(d->covering), metre).front.lost, 0);
  std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(d->covering);
  hulls.push_back(box_hull(V(2, 0.25, 2), V(3, 0.6, 3))); // floating above the ground
  const ProbeReport r = probe(*d, hulls, metre);
  EXPECT_GT(r.front.lost, 0);
  EXPECT_EQ(r.front.deepest.hull, static_cast<int>(hulls.size()) - 1);
}

TEST(AccessibleSpace, AHullFillingARoomSeenFromInsideIsCaught) {
  Mesh room;
  add_box(room, V(0, 0, 0), V(4, 3, 5), false);
  const auto d = test::decompose_and_check(room);
  ASSERT_TRUE(d);
  EXPECT_EQ(probe(*d, bvh::runtime_hulls(d->covering)).front.lost, 0);
  // Every front ray crosses the room from wall to wall, inside the hull
  // but for tol at either end; no point is deeper than half the 3 m height.
  const ProbeReport filled = probe(*d, {box_hull(V(0, 0, 0), V(4, 3, 5))});
  EXPECT_EQ(filled.front.lost, filled.front.rays);
  EXPECT_NEAR(filled.front.deepest.depth, 1.5, 0.05);
  EXPECT_LE(filled.max_lost_depth, 1.5 + 1e-9);
}

// A map inside a world is audited as finely as alone: each island's rays
// are spaced by its own diagonal, not the world's.
TEST(AccessibleSpace, AMapInAWorldGetsTheRaysItGetsAlone) {
  const Mesh building = demo_building();
  Mesh terrain;
  add_height_field(terrain, {0, 50, 100, 150, 200}, {0, 50, 100, 150, 200},
                   [](double x, double z) { return 0.01 * (x + z); });
  for (V& p : terrain.positions) p += V(1000.0, 0.0, 0.0);
  Mesh world = building;
  const int base = static_cast<int>(world.positions.size());
  world.positions.insert(world.positions.end(), terrain.positions.begin(), terrain.positions.end());
  for (const Eigen::Vector3i& t : terrain.triangles) world.triangles.push_back(t + Eigen::Vector3i::Constant(base));
  world.material_ids.insert(world.material_ids.end(), terrain.material_ids.begin(), terrain.material_ids.end());
  const auto a = test::decompose_and_check(building);
  const auto b = test::decompose_and_check(terrain);
  const auto w = test::decompose_and_check(world);
  ASSERT_TRUE(a && b && w);
  const ProbeReport alone = probe(*a, bvh::runtime_hulls(a->covering));
  const ProbeReport terrain_alone = probe(*b, bvh::runtime_hulls(b->covering));
  const ProbeReport in_world = probe(*w, bvh::runtime_hulls(w->covering));
  EXPECT_EQ(in_world.front.rays, alone.front.rays + terrain_alone.front.rays);
  EXPECT_EQ(in_world.opening.rays, alone.opening.rays + terrain_alone.opening.rays);
  EXPECT_DOUBLE_EQ(in_world.finest_spacing, alone.finest_spacing);
  EXPECT_GT(in_world.coarsest_spacing, 10.0 * in_world.finest_spacing);
  EXPECT_EQ(in_world.lost_rays(), 0);
}

TEST(AccessibleSpace, RefusesBadOptions) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  const auto world = bvh::HullWorld::build(bvh::runtime_hulls(d->covering)).value();
  const auto triangles = bvh::TriangleWorld::build(d->prepared.mesh, d->tol()).value();
  ProbeOptions o;
  o.probe_distance = -1.0;
  EXPECT_EQ(probe_accessible_space(d->prepared, *triangles, *world, o).status().code(), StatusCode::invalid_argument);
  o.probe_distance = 1.0;
  o.resolution = 1e-9; // more than the octree's 16 levels
  EXPECT_EQ(probe_accessible_space(d->prepared, *triangles, *world, o).status().code(), StatusCode::invalid_argument);
}

TEST(Recheck, AVertexPokingIntoAHullIsCaught) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  std::vector<bvh::RuntimeHull> hulls = bvh::runtime_hulls(d->covering);
  EXPECT_EQ(recheck_hulls(d->prepared, hulls_under_check(hulls), d->covering.bar_half_length).total(), 0);
  hulls.push_back(box_hull(V(4.5, 2.5, -4.2), V(5.2, 3.4, -3.5))); // around the building's back right top corner
  const CheckReport poked = recheck_hulls(d->prepared, hulls_under_check(hulls), d->covering.bar_half_length);
  EXPECT_GT(poked.vertices_inside, 0);
  EXPECT_GT(poked.edges_inside, 0);
}

// A flat hull claims only faces on its polygon: on its plane but outside
// its sides is off the hull (a flat hull has no side facets to say so).
TEST(Recheck, AFlatHullClaimingAFaceBesideItsPolygonIsCaught) {
  Mesh m;
  add_quad(m, V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)); // faces 0, 1
  add_quad(m, V(3, 0, 0), V(4, 0, 0), V(4, 1, 0), V(3, 1, 0)); // faces 2, 3, same plane
  const PreparedMesh prepared = prepare_mesh(m, std::nullopt).value();
  const FlatPolygon square = make_flat_polygon(prepared.mesh.positions, {0, 1, 2, 3}, V(0, 0, 1), 1e-6);
  CoveringHull hull;
  hull.polytope = flat_polytope(square, false);
  hull.planar = true;
  hull.faces = {0, 1};
  Covering covering;
  covering.hulls = {hull};
  EXPECT_EQ(recheck_hulls(prepared, hulls_under_check(covering), 0.1).faces_off_hull, 0);
  covering.hulls[0].faces = {0, 1, 2};
  EXPECT_EQ(recheck_hulls(prepared, hulls_under_check(covering), 0.1).faces_off_hull, 1);
}

TEST(Behaviour, TheDecomposedBuildingCollidesLikeItsTrianglesAndABlobDoesNot) {
  const auto d = test::decompose_and_check(demo_building());
  ASSERT_TRUE(d);
  const auto triangles = bvh::TriangleWorld::build(d->prepared.mesh, d->tol()).value();
  const auto hulls = bvh::HullWorld::build(bvh::runtime_hulls(d->covering)).value();
  BehaviourOptions o;
  o.proxies = 900;
  const Result<BehaviourReport> same = compare_behaviour(d->prepared, *triangles, *hulls, o);
  ASSERT_TRUE(same.ok());
  EXPECT_GT(same.value().poses, 500);
  EXPECT_GT(same.value().both_touch, 100);
  EXPECT_EQ(same.value().missed, 0);
  // One hull over the whole building: poses clear of the room surfaces
  // touch it, and inside it the push points out of the blob, not the room.
  const auto blob = bvh::HullWorld::build({box_hull(V(-5, -0.2, -4), V(5, 3.2, 4))}).value();
  const Result<BehaviourReport> other = compare_behaviour(d->prepared, *triangles, *blob, o);
  ASSERT_TRUE(other.ok());
  EXPECT_GT(other.value().false_contacts, 5);
  EXPECT_GT(other.value().max_normal_angle, 90.0);
  EXPECT_GT(other.value().missed, 10); // the terrain has no hull at all
  o.proxies = 0;
  EXPECT_EQ(compare_behaviour(d->prepared, *triangles, *hulls, o).status().code(), StatusCode::invalid_argument);
}

TEST(HullSet, ReadsObjGroupsAndRefusesBadOnes) {
  test::TempDir dir;
  std::string obj;
  for (int h = 0; h < 2; ++h) {
    obj += "o hull" + std::to_string(h) + "\n";
    for (int i = 0; i < 8; ++i)
      obj += "v " + std::to_string((i & 1) + 3 * h) + " " + std::to_string((i >> 1) & 1) + " " +
             std::to_string((i >> 2) & 1) + "\n";
    obj += "f -8 -7 -6 -5\nf -4 -3 -2 -1\n";
  }
  // A flat group is a polygon of thickness 0 facing the way it winds (+z);
  // one on a line spans no area and is skipped.
  obj += "g flat\nv 0 0 9\nv 1 0 9\nv 0 1 9\nf -3 -2 -1\n";
  obj += "g line\nv 0 0 12\nv 1 0 12\nv 2 0 12\nf -3 -2 -1\n";
  const Result<HullSet> set = load_hull_set(dir.write("hulls.obj", obj));
  ASSERT_TRUE(set.ok()) << set.status().message();
  ASSERT_EQ(set.value().hulls.size(), 3u);
  EXPECT_EQ(set.value().groups_without_area, 1);
  EXPECT_NEAR(polytope_volume(set.value().hulls[1].shape), 1.0, 1e-12);
  const ConvexPolytope& flat = set.value().hulls[2].shape;
  EXPECT_EQ(flat.vertices.size(), 3u);
  ASSERT_EQ(flat.facets.size(), 2u);
  EXPECT_NEAR(flat.planes[0].normal.z(), 1.0, 1e-12);
  EXPECT_NEAR(flat.planes[0].offset, 9.0, 1e-12);
  EXPECT_EQ(polytope_volume(flat), 0.0);
  EXPECT_EQ(load_hull_set(dir.write("bad.obj", "v 0 0 0\nf 1 2 3\n")).status().code(), StatusCode::unreadable_file);
  EXPECT_EQ(load_hull_set(dir.path("missing.obj")).status().code(), StatusCode::file_not_found);
  EXPECT_EQ(load_hull_set(dir.write("none.obj", "# nothing\n")).status().code(), StatusCode::empty_scene);
}

} // namespace
} // namespace hullcover::validate

// The decomposer's own ray against the mesh (mesh_ray.h) and a hull's
// interior (free_space_sweep.h): the two things exact mode's witness rays
// are made of.

#include "indexed_scene.h"
#include "hullcover/covering/convex_hull_3d.h"
#include "validity/exact_conditions.h"
#include "validity/mesh_ray.h"
#include "hullcover/mesh/scene_builder.h"
#include "hullcover/geometry/incremental_hull.h"
#include "hullcover/geometry/tolerances.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <limits>
#include <random>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;

std::unique_ptr<test::IndexedScene> indexed(const Mesh& m) {
  return test::index_scene(m, std::nullopt, {1.0, false, ValidityMode::exact, 1.0});
}

TEST(MeshRay, ARayThroughTheEdgeTwoTrianglesShareMeetsThem) {
  Mesh m;
  add_quad(m, V(0, 0, 0), V(2, 0, 0), V(2, 0, 2), V(0, 0, 2)); // its diagonal runs (0,0,0)-(2,0,2)
  const auto s = indexed(m);
  std::vector<int> scratch;
  for (const V& through : {V(1, 0, 1), V(0.5, 0, 0.5), V(1.3, 0, 0.7)}) {
    const auto hit = first_mesh_hit(s->index, through + V(0, 5, 0), V(0, -1, 0), 0.0, 10.0, scratch);
    ASSERT_TRUE(hit) << through.transpose();
    EXPECT_NEAR(hit->t, 5.0, 1e-12);
  }
  EXPECT_FALSE(first_mesh_hit(s->index, V(3, 5, 1), V(0, -1, 0), 0.0, 10.0, scratch));
}

TEST(MeshRay, TellsWhichSideItMeetsAndACoincidentFrontMakesItOpen) {
  Mesh m;
  add_quad(m, V(0, 0, 0), V(1, 0, 0), V(1, 0, 1), V(0, 0, 1)); // facing one way
  const auto one = indexed(m);
  std::vector<int> scratch;
  const V normal = one->index.face_normals[0];
  const auto from_front = first_mesh_hit(one->index, V(0.3, 0, 0.6) + 2 * normal, -normal, 0.0, 4.0, scratch);
  const auto from_back = first_mesh_hit(one->index, V(0.3, 0, 0.6) - 2 * normal, normal, 0.0, 4.0, scratch);
  ASSERT_TRUE(from_front && from_back);
  EXPECT_FALSE(from_front->from_behind);
  EXPECT_TRUE(from_back->from_behind);
  // A second copy facing the other way (a double-sided sheet): the ray meets
  // one from behind and one from the front at the same distance. Under
  // the strict definition (docs/definitions-and-proofs.md) it ends on a front: open, from either side.
  add_quad(m, V(0, 0, 0), V(0, 0, 1), V(1, 0, 1), V(1, 0, 0));
  const auto two = indexed(m);
  for (const double side : {1.0, -1.0}) {
    const auto both = first_mesh_hit(two->index, V(0.3, 0, 0.6) + 2 * side * normal, -side * normal, 0.0, 4.0, scratch);
    ASSERT_TRUE(both);
    EXPECT_FALSE(both->from_behind) << side;
  }
  // Two coincident copies facing the same way, met from behind: enclosed.
  Mesh same;
  add_quad(same, V(0, 0, 0), V(1, 0, 0), V(1, 0, 1), V(0, 0, 1));
  add_quad(same, V(0, 0, 0), V(1, 0, 0), V(1, 0, 1), V(0, 0, 1));
  const auto twins = indexed(same);
  const auto behind_both = first_mesh_hit(twins->index, V(0.3, 0, 0.6) - 2 * normal, normal, 0.0, 4.0, scratch);
  ASSERT_TRUE(behind_both);
  EXPECT_TRUE(behind_both->from_behind);
}

TEST(HullInterior, IsTheHullShrunkByTolAndVanishesWhenThin) {
  Mesh m;
  add_box(m, V(0, 0, 0), V(1, 1, 1), true);
  ConvexHullBuilder builder;
  std::vector<V> corners = m.positions;
  const ConvexPolytope cube = builder.build(corners, {}).value();
  const double tol = 0.01;
  const HullInterior inside = hull_interior(cube, tol);
  ASSERT_FALSE(inside.empty());
  for (size_t k = 0; k < inside.facets.size(); ++k)
    for (const V& p : inside.facets[k]) {
      EXPECT_NEAR(deepest_signed_distance(cube.planes, p), -tol, 1e-12);
      EXPECT_LE(deepest_signed_distance(inside.planes, p), 1e-12);
    }
  Mesh slab;
  add_box(slab, V(0, 0, 0), V(1, 1.5 * tol, 1), true);
  std::vector<V> slab_corners = slab.positions;
  EXPECT_TRUE(hull_interior(builder.build(slab_corners, {}).value(), tol).empty());
}

// Whether the ray from `p` (inside the interior) along `dir` leaves through
// one of the interior's facet polygons (interior of a hull shrunk by tol).
bool leaves_through_a_facet(const HullInterior& interior, const V& p, const V& dir, double tol) {
  double leave = std::numeric_limits<double>::infinity();
  for (const Plane& plane : interior.planes)
    if (plane.normal.dot(dir) > 0.0) leave = std::min(leave, -plane.signed_distance(p) / plane.normal.dot(dir));
  const V exit = p + leave * dir;
  for (size_t k = 0; k < interior.facets.size(); ++k) {
    const std::vector<V>& f = interior.facets[k];
    // Planes that stay within kOnePlaneInTolerances tol of each other share
    // one facet.
    if (f.size() < 3 || std::abs(interior.planes[k].signed_distance(exit)) > kOnePlaneInTolerances * tol) continue;
    bool inside = true; // on the inner side of each edge of the convex facet
    for (size_t e = 0; e < f.size() && inside; ++e)
      inside = (f[(e + 1) % f.size()] - f[e]).cross(exit - f[e]).dot(interior.planes[k].normal) >= -1e-9;
    if (inside) return true;
  }
  return false;
}

// A hull grown point by point (as merging grows them) over a bumpy, nearly
// flat floor: its bottom is many triangles meeting at shallow angles.
// Shrunk by tol, a sliver among them vanishes and its neighbours' shrunk
// planes take its place, beyond the facets moved in by tol: every ray
// leaving the interior must still leave through some interior facet
// (dungeon, face 3204's tilted opening leaving through such a gap went
// unjudged).
TEST(HullInterior, NearlyCoplanarFacetsStillCloseTheInterior) {
  const double tol = 0.001;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int failures = 0, checked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<V> points;
    for (int i = 0; i < 24; ++i) points.push_back(V(u(rng), u(rng), 3 * tol * u(rng))); // the bumpy floor
    for (const V& top : {V(0, 0, 0.2), V(1, 0, 0.2), V(1, 1, 0.2), V(0, 1, 0.2)}) points.push_back(top);
    ConvexHullBuilder builder;
    std::optional<ConvexPolytope> hull =
        builder.build({points[24], points[25], points[26], points[27], points[0]}, {24, 25, 26, 27, 0}).value();
    for (int i = 1; i < 24 && hull; ++i) hull = add_point_to_hull(*hull, points[i], i, kVisibleBeyondTolerances * tol);
    ASSERT_TRUE(hull);
    const HullInterior interior = hull_interior(*hull, tol);
    for (int i = 0; i < 200; ++i) {
      const V p(u(rng), u(rng), 0.1);
      if (deepest_signed_distance(interior.planes, p) > 0.0) continue;
      const V dir = V(0.2 * (u(rng) - 0.5), 0.2 * (u(rng) - 0.5), -1).normalized();
      ++checked;
      failures += !leaves_through_a_facet(interior, p, dir, tol);
    }
  }
  EXPECT_EQ(failures, 0) << "of " << checked << " rays down through the bumpy floor";
  EXPECT_GT(checked, 2000);
}

// Witness rays (witness_rays.h) through sweep_enters_hull: a wall W at x = 0
// facing +x looks into a box hull [0.5, 1.5] x [0, 1] x [0, 1]; its front
// space runs through the box, which only a face closing it from behind may
// allow.
struct WallLookingIntoBox {
  Mesh mesh;
  ConvexPolytope box;

  WallLookingIntoBox() {
    add_quad(mesh, V(0, 0, 0), V(0, 1, 0), V(0, 1, 1), V(0, 0, 1)); // faces +x
    ConvexHullBuilder builder;
    Mesh hull;
    add_box(hull, V(0.5, 0, 0), V(1.5, 1, 1), true);
    box = builder.build(hull.positions, {}).value();
  }

  // A quad across the box at x, over y in [y0, y1] and z in [z0, z1],
  // facing `front` (+x: met from behind by W's rays, -x: from the front).
  void add_screen(double x, double y0, double y1, double z0, double z1, double front) {
    if (front > 0)
      add_quad(mesh, V(x, y0, z0), V(x, y1, z0), V(x, y1, z1), V(x, y0, z1));
    else
      add_quad(mesh, V(x, y0, z0), V(x, y0, z1), V(x, y1, z1), V(x, y1, z0));
  }

  bool wall_space_enters_box() const {
    const auto s = indexed(mesh);
    const double tol = s->index.tol();
    const HullInterior interior = hull_interior(box, tol);
    detail::SweepJudgeStorage storage;
    for (int f : {0, 1}) {
      std::vector<V> triangle;
      for (int k = 0; k < 3; ++k) triangle.push_back(s->prepared.mesh.positions[s->prepared.mesh.triangles[f][k]]);
      if (sweep_enters_hull(s->index, front_space_sweep(triangle, s->index.face_normals[f], 2.0, tol), interior,
                            storage))
        return true;
    }
    return false;
  }
};

TEST(WitnessRays, SpaceClosedFromBehindMayEnterAHull) {
  WallLookingIntoBox scene;
  scene.add_screen(1.0, -0.5, 1.5, -0.5, 1.5, +1);
  EXPECT_FALSE(scene.wall_space_enters_box());
}

// The screen leaves a strip 1% wide open along y = 0, narrower than the
// inset of the witness grid: the witnesses all meet the screen, but it
// shadows only part of their region, which is cut along its shadow.
TEST(WitnessRays, AFaceShadowingMostOfARegionDoesNotSpeakForTheRest) {
  WallLookingIntoBox scene;
  scene.add_screen(1.0, 0.01, 1.5, -0.5, 1.5, +1);
  EXPECT_TRUE(scene.wall_space_enters_box());
}

// A sliver facing the wall stands in the box in front of the screen, away
// from the witnesses: rays meeting it end in front of a face, in free
// space the box holds.
TEST(WitnessRays, AFaceMetFromTheFrontInsideEnclosedSpaceIsFound) {
  WallLookingIntoBox scene;
  scene.add_screen(1.0, -0.5, 1.5, -0.5, 1.5, +1);
  scene.add_screen(0.8, 0.437, 0.441, 0.21, 0.29, -1);
  EXPECT_TRUE(scene.wall_space_enters_box());
}

} // namespace
} // namespace hullcover

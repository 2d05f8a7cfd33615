// The conditions exact mode adds to the paper's (exact_conditions.h), each
// with a case built from the cause it fixes (../shared/DESIGN.md, "Where the
// paper's four conditions are not enough"): the paper's conditions alone
// put a known point of free space inside a hull; exact mode must not, and
// both coverings must pass the independent re-check.

#include "covering_fixture.h"

#include "indexed_scene.h"
#include "scene_index.h"
#include "validity_conditions.h"

#include "hullcover/covering/convex_hull_3d.h"

#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

namespace hullcover {
namespace {

using test::add_quad_facing;
using test::decompose_and_check;
using V = Eigen::Vector3d;

// A wedge: top T (y = 1, facing up) and side S (x = 1, facing +x) meet at a
// convex edge; their hull has a virtual slanted facet x + y = 1 and open
// ends at z = 0 and z = 1.
void add_wedge(Mesh& m) {
  add_quad_facing(m, V(0, 1, 0), V(1, 1, 0), V(1, 1, 1), V(0, 1, 1), V(0, 1, 0));
  add_quad_facing(m, V(1, 0, 0), V(1, 1, 0), V(1, 1, 1), V(1, 0, 1), V(1, 0, 0));
}

DecomposeOptions with_conditions(ValidityMode mode) {
  DecomposeOptions o;
  o.conditions = mode;
  o.free_space_reach = 2.0;  // the whole scene
  return o;
}

void expect_paper_loses_exact_keeps(const Mesh& m, const V& free_point) {
  const auto paper = decompose_and_check(m, with_conditions(ValidityMode::paper));
  const auto exact = decompose_and_check(m, with_conditions(ValidityMode::exact));
  ASSERT_TRUE(paper && exact);
  EXPECT_TRUE(test::point_inside_covering(paper->covering, free_point, paper->tol()))
      << "the case no longer shows the paper's loss";
  EXPECT_FALSE(test::point_inside_covering(exact->covering, free_point, exact->tol()));
  EXPECT_GT(exact->covering.hulls.size(), paper->covering.hulls.size());
}

// E1, cause 1: a wall W rests against the wedge's open end (z = 1), facing
// into it. Its front space runs through the wedge and out of its other end:
// the paper's conditions see nothing of W strictly inside and merge T + S.
TEST(ExactConditions, E1FaceOnTheHullFacingIntoItKeepsItsFrontSpace) {
  Mesh m;
  add_wedge(m);
  add_quad_facing(m, V(-1, -1, 1), V(2, -1, 1), V(2, 2, 1), V(-1, 2, 1), V(0, 0, -1));
  expect_paper_loses_exact_keeps(m, V(0.6, 0.6, 0.5));
}

// E2, cause 2: a floor's open edge (z = 1) looks out over an opening in
// which a ridge stands end on, its hull's open end facing the edge far from
// the edge's midpoint: the paper's one bar misses it.
TEST(ExactConditions, E2OpeningIsKeptAlongTheWholeEdge) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(4, 0, 0), V(4, 0, 1), V(0, 0, 1), V(0, 1, 0));
  add_quad_facing(m, V(0.2, -0.2, 1.2), V(0.5, 0.3, 1.2), V(0.5, 0.3, 2), V(0.2, -0.2, 2), V(-0.5, 0.3, 0));
  add_quad_facing(m, V(0.5, 0.3, 1.2), V(0.8, -0.2, 1.2), V(0.8, -0.2, 2), V(0.5, 0.3, 2), V(0.5, 0.3, 0));
  expect_paper_loses_exact_keeps(m, V(0.5, 0, 1.5));
}

// E3, cause 3: a sheet facing down (y = 0.5) passes through the wedge with
// its vertices and edges all outside; below it, the wedge holds its front
// space, which leaves through the wedge's slanted virtual facet.
TEST(ExactConditions, E3FaceCrossingTheHullKeepsItsFrontSpace) {
  Mesh m;
  add_wedge(m);
  // Its diagonal (first to third corner) misses the wedge's interior.
  add_quad_facing(m, V(-1, 0.5, 3), V(-1, 0.5, -1), V(3, 0.5, -1), V(3, 0.5, 3), V(0, -1, 0));
  expect_paper_loses_exact_keeps(m, V(0.8, 0.4, 0.5));
}

// Enclosed space stays allowed (DESIGN.md): a closed box resting on a floor
// is one hull in exact mode too, though the floor's front space runs into it.
TEST(ExactConditions, EnclosedSpaceMayBeFilled) {
  Mesh m;
  add_quad_facing(m, V(-2, 0, -2), V(3, 0, -2), V(3, 0, 3), V(-2, 0, 3), V(0, 1, 0));
  add_box(m, V(0, 0, 0), V(1, 1, 1), true);
  const auto exact = decompose_and_check(m, with_conditions(ValidityMode::exact));
  ASSERT_TRUE(exact);
  for (const CoveringHull& h : exact->covering.hulls)
    if (!h.planar) {
      EXPECT_NEAR(h.volume, 1.0, 1e-9);
    }
  EXPECT_TRUE(test::point_inside_covering(exact->covering, V(0.5, 0.5, 0.5), exact->tol()));
}

// Coplanar tiles of one floor still make one polygon: what a merge adds
// beyond its two parts is covered by the tiles merged later.
TEST(ExactConditions, FlatPolygonOverTilesOfOtherPatchesIsOneHull) {
  Mesh m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      add_quad_facing(m, V(i, 0, j), V(i + 1, 0, j), V(i + 1, 0, j + 1), V(i, 0, j + 1), V(0, 1, 0));
  const auto d = decompose_and_check(m);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->covering.hulls.size(), 1u);
}

TEST(ExactConditions, FoldEdgeIsOpen) {
  // The rim of a double-sided sheet is a fold edge: both faces use it.
  Mesh m;
  m.positions = {V(0, 0, 0), V(1, 0, 0), V(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 2}};
  m.material_ids = {0, 0};
  Result<PreparedMesh> prepared = prepare_mesh(m, std::nullopt);
  ASSERT_TRUE(prepared.ok());
  int folds = 0;
  for (int e = 0; e < static_cast<int>(prepared.value().connectivity.edges.size()); ++e)
    folds += is_fold_edge(prepared.value(), e);
  EXPECT_EQ(folds, 3);
}


// ---- DESIGN.md's strict free space, decided on hand-made hulls ---------------
// Each case asks check_solid_hull about one hull over a small scene, at the
// default (uncapped) reach, as the decomposer asks about a merged patch.

ConvexPolytope box_hull(const V& min, const V& max) {
  Mesh box;
  add_box(box, min, max, true);
  return ConvexHullBuilder().build(box.positions, {}).value();
}

Validity exact_verdict(const Mesh& m, const ConvexPolytope& hull) {
  Result<PreparedMesh> prepared = prepare_mesh(m, std::nullopt);
  EXPECT_TRUE(prepared.ok());
  const double margin = 0.0;  // the hulls below lie within the scene's box
  BarOptions bars{kExactBarHalfLengthInTolerances * prepared.value().tolerance.length, false, ValidityMode::exact,
                  uncapped_free_space_reach(prepared.value(), margin), margin};
  const auto scene = test::index_scene(m, std::nullopt, bars);
  std::vector<int> scratch;
  return check_solid_hull(scene->index, hull, scratch);
}

// A floor (y = 0, facing up) and, standing on it, a tube x, z in [0, 1] up
// to y = 2 with walls facing out: the floor inside the tube looks up.
Mesh floor_and_open_tube() {
  Mesh m;
  add_quad_facing(m, V(-3, 0, -3), V(4, 0, -3), V(4, 0, 4), V(-3, 0, 4), V(0, 1, 0));
  add_quad_facing(m, V(0, 0, 0), V(1, 0, 0), V(1, 2, 0), V(0, 2, 0), V(0, 0, -1));
  add_quad_facing(m, V(0, 0, 1), V(1, 0, 1), V(1, 2, 1), V(0, 2, 1), V(0, 0, 1));
  add_quad_facing(m, V(0, 0, 0), V(0, 0, 1), V(0, 2, 1), V(0, 2, 0), V(-1, 0, 0));
  add_quad_facing(m, V(1, 0, 0), V(1, 0, 1), V(1, 2, 1), V(1, 2, 0), V(1, 0, 0));
  return m;
}

TEST(StrictFreeSpace, HullFillingAnOpenTopTubeTakesTheRaysThatEscape) {
  EXPECT_EQ(exact_verdict(floor_and_open_tube(), box_hull(V(0, 0, 0), V(1, 2, 1))), Validity::front_space_inside);
}

TEST(StrictFreeSpace, HullFillingACappedTubeIsEnclosed) {
  Mesh m = floor_and_open_tube();
  // One-sided cap facing up: the floor's rays end on its back.
  add_quad_facing(m, V(0, 2, 0), V(1, 2, 0), V(1, 2, 1), V(0, 2, 1), V(0, 1, 0));
  EXPECT_EQ(exact_verdict(m, box_hull(V(0, 0, 0), V(1, 2, 1))), Validity::valid);
}

TEST(StrictFreeSpace, HullFloatingFarAboveAFloorTakesItsSpace) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(10, 0, 0), V(10, 0, 10), V(0, 0, 10), V(0, 1, 0));
  add_quad_facing(m, V(0, 9, 0), V(0.1, 9, 0), V(0.1, 9, 0.1), V(0, 9, 0.1), V(0, 1, 0));  // only to size the scene
  // 8 units up: far beyond the old 0.02 x diagonal reach.
  EXPECT_EQ(exact_verdict(m, box_hull(V(4, 8, 4), V(5, 8.5, 5))), Validity::front_space_inside);
}

TEST(StrictFreeSpace, HullUnderAOneSidedTableTopIsEnclosed) {
  Mesh m;
  add_quad_facing(m, V(-2, 0, -2), V(3, 0, -2), V(3, 0, 3), V(-2, 0, 3), V(0, 1, 0));
  add_quad_facing(m, V(0, 1, 0), V(1, 1, 0), V(1, 1, 1), V(0, 1, 1), V(0, 1, 0));
  EXPECT_EQ(exact_verdict(m, box_hull(V(0, 0, 0), V(1, 1, 1))), Validity::valid);
  // The same top facing down is a ceiling: the space under it is open.
  Mesh ceiling;
  add_quad_facing(ceiling, V(-2, 0, -2), V(3, 0, -2), V(3, 0, 3), V(-2, 0, 3), V(0, 1, 0));
  add_quad_facing(ceiling, V(0, 1, 0), V(1, 1, 0), V(1, 1, 1), V(0, 1, 1), V(0, -1, 0));
  EXPECT_NE(exact_verdict(ceiling, box_hull(V(0, 0, 0), V(1, 1, 1))), Validity::valid);
}

// Interpenetrating kit pieces: a floor triangle (facing up, its edges all
// outside) runs through a closed pillar; inside it, its rays end on the
// pillar's top from behind.
TEST(StrictFreeSpace, FloorRunningIntoAClosedPillarIsEnclosed) {
  Mesh m;
  test::add_triangle(m, V(-5, 0.5, -5), V(-5, 0.5, 10), V(10, 0.5, -5));
  ASSERT_GT(triangle_area_vector(m, 0).y(), 0.0);
  add_box(m, V(0, 0, 0), V(1, 2, 1), true);
  EXPECT_EQ(exact_verdict(m, box_hull(V(0, 0, 0), V(1, 2, 1))), Validity::valid);
}

// A floor's open edge at x = 1; a hull lies beyond it, below the floor's
// plane, where only the opening's fan tilted to the back (kOpeningTiltSine)
// passes: at x = 1.5 that fan is 0.05 below the plane.
TEST(StrictFreeSpace, TiltedOpeningIsKept) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(1, 0, 0), V(1, 0, 1), V(0, 0, 1), V(0, 1, 0));
  add_quad_facing(m, V(-1, -1, -1), V(-0.9, -1, -1), V(-0.9, -1, -0.9), V(-1, -1, -0.9), V(0, 1, 0));  // sizes the scene
  add_quad_facing(m, V(3, 1, 2), V(3.1, 1, 2), V(3.1, 1, 2.1), V(3, 1, 2.1), V(0, 1, 0));
  const ConvexPolytope below = box_hull(V(1.5, -0.08, 0.2), V(2, -0.03, 0.8));
  EXPECT_EQ(exact_verdict(m, below), Validity::opening_inside);
  // Lower, out of the tilted fan's reach there, it takes nothing.
  EXPECT_EQ(exact_verdict(m, box_hull(V(1.5, -0.6, 0.2), V(2, -0.3, 0.8))), Validity::valid);
}

} // namespace
} // namespace hullcover

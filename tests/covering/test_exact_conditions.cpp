// The conditions exact mode adds to the paper's (exact_conditions.h), each
// with a case built from the cause it fixes (docs/definitions-and-proofs.md,
// "Exact mode: no free space lost"): the paper's conditions alone
// put a known point of free space inside a hull; exact mode must not, and
// both coverings must pass the independent re-check.

#include "covering_fixture.h"

#include "indexed_scene.h"
#include "validity/scene_index_build.h"
#include "validity/validity_conditions.h"

#include "hullcover/covering/convex_hull_3d.h"

#include "hullcover/mesh/scene_builder.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

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
  o.free_space_reach = 2.0; // the whole scene
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

// Enclosed space stays allowed (docs/definitions-and-proofs.md): a closed box resting on a floor
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
    folds += is_fold_edge(view_of(prepared.value()), e);
  EXPECT_EQ(folds, 3);
}

// ---- docs/definitions-and-proofs.md's strict free space, decided on hand-made hulls ---------------
// Each case asks check_solid_hull about one hull over a small scene, at the
// default (uncapped) reach, as the decomposer asks about a merged patch.

ConvexPolytope box_hull(const V& min, const V& max) {
  Mesh box;
  add_box(box, min, max, true);
  return ConvexHullBuilder().build(box.positions, {}).value();
}

// `hull_place`: the place (hullcover/mesh/tolerance.h) the hull belongs to,
// as the decomposer's view of an island's cells gives it; -1 for none.
Validity exact_verdict(const Mesh& m, const ConvexPolytope& hull, int hull_place = -1) {
  Result<PreparedMesh> prepared = prepare_mesh(m, std::nullopt);
  EXPECT_TRUE(prepared.ok());
  const double margin = 0.0; // the hulls below lie within the scene's box
  BarOptions bars{kExactBarHalfLengthInTolerances * prepared.value().tolerance.length, false, ValidityMode::exact,
                  uncapped_free_space_reach(view_of(prepared.value()), margin), margin};
  const auto scene = test::index_scene(m, std::nullopt, bars);
  SceneIndex view = scene->index;
  view.place = hull_place;
  std::vector<int> scratch;
  return check_solid_hull(view, hull, scratch);
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

// Judging first the pieces of free space that rejected the latest hulls
// (RecentRejections, as the merger does) never changes whether a hull is
// valid: random boxes about the demo building, each judged with and without
// the memory of the ones before.
TEST(StrictFreeSpace, RecentRejectionsChangeNoVerdict) {
  const Mesh m = demo_building();
  Result<PreparedMesh> prepared = prepare_mesh(m, std::nullopt);
  ASSERT_TRUE(prepared.ok());
  const double margin = 0.0;
  BarOptions bars{kExactBarHalfLengthInTolerances * prepared.value().tolerance.length, false, ValidityMode::exact,
                  uncapped_free_space_reach(view_of(prepared.value()), margin), margin};
  const auto scene = test::index_scene(m, std::nullopt, bars);
  Aabb box;
  for (const V& p : m.positions) box.extend(p);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RecentRejections recent;
  std::vector<int> scratch;
  int exact_rejections = 0, valid = 0, told_first = 0;
  for (int trial = 0; trial < 400; ++trial) {
    V low, high;
    for (int k = 0; k < 3; ++k) {
      const double extent = box.max[k] - box.min[k];
      low[k] = box.min[k] + unit(rng) * extent;
      high[k] = low[k] + (0.02 + 0.2 * unit(rng)) * extent;
    }
    if (trial % 4 == 0) { // under the scene, where no ray of free space reaches: valid
      const double height = box.max.y() - box.min.y();
      high.y() = box.min.y() - 0.1 * height;
      low.y() = high.y() - 0.2 * height;
    }
    const ConvexPolytope hull = box_hull(low, high);
    const Validity alone = check_solid_hull(scene->index, hull, scratch);
    const SweepRef first_before = *recent.begin();
    const Validity remembered = check_solid_hull(scene->index, hull, scratch, &recent);
    EXPECT_EQ(alone == Validity::valid, remembered == Validity::valid) << "trial " << trial;
    exact_rejections += alone == Validity::front_space_inside || alone == Validity::opening_inside;
    valid += alone == Validity::valid;
    told_first += remembered != Validity::valid && first_before.item >= 0 && *recent.begin() == first_before;
  }
  // Both verdicts occur, and a remembered piece rejected hulls again.
  EXPECT_GT(exact_rejections, 10);
  EXPECT_GT(valid, 10);
  EXPECT_GT(told_first, 0);
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

// A world of two maps: the open tube on its floor, and far above it another
// map, a closed room whose walls face in (as a game map's do). The tube's
// rays leave through its open top into the back of the room's floor: in
// the world that space is enclosed, in the tube's map alone it is open. A
// hull of the tube's own place (0) may not fill it, so that map's hulls are
// valid alone too; a hull of no one place is judged by the world's rule.
// The room's floor meeting the tube map's box makes one place, and there
// it encloses the tube.
TEST(StrictFreeSpace, AnotherMapAboveEnclosesNothingForTheMapsOwnHulls) {
  Mesh m = floor_and_open_tube();
  add_box(m, V(-3, 20, -3), V(4, 30, 4), false);
  ASSERT_EQ(prepare_mesh(m, std::nullopt).value().tolerance.places, 2);
  const ConvexPolytope filling = box_hull(V(0, 0, 0), V(1, 2, 1));
  EXPECT_EQ(exact_verdict(m, filling, 0), Validity::front_space_inside);
  EXPECT_EQ(exact_verdict(m, filling, -1), Validity::valid);
  Mesh touching = floor_and_open_tube();
  add_box(touching, V(-3, 2, -3), V(4, 12, 4), false);
  ASSERT_EQ(prepare_mesh(touching, std::nullopt).value().tolerance.places, 1);
  EXPECT_EQ(exact_verdict(touching, filling, 0), Validity::valid);
}

TEST(StrictFreeSpace, HullFloatingFarAboveAFloorTakesItsSpace) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(10, 0, 0), V(10, 0, 10), V(0, 0, 10), V(0, 1, 0));
  add_quad_facing(m, V(0, 9, 0), V(0.1, 9, 0), V(0.1, 9, 0.1), V(0, 9, 0.1), V(0, 1, 0)); // only to size the scene
  // 8 units up: far beyond the old 0.02 x diagonal reach.
  EXPECT_EQ(exact_verdict(m, box_hull(V(4, 8, 4), V(5, 8.5, 5))), Validity::front_space_inside);
}

// A slab hovering just over a floor, within the rays' stand-off: the floor's
// rays are judged from the floor itself (the strict definition's 0 < t), so a slab whose
// inside (shrunk by tol) lies within 2 tol of the floor takes their space
// (judged from the stand-off, it passed: Red Eclipse's biolytic had one
// beyond an open edge). A slab 1.7 tol thick has no inside and takes nothing.
TEST(StrictFreeSpace, ASlabHoveringWithinTheStandOffTakesTheFloorsSpace) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(10, 0, 0), V(10, 0, 10), V(0, 0, 10), V(0, 1, 0));
  const double tol = prepare_mesh(m, std::nullopt).value().tolerance.length;
  // Beside the quad's diagonal (x = z), so no mesh edge runs under it.
  EXPECT_EQ(exact_verdict(m, box_hull(V(6, 0.2 * tol, 1), V(8, 2.8 * tol, 3))), Validity::front_space_inside);
  EXPECT_EQ(exact_verdict(m, box_hull(V(6, 0.2 * tol, 1), V(8, 1.9 * tol, 3))), Validity::valid);
}

// A floor with a wall on its edge (the room's box holds the table: one
// place, hullcover/mesh/tolerance.h; the wall faces out) and a one-sided
// table top on it.
void add_floor_and_wall(Mesh& m) {
  add_quad_facing(m, V(-2, 0, -2), V(3, 0, -2), V(3, 0, 3), V(-2, 0, 3), V(0, 1, 0));
  add_quad_facing(m, V(-2, 0, -2), V(-2, 0, 3), V(-2, 2, 3), V(-2, 2, -2), V(-1, 0, 0));
}

TEST(StrictFreeSpace, HullUnderAOneSidedTableTopIsEnclosed) {
  Mesh m;
  add_floor_and_wall(m);
  add_quad_facing(m, V(0, 1, 0), V(1, 1, 0), V(1, 1, 1), V(0, 1, 1), V(0, 1, 0));
  EXPECT_EQ(exact_verdict(m, box_hull(V(0, 0, 0), V(1, 1, 1))), Validity::valid);
  // The same top facing down is a ceiling: the space under it is open.
  Mesh ceiling;
  add_floor_and_wall(ceiling);
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
  add_quad_facing(m, V(-1, -1, -1), V(-0.9, -1, -1), V(-0.9, -1, -0.9), V(-1, -1, -0.9), V(0, 1, 0)); // sizes the scene
  add_quad_facing(m, V(3, 1, 2), V(3.1, 1, 2), V(3.1, 1, 2.1), V(3, 1, 2.1), V(0, 1, 0));
  const ConvexPolytope below = box_hull(V(1.5, -0.08, 0.2), V(2, -0.03, 0.8));
  EXPECT_EQ(exact_verdict(m, below), Validity::opening_inside);
  // Lower, out of the tilted fan's reach there, it takes nothing.
  EXPECT_EQ(exact_verdict(m, box_hull(V(1.5, -0.6, 0.2), V(2, -0.3, 0.8))), Validity::valid);
}

// A grown hull (a merged patch's hull before Qhull rebuilds it, one plane per
// triangle it grew by, kept when the rebuild fails its checks) whose front is
// many triangles of one wall, their planes a few millionths of a radian
// apart by float32 rounding: hull 1641 of sauerbraten-fdm6 as `hullcover
// world` scales it. Shrunk by tol, planes within tol/16 of each other were
// one, yet a facet was still cut by a plane that is one with another: two
// such planes cross a third at that shallow angle along lines metres apart,
// and rays entering between the lines lay on no facet, so no sweep judged
// them. The audit found a ray there 3.8 tol deep that meets no face at all.
ConvexPolytope fdm6_grown_wall_hull() {
  ConvexPolytope hull;
  hull.vertices = {V(6.4000000953674308, 4.0, 9.6000003814697248),
                   V(6.5999999046325684, 2.4000000953674316, 9.3999996185302734),
                   V(6.4000000953674308, 2.4000000953674316, 9.6000003814697248),
                   V(6.4000000953674316, 2.5999999046325684, 9.8000001907348633),
                   V(8.8000001907348633, 2.4000000953674316, 7.1999998092651367),
                   V(6.4000000953674316, 5.5999999046325684, 9.6000003814697266),
                   V(8.8000001907348633, 4.0, 7.1999998092651367),
                   V(8.0, 5.5999999046325684, 8.0),
                   V(9.3999996185302734, 2.5999999046325684, 6.5999999046325684),
                   V(9.6000003814697266, 2.5999999046325684, 6.4000000953674316),
                   V(9.6000003814697266, 5.5999999046325684, 6.4000000953674316),
                   V(6.4000000953674316, 4.0, 9.8000001907348633)};
  hull.facets = {{0, 1, 2},  {2, 1, 3},  {0, 2, 3},  {1, 0, 4},  {3, 1, 4},   {0, 3, 5},  {4, 0, 5},
                 {4, 5, 6},  {6, 5, 7},  {4, 6, 8},  {6, 7, 9},  {3, 4, 9},   {4, 8, 9},  {8, 6, 9},
                 {3, 9, 10}, {9, 7, 10}, {5, 3, 11}, {7, 5, 11}, {3, 10, 11}, {10, 7, 11}};
  for (const std::vector<int>& f : hull.facets) {
    const V& a = hull.vertices[f[0]];
    const V n = (hull.vertices[f[1]] - a).cross(hull.vertices[f[2]] - a).normalized();
    hull.planes.push_back({n, n.dot(a)});
  }
  return hull;
}

TEST(StrictFreeSpace, RaysEnteringAGrownHullBetweenNearlyCoplanarFacetsAreJudged) {
  const double tol = 0.000399119; // the map's
  const ConvexPolytope hull = fdm6_grown_wall_hull();
  // A small face at x = 3.2 facing +x (on the map, part of face 3132): its
  // rays pass the hull's front where the map's wall has a gap, and meet
  // nothing.
  Mesh m;
  test::add_triangle(m, V(3.2, 2.42, 7.12), V(3.2, 2.44, 7.12), V(3.2, 2.43, 7.15));
  // The audit's lost ray, at the depth it found: deeper than tol in the hull.
  const V lost(8.8635879939332973, 2.4333334267139435, 7.1385417580604553);
  EXPECT_LT(deepest_signed_distance(hull.planes, lost), -3.0 * tol);
  Result<PreparedMesh> prepared = prepare_mesh(m, tol);
  ASSERT_TRUE(prepared.ok());
  const double margin = 10.0; // the hull lies this far from the face, beyond the scene's box
  BarOptions bars{kExactBarHalfLengthInTolerances * tol, false, ValidityMode::exact,
                  uncapped_free_space_reach(view_of(prepared.value()), margin), margin};
  const auto scene = test::index_scene(m, tol, bars);
  std::vector<int> scratch;
  EXPECT_EQ(check_solid_hull(scene->index, hull, scratch), Validity::front_space_inside);

  // Every ray along +x that enters the shrunk hull enters through a facet of
  // it facing against the ray (within tol of the facet's outline).
  const HullInterior interior = hull_interior(hull, tol);
  for (double y = 2.41; y < 5.59; y += 0.05)
    for (double z = 6.45; z < 9.75; z += 0.05) {
      double enter = -std::numeric_limits<double>::infinity(), leave = -enter;
      for (const Plane& p : interior.planes) {
        if (p.normal.x() == 0.0) continue;
        const double t = (p.offset - p.normal.y() * y - p.normal.z() * z) / p.normal.x();
        if (p.normal.x() < 0.0)
          enter = std::max(enter, t);
        else
          leave = std::min(leave, t);
      }
      if (!(enter < leave) || deepest_signed_distance(interior.planes, V(0.5 * (enter + leave), y, z)) >= 0.0) continue;
      bool on_facet = false;
      for (size_t k = 0; k < interior.facets.size() && !on_facet; ++k) {
        const std::vector<V>& f = interior.facets[k];
        if (f.size() < 3 || interior.planes[k].normal.x() >= 0.0) continue;
        // Seen along x, the facet's outline holds (y, z) (any winding).
        double low = 0.0, high = 0.0;
        for (size_t i = 0; i < f.size(); ++i) {
          const V& a = f[i];
          const V& b = f[(i + 1) % f.size()];
          const double e = (b.y() - a.y()) * (z - a.z()) - (b.z() - a.z()) * (y - a.y());
          const double length = std::hypot(b.y() - a.y(), b.z() - a.z());
          low = std::min(low, e + tol * length);
          high = std::max(high, e - tol * length);
        }
        on_facet = low >= 0.0 || high <= 0.0;
      }
      EXPECT_TRUE(on_facet) << "the ray at y " << y << ", z " << z << " enters through no facet";
    }
}

} // namespace
} // namespace hullcover

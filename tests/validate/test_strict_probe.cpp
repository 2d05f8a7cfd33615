// The probe against the strict definition (docs/definitions-and-proofs.md) of free space, on scenes
// built here whose answer is known by hand: rays with no cap, decided
// exactly against each hull; enclosed rays (first hit a back face) allowed;
// every face probed however small; openings tilted to either side.

#include "box_hulls.h"
#include "hullcover/validate/accessible_space.h"

#include "covering_fixture.h"

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/planar_hull.h"
#include "hullcover/geometry/tolerances.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hullcover::validate {
namespace {

using V = Eigen::Vector3d;
using test::add_quad_facing;
using test::box_hull;

const V kUpward = V::UnitY();

ProbeReport strict_probe(const Mesh& mesh, const std::vector<bvh::RuntimeHull>& hulls, ProbeOptions options = {},
                         std::optional<double> tol = std::nullopt) {
  const PreparedMesh prepared = prepare_mesh(mesh, tol).value();
  const auto world = bvh::HullWorld::build(hulls).value();
  const auto triangles = bvh::TriangleWorld::build(prepared.mesh, prepared.tolerance.length).value();
  Result<ProbeReport> r = probe_accessible_space(prepared, *triangles, *world, options);
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? r.value() : ProbeReport{};
}

// A floor (y = 0, x and z in [-5, 5]) with a square tube x, z in [-1, 1]
// rising to y = 4 on it; walls facing in or out; an upward-facing cap on
// top when asked.
Mesh tube_on_floor(bool walls_inward, bool cap) {
  Mesh m;
  add_quad_facing(m, V(-5, 0, -5), V(5, 0, -5), V(5, 0, 5), V(-5, 0, 5), kUpward);
  const double side = walls_inward ? -1.0 : 1.0;
  add_quad_facing(m, V(-1, 0, -1), V(-1, 4, -1), V(-1, 4, 1), V(-1, 0, 1), V(-side, 0, 0));
  add_quad_facing(m, V(1, 0, -1), V(1, 4, -1), V(1, 4, 1), V(1, 0, 1), V(side, 0, 0));
  add_quad_facing(m, V(-1, 0, -1), V(-1, 4, -1), V(1, 4, -1), V(1, 0, -1), V(0, 0, -side));
  add_quad_facing(m, V(-1, 0, 1), V(-1, 4, 1), V(1, 4, 1), V(1, 0, 1), V(0, 0, side));
  if (cap) add_quad_facing(m, V(-1, 4, -1), V(1, 4, -1), V(1, 4, 1), V(-1, 4, 1), kUpward);
  return m;
}

// Open at the top: the rays from the floor inside escape upwards, so the
// hull filling the tube takes open space; no point of it is deeper than 1
// (its half width).
TEST(StrictProbe, AnOpenToppedTubeFilledByAHullLosesSpace) {
  const ProbeReport r = strict_probe(tube_on_floor(true, false), {box_hull(V(-1, 0, -1), V(1, 4, 1))});
  EXPECT_GT(r.front.lost, 0);
  EXPECT_GT(r.front.lost_length, 0.0);
  EXPECT_EQ(r.front.deepest.hull, 0);
  EXPECT_GT(r.front.deepest.depth, 0.5);
  EXPECT_LE(r.front.deepest.depth, 1.0 + 1e-9);
  EXPECT_GT(r.lost_cells, 0);
}

// Walls facing out and a cap facing up: the floor's rays inside meet the
// cap's back (enclosed), the pillar is closed: the hull takes nothing.
TEST(StrictProbe, TheSameTubeCappedIsEnclosedAndClean) {
  const ProbeReport r = strict_probe(tube_on_floor(false, true), {box_hull(V(-1, 0, -1), V(1, 4, 1))});
  EXPECT_EQ(r.front.lost, 0);
  EXPECT_EQ(r.opening.lost, 0);
  EXPECT_GT(r.front.enclosed, 0);
  // Open at the top again, with walls facing out: the floor's rays escape.
  EXPECT_GT(strict_probe(tube_on_floor(false, false), {box_hull(V(-1, 0, -1), V(1, 4, 1))}).front.lost, 0);
}

// One floor triangle whose centroid (5, 0, 5) lies under the centre of a
// 2-unit hull 400 units up (40 times the scene's size): no cap, so its
// centroid ray passes through the hull's centre, 1 deep, at (5, 401, 5).
TEST(StrictProbe, AHullFloatingFarAboveAFloorIsLostWithItsDeepestPoint) {
  Mesh m;
  test::add_triangle(m, V(0, 0, 0), V(0, 0, 15), V(15, 0, 0));
  const ProbeReport r = strict_probe(m, {box_hull(V(4, 400, 4), V(6, 402, 6))});
  EXPECT_GT(r.front.lost, 0);
  EXPECT_EQ(r.front.deepest.hull, 0);
  EXPECT_EQ(r.front.deepest.face, 0);
  EXPECT_NEAR(r.front.deepest.depth, 1.0, 1e-9);
  EXPECT_LT((r.front.deepest.point - V(5, 401, 5)).norm(), 1e-6);
  ASSERT_EQ(r.worst.size(), 1u);
  EXPECT_EQ(r.worst[0].hull, 0);
  EXPECT_NEAR(r.max_lost_depth, 1.0, 1e-9);
  // Every lost ray runs 2 units through it, less tol at either end: at most 2 each.
  EXPECT_LE(r.front.lost_length, 2.0 * static_cast<double>(r.front.lost));
  // A cap of 100 units keeps the rays short of it: what a cap gives up.
  ProbeOptions capped;
  capped.probe_distance = 100.0;
  EXPECT_EQ(strict_probe(m, {box_hull(V(4, 400, 4), V(6, 402, 6))}, capped).front.lost, 0);
}

// The probe judges hulls from the ray's origin on the surface (docs/definitions-and-proofs.md's
// 0 < t), not from its stand-off: a slab hovering 0.2 tol over a floor,
// 2.6 tol thick, has an inside the floor's rays cross within 2 tol of it.
// One 1.7 tol thick has no inside.
TEST(StrictProbe, ASlabHoveringWithinTheStandOffLosesSpace) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(10, 0, 0), V(10, 0, 10), V(0, 0, 10), kUpward);
  const double tol = 1e-3;
  const ProbeReport r = strict_probe(m, {box_hull(V(6, 0.2 * tol, 1), V(8, 2.8 * tol, 3))}, {}, tol);
  EXPECT_GT(r.front.lost, 0);
  EXPECT_NEAR(r.front.deepest.depth, 1.3 * tol, 1e-9); // half its thickness
  EXPECT_EQ(strict_probe(m, {box_hull(V(6, 0.2 * tol, 1), V(8, 1.9 * tol, 3))}, {}, tol).front.lost, 0);
}

// A one-sided table top (facing up) over a floor, its hull reaching down to
// the floor: the floor's rays under it meet the top's back: enclosed.
TEST(StrictProbe, AHullUnderAOneSidedTableTopIsEnclosed) {
  Mesh m;
  add_quad_facing(m, V(-3, 0, -3), V(5, 0, -3), V(5, 0, 5), V(-3, 0, 5), kUpward);
  add_quad_facing(m, V(0, 1, 0), V(2, 1, 0), V(2, 1, 2), V(0, 1, 2), kUpward);
  const ProbeReport r = strict_probe(m, {box_hull(V(0, 0, 0), V(2, 1, 2))});
  EXPECT_EQ(r.front.lost, 0);
  EXPECT_EQ(r.opening.lost, 0);
  EXPECT_GT(r.front.enclosed, 0);
}

// A floor running into a closed pillar filled by its hull: allowed.
TEST(StrictProbe, AFloorRunningIntoAClosedPillarIsClean) {
  Mesh m;
  add_quad_facing(m, V(-5, 0, -5), V(5, 0, -5), V(5, 0, 5), V(-5, 0, 5), kUpward);
  add_box(m, V(-1, 0, -1), V(1, 3, 1), true);
  const ProbeReport r = strict_probe(m, {box_hull(V(-1, 0, -1), V(1, 3, 1))});
  EXPECT_EQ(r.front.lost, 0);
  EXPECT_EQ(r.opening.lost, 0);
  EXPECT_GT(r.front.enclosed, 0); // the floor under the pillar
}

// A face far smaller than the ray spacing still gets rays: the hull in
// front of it is found, from that face.
TEST(StrictProbe, ATinyFaceInFrontOfAHullIsStillProbed) {
  Mesh m;
  test::add_triangle(m, V(0, 0, 0), V(0, 0, 0.01), V(0.01, 0, 0)); // face 0, facing up
  add_quad_facing(m, V(3, 0, -5), V(13, 0, -5), V(13, 0, 5), V(3, 0, 5), kUpward);
  ProbeOptions coarse;
  coarse.resolution = 1.0; // a hundred times the tiny face
  const ProbeReport r = strict_probe(m, {box_hull(V(-0.1, 0.5, -0.1), V(0.1, 0.7, 0.1))}, coarse);
  EXPECT_GT(r.front.lost, 0);
  EXPECT_EQ(r.front.deepest.face, 0);
  EXPECT_EQ(r.front.deepest.hull, 0);
}

// A square face (y = 0, facing up) with a hull beyond its edge x = 2 and
// below its plane: only the opening rays tilted down reach it. Along
// (c, -s, 0) from the edge (c = sqrt(1 - s^2)), depth is
// min(6 - x, -0.2 - y), largest where the two meet: t = 4.2 / (c + s).
TEST(StrictProbe, AnOpeningIsLostToATiltedRay) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(2, 0, 0), V(2, 0, 2), V(0, 0, 2), kUpward);
  const ProbeReport r = strict_probe(m, {box_hull(V(3, -1, 0.5), V(6, -0.2, 1.5))});
  EXPECT_EQ(r.front.lost, 0);
  EXPECT_GT(r.opening.lost, 0);
  EXPECT_GT(r.opening.rays, 0);
  EXPECT_EQ(r.opening.deepest.hull, 0);
  EXPECT_TRUE(r.opening.deepest.opening);
  const double s = kOpeningTiltSine, c = std::sqrt(1.0 - s * s);
  const double t = 4.2 / (c + s);
  EXPECT_NEAR(r.opening.deepest.depth, s * t - 0.2, 1e-9);
  EXPECT_NEAR(r.opening.deepest.point.x(), 2.0 + c * t, 1e-6);
  EXPECT_NEAR(r.opening.deepest.point.y(), -s * t, 1e-6);
  // Level with the face instead, the in-plane rays are lost too.
  EXPECT_GT(strict_probe(m, {box_hull(V(3, -0.2, 0.5), V(6, 0.2, 1.5))}).opening.lost, 0);
}

// A flat hull has no inside: it loses nothing, whatever crosses it.
TEST(StrictProbe, AFlatHullLosesNothing) {
  Mesh m;
  add_quad_facing(m, V(0, 0, 0), V(2, 0, 0), V(2, 0, 2), V(0, 0, 2), kUpward);
  FlatPolygon square;
  square.corners = {V(0, 1, 0), V(0, 1, 2), V(2, 1, 2), V(2, 1, 0)}; // counter-clockwise seen from above
  square.corner_vertices = {-1, -1, -1, -1};
  square.plane = {kUpward, 1.0};
  square.sides = polygon_side_planes(square.corners, kUpward);
  const ProbeReport r = strict_probe(m, {bvh::make_runtime_hull(flat_polytope(square, true), 0)});
  EXPECT_EQ(r.front.lost, 0);
}

// Cut from Red Eclipse's depot (its coordinates and tolerance): a rail's
// top (y = 69, facing up) ends on the side (z = -6) of a closed post, so its
// open edge's rays run into the post and end on the back of its far side
// (z = -8): enclosed, and the decomposer filled the post with a wedge. A
// second rail leaves the post's far corner at 45 degrees; its side's
// 11-degree tip at (-435, 69, -8) lies 0.06-0.15 off those rays, beyond the
// rail by far more than tol, yet within tol of both of the tip's edges
// pushed out by tol. Counted as a hit there (the triangle baseline did not
// keep to the face's grown box, as the decomposer's rays do), that front
// ended the rays before the post's back: the audit called them open and
// the wedge lost space (6 rays on depot).
TEST(StrictProbe, ARayPassingASharpTipByMoreThanTolDoesNotMeetIt) {
  const double tol = 0.0210516;
  Mesh m;
  test::add_triangle(m, V(-434, 69, -6), V(-435, 69, -6), V(-435, 69, 0));                            // the rail's top
  add_quad_facing(m, V(-435, 64, -6), V(-434, 64, -6), V(-434, 72, -6), V(-435, 72, -6), V(0, 0, 1)); // post, near
  test::add_triangle(m, V(-435, 69, -8), V(-440, 69, -13), V(-440, 68, -13));                         // the tip
  const Mesh open = m;
  add_quad_facing(m, V(-435, 64, -8), V(-434, 64, -8), V(-434, 72, -8), V(-435, 72, -8), V(0, 0, -1)); // post, far
  ConvexHullBuilder builder;
  const Result<ConvexPolytope> wedge = builder.build(
      {V(-434, 72, -8), V(-435, 72, -6), V(-435, 64, -6), V(-434, 64, -8), V(-434, 64, -6), V(-434, 72, -6)});
  ASSERT_TRUE(wedge.ok()) << wedge.status().message();
  const std::vector<bvh::RuntimeHull> hulls = {bvh::make_runtime_hull(wedge.value(), 0)};
  ProbeOptions fine;
  fine.resolution = 0.01; // rays every 0.01 along the rail's edge, through the tip's reach
  const ProbeReport enclosed = strict_probe(m, hulls, fine, tol);
  EXPECT_EQ(enclosed.opening.lost, 0) << "deepest " << enclosed.opening.deepest.depth << " at x "
                                      << enclosed.opening.deepest.point.x();
  EXPECT_EQ(enclosed.front.lost, 0);
  EXPECT_GT(enclosed.opening.enclosed, 0);
  // Without the post's far side the same rays escape, and the wedge takes them.
  const ProbeReport escaping = strict_probe(open, hulls, fine, tol);
  EXPECT_GT(escaping.opening.lost, 0);
  EXPECT_EQ(escaping.opening.deepest.hull, 0);
}

} // namespace
} // namespace hullcover::validate

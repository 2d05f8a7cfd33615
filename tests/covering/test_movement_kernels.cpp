// The movement covering's kernels (lib/covering/src/movement/), each
// against the geometry it is meant to see: the uncovered boundary of a
// hull, the reach grid's cells, and a hull's proof.

#include "movement_scene.h"

#include "movement/movement_validity.h"
#include "movement/reach_grid.h"
#include "movement/scene_clearance.h"
#include "movement/uncovered_boundary.h"
#include "movement/within_slop.h"

#include "hullcover/covering/convex_hull_3d.h"
#include "hullcover/geometry/planar_hull.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace hullcover::detail {
namespace {

using V = Eigen::Vector3d;

constexpr double kTol = 1e-6;

ConvexPolytope unit_cube() {
  ConvexHullBuilder builder;
  std::vector<V> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  return builder.build(corners).value();
}

TEST(UncoveredBoundary, ACubeOnItsOwnFacesHasNoneAndLosesOneSideWithThatFace) {
  Mesh mesh;
  test::add_level_box(mesh, V(0, 0, 0), V(1, 1, 1));
  const ConvexPolytope cube = unit_cube();
  UncoveredBoundary boundary;
  uncovered_boundary(SceneClearance(mesh), cube, false, {}, kTol, boundary);
  EXPECT_TRUE(boundary.pieces.empty());
  EXPECT_TRUE(boundary.segments.empty());
  // Without the top's two triangles (add_level_box's +y quad), the top is
  // uncovered: one square, four sides on the cube's edges.
  Mesh open = mesh;
  open.triangles.erase(open.triangles.begin() + 6, open.triangles.begin() + 8);
  uncovered_boundary(SceneClearance(open), cube, false, {}, kTol, boundary);
  double area = 0.0;
  for (const BoundaryPiece& piece : boundary.pieces) {
    EXPECT_NEAR(piece.normal.y(), 1.0, 1e-12);
    for (size_t i = 1; i + 1 < piece.corners.size(); ++i)
      area += 0.5 * (piece.corners[i] - piece.corners[0]).cross(piece.corners[i + 1] - piece.corners[0]).norm();
  }
  EXPECT_NEAR(area, 1.0, 1e-9);
  double length = 0.0;
  for (const BoundarySegment& s : boundary.segments) length += (s.b - s.a).norm();
  EXPECT_NEAR(length, 4.0, 1e-9);
  // A known hull holding the top (the cube itself) leaves nothing to prove.
  boundary.clear();
  uncovered_boundary(SceneClearance(open), cube, false, {&cube}, kTol, boundary);
  EXPECT_TRUE(boundary.pieces.empty());
}

// A facet cut by many triangles that do not tile it splits into ever more
// slivers (on pandora's floors, past 23 GB): past kMostUncoveredPieces the
// boundary is given up and the hull's proof is undecided.
TEST(UncoveredBoundary, AFacetCutIntoTooManyPiecesIsGivenUpAndItsHullIsUndecided) {
  Mesh specks;
  constexpr int kSide = 80; // 6,400 small triangles on the top of the cube, gaps between them
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      const double x = (i + 0.2) / kSide, z = (j + 0.2) / kSide, d = 0.5 / kSide;
      const int base = static_cast<int>(specks.positions.size());
      specks.positions.insert(specks.positions.end(), {V(x, 1, z), V(x, 1, z + d), V(x + d, 1, z)});
      specks.triangles.emplace_back(base, base + 1, base + 2);
    }
  const SceneClearance clearance(specks);
  const ConvexPolytope cube = unit_cube();
  UncoveredBoundary boundary;
  uncovered_boundary(clearance, cube, false, {}, kTol, boundary);
  EXPECT_TRUE(boundary.overflow);
  EXPECT_LE(boundary.pieces.size(), kMostUncoveredPieces);
  const AgentShape agent = test::level_agent(AgentReach::fly);
  const ReachGrid grid = build_reach_grid(specks, clearance, agent, {V(0.5, 3, 0.5)}, true, 1).value();
  const MovementContext context{specks, clearance, grid, agent, kTol};
  EXPECT_EQ(check_movement_hull(context, cube, false, {}, boundary), MovementVerdict::undecided);
}

TEST(ReachGrid, AWalkerReachesTheFloorAroundACrateButNotItsCavityOrTheSkyAboveItsHead) {
  const test::MovementLevel level = test::movement_level();
  const SceneClearance clearance(level.mesh);
  const AgentShape agent = test::level_agent();
  const Result<ReachGrid> grid = build_reach_grid(level.mesh, clearance, agent, {level.spawn}, true, 1);
  ASSERT_TRUE(grid.ok()) << grid.status().message();
  const ReachGrid& g = grid.value();
  EXPECT_TRUE(g.reachable_at(level.spawn));
  EXPECT_TRUE(g.reachable_at(V(6, 1.0, 2)));   // on the floor, beside the crate
  EXPECT_FALSE(g.reachable_at(level.in_void)); // the crate's sealed cavity
  EXPECT_FALSE(g.reachable_at(V(6, 3.0, 2)));  // above a walker's head
  EXPECT_FALSE(g.reachable_at(V(9, 3.6, 9)));  // on the balcony, out of reach
  // A flyer from the same spawn reaches both.
  const Result<ReachGrid> flying =
      build_reach_grid(level.mesh, clearance, test::level_agent(AgentReach::fly), {level.spawn}, true, 1);
  ASSERT_TRUE(flying.ok());
  EXPECT_TRUE(flying.value().reachable_at(V(6, 3.0, 2)));
  EXPECT_TRUE(flying.value().reachable_at(V(9, 3.6, 9)));
  EXPECT_FALSE(flying.value().reachable_at(level.in_void));
}

// The grid's box query against the cells themselves: a box meets a
// reachable cell exactly when some cell whose closed extent it meets (by
// floor of each coordinate) is reachable; an empty box meets none, and a
// box leaving the grid may reach. Points ask the cell that holds them.
TEST(ReachGrid, ABoxMeetsAReachableCellExactlyWhenOneOfItsCellsIs) {
  const test::MovementLevel level = test::movement_level();
  const SceneClearance clearance(level.mesh);
  const ReachGrid grid = build_reach_grid(level.mesh, clearance, test::level_agent(), {level.spawn}, true, 1).value();
  std::mt19937 random(20261206);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const V extent = grid.dims.cast<double>() * grid.cell;
  int reached = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Aabb box;
    for (int k = 0; k < 2; ++k)
      box.extend(grid.origin + V(unit(random), unit(random), unit(random)).cwiseProduct(extent) * 0.999);
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = static_cast<int>(std::floor((box.min[a] - grid.origin[a]) / grid.cell));
      hi[a] = static_cast<int>(std::floor((box.max[a] - grid.origin[a]) / grid.cell));
    }
    bool any = false;
    for (int k = lo[2]; k <= hi[2] && !any; ++k)
      for (int j = lo[1]; j <= hi[1] && !any; ++j)
        for (int i = lo[0]; i <= hi[0] && !any; ++i) any = grid.reachable(i, j, k);
    ASSERT_EQ(grid.any_reachable(box), any) << "trial " << trial;
    reached += any;
    const V p = box.min;
    EXPECT_EQ(grid.reachable_at(p), grid.reachable(lo[0], lo[1], lo[2]));
  }
  EXPECT_GT(reached, 100); // the boxes found reachable cells and empty space alike
  EXPECT_LT(reached, 1900);
  Aabb empty;
  empty.min = level.spawn;
  empty.max = level.spawn - V(grid.cell, 0.0, 0.0);
  EXPECT_FALSE(grid.any_reachable(empty));
  Aabb leaving;
  leaving.min = grid.origin - V::Constant(grid.cell);
  leaving.max = grid.origin;
  EXPECT_TRUE(grid.any_reachable(leaving));
  EXPECT_TRUE(grid.reachable_at(grid.origin - V::Constant(grid.cell)));
}

// Regressions: the grid once ended r and a cell above the scene, so a
// walker on the highest face had no headroom there and its seed was
// refused; and a flying seed beyond the grid started the flood nowhere.
TEST(ReachGrid, AWalkerStandsOnTheHighestFaceAndAFlyerFromTheSkyReachesTheScene) {
  Mesh block;
  test::add_level_box(block, V(0, 0, 0), V(4, 1, 4));
  const SceneClearance clearance(block);
  const Result<ReachGrid> walking = build_reach_grid(block, clearance, test::level_agent(), {V(2, 1.5, 2)}, true, 1);
  ASSERT_TRUE(walking.ok()) << walking.status().message();
  EXPECT_TRUE(walking.value().reachable_at(V(2, 2.5, 2))); // a walker's head, 1.5 above the top
  const Result<ReachGrid> flying =
      build_reach_grid(block, clearance, test::level_agent(AgentReach::fly), {V(2, 100, 2)}, true, 1);
  ASSERT_TRUE(flying.ok()) << flying.status().message();
  EXPECT_TRUE(flying.value().reachable_at(V(2, 1.5, 2)));
  EXPECT_TRUE(flying.value().reachable_at(V(-0.5, 0.5, 2))); // beside the block
  const Result<ReachGrid> refused = build_reach_grid(block, clearance, test::level_agent(), {V(2, 100, 2)}, true, 1);
  EXPECT_FALSE(refused.ok());
}

// A walker on a hillside stands above it: the standing cells of a column
// start at the lowest point of the face near it, not at the face's lowest
// point, so no walker reaches the space under the slope round its side
// edges (where every hull below a hillside would be refused).
TEST(ReachGrid, AWalkerOnAHillsideStaysAboveIt) {
  const double slope = std::tan(40.0 * M_PI / 180.0);
  // Up +y, and the same hillside upside down with up -y.
  for (double up : {1.0, -1.0}) {
    SCOPED_TRACE(up);
    const V flip(1, up, 1);
    Mesh hillside;
    for (const V& p : {V(0, 0, 0), V(6, 6 * slope, 0), V(6, 6 * slope, 6), V(0, 0, 6)})
      hillside.positions.push_back(p.cwiseProduct(flip));
    hillside.triangles = {Eigen::Vector3i(0, 2, 1), Eigen::Vector3i(0, 3, 2)};
    if (up < 0)
      for (Eigen::Vector3i& t : hillside.triangles) std::swap(t[1], t[2]);
    AgentShape agent = test::level_agent();
    agent.up_sign = up;
    const SceneClearance clearance(hillside);
    const V above = V(3, 3 * slope + 0.5, 3).cwiseProduct(flip), under = V(3, 3 * slope - 1.5, 3).cwiseProduct(flip);
    ASSERT_GE(clearance.nearest(under, 1.0).distance, 1.0);
    const Result<ReachGrid> grid = build_reach_grid(hillside, clearance, agent, {above}, true, 1);
    ASSERT_TRUE(grid.ok()) << grid.status().message();
    EXPECT_TRUE(grid.value().reachable_at(above));
    EXPECT_FALSE(grid.value().reachable_at(under));
    EXPECT_FALSE(grid.value().reachable_at(V(1, slope - 1.0, 1).cwiseProduct(flip)));
  }
}

// Two copies of the level 3 km apart, as the maps of a world: the grid
// spans billions of cells (far past what a cell each could hold) but keeps
// a byte a cell only near surfaces while it is built, and walkers and
// flyers reach what they reach in each copy alone; the flyer crosses the
// empty sky between them, block by block.
TEST(ReachGrid, TwoLevelsFarApartEachReachWhatTheyReachAlone) {
  const test::MovementLevel level = test::movement_level();
  const V apart(3000, 0, 3000);
  const Mesh world = test::with_a_copy(level.mesh, apart);
  const SceneClearance clearance(world);

  const Result<ReachGrid> walking =
      build_reach_grid(world, clearance, test::level_agent(), {level.spawn, level.spawn + apart}, true, 2);
  ASSERT_TRUE(walking.ok()) << walking.status().message();
  const ReachGrid& grid = walking.value();
  EXPECT_GT(grid.cell_count(), 1LL << 32);
  EXPECT_LT(grid.cells_held(), grid.cell_count() / 10000);
  EXPECT_EQ(grid.seeds_used, 2);
  for (const V& shift : {V(0, 0, 0), apart}) {
    EXPECT_TRUE(grid.reachable_at(level.spawn + shift));
    EXPECT_TRUE(grid.reachable_at(V(6, 1.0, 2) + shift));
    EXPECT_FALSE(grid.reachable_at(level.in_void + shift));
    EXPECT_FALSE(grid.reachable_at(V(6, 3.0, 2) + shift));
    EXPECT_FALSE(grid.reachable_at(level.on_balcony + shift));
  }
  EXPECT_FALSE(grid.reachable_at(0.5 * apart + V(0, 1, 0))); // no floor halfway

  // A flyer from the first copy alone reaches the second copy's balcony.
  const Result<ReachGrid> flying =
      build_reach_grid(world, clearance, test::level_agent(AgentReach::fly), {level.spawn}, true, 2);
  ASSERT_TRUE(flying.ok()) << flying.status().message();
  EXPECT_TRUE(flying.value().reachable_at(level.on_balcony + apart + V(0, 0.3, 0)));
  EXPECT_TRUE(flying.value().reachable_at(0.5 * apart + V(0, 1, 0)));
  EXPECT_FALSE(flying.value().reachable_at(level.in_void + apart));
  EXPECT_LT(flying.value().cells_held(), flying.value().cell_count() / 10000);
}

// A scene wider than the grid's coordinates hold is refused with a message,
// never allocated.
TEST(ReachGrid, ASceneTooWideForTheGridIsRefused) {
  Mesh far;
  test::add_level_box(far, V(0, 0, 0), V(1, 1, 1));
  test::add_level_box(far, V(1e6, 0, 0), V(1e6 + 1, 1, 1));
  const SceneClearance clearance(far);
  const Result<ReachGrid> grid = build_reach_grid(far, clearance, test::level_agent(), {}, false, 1);
  ASSERT_FALSE(grid.ok());
  EXPECT_EQ(grid.status().code(), StatusCode::limit_exceeded);
  EXPECT_NE(grid.status().message().find("along an axis"), std::string::npos) << grid.status().message();
}

TEST(MovementProof, RefusesAHullAcrossTheFloorsCornerAndAcceptsTheCrate) {
  const test::MovementLevel level = test::movement_level();
  const SceneClearance clearance(level.mesh);
  const AgentShape agent = test::level_agent();
  const ReachGrid grid = build_reach_grid(level.mesh, clearance, agent, {level.spawn}, true, 1).value();
  const MovementContext context{level.mesh, clearance, grid, agent, kTol};
  ConvexHullBuilder builder;
  UncoveredBoundary boundary;
  // The crate's outside: every facet on its faces.
  std::vector<V> crate;
  for (int i = 0; i < 8; ++i) crate.emplace_back((i & 1) ? 10 : 8, (i & 2) ? 1.5 : 0, (i & 4) ? 3 : 1);
  EXPECT_EQ(check_movement_hull(context, builder.build(crate).value(), false, {}, boundary), MovementVerdict::valid);
  // The crate's side and the floor in front of it: the hull's slanted top
  // runs through the space a walker stands in.
  std::vector<V> wedge = {V(8, 0, 1), V(8, 1.5, 1), V(8, 0, 3), V(8, 1.5, 3), V(6, 0, 1), V(6, 0, 3)};
  EXPECT_EQ(check_movement_hull(context, builder.build(wedge).value(), false, {}, boundary),
            MovementVerdict::centre_near_boundary);
}

// A square hovering exactly E over a floor, under the sky: a flyer resting
// on the floor under it is exactly r - E from it, the promise's limit. The
// proof counts a centre within tol of its region as in it, and clears a box
// only where every point is nearer than r - tol / 8 to a triangle, so a box
// narrower than the gap between the two is always decided: the square is
// refused by a witness at once. (The proof once searched such a region down
// to its smallest box and gave up, undecided.) A little higher, the square
// is refused as well; a little lower (within E - tol of the floor), it is
// held by the floor and valid.
TEST(MovementProof, ASquareExactlyTheSlopOverTheFloorIsDecidedNotGivenUp) {
  Mesh floor;
  floor.positions = {V(-3, 0, -3), V(3, 0, -3), V(3, 0, 3), V(-3, 0, 3)};
  floor.triangles = {Eigen::Vector3i(0, 2, 1), Eigen::Vector3i(0, 3, 2)};
  const SceneClearance clearance(floor);
  const AgentShape agent = test::level_agent(AgentReach::fly);
  const ReachGrid grid = build_reach_grid(floor, clearance, agent, {V(0, 1, 0)}, true, 1).value();
  const MovementContext context{floor, clearance, grid, agent, kTol};
  const auto square = [&](double y) {
    const std::vector<V> corners = {V(-0.5, y, -0.5), V(0.5, y, -0.5), V(0.5, y, 0.5), V(-0.5, y, 0.5)};
    return flat_polytope(make_flat_polygon(corners, {0, 1, 2, 3}, V(0, 1, 0), kTol), true);
  };
  UncoveredBoundary boundary;
  EXPECT_EQ(check_movement_hull(context, square(agent.slop), true, {}, boundary),
            MovementVerdict::centre_near_boundary);
  EXPECT_EQ(check_movement_hull(context, square(agent.slop + 0.01), true, {}, boundary),
            MovementVerdict::centre_near_boundary);
  EXPECT_EQ(check_movement_hull(context, square(agent.slop - 2 * kTol), true, {}, boundary), MovementVerdict::valid);
}

} // namespace
} // namespace hullcover::detail

namespace hullcover::detail {
namespace {

// A roof ridge along z: two triangles falling away from x = 0 with slope
// 0.1. A square just under the ridge, 0.01 below it at x = 0 and 0.01 above
// the slopes at x = +-0.2, lies within the slop (0.02) of the two triangles
// but not of either alone (its far corners are 0.03 from the other's
// plane): the plane between them parts it into halves one triangle each
// holds. The same square 0.03 below the ridge is not held: its middle is
// farther than the slop from both.
TEST(MovementProof, APieceOverACreaseIsHeldByTheTwoTrianglesBesideIt) {
  Mesh ridge;
  ridge.positions = {V(0, 0, -1), V(0, 0, 1), V(-1, -0.1, 0), V(1, -0.1, 0)};
  ridge.triangles = {Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(1, 0, 3)};
  const SceneClearance clearance(ridge);
  const AgentShape agent = test::level_agent(AgentReach::fly);
  const ReachGrid grid = build_reach_grid(ridge, clearance, agent, {V(0, 1, 0)}, true, 1).value();
  const MovementContext context{ridge, clearance, grid, agent, kTol};
  const auto square = [](double y) {
    return std::vector<V>{V(-0.2, y, -0.2), V(0.2, y, -0.2), V(0.2, y, 0.2), V(-0.2, y, 0.2)};
  };
  std::vector<int> near;
  for (int face = 0; face < 2; ++face) {
    bool all = true;
    for (const V& corner : square(-0.01)) all = all && clearance.to_face(corner, face) <= agent.slop - kTol;
    EXPECT_FALSE(all) << "one triangle alone holds the square: the case tests nothing";
  }
  EXPECT_TRUE(held_within_slop(context, square(-0.01), near));
  EXPECT_FALSE(held_within_slop(context, square(-0.03), near));
  // Its side across the ridge, likewise.
  EXPECT_TRUE(segment_within_slop(context, {V(-0.2, -0.01, 0), V(0.2, -0.01, 0)}, near));
  EXPECT_FALSE(segment_within_slop(context, {V(-0.2, -0.03, 0), V(0.2, -0.03, 0)}, near));
}

} // namespace
} // namespace hullcover::detail

namespace hullcover::detail {
namespace {

// The proofs' nearest triangle from a short list gathered over a region
// (nearest_among) is the tree's answer whenever the list holds every
// triangle within the limit: here 400 random triangles, 2,000 points, with
// and without a hint. With the nearest left out of the list, the answer
// differs (so the comparison can fail).
TEST(SceneClearance, TheNearestFromAListOfTheTrianglesInReachIsTheTreesAnswer) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> across(0.0, 10.0), side(-0.5, 0.5);
  Mesh soup;
  for (int t = 0; t < 400; ++t) {
    const V corner(across(random), across(random), across(random));
    const int base = static_cast<int>(soup.positions.size());
    soup.positions.insert(soup.positions.end(), {corner, corner + V(side(random), side(random), side(random)),
                                                 corner + V(side(random), side(random), side(random))});
    soup.triangles.emplace_back(base, base + 1, base + 2);
  }
  const SceneClearance clearance(soup);
  const double limit = 1.5;
  int found = 0, with_nearest = 0, missed = 0;
  std::vector<int> listed;
  for (int i = 0; i < 2000; ++i) {
    const V p(across(random), across(random), across(random));
    listed.clear();
    clearance.faces_meeting(grown(Aabb{p, p}, limit), listed);
    for (int hint : {-1, i % 400}) {
      const NearestFace tree = clearance.nearest(p, limit, hint);
      const NearestFace list = clearance.nearest_among(listed, p, limit, hint);
      EXPECT_EQ(list.face, tree.face);
      EXPECT_EQ(list.distance, tree.distance);
      found += tree.face >= 0 && tree.face != hint;
    }
    const NearestFace tree = clearance.nearest(p, limit, -1);
    if (tree.face < 0) continue;
    ++with_nearest;
    listed.erase(std::remove(listed.begin(), listed.end(), tree.face), listed.end());
    missed += clearance.nearest_among(listed, p, limit, -1).face != tree.face;
  }
  EXPECT_GT(found, 500);
  // Every point whose nearest was left out of the list gets another answer.
  EXPECT_GT(with_nearest, 250);
  EXPECT_EQ(missed, with_nearest);
}

} // namespace
} // namespace hullcover::detail

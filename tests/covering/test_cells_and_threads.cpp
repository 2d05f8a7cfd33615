// Worlds: islands and the tolerance that follows them, cells, the seam pass
// and threads, on scenes built in code (the shared scenes:
// tests/scenes/test_scene_worlds.cpp).

#include "covering_fixture.h"

#include "hullcover/covering/merge_cells.h"
#include "hullcover/mesh/mesh_islands.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace hullcover {
namespace {

using V = Eigen::Vector3d;

// `mesh` followed by a copy of it moved by `offset`.
Mesh with_moved_copy(const Mesh& mesh, const Eigen::Vector3d& offset) {
  Mesh out = mesh;
  const int base = static_cast<int>(out.positions.size());
  for (const Eigen::Vector3d& p : mesh.positions) out.positions.push_back(p + offset);
  for (const Eigen::Vector3i& t : mesh.triangles) out.triangles.push_back(t + Eigen::Vector3i::Constant(base));
  out.material_ids.insert(out.material_ids.end(), mesh.material_ids.begin(), mesh.material_ids.end());
  return out;
}

// A flat floor of 2 x n x n triangles over [0, n]^2 at height 0, facing up.
Mesh flat_floor(int n) {
  Mesh m;
  std::vector<double> ticks;
  for (int i = 0; i <= n; ++i) ticks.push_back(i);
  add_height_field(m, ticks, ticks, [](double, double) { return 0.0; });
  return m;
}

TEST(MeshIslands, FarApartCopiesAreIslandsOfTheirOwn) {
  const Mesh building = demo_building();
  const MeshIslands one = find_mesh_islands(building);
  // 1024 is a power of two: the copy's coordinates are the original's to the bit
  // but for the move, so both islands have the same box diagonal.
  const MeshIslands two = find_mesh_islands(with_moved_copy(building, {1024.0, 0.0, 0.0}));
  ASSERT_EQ(two.boxes.size(), 2 * one.boxes.size());
  EXPECT_DOUBLE_EQ(two.largest_diagonal(), one.largest_diagonal());
  // Numbered by their lowest face: the original's islands come first.
  for (size_t f = 0; f < building.triangles.size(); ++f)
    EXPECT_LT(two.island_of_face[f], static_cast<int>(one.boxes.size()));
}

TEST(MeshIslands, PiecesWithinATenthOfAPercentOfEachOtherAreOneIsland) {
  const Mesh floor = flat_floor(4); // diagonal sqrt(32)
  // A gap of 0.1% of each floor's diagonal, added up, minus a little:
  // within reach (a crack between kit pieces).
  const double near_gap = 4.0 + 0.0019 * std::sqrt(32.0);
  EXPECT_EQ(find_mesh_islands(with_moved_copy(floor, {near_gap, 0.0, 0.0})).boxes.size(), 1u);
  // A gap of 0.5% apart: two maps laid side by side, two islands.
  const double far_gap = 4.0 + 0.005 * std::sqrt(32.0);
  EXPECT_EQ(find_mesh_islands(with_moved_copy(floor, {far_gap, 0.0, 0.0})).boxes.size(), 2u);
}

TEST(Tolerance, AMapKeepsItsToleranceInAWorld) {
  const Mesh building = demo_building();
  Mesh world = building;
  for (int i = 1; i <= 5; ++i) world = with_moved_copy(world, {2048.0 * i, 0.0, 1024.0 * i});
  const Result<PreparedMesh> alone = prepare_mesh(building, std::nullopt);
  const Result<PreparedMesh> in_world = prepare_mesh(world, std::nullopt);
  ASSERT_TRUE(alone.ok() && in_world.ok());
  EXPECT_DOUBLE_EQ(in_world.value().tolerance.length, alone.value().tolerance.length);
  EXPECT_GT(in_world.value().tolerance.diagonal, 100.0 * alone.value().tolerance.diagonal);
}

TEST(Decompose, FarApartCopiesGiveEachCopyTheHullsOfOne) {
  const Mesh building = demo_building();
  const auto one = test::decompose_and_check(building);
  const auto two = test::decompose_and_check(with_moved_copy(building, {1024.0, 0.0, 0.0}));
  ASSERT_TRUE(one && two);
  ASSERT_EQ(two->covering.hulls.size(), 2 * one->covering.hulls.size());
  // The copy's hulls are the original's, moved: compare their faces.
  const int faces = static_cast<int>(building.triangles.size());
  std::set<std::vector<int>> original, copy;
  for (const CoveringHull& h : two->covering.hulls) {
    std::vector<int> ids = h.faces;
    const bool moved = ids.front() >= faces;
    if (moved)
      for (int& f : ids) f -= faces;
    (moved ? copy : original).insert(ids);
  }
  EXPECT_EQ(original, copy);
}

TEST(Tolerance, ASmallObjectBesideALargeMapKeepsItsOwnPrecision) {
  // The building at 1/8 scale (exact: a power of two) beside the full one:
  // the tolerance follows the smaller, never the larger, and the small one
  // decomposes to the hulls it has alone, face for face.
  const Mesh building = demo_building();
  Mesh small = building;
  for (Eigen::Vector3d& p : small.positions) p *= 0.125;
  Mesh world = small;
  const int small_faces = static_cast<int>(small.triangles.size());
  Mesh large = building;
  for (Eigen::Vector3d& p : large.positions) p += Eigen::Vector3d(512.0, 0.0, 0.0);
  const int base = static_cast<int>(world.positions.size());
  world.positions.insert(world.positions.end(), large.positions.begin(), large.positions.end());
  for (const Eigen::Vector3i& t : large.triangles) world.triangles.push_back(t + Eigen::Vector3i::Constant(base));
  world.material_ids.insert(world.material_ids.end(), large.material_ids.begin(), large.material_ids.end());

  const Result<PreparedMesh> alone = prepare_mesh(small, std::nullopt);
  const Result<PreparedMesh> large_alone = prepare_mesh(building, std::nullopt);
  const Result<PreparedMesh> in_world = prepare_mesh(world, std::nullopt);
  ASSERT_TRUE(alone.ok() && large_alone.ok() && in_world.ok());
  EXPECT_DOUBLE_EQ(in_world.value().tolerance.length, alone.value().tolerance.length);
  EXPECT_LT(in_world.value().tolerance.length, large_alone.value().tolerance.length);

  const auto d_alone = test::decompose_and_check(small);
  const auto d_world = test::decompose_and_check(world);
  ASSERT_TRUE(d_alone && d_world);
  std::set<std::vector<int>> hulls_alone, hulls_in_world;
  for (const CoveringHull& h : d_alone->covering.hulls) hulls_alone.insert(h.faces);
  for (const CoveringHull& h : d_world->covering.hulls)
    if (h.faces.front() < small_faces) hulls_in_world.insert(h.faces);
  EXPECT_EQ(hulls_in_world, hulls_alone);

  // And the large one keeps ITS tolerance (each island has its own) and
  // its hulls, face for face; the world audits clean (decompose_and_check's
  // independent re-check judges each hull at the tolerance of its place).
  const PreparedMesh& w = in_world.value();
  for (int f = 0; f < small_faces; ++f) {
    ASSERT_DOUBLE_EQ(w.face_tolerance(f), alone.value().face_tolerance(f)) << f;
    ASSERT_DOUBLE_EQ(w.face_tolerance(small_faces + f), large_alone.value().face_tolerance(f)) << f;
  }
  EXPECT_GT(w.face_tolerance(small_faces), w.face_tolerance(0));
  const auto d_large = test::decompose_and_check(building);
  ASSERT_TRUE(d_large);
  std::set<std::vector<int>> large_alone_hulls, large_in_world;
  for (const CoveringHull& h : d_large->covering.hulls) large_alone_hulls.insert(h.faces);
  for (const CoveringHull& h : d_world->covering.hulls)
    if (h.faces.front() >= small_faces) {
      std::vector<int> faces = h.faces;
      for (int& f : faces) f -= small_faces;
      large_in_world.insert(faces);
    }
  EXPECT_EQ(large_in_world, large_alone_hulls);
}

// A pillar: four walls facing out, open at top and bottom (its inside is
// behind every wall: enclosed, a hull may fill it).
Mesh pillar() {
  Mesh m;
  test::add_quad_facing(m, V(0, 0, 0), V(1, 0, 0), V(1, 2, 0), V(0, 2, 0), V(0, 0, -1));
  test::add_quad_facing(m, V(0, 0, 1), V(1, 0, 1), V(1, 2, 1), V(0, 2, 1), V(0, 0, 1));
  test::add_quad_facing(m, V(0, 0, 0), V(0, 0, 1), V(0, 2, 1), V(0, 2, 0), V(-1, 0, 0));
  test::add_quad_facing(m, V(1, 0, 0), V(1, 0, 1), V(1, 2, 1), V(1, 2, 0), V(1, 0, 0));
  return m;
}

TEST(Decompose, AnotherIslandsRaysStillKeepTheirSpace) {
  // Alone, the pillar is one hull filling its inside. With a ceiling far
  // above it (another island) facing down, the ceiling's front rays fall
  // through the pillar and out of its open bottom: its inside is free space,
  // which no hull may take, though the ray comes from another island.
  const Eigen::Vector3d inside(0.5, 1.0, 0.5);
  const auto alone = test::decompose_and_check(pillar());
  ASSERT_TRUE(alone);
  EXPECT_EQ(alone->covering.hulls.size(), 1u);
  EXPECT_TRUE(test::point_inside_covering(alone->covering, inside, alone->tol()));

  Mesh world = pillar();
  test::add_quad_facing(world, V(-1, 40, -1), V(2, 40, -1), V(2, 40, 2), V(-1, 40, 2), V(0, -1, 0));
  ASSERT_EQ(find_mesh_islands(world).boxes.size(), 2u);
  const auto under_ceiling = test::decompose_and_check(world);
  ASSERT_TRUE(under_ceiling);
  EXPECT_FALSE(test::point_inside_covering(under_ceiling->covering, inside, under_ceiling->tol()));
}

TEST(MergeCells, EveryFaceIsInOneCellAndSmallIslandsAreOneCell) {
  const Result<PreparedMesh> p = prepare_mesh(flat_floor(8), std::nullopt);
  ASSERT_TRUE(p.ok());
  const MeshIslands islands = find_mesh_islands(p.value().mesh);
  const CellLayout automatic = lay_out_cells(view_of(p.value()), view_of(islands), std::nullopt);
  EXPECT_EQ(automatic.faces_of_cell.size(), 1u); // 128 faces: far below kFacesPerAutomaticCell
  const CellLayout cells = lay_out_cells(view_of(p.value()), view_of(islands), 2.0);
  EXPECT_EQ(cells.faces_of_cell.size(), 16u); // a grid of side 2 centred on (4, 4) over [0, 8]^2
  std::vector<int> seen(p.value().mesh.triangles.size(), 0);
  for (size_t c = 0; c < cells.faces_of_cell.size(); ++c) {
    EXPECT_FALSE(cells.faces_of_cell[c].empty());
    for (size_t slot = 0; slot < cells.faces_of_cell[c].size(); ++slot) {
      const int f = cells.faces_of_cell[c][slot];
      ++seen[f];
      EXPECT_EQ(cells.cell_of_face[f], static_cast<int>(c));
      EXPECT_EQ(cells.slot_in_cell[f], static_cast<int>(slot));
    }
  }
  for (int count : seen) EXPECT_EQ(count, 1);
}

TEST(MergeCells, AQuarterTurnKeepsTheCells) {
  Mesh floor;
  add_height_field(floor, {0, 1, 2, 3, 4, 5, 6}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10},
                   [](double x, double z) { return 0.1 * x * z; });
  Mesh turned = floor;
  for (Eigen::Vector3d& v : turned.positions) v = Eigen::Vector3d(-v.z(), v.y(), v.x());
  const auto partition = [](const Mesh& m) {
    const Result<PreparedMesh> p = prepare_mesh(m, std::nullopt);
    const CellLayout cells = lay_out_cells(view_of(p.value()), view_of(find_mesh_islands(p.value().mesh)), 2.0);
    return std::set<std::vector<int>>(cells.faces_of_cell.begin(), cells.faces_of_cell.end());
  };
  EXPECT_EQ(partition(floor), partition(turned));
  EXPECT_GT(partition(floor).size(), 4u);
}

// A floor over [0, 64]^2, sparse (a tick every 4) but for 20,000 small
// triangles over [0, 4]^2: a dense cluster of detail in a sparse map;
// added after whatever `m` holds.
Mesh floor_with_a_dense_corner(Mesh m = {}) {
  std::vector<double> ticks;
  for (int i = 0; i < 100; ++i) ticks.push_back(0.04 * i);
  for (int i = 1; i <= 16; ++i) ticks.push_back(4.0 * i);
  add_height_field(m, ticks, ticks, [](double, double) { return 0.0; });
  return m;
}

TEST(MergeCells, ACrowdedCellIsCutIntoTheEightOfHalfItsSide) {
  const Mesh floor = floor_with_a_dense_corner();
  const Result<PreparedMesh> p = prepare_mesh(floor, std::nullopt);
  ASSERT_TRUE(p.ok());
  const MeshIslands islands = find_mesh_islands(p.value().mesh);
  ASSERT_EQ(islands.boxes.size(), 1u);
  const CellLayout automatic = lay_out_cells(view_of(p.value()), view_of(islands), std::nullopt);
  const double side = automatic.island_cell_size[0];
  ASSERT_GT(side, 0.0);
  // The grid alone, at the side the automatic layout chose, has a cell over
  // the bound: the dense corner's.
  const CellLayout grid = lay_out_cells(view_of(p.value()), view_of(islands), side);
  size_t largest = 0;
  for (const std::vector<int>& cell : grid.faces_of_cell) largest = std::max(largest, cell.size());
  ASSERT_GT(largest, static_cast<size_t>(kMostFacesPerAutomaticCell));
  EXPECT_GT(automatic.faces_of_cell.size(), grid.faces_of_cell.size());
  // No cell over the bound, every face in one cell, and each cell inside one
  // cell of the grid (halves nest in the cube they were cut from).
  std::vector<int> seen(floor.triangles.size(), 0);
  for (const std::vector<int>& cell : automatic.faces_of_cell) {
    EXPECT_LE(cell.size(), static_cast<size_t>(kMostFacesPerAutomaticCell));
    for (int f : cell) {
      ++seen[f];
      EXPECT_EQ(grid.cell_of_face[f], grid.cell_of_face[cell.front()]);
    }
  }
  for (int count : seen) EXPECT_EQ(count, 1);
  // Each cut cell says how often its cube was halved (the near-merge reach
  // halves with it), and its faces' centroids lie within a cube that small;
  // the sparse cells were not cut.
  ASSERT_EQ(automatic.cell_halvings.size(), automatic.faces_of_cell.size());
  int deepest = 0, uncut = 0;
  for (size_t c = 0; c < automatic.faces_of_cell.size(); ++c) {
    const int halvings = automatic.cell_halvings[c];
    deepest = std::max(deepest, halvings);
    Aabb centroids;
    for (int f : automatic.faces_of_cell[c]) {
      const Eigen::Vector3i& t = floor.triangles[f];
      centroids.extend((floor.positions[t[0]] + floor.positions[t[1]] + floor.positions[t[2]]) / 3.0);
    }
    EXPECT_LE((centroids.max - centroids.min).maxCoeff(), std::ldexp(side, -halvings)) << "cell " << c;
    uncut += halvings == 0;
  }
  EXPECT_GE(deepest, 2);
  EXPECT_GT(uncut, 0);
  for (int halvings : grid.cell_halvings) EXPECT_EQ(halvings, 0);
  // Cut alike when the map is turned a quarter about the up axis.
  Mesh turned = floor;
  for (Eigen::Vector3d& v : turned.positions) v = Eigen::Vector3d(-v.z(), v.y(), v.x());
  const Result<PreparedMesh> q = prepare_mesh(turned, std::nullopt);
  ASSERT_TRUE(q.ok());
  const CellLayout turned_cells =
      lay_out_cells(view_of(q.value()), view_of(find_mesh_islands(q.value().mesh)), std::nullopt);
  EXPECT_EQ(std::set<std::vector<int>>(automatic.faces_of_cell.begin(), automatic.faces_of_cell.end()),
            std::set<std::vector<int>>(turned_cells.faces_of_cell.begin(), turned_cells.faces_of_cell.end()));
  // A side the user gives is kept as it is: no cell is cut.
  EXPECT_EQ(lay_out_cells(view_of(p.value()), view_of(islands), side).faces_of_cell.size(), grid.faces_of_cell.size());
}

TEST(MergeCells, EachCellKeepsItsOwnHalvingsBesideAnIslandLeftWhole) {
  // A small floor far off, laid out first and kept as one cell, then the
  // dense floor: each cell of the dense floor must carry the halvings it has
  // alone (a regression: the whole island's cell once took no entry, and
  // every later cell read its predecessor's).
  Mesh small;
  add_height_field(small, {-20.0, -19.0, -18.0}, {-20.0, -19.0, -18.0}, [](double, double) { return 0.0; });
  const int offset = static_cast<int>(small.triangles.size());
  const Mesh both = floor_with_a_dense_corner(small);
  const auto layout_of = [](const Mesh& m) {
    const Result<PreparedMesh> p = prepare_mesh(m, std::nullopt);
    EXPECT_TRUE(p.ok());
    return lay_out_cells(view_of(p.value()), view_of(find_mesh_islands(p.value().mesh)), std::nullopt);
  };
  const CellLayout alone = layout_of(floor_with_a_dense_corner());
  const CellLayout beside = layout_of(both);
  ASSERT_EQ(beside.cell_halvings.size(), beside.faces_of_cell.size());
  std::set<std::pair<std::vector<int>, int>> cut_alone, cut_beside;
  for (size_t c = 0; c < alone.faces_of_cell.size(); ++c)
    cut_alone.insert({alone.faces_of_cell[c], alone.cell_halvings[c]});
  int whole_cells = 0;
  for (size_t c = 0; c < beside.faces_of_cell.size(); ++c) {
    std::vector<int> faces = beside.faces_of_cell[c];
    if (faces.front() < offset) {
      ++whole_cells;
      EXPECT_EQ(beside.cell_halvings[c], 0);
      continue;
    }
    for (int& f : faces) f -= offset;
    cut_beside.insert({faces, beside.cell_halvings[c]});
  }
  EXPECT_EQ(whole_cells, 1);
  EXPECT_EQ(cut_beside, cut_alone);
}

TEST(Decompose, TheSeamPassJoinsPatchesAcrossCellBorders) {
  // One flat floor: a single polygon, however it is cut into cells.
  DecomposeOptions o;
  o.cell_size = 2.0;
  const auto d = test::decompose_and_check(flat_floor(8), o);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->covering.statistics.cells, 16);
  EXPECT_EQ(d->covering.hulls.size(), 1u);
  EXPECT_EQ(d->covering.statistics.seam_merges, 15);
}

TEST(Decompose, SameCoveringForAnyThreadCount) {
  const Mesh building = demo_building();
  const Result<PreparedMesh> p = prepare_mesh(building, std::nullopt);
  ASSERT_TRUE(p.ok());
  DecomposeOptions o;
  o.cell_size = p.value().tolerance.local_extent / 6.0;
  std::string first;
  int cells = 0;
  for (int threads : {1, 2, 3, 8}) {
    o.threads = threads;
    const auto d = test::decompose_and_check(building, o);
    ASSERT_TRUE(d);
    cells = d->covering.statistics.cells;
    const std::string bytes = test::covering_obj_bytes(d->covering);
    if (first.empty()) first = bytes;
    EXPECT_EQ(bytes, first) << threads << " threads";
  }
  EXPECT_GT(cells, 8);
}

TEST(Decompose, RejectsACellSizeOrThreadCountOutOfRange) {
  Result<PreparedMesh> p = prepare_mesh(demo_building(), std::nullopt);
  ASSERT_TRUE(p.ok());
  for (double size : {-1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    DecomposeOptions o;
    o.cell_size = size;
    EXPECT_EQ(decompose(p.value(), o).status().code(), StatusCode::invalid_argument) << size;
  }
  DecomposeOptions o;
  o.threads = -1;
  EXPECT_EQ(decompose(p.value(), o).status().code(), StatusCode::invalid_argument);
}

} // namespace
} // namespace hullcover

// What an edit changed since the cell cache's last bake (scene_change.h):
// the patches it says no change can reach must hold, as a full re-check
// finds; a re-bake that trusts it is valid, and about as small as one that
// re-checks everything.

#include "covering_fixture.h"
#include "temp_dir.h"

#include "cells/cell_merging.h"
#include "cells/cell_result_bytes.h"
#include "cells/scene_change.h"

#include "hullcover/covering/cell_cache.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <random>

namespace hullcover {
namespace {

// A scene's stages and every cell merged, as a bake with a cache leaves them.
struct Bake {
  std::unique_ptr<PreparedMesh> prepared;
  std::unique_ptr<detail::DecompositionStages> stages;
  std::vector<std::string> cells;
  /// The snapshot a bake with a cache would leave of it (merged bakes only).
  std::string snapshot() const {
    std::vector<std::uint64_t> keys;
    for (int c = 0; c < static_cast<int>(cells.size()); ++c) keys.push_back(detail::cell_key(*stages, c));
    return detail::scene_snapshot_bytes(*stages, detail::face_hashes_of(*stages), keys, cells);
  }
  /// The change from `before` to this scene.
  detail::SceneChange change_since(const detail::SceneSnapshot& before) const {
    return detail::scene_change_since(*stages, detail::face_hashes_of(*stages), before);
  }
};

Bake bake(const Mesh& mesh, const DecomposeOptions& options, bool merge) {
  Bake b;
  b.prepared = std::make_unique<PreparedMesh>(prepare_mesh(mesh, std::nullopt).value());
  b.stages = detail::prepare_stages(view_of(*b.prepared), options).value();
  if (merge)
    for (int c = 0; c < static_cast<int>(b.stages->cells.faces_of_cell.size()); ++c)
      b.cells.push_back(detail::cell_result_bytes(*b.stages, c, detail::merge_cell(*b.stages, c, nullptr)));
  return b;
}

Mesh without_faces(const Mesh& mesh, const std::vector<int>& faces) {
  Mesh m = mesh;
  m.triangles.clear();
  m.material_ids.clear();
  for (int f = 0; f < static_cast<int>(mesh.triangles.size()); ++f)
    if (std::find(faces.begin(), faces.end(), f) == faces.end()) {
      m.triangles.push_back(mesh.triangles[f]);
      m.material_ids.push_back(mesh.material_ids[f]);
    }
  return m;
}

// Edits of the demo building: wall faces taken out (space a kept hull
// takes may open, far off), a triangle put in (it may poke into a hull), both.
std::vector<std::pair<Mesh, int>> edits_of(const Mesh& building) {
  std::vector<int> walls;
  for (int f = 0; f < static_cast<int>(building.triangles.size()); ++f)
    if (building.material_ids[f] == demo_wall) walls.push_back(f);
  std::vector<std::pair<Mesh, int>> edits;
  std::mt19937 rng(7);
  for (int e = 0; e < 8; ++e) {
    std::vector<int> gone;
    for (int k = 0; k < 2; ++k) gone.push_back(walls[std::uniform_int_distribution<size_t>(0, walls.size() - 1)(rng)]);
    if (gone[0] == gone[1]) gone.pop_back();
    edits.emplace_back(without_faces(building, gone), static_cast<int>(gone.size()));
  }
  std::uniform_real_distribution<double> x(-5.0, 5.0), y(0.0, 3.0), z(-4.0, 4.0);
  for (int e = 0; e < 3; ++e) {
    Mesh m = e == 2 ? edits.front().first : building;
    const Eigen::Vector3d a(x(rng), y(rng), z(rng));
    test::add_triangle(m, a, a + Eigen::Vector3d(0.7, 0.1, 0.0), a + Eigen::Vector3d(0.0, 0.3, 0.6));
    edits.emplace_back(std::move(m), e == 2 ? edits.front().second + 1 : 1);
  }
  return edits;
}

TEST(SceneChange, PatchesNoEditCanReachHoldAndKeepTheirHulls) {
  const Mesh building = demo_building();
  const DecomposeOptions o = test::options_with_small_cells(building);
  const Bake before = bake(building, o, true);
  Result<detail::SceneSnapshot> snapshot = detail::read_scene_snapshot(before.snapshot());
  ASSERT_TRUE(snapshot.ok()) << snapshot.status().message();
  // Its islands have tolerances of their own: hulls are checked in views of
  // several, and sweeps followed past their own reach.
  const std::vector<double>& views = before.stages->island_tolerance;
  EXPECT_LT(*std::min_element(views.begin(), views.end()), *std::max_element(views.begin(), views.end()));
  std::map<std::uint64_t, int> old_cell;
  for (int c = 0; c < static_cast<int>(before.cells.size()); ++c) old_cell[detail::cell_key(*before.stages, c)] = c;
  int untouched = 0, touched = 0, broken = 0;
  for (const auto& [mesh, changed_faces] : edits_of(building)) {
    const Bake after = bake(mesh, o, false);
    const detail::SceneChange change = after.change_since(snapshot.value());
    ASSERT_FALSE(change.everything);
    EXPECT_EQ(change.changed_faces, changed_faces);
    // Cells are found by key: an edit may split an island, and number its
    // cells anew.
    for (int c = 0; c < static_cast<int>(after.stages->cells.faces_of_cell.size()); ++c) {
      const auto old = old_cell.find(detail::cell_key(*after.stages, c));
      if (old == old_cell.end()) continue;
      const std::string& bytes = before.cells[old->second];
      Result<detail::CellResult> kept = detail::cell_result_from_bytes(*after.stages, c, bytes);
      ASSERT_TRUE(kept.ok()) << kept.status().message();
      for (size_t p = 0; p < kept.value().patches.size(); ++p) {
        const detail::Patch& patch = kept.value().patches[p];
        const bool reachable = detail::patch_may_be_touched(*after.stages, change, patch, kept.value().hulls[p]);
        std::string why;
        const bool holds = detail::cell_bytes_hold(
            *after.stages, c, bytes,
            [&](const detail::Patch& q, const detail::PatchHull&) { return q.faces == patch.faces; }, &why);
        (reachable ? touched : untouched) += 1;
        broken += !holds;
        if (!reachable) {
          EXPECT_TRUE(holds) << "cell " << c << " patch " << p << ", out of reach: " << why;
        }
      }
    }
  }
  // Not vacuous: most patches are out of reach, and the edits do break
  // some kept patches (all within reach).
  EXPECT_GT(untouched, touched);
  EXPECT_GT(broken, 0);
}

// A wall W (x = 0, facing +x) and a wall V (x = 20, facing -x), a floor F
// (y = 0, x in [5, 9]) between them, and a panel Q (x = 2) facing W. Q
// stops W's rays, and V's end on Q's back: the space under F is enclosed
// and F's prism fills it. Take Q out, 3 m from F: W's rays run under F to
// V's front, and F's prism takes free space, though no changed face is
// near it.
Mesh floor_between_walls(bool with_panel) {
  Mesh m;
  const auto wall = [&m](double x, double front) {
    test::add_quad_facing(m, {x, -2.0, -2.0}, {x, 2.0, -2.0}, {x, 2.0, 2.0}, {x, -2.0, 2.0}, {front, 0.0, 0.0});
  };
  wall(0.0, 1.0);
  wall(20.0, -1.0);
  // A roof joins W and V: one place, whose box holds F and Q (enclosure
  // counts only within a place, hullcover/mesh/tolerance.h).
  test::add_quad_facing(m, {0.0, 2.0, -2.0}, {20.0, 2.0, -2.0}, {20.0, 2.0, 2.0}, {0.0, 2.0, 2.0}, {0.0, -1.0, 0.0});
  test::add_quad_facing(m, {5.0, 0.0, -2.0}, {9.0, 0.0, -2.0}, {9.0, 0.0, 2.0}, {5.0, 0.0, 2.0}, {0.0, 1.0, 0.0});
  if (with_panel) wall(2.0, -1.0);
  return m;
}

TEST(SceneChange, AWallTakenOutFarAwayReachesAPrismThroughTheSweepsItStopped) {
  DecomposeOptions o;
  o.prism_thickness_cap = 0.5;
  o.cell_size = 2.0;
  const Bake before = bake(floor_between_walls(true), o, true);
  const Bake after = bake(floor_between_walls(false), o, false);
  const detail::SceneChange change = after.change_since(detail::read_scene_snapshot(before.snapshot()).value());
  ASSERT_FALSE(change.everything);
  EXPECT_EQ(change.changed_faces, 2);
  detail::SceneChange near_only = change;
  near_only.sweeps.clear();
  near_only.sweep_tree = AabbTree();
  // F's faces are 6 and 7 in both scenes.
  const int cell = after.stages->cells.cell_of_face[6];
  const auto old = std::find_if(before.cells.begin(), before.cells.end(), [&](const std::string& bytes) {
    return detail::cell_result_from_bytes(*after.stages, cell, bytes).ok();
  });
  ASSERT_NE(old, before.cells.end()) << "F's cell has a new key";
  const detail::CellResult kept = detail::cell_result_from_bytes(*after.stages, cell, *old).value();
  ASSERT_EQ(kept.patches.size(), 1u);
  ASSERT_GT(kept.hulls[0].hull.thickness, 0.25) << "F's prism was not thick before the edit";
  EXPECT_FALSE(detail::patch_may_be_touched(*after.stages, near_only, kept.patches[0], kept.hulls[0]));
  EXPECT_TRUE(detail::patch_may_be_touched(*after.stages, change, kept.patches[0], kept.hulls[0]));
  std::string why;
  EXPECT_FALSE(detail::cell_bytes_hold(*after.stages, cell, *old, {}, &why));
  // Through the cache: F's cell is stale, merged again, and the covering valid.
  test::TempDir dir;
  CellCacheReport report;
  ASSERT_TRUE(decompose_with_cell_cache(*before.prepared, o, dir.path("cache"), report).ok());
  const PreparedMesh edited = prepare_mesh(floor_between_walls(false), std::nullopt).value();
  Result<Covering> rebaked = decompose_with_cell_cache(edited, o, dir.path("cache"), report);
  ASSERT_TRUE(rebaked.ok());
  EXPECT_EQ(report.changed_faces, 2);
  EXPECT_GE(report.stale, 1);
  const validate::CheckReport check = validate::check_covering_independently(edited, rebaked.value(), false);
  EXPECT_EQ(check.violations(), 0) << check.summary();
}

TEST(SceneChange, AReBakeTrustingTheSnapshotIsValidAndAsSmallAsAFullReCheck) {
  const Mesh building = demo_building();
  const DecomposeOptions o = test::options_with_small_cells(building);
  test::TempDir dir;
  const std::string trusting = dir.path("trusting"), checking = dir.path("checking");
  CellCacheReport report;
  ASSERT_TRUE(decompose_with_cell_cache(prepare_mesh(building, std::nullopt).value(), o, trusting, report).ok());
  EXPECT_EQ(report.changed_faces, -1);
  std::filesystem::copy(trusting, checking);
  std::filesystem::remove(checking + "/last-bake.scene");
  for (const auto& [mesh, changed_faces] : edits_of(building)) {
    const PreparedMesh prepared = prepare_mesh(mesh, std::nullopt).value();
    CellCacheReport trusted, checked;
    Result<Covering> a = decompose_with_cell_cache(prepared, o, trusting, trusted);
    Result<Covering> b = decompose_with_cell_cache(prepared, o, checking, checked);
    ASSERT_TRUE(a.ok() && b.ok());
    // Both valid; they may differ where the edit freed room a full re-check
    // finds (scene_change.h), so the hull counts are compared, not the bytes.
    EXPECT_LE(a.value().hulls.size(), b.value().hulls.size() + b.value().hulls.size() / 50);
    EXPECT_GT(trusted.patches_kept_unchecked, 0);
    EXPECT_EQ(checked.patches_kept_unchecked, 0);
    // Each bake leaves its own snapshot: the next edit is measured from this one.
    std::filesystem::remove(checking + "/last-bake.scene");
    // And after an edit, the re-bake is still a valid covering.
    const validate::CheckReport check = validate::check_covering_independently(prepared, a.value(), false);
    EXPECT_EQ(check.violations(), 0) << check.summary();
  }
  // The same scene again: nothing changed, nothing re-checked.
  CellCacheReport again;
  ASSERT_TRUE(
      decompose_with_cell_cache(prepare_mesh(edits_of(building).back().first, std::nullopt).value(), o, trusting, again)
          .ok());
  EXPECT_EQ(again.changed_faces, 0);
  EXPECT_EQ(again.patches_rechecked, 0);
  EXPECT_EQ(again.merged, 0);
}

TEST(SceneChange, ASnapshotIsCheckedBeforeUseAndOtherOptionsReCheckEverything) {
  const Mesh building = demo_building();
  const DecomposeOptions o = test::options_with_small_cells(building);
  const Bake before = bake(building, o, true);
  const std::string bytes = before.snapshot();
  for (size_t at : {size_t{0}, size_t{9}, bytes.size() / 2, bytes.size() - 1}) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    EXPECT_FALSE(detail::read_scene_snapshot(flipped).ok()) << at;
  }
  for (size_t keep : {size_t{0}, size_t{12}, bytes.size() / 3, bytes.size() - 1})
    EXPECT_FALSE(detail::read_scene_snapshot(bytes.substr(0, keep)).ok()) << keep;
  const detail::SceneSnapshot snapshot = detail::read_scene_snapshot(bytes).value();
  EXPECT_EQ(snapshot.cell_checksums.size(), before.cells.size());
  EXPECT_FALSE(before.change_since(snapshot).everything);
  DecomposeOptions capped = o;
  capped.free_space_reach = 100.0; // rays run on past a cap: no bound
  const Bake capped_bake = bake(building, capped, true);
  EXPECT_TRUE(capped_bake.change_since(detail::read_scene_snapshot(capped_bake.snapshot()).value()).everything);
  DecomposeOptions other = o;
  other.seed += 1;
  EXPECT_TRUE(bake(building, other, false).change_since(snapshot).everything);
  DecomposeOptions agent = o;
  agent.agent_radius = 0.3;
  EXPECT_TRUE(bake(building, agent, false).change_since(snapshot).everything);
}

} // namespace
} // namespace hullcover

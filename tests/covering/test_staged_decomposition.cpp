// The staged decomposition (staged_decomposition.h): cells merged apart and
// carried as bytes give decompose()'s covering; bytes are checked before
// use; after an edit, a cell's earlier result stands only where its key is
// unchanged and every hull it keeps still holds in the edited scene.

#include "covering_fixture.h"

#include "hullcover/covering/staged_decomposition.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace hullcover {
namespace {

// Every cell merged, last cell first (the order must not matter).
std::vector<std::string> merge_every_cell(const StagedDecomposition& s) {
  std::vector<std::string> cells(s.cell_count());
  for (int c = s.cell_count() - 1; c >= 0; --c) {
    Result<std::string> bytes = s.merge_cell(c);
    EXPECT_TRUE(bytes.ok()) << bytes.status().message();
    if (bytes.ok()) cells[c] = std::move(bytes).value();
  }
  return cells;
}

TEST(StagedDecomposition, CellsCarriedAsBytesGiveDecomposesCovering) {
  const Mesh building = demo_building();
  const DecomposeOptions o = test::options_with_small_cells(building);
  const auto whole = test::decompose_and_check(building, o);
  const auto s = test::staged_decomposition(building, o);
  ASSERT_TRUE(whole && s);
  ASSERT_GT(s->cell_count(), 8);
  Result<Covering> finished = s->finish(merge_every_cell(*s));
  ASSERT_TRUE(finished.ok()) << finished.status().message();
  EXPECT_EQ(test::covering_obj_bytes(finished.value()), test::covering_obj_bytes(whole->covering));
  const CoveringStatistics& a = finished.value().statistics;
  const CoveringStatistics& b = whole->covering.statistics;
  EXPECT_EQ(a.merges, b.merges);
  EXPECT_EQ(a.seam_merges, b.seam_merges);
  EXPECT_EQ(a.near_merges, b.near_merges);
  EXPECT_EQ(a.candidates_tested, b.candidates_tested);
  EXPECT_EQ(a.rejections, b.rejections);
  EXPECT_EQ(a.qhull_calls, b.qhull_calls);
  EXPECT_EQ(a.cells, b.cells);
}

TEST(StagedDecomposition, CellBytesAreCheckedBeforeUse) {
  const Mesh building = demo_building();
  const auto s = test::staged_decomposition(building, test::options_with_small_cells(building));
  ASSERT_TRUE(s);
  const std::vector<std::string> cells = merge_every_cell(*s);
  const auto finish_with = [&](int cell, const std::string& bytes) {
    std::vector<std::string> changed = cells;
    changed[cell] = bytes;
    return s->finish(changed).status();
  };
  std::string why;
  EXPECT_TRUE(s->still_valid(1, cells[1], &why)) << why;
  // Any byte changed: the checksum says so.
  for (size_t at : {size_t{0}, size_t{9}, cells[1].size() / 2, cells[1].size() - 1}) {
    std::string flipped = cells[1];
    flipped[at] = static_cast<char>(flipped[at] ^ 0x20);
    EXPECT_NE(finish_with(1, flipped).code(), StatusCode::ok) << at;
    EXPECT_FALSE(s->still_valid(1, flipped));
  }
  for (size_t keep : {size_t{0}, size_t{7}, size_t{20}, cells[1].size() - 1})
    EXPECT_NE(finish_with(1, cells[1].substr(0, keep)).code(), StatusCode::ok) << keep;
  // Another cell's bytes, though whole and checksummed: another key.
  const Status other = finish_with(1, cells[2]);
  EXPECT_EQ(other.code(), StatusCode::unreadable_file);
  EXPECT_NE(other.message().find("cell key"), std::string::npos) << other.message();
  EXPECT_FALSE(s->still_valid(1, cells[2], &why));
  EXPECT_EQ(finish_with(1, "not a cell at all").code(), StatusCode::unknown_format);
  EXPECT_EQ(s->finish({cells[0]}).status().code(), StatusCode::invalid_argument);
  EXPECT_EQ(s->merge_cell(s->cell_count()).status().code(), StatusCode::invalid_argument);
}

// A closed box (its 12 faces last) just above a floor, cut into cells.
Mesh box_on_floor() {
  Mesh m;
  std::vector<double> ticks;
  for (int i = -8; i <= 8; ++i) ticks.push_back(i);
  add_height_field(m, ticks, ticks, [](double, double) { return 0.0; });
  // 0.02 above the floor: within kIslandJoinRelative, one island.
  add_box(m, {2.2, 0.02, 2.2}, {3.8, 1.22, 3.8});
  return m;
}

TEST(StagedDecomposition, AnEditInvalidatesOnlyTheHullsItReaches) {
  const Mesh before = box_on_floor();
  DecomposeOptions o;
  o.cell_size = 4.0;
  const auto old_bake = test::staged_decomposition(before, o);
  ASSERT_TRUE(old_bake);
  const std::vector<std::string> old_cells = merge_every_cell(*old_bake);
  // The edit: a long thin triangle whose centroid lies in the next cell
  // over (x < 0) but whose tip reaches into the box.
  Mesh after = before;
  test::add_triangle(after, {-6.0, 0.3, 3.0}, {-6.0, 0.4, 3.1}, {3.0, 0.5, 3.0});
  const auto new_bake = test::staged_decomposition(after, o);
  ASSERT_TRUE(new_bake);
  ASSERT_EQ(new_bake->cell_count(), old_bake->cell_count());
  const int box_faces = static_cast<int>(before.triangles.size()) - 12;
  int reused = 0, refused = 0, changed = 0;
  std::vector<std::string> cells(new_bake->cell_count()), stale(new_bake->cell_count());
  for (int c = 0; c < new_bake->cell_count(); ++c) {
    const std::vector<int>& faces = new_bake->cell_faces(c);
    const bool has_box =
        std::any_of(faces.begin(), faces.end(), [&](int f) { return f >= box_faces && f < box_faces + 12; });
    const bool same_faces = new_bake->cell_key(c) == old_bake->cell_key(c);
    std::string why;
    if (same_faces && new_bake->still_valid(c, old_cells[c], &why)) {
      EXPECT_FALSE(has_box) << "the box's hull now has a face through it";
      cells[c] = old_cells[c];
      ++reused;
    } else {
      if (same_faces) {
        EXPECT_TRUE(has_box) << "cell " << c << " refused: " << why;
        EXPECT_NE(why.find("no longer valid"), std::string::npos) << why;
        ++refused;
      }
      cells[c] = new_bake->merge_cell(c).value();
      changed += !same_faces;
    }
    stale[c] = same_faces ? old_cells[c] : cells[c];
  }
  // Only the cell the new face is in has other faces; only a cell of the
  // box's can hold a hull the new face pokes into.
  EXPECT_EQ(changed, 1);
  EXPECT_GE(refused, 1);
  EXPECT_EQ(reused + refused + changed, new_bake->cell_count());
  Result<Covering> covering = new_bake->finish(cells);
  ASSERT_TRUE(covering.ok()) << covering.status().message();
  const validate::CheckReport report =
      validate::check_covering_independently(new_bake->prepared(), covering.value(), false);
  EXPECT_EQ(report.violations(), 0) << report.summary();
  // Reusing the refused cells too (unchecked) would be wrong: the
  // independent check finds what the re-check caught.
  Result<Covering> unchecked = new_bake->finish(stale);
  ASSERT_TRUE(unchecked.ok()) << unchecked.status().message();
  EXPECT_GT(validate::check_covering_independently(new_bake->prepared(), unchecked.value(), false).violations(), 0);
}

} // namespace
} // namespace hullcover

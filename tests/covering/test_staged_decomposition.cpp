// The staged decomposition (staged_decomposition.h): cells merged apart and
// carried as bytes give decompose()'s covering; bytes are checked before
// use; after an edit, a cell's earlier result stands only where its key is
// unchanged and every hull it keeps still holds in the edited scene.

#include "covering_fixture.h"

#include "hullcover/covering/staged_decomposition.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace hullcover {
namespace {

// The bytes `make(i)` gives for every i < count, last first (the order
// must not matter).
template <class Make>
std::vector<std::string> bytes_of_each(int count, const Make& make) {
  std::vector<std::string> all(static_cast<size_t>(count));
  for (int i = count - 1; i >= 0; --i) {
    Result<std::string> bytes = make(i);
    EXPECT_TRUE(bytes.ok()) << i << ": " << bytes.status().message();
    if (bytes.ok()) all[i] = std::move(bytes).value();
  }
  return all;
}

// Every cell merged.
std::vector<std::string> merge_every_cell(const StagedDecomposition& s) {
  return bytes_of_each(s.cell_count(), [&](int c) { return s.merge_cell(c); });
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

// A building, a floor and a box apart from both: three islands, the
// building's and the floor's cut into several cells.
Mesh three_islands() {
  Mesh m = demo_building();
  std::vector<double> ticks;
  for (int i = 0; i <= 12; ++i) ticks.push_back(40.0 + i);
  add_height_field(m, ticks, ticks, [](double x, double z) { return 0.1 * std::sin(x) * std::cos(z); });
  add_box(m, {-30.0, 0.0, -30.0}, {-28.0, 2.0, -27.0});
  return m;
}

// Every seam cell finished from its cells' bytes.
std::vector<std::string> finish_every_seam(const StagedDecomposition& s, const std::vector<std::string>& cells) {
  return bytes_of_each(s.seam_count(), [&](int seam) {
    std::vector<std::string> its;
    for (int c : s.seam_cells(seam)) its.push_back(cells[c]);
    return s.finish_seam(seam, its);
  });
}

TEST(StagedDecomposition, SeamCellsFinishedApartGiveDecomposesCovering) {
  const Mesh mesh = three_islands();
  const DecomposeOptions o = test::options_with_small_cells(mesh);
  const auto whole = test::decompose_and_check(mesh, o);
  const auto s = test::staged_decomposition(mesh, o);
  ASSERT_TRUE(whole && s);
  ASSERT_GE(s->seam_count(), 3);
  // The seam cells share out the cells, each cell to one.
  std::vector<int> seam_of(s->cell_count(), -1);
  size_t most = 0;
  for (int seam = 0; seam < s->seam_count(); ++seam) {
    const std::vector<int> cells = s->seam_cells(seam);
    most = std::max(most, cells.size());
    for (int c : cells) {
      EXPECT_EQ(seam_of[c], -1) << "cell " << c << " in two seam cells";
      seam_of[c] = seam;
    }
  }
  EXPECT_EQ(std::count(seam_of.begin(), seam_of.end(), -1), 0);
  EXPECT_GT(most, 1u) << "no seam cell has a border to merge across";
  const std::vector<std::string> cells = merge_every_cell(*s);
  Result<Covering> finished = s->finish_seams(finish_every_seam(*s, cells));
  ASSERT_TRUE(finished.ok()) << finished.status().message();
  EXPECT_EQ(test::covering_obj_bytes(finished.value()), test::covering_obj_bytes(whole->covering));
  const CoveringStatistics& a = finished.value().statistics;
  const CoveringStatistics& b = whole->covering.statistics;
  EXPECT_GT(b.seam_merges, 0);
  EXPECT_EQ(a.merges, b.merges);
  EXPECT_EQ(a.seam_merges, b.seam_merges);
  EXPECT_EQ(a.qhull_calls, b.qhull_calls);
  EXPECT_EQ(a.rejections, b.rejections);
  EXPECT_EQ(a.kept_try, b.kept_try);
  EXPECT_EQ(a.faces_given_flat_hulls, b.faces_given_flat_hulls);
}

TEST(StagedDecomposition, SeamBytesAreCheckedBeforeUse) {
  const Mesh mesh = three_islands();
  const auto s = test::staged_decomposition(mesh, test::options_with_small_cells(mesh));
  ASSERT_TRUE(s);
  const std::vector<std::string> cells = merge_every_cell(*s);
  const std::vector<std::string> seams = finish_every_seam(*s, cells);
  ASSERT_TRUE(s->finish_seams(seams).ok());
  const auto finish_with = [&](int seam, const std::string& bytes) {
    std::vector<std::string> changed = seams;
    changed[seam] = bytes;
    return s->finish_seams(changed).status();
  };
  for (size_t at : {size_t{0}, size_t{9}, seams[0].size() / 2, seams[0].size() - 1}) {
    std::string flipped = seams[0];
    flipped[at] = static_cast<char>(flipped[at] ^ 0x20);
    EXPECT_NE(finish_with(0, flipped).code(), StatusCode::ok) << at;
  }
  for (size_t keep : {size_t{0}, size_t{7}, size_t{20}, seams[0].size() - 1})
    EXPECT_NE(finish_with(0, seams[0].substr(0, keep)).code(), StatusCode::ok) << keep;
  // Another seam cell's bytes, whole and checksummed.
  const Status other = finish_with(0, seams[1]);
  EXPECT_EQ(other.code(), StatusCode::unreadable_file);
  EXPECT_NE(other.message().find("another seam cell"), std::string::npos) << other.message();
  EXPECT_EQ(finish_with(0, "not a seam cell at all").code(), StatusCode::unknown_format);
  EXPECT_EQ(s->finish_seams({seams[0]}).status().code(), StatusCode::invalid_argument);
  // A cell's bytes standing in for another's, too few, and no such seam cell.
  const std::vector<int> first = s->seam_cells(0);
  std::vector<std::string> wrong;
  for (int c : first) wrong.push_back(cells[(c + 1) % s->cell_count()]);
  EXPECT_EQ(s->finish_seam(0, wrong).status().code(), StatusCode::unreadable_file);
  EXPECT_EQ(s->finish_seam(0, {}).status().code(), StatusCode::invalid_argument);
  EXPECT_EQ(s->finish_seam(s->seam_count(), {}).status().code(), StatusCode::invalid_argument);
  EXPECT_TRUE(s->seam_cells(-1).empty());
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
      validate::check_covering_independently(*new_bake->prepared(), covering.value(), false);
  EXPECT_EQ(report.violations(), 0) << report.summary();
  // Reusing the refused cells too (unchecked) would be wrong: the
  // independent check finds what the re-check caught.
  Result<Covering> unchecked = new_bake->finish(stale);
  ASSERT_TRUE(unchecked.ok()) << unchecked.status().message();
  EXPECT_GT(validate::check_covering_independently(*new_bake->prepared(), unchecked.value(), false).violations(), 0);
}

} // namespace
} // namespace hullcover

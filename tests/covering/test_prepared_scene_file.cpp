// The prepared scene file (StagedDecomposition::write_prepared and
// ::map_prepared, lib/covering/src/cells/prepared_scene_file.h): stages read
// back from it merge every cell to the same bytes and finish to the same
// covering as the stages that wrote it; a damaged, cut, foreign or hostile
// file is refused with a message naming what is wrong, before any cell
// reads it.

#include "covering_fixture.h"
#include "mesh_transforms.h"
#include "prepared_scene_edits.h"
#include "temp_dir.h"

#include "cells/prepared_scene_file.h"

#include "hullcover/covering/staged_decomposition.h"
#include "hullcover/geometry/mapped_file.h"
#include "hullcover/mesh/scene_builder.h"

#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <thread>

namespace hullcover {
namespace {

void write_bytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Maps the file and expects it merged and finished exactly as `written`.
void expect_same_stages(const StagedDecomposition& written, const std::string& path, const DecomposeOptions& options) {
  Result<std::unique_ptr<StagedDecomposition>> mapped = StagedDecomposition::map_prepared(path, options);
  ASSERT_TRUE(mapped.ok()) << mapped.status().message();
  const StagedDecomposition& m = *mapped.value();
  ASSERT_EQ(m.cell_count(), written.cell_count());
  std::vector<std::string> cells;
  for (int c = 0; c < m.cell_count(); ++c) {
    EXPECT_EQ(m.cell_faces(c), written.cell_faces(c));
    EXPECT_EQ(m.cell_key(c), written.cell_key(c));
    Result<std::string> a = m.merge_cell(c);
    Result<std::string> b = written.merge_cell(c);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a.value(), b.value()) << "cell " << c;
    cells.push_back(std::move(a).value());
    // Pages handed back are read again from the file when next touched.
    m.release_mapped_pages();
  }
  Result<Covering> from_mapped = m.finish(cells);
  Result<Covering> from_written = written.finish(cells);
  ASSERT_TRUE(from_mapped.ok() && from_written.ok());
  EXPECT_EQ(test::covering_obj_bytes(from_mapped.value()), test::covering_obj_bytes(from_written.value()));
  EXPECT_GT(from_mapped.value().hulls.size(), 0u);
}

TEST(PreparedSceneFile, MappedStagesMergeAndFinishAsTheStagesThatWroteIt) {
  const Mesh building = demo_building();
  const DecomposeOptions o = test::options_with_small_cells(building);
  const auto s = test::staged_decomposition(building, o);
  ASSERT_TRUE(s);
  ASSERT_GT(s->cell_count(), 8);
  const test::TempDir dir;
  ASSERT_TRUE(s->write_prepared(dir.path("scene.hcp")).ok());
  expect_same_stages(*s, dir.path("scene.hcp"), o);
}

TEST(PreparedSceneFile, TheScenesArraysAreReadWhereTheyLieInTheFile) {
  // A worker's memory follows its cells only if it copies no array of the
  // world: every per-vertex, per-face and per-edge array is viewed in the
  // mapping.
  const Mesh building = demo_building();
  const auto s = test::staged_decomposition(building, test::options_with_small_cells(building));
  ASSERT_TRUE(s);
  const test::TempDir dir;
  ASSERT_TRUE(s->write_prepared(dir.path("scene.hcp")).ok());
  Result<std::unique_ptr<MappedFile>> file = MappedFile::open(dir.path("scene.hcp"));
  ASSERT_TRUE(file.ok());
  const MappedFile& mapping = *file.value();
  Result<detail::MappedPreparedScene> read = detail::read_prepared_scene(mapping, "scene.hcp");
  ASSERT_TRUE(read.ok()) << read.status().message();
  const PreparedSceneView& scene = read.value().scene;
  const auto in_file = [&](const auto& array) {
    const auto* first = reinterpret_cast<const unsigned char*>(array.data());
    return array.is_view() && array.size() > 0 && first >= mapping.data() &&
           first + sizeof(array[0]) * array.size() <= mapping.data() + mapping.size();
  };
  EXPECT_TRUE(in_file(scene.mesh.positions));
  EXPECT_TRUE(in_file(scene.mesh.triangles));
  EXPECT_TRUE(in_file(scene.mesh.material_ids));
  EXPECT_TRUE(in_file(scene.islands.island_of_face));
  EXPECT_TRUE(in_file(scene.connectivity.edges));
  EXPECT_TRUE(in_file(scene.connectivity.edge_uses));
  EXPECT_TRUE(in_file(scene.connectivity.face_edges));
  EXPECT_TRUE(in_file(scene.connectivity.face_neighbours));
  EXPECT_TRUE(in_file(scene.connectivity.zero_area));
  EXPECT_TRUE(in_file(scene.connectivity.face_component));
  EXPECT_TRUE(in_file(read.value().index.face_normals));
  // And read back as the stages that wrote it hold them.
  const PreparedMesh& written = *s->prepared();
  ASSERT_EQ(scene.connectivity.edges.size(), written.connectivity.edges.size());
  for (std::size_t e = 0; e < written.connectivity.edges.size(); ++e) {
    const MeshEdge &a = scene.connectivity.edges[e], &b = written.connectivity.edges[e];
    ASSERT_TRUE(a.v0 == b.v0 && a.v1 == b.v1 && a.first_use == b.first_use && a.use_count == b.use_count &&
                a.kind == b.kind)
        << "edge " << e;
  }
}

TEST(PreparedSceneFile, PagesHandedBackWhileCellsMergeChangeNothing) {
  // A bake's worker hands the file's pages back on a timer while a cell
  // merges: every page dropped under the merge is read again, alike.
  const Mesh building = demo_building();
  const DecomposeOptions o = test::options_with_small_cells(building);
  const auto s = test::staged_decomposition(building, o);
  ASSERT_TRUE(s);
  const test::TempDir dir;
  ASSERT_TRUE(s->write_prepared(dir.path("scene.hcp")).ok());
  Result<std::unique_ptr<StagedDecomposition>> mapped = StagedDecomposition::map_prepared(dir.path("scene.hcp"), o);
  ASSERT_TRUE(mapped.ok()) << mapped.status().message();
  const StagedDecomposition& m = *mapped.value();
  std::atomic<bool> merging{true};
  std::atomic<long> drops{0};
  std::thread dropper([&] {
    while (merging) {
      m.release_mapped_pages();
      ++drops;
    }
  });
  for (int c = 0; c < m.cell_count(); ++c) {
    Result<std::string> a = m.merge_cell(c);
    Result<std::string> b = s->merge_cell(c);
    if (!a.ok() || !b.ok()) { // not ASSERT: the dropper must be joined
      ADD_FAILURE() << "cell " << c << " did not merge";
      break;
    }
    EXPECT_EQ(a.value(), b.value()) << "cell " << c;
  }
  merging = false;
  dropper.join();
  EXPECT_GT(drops.load(), m.cell_count());
}

TEST(PreparedSceneFile, AFarSceneIsMappedInTheSameLocalFrame) {
  // Far from the origin the stages work on a moved copy; the mapped stages
  // must move the scene read back exactly alike.
  const Mesh far = test::transformed(demo_building(), Eigen::Affine3d(Eigen::Translation3d(3.0e6, -2.0e5, 7.0e5)));
  const DecomposeOptions o = test::options_with_small_cells(far);
  const auto s = test::staged_decomposition(far, o);
  ASSERT_TRUE(s);
  const test::TempDir dir;
  ASSERT_TRUE(s->write_prepared(dir.path("far.hcp")).ok());
  expect_same_stages(*s, dir.path("far.hcp"), o);
}

class DamagedPreparedFile : public ::testing::Test {
protected:
  void SetUp() override {
    const Mesh building = demo_building();
    options_ = test::options_with_small_cells(building);
    stages_ = test::staged_decomposition(building, options_);
    ASSERT_TRUE(stages_);
    ASSERT_TRUE(stages_->write_prepared(dir_.path("good.hcp")).ok());
    good_ = test::slurp(dir_.path("good.hcp"));
    ASSERT_GT(good_.size(), 1000u);
  }
  // Maps `bytes` written as a file; the status it gives.
  Status map_bytes(const std::string& bytes) {
    write_bytes(dir_.path("bad.hcp"), bytes);
    Result<std::unique_ptr<StagedDecomposition>> m = StagedDecomposition::map_prepared(dir_.path("bad.hcp"), options_);
    return m.ok() ? Status::success() : m.status();
  }
  std::pair<std::uint64_t, std::uint64_t> section(std::uint32_t id) const {
    return test::prepared_section_at(good_, id);
  }
  DecomposeOptions options_;
  std::unique_ptr<StagedDecomposition> stages_;
  test::TempDir dir_;
  std::string good_;
};

TEST_F(DamagedPreparedFile, AChangedByteIsRefusedNamingItsSection) {
  for (const std::uint32_t id : {std::uint32_t{detail::kFaceNormals}, std::uint32_t{detail::kTriangles},
                                 std::uint32_t{detail::kFirstTreeSection + 8}}) {
    const auto [offset, length] = section(id);
    ASSERT_GT(length, 0u);
    std::string bytes = good_;
    bytes[offset + length / 2] ^= 0x10;
    const Status s = map_bytes(bytes);
    EXPECT_EQ(s.code(), StatusCode::unreadable_file);
    EXPECT_NE(s.message().find(detail::section_name(id) + ": its checksum does not match"), std::string::npos)
        << s.message();
  }
}

TEST_F(DamagedPreparedFile, ACutOrForeignFileIsRefused) {
  EXPECT_EQ(map_bytes(good_.substr(0, good_.size() / 2)).code(), StatusCode::unreadable_file);
  EXPECT_EQ(map_bytes(good_.substr(0, 100)).code(), StatusCode::unreadable_file);
  EXPECT_EQ(map_bytes(good_.substr(0, 10)).code(), StatusCode::unknown_format);
  EXPECT_EQ(map_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").code(), StatusCode::unknown_format);
  std::string later = good_;
  later[8] = 2; // version 2
  test::reseal_prepared_scene(later);
  const Status version = map_bytes(later);
  EXPECT_EQ(version.code(), StatusCode::unknown_format);
  EXPECT_NE(version.message().find("version 2"), std::string::npos) << version.message();
  std::string header = good_;
  header[40] ^= 1; // inside the table, under the header's checksum
  EXPECT_NE(map_bytes(header).message().find("header's checksum"), std::string::npos);
  EXPECT_EQ(StatusCode::file_not_found,
            StagedDecomposition::map_prepared(dir_.path("none.hcp"), options_).status().code());
  EXPECT_EQ(StatusCode::unreadable_file, StagedDecomposition::map_prepared(dir_.path(""), options_).status().code());
  EXPECT_EQ(map_bytes("").code(), StatusCode::unreadable_file);
}

TEST_F(DamagedPreparedFile, LinksOutOfRangeAreRefusedEvenWithRightChecksums) {
  // A file edited with its checksums made right again: the reader's own
  // checks must keep every read inside the arrays.
  const auto edit_ints = [&](std::uint32_t id, std::initializer_list<std::pair<std::uint64_t, std::int32_t>> edits) {
    std::string bytes = good_;
    const auto [offset, length] = section(id);
    for (const auto& [index, value] : edits) {
      EXPECT_LE((index + 1) * 4, length);
      std::memcpy(&bytes[offset + 4 * index], &value, 4);
    }
    test::reseal_prepared_scene(bytes);
    return map_bytes(bytes);
  };
  const auto edit_int = [&](std::uint32_t id, std::uint64_t index, std::int32_t value) {
    return edit_ints(id, {{index, value}});
  };
  const std::uint32_t face_tree = detail::kFirstTreeSection + 2 * detail::kSectionsPerTree;
  Status s = edit_int(face_tree + 1, 0, 1 << 30); // a face tree item past the faces
  EXPECT_NE(s.message().find("face tree nodes: an item out of range"), std::string::npos) << s.message();
  // The first node's first child (ints 12 and 13 of the node: index, count)
  // made an inner node pointing back at the node itself: a cycle.
  s = edit_ints(face_tree, {{12, 0}, {13, 0}});
  EXPECT_NE(s.message().find("face tree nodes: a link out of range"), std::string::npos) << s.message();
  // A leaf running past the items.
  s = edit_ints(face_tree, {{12, 0}, {13, 1 << 29}});
  EXPECT_NE(s.message().find("face tree nodes: a link out of range"), std::string::npos) << s.message();
  s = edit_int(detail::kCellOfFace, 0, 1 << 20);
  EXPECT_NE(s.message().find("cells"), std::string::npos) << s.message();
  s = edit_int(detail::kTriangles, 0, -5);
  EXPECT_NE(s.message().find("its scene"), std::string::npos) << s.message();
  s = edit_int(detail::kFrontSweepFace, 0, -1);
  EXPECT_NE(s.message().find("scene index"), std::string::npos) << s.message();
  // An edge is read in place: its kind (the fifth int) must be one of the
  // four, its padding zero.
  s = edit_int(detail::kEdges, 4, 1 << 8);
  EXPECT_NE(s.message().find("edges"), std::string::npos) << s.message();
  s = edit_int(detail::kEdgeUses, 0, 1 << 30); // a face past the faces
  EXPECT_NE(s.message().find("edge uses"), std::string::npos) << s.message();
  s = edit_int(detail::kIslandOfFace, 0, 1 << 20);
  EXPECT_NE(s.message().find("islands"), std::string::npos) << s.message();
  s = edit_int(detail::kFaceNeighbours, 0, 1 << 30);
  EXPECT_NE(s.message().find("connectivity"), std::string::npos) << s.message();
  s = edit_ints(detail::kPositions, {{0, 0}, {1, 0x7ff80000}}); // the first x a NaN
  EXPECT_NE(s.message().find("its scene"), std::string::npos) << s.message();
  // Unchanged but resealed: still read.
  std::string same = good_;
  test::reseal_prepared_scene(same);
  EXPECT_TRUE(map_bytes(same).ok());
}

TEST_F(DamagedPreparedFile, OtherOptionsThanThePreparedOnesAreRefused) {
  DecomposeOptions other = options_;
  other.near_merge_distance = 0.25;
  Result<std::unique_ptr<StagedDecomposition>> m = StagedDecomposition::map_prepared(dir_.path("good.hcp"), other);
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.status().code(), StatusCode::invalid_argument);
  EXPECT_NE(m.status().message().find("prepared with other options"), std::string::npos);
  other = options_;
  other.threads = 3; // threads do not change the stages
  EXPECT_TRUE(StagedDecomposition::map_prepared(dir_.path("good.hcp"), other).ok());
}

} // namespace
} // namespace hullcover

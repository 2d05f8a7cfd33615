// Reading the prepared scene file (prepared_scene_file.h). No length, index
// or tree link in it is trusted: each is checked against what it points
// into before the stages read it, so a damaged or hostile file is refused
// with a message, never read past an array's end. Its numbers (reaches,
// boxes) are trusted as its writer made them, as the cell cache's are: a
// checksum finds damage, it does not sign.

#include "cells/prepared_scene_file.h"
#include "cells/prepared_scene_sections.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

namespace hullcover::detail {

std::string AabbTreeStorage::read(const unsigned char* nodes, std::size_t node_count, const int* items,
                                  std::size_t item_count, const Aabb* leaf_boxes, std::size_t leaf_box_count,
                                  std::size_t item_limit, LittleEndianReader& scalars, AabbTree& tree) {
  AabbTree::ChildRef root{};
  root.index = scalars.i32();
  root.count = scalars.i32();
  AabbTree::FloatBox root_box{};
  for (int axis = 0; axis < 3; ++axis) {
    const std::uint32_t low = scalars.u32(), high = scalars.u32();
    std::memcpy(&root_box.min[axis], &low, 4);
    std::memcpy(&root_box.max[axis], &high, 4);
  }
  if (scalars.failed) return "the scalars end early";
  if (leaf_box_count != item_count) return "a leaf box per item";
  for (std::size_t i = 0; i < item_count; ++i)
    if (items[i] < 0 || static_cast<std::size_t>(items[i]) >= item_limit) return "an item out of range";
  const auto* node = reinterpret_cast<const AabbTree::Node*>(nodes);
  // A child is a leaf inside the items, or an inner node after its parent
  // (as the build lays them out): no cycle, and a depth known in one pass.
  const auto link_ok = [&](const AabbTree::ChildRef& ref, long long parent) {
    if (ref.count > 0)
      return ref.index >= 0 && static_cast<std::size_t>(ref.index) <= item_count &&
             static_cast<std::size_t>(ref.count) <= item_count - static_cast<std::size_t>(ref.index);
    return ref.count == 0 && ref.index > parent && static_cast<std::size_t>(ref.index) < node_count;
  };
  if (item_count > 0 && !link_ok(root, -1)) return "the root out of range";
  std::vector<int> depth(node_count, -1);
  if (item_count > 0 && root.count == 0) depth[static_cast<std::size_t>(root.index)] = 0;
  for (std::size_t i = 0; i < node_count; ++i) {
    if (depth[i] < 0) continue; // never reached by a walk
    // A walk's stack holds the path and one sibling per level.
    if (depth[i] + 2 >= AabbTree::kMaxDepth) return "deeper than a walk can follow";
    for (const AabbTree::ChildRef& child : node[i].child) {
      if (!link_ok(child, static_cast<long long>(i))) return "a link out of range";
      if (child.count == 0)
        depth[static_cast<std::size_t>(child.index)] =
            std::max(depth[static_cast<std::size_t>(child.index)], depth[i] + 1);
    }
  }
  tree.nodes_ = MappableArray<AabbTree::Node>::view(node, node_count);
  tree.items_ = MappableArray<int>::view(items, item_count);
  tree.leaf_boxes_ = MappableArray<Aabb>::view(leaf_boxes, leaf_box_count);
  tree.root_ = item_count > 0 ? root : AabbTree::ChildRef{0, 0};
  tree.root_box_ = root_box;
  return {};
}

namespace {

struct Section {
  const unsigned char* data = nullptr;
  std::size_t bytes = 0;
  std::size_t count = 0;
};

// The file's sections, found and checked against the table.
class SectionTable {
public:
  SectionTable(const MappedFile& file, std::string name) : file_(file), name_(std::move(name)) {}

  Status read_header(std::uint64_t& options_key);
  /// Checks every section's checksum, handing its pages back after.
  Status check_sums() const;

  const Section& operator[](std::uint32_t id) const { return sections_[id]; }
  std::size_t count(std::uint32_t id) const { return sections_[id].count; }
  template <class T>
  std::vector<T> copy(std::uint32_t id) const {
    const Section& s = sections_[id];
    std::vector<T> out(s.count);
    if (s.bytes > 0) std::memcpy(static_cast<void*>(out.data()), s.data, s.bytes);
    release(id);
    return out;
  }
  template <class T>
  MappableArray<T> view(std::uint32_t id) const {
    return MappableArray<T>::view(reinterpret_cast<const T*>(sections_[id].data), sections_[id].count);
  }
  template <class T>
  const T* at(std::uint32_t id) const {
    return reinterpret_cast<const T*>(sections_[id].data);
  }
  /// Whether `ok`, handing back the pages read to decide it.
  bool checked(std::uint32_t id, bool ok) const {
    release(id);
    return ok;
  }
  Status damaged(const std::string& what) const {
    return {StatusCode::unreadable_file, name_ + ": damaged prepared scene file: " + what};
  }
  void release(std::uint32_t id) const {
    file_.release_pages(static_cast<std::size_t>(sections_[id].data - file_.data()), sections_[id].bytes);
  }

private:
  const MappedFile& file_;
  std::string name_;
  Section sections_[kSectionCount + 1];
  std::uint64_t sums_[kSectionCount + 1] = {};
};

Status SectionTable::read_header(std::uint64_t& options_key) {
  const unsigned char* data = file_.data();
  const std::size_t size = file_.size();
  if (size < kPreparedHeadBytes || std::memcmp(data, kPreparedMagic, sizeof kPreparedMagic) != 0)
    return {StatusCode::unknown_format, name_ + ": not a prepared scene file"};
  if (!host_is_little_endian())
    return {StatusCode::unknown_format, name_ + ": prepared scene files are read on little-endian machines only"};
  LittleEndianReader head{data, size, sizeof kPreparedMagic};
  const std::uint32_t version = head.u32();
  if (version != kPreparedVersion)
    return {StatusCode::unknown_format, name_ + ": prepared scene file version " + std::to_string(version) +
                                            "; this build reads version " + std::to_string(kPreparedVersion) +
                                            ": prepare the scene again"};
  const std::uint32_t count = head.u32();
  if (count != kSectionCount)
    return damaged(std::to_string(count) + " sections, where version 1 has " + std::to_string(kSectionCount));
  options_key = head.u64();
  head.u64();
  const std::uint64_t table_end = kPreparedHeadBytes + kSectionEntryBytes * count;
  if (size < table_end + 8) return damaged("the section table is cut short");
  LittleEndianReader sum{data, size, table_end};
  if (sum.u64() != fnv1a(data, table_end)) return damaged("the header's checksum does not match");
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t id = head.u32(), element = head.u32();
    const std::uint64_t offset = head.u64(), bytes = head.u64(), checksum = head.u64();
    if (id < 1 || id > kSectionCount || sections_[id].data) return damaged("section id " + std::to_string(id));
    const std::string what = section_name(id);
    if (element != element_bytes_of(id)) return damaged(what + ": elements of " + std::to_string(element) + " bytes");
    if (offset % kSectionAlignment != 0 || offset < table_end + 8 || offset > size || bytes > size - offset ||
        bytes % element != 0)
      return damaged(what + ": outside the file");
    Section& s = sections_[id];
    s.data = data + offset;
    s.bytes = static_cast<std::size_t>(bytes);
    s.count = static_cast<std::size_t>(bytes / element);
    sums_[id] = checksum;
  }
  return Status::success();
}

Status SectionTable::check_sums() const {
  // Read from the file, not the mapping: the pass takes no memory of the
  // process, and the mapping then holds only the pages cells read.
  constexpr std::size_t kChunk = std::size_t{1} << 22; // a multiple of 8: the checksum runs on across chunks
  std::vector<unsigned char> chunk(kChunk);
  for (std::uint32_t id = 1; id <= kSectionCount; ++id) {
    const Section& s = sections_[id];
    const auto start = static_cast<std::size_t>(s.data - file_.data());
    std::uint64_t sum = section_checksum(nullptr, 0);
    for (std::size_t at = 0; at < s.bytes; at += kChunk) {
      const std::size_t n = std::min(kChunk, s.bytes - at);
      if (!file_.read(start + at, chunk.data(), n)) return damaged(section_name(id) + ": cannot be read");
      sum = section_checksum(chunk.data(), n, sum);
    }
    if (sum != sums_[id]) return damaged(section_name(id) + ": its checksum does not match");
  }
  return Status::success();
}

// Whether every value lies in [low, high).
template <class T>
bool all_within(const T* values, std::size_t count, long long low, long long high) {
  for (std::size_t i = 0; i < count; ++i)
    if (values[i] < low || values[i] >= high) return false;
  return true;
}

std::vector<std::string> read_material_names(const Section& s, bool& ok) {
  LittleEndianReader in{s.data, s.bytes, 0};
  const std::uint32_t count = in.u32();
  std::vector<std::string> names;
  for (std::uint32_t i = 0; i < count && !in.failed; ++i) {
    const std::uint32_t length = in.u32();
    if (!in.has(length)) {
      in.failed = true;
      break;
    }
    names.emplace_back(reinterpret_cast<const char*>(s.data + in.at), length);
    in.at += length;
  }
  ok = !in.failed && in.at == s.bytes;
  return names;
}

// The scene, as prepare_mesh made it, viewed in the file (the tolerance's
// per-island entries copied); `scalars` is read on to the index's numbers.
Status read_scene(const SectionTable& file, LittleEndianReader& scalars, PreparedSceneView& scene) {
  MeshView& mesh = scene.mesh;
  const auto faces = static_cast<long long>(file.count(kTriangles));
  const auto vertices = static_cast<long long>(file.count(kPositions));
  // prepare_mesh keeps only referenced vertices, so every position must be
  // finite: what validate_mesh asks of a scene.
  const Eigen::Vector3d* positions = file.at<Eigen::Vector3d>(kPositions);
  bool finite = true;
  for (long long v = 0; v < vertices && finite; ++v) finite = positions[v].allFinite();
  if (faces == 0 || file.count(kMaterialIds) != static_cast<std::size_t>(faces) || !file.checked(kPositions, finite) ||
      !file.checked(kTriangles, all_within(file.at<int>(kTriangles), 3 * file.count(kTriangles), 0, vertices)))
    return file.damaged("its scene");
  mesh.positions = file.view<Eigen::Vector3d>(kPositions);
  mesh.triangles = file.view<Eigen::Vector3i>(kTriangles);
  mesh.material_ids = file.view<int>(kMaterialIds);
  bool names_ok = false;
  mesh.material_names = read_material_names(file[kMaterialNames], names_ok);
  if (!names_ok) return file.damaged("material names");
  mesh.coordinate_error = scalars.f64();
  mesh.coordinate_relative_error = scalars.f64();
  Tolerance& t = scene.tolerance;
  t.length = scalars.f64();
  t.places = scalars.i32();
  t.floor = scalars.f64();
  t.diagonal = scalars.f64();
  t.local_extent = scalars.f64();
  t.largest_island = scalars.f64();
  t.islands = scalars.i32();
  t.user_given = scalars.u8() != 0;
  t.raised_to_floor = scalars.u8() != 0;
  t.island_lengths = file.copy<double>(kIslandLengths);
  t.island_zones = file.copy<Aabb>(kIslandZones);
  t.island_place = file.copy<int>(kIslandPlace);
  IslandsView& islands = scene.islands;
  islands.boxes = file.view<Aabb>(kIslandBoxes);
  islands.face_counts = file.view<int>(kIslandFaceCounts);
  const auto island_count = static_cast<long long>(islands.boxes.size());
  if (t.islands != island_count || t.island_lengths.size() != islands.boxes.size() ||
      t.island_zones.size() != islands.boxes.size() || t.island_place.size() != islands.boxes.size() ||
      islands.face_counts.size() != islands.boxes.size() ||
      !all_within(t.island_place.data(), t.island_place.size(), 0, t.places) ||
      file.count(kIslandOfFace) != static_cast<std::size_t>(faces) ||
      !file.checked(kIslandOfFace, all_within(file.at<int>(kIslandOfFace), file.count(kIslandOfFace), 0, island_count)))
    return file.damaged("islands");
  islands.island_of_face = file.view<int>(kIslandOfFace);
  scene.vertices_before_weld = scalars.i32();
  scene.unreferenced_dropped = scalars.i32();
  ConnectivityView& c = scene.connectivity;
  c.component_count = scalars.i32();
  const auto uses = static_cast<long long>(file.count(kEdgeUses));
  // An edge is stored as five ints, the kind's padding zero: on a
  // little-endian host, a MeshEdge's bytes.
  static_assert(sizeof(MeshEdge) == sizeof(StoredEdge) && offsetof(MeshEdge, kind) == 4 * sizeof(std::int32_t),
                "a stored edge is read in place as a MeshEdge");
  const StoredEdge* edges = file.at<StoredEdge>(kEdges);
  bool edges_ok = true;
  for (std::size_t e = 0; e < file.count(kEdges) && edges_ok; ++e) {
    const StoredEdge& f = edges[e];
    edges_ok = !(f[0] < 0 || f[0] >= vertices || f[1] < 0 || f[1] >= vertices || f[2] < 0 || f[3] < 0 ||
                 f[2] > uses - f[3] || f[4] < 0 || f[4] > static_cast<int>(EdgeKind::non_manifold));
  }
  if (!file.checked(kEdges, edges_ok)) return file.damaged("edges");
  c.edges = file.view<MeshEdge>(kEdges);
  const EdgeUse* use = file.at<EdgeUse>(kEdgeUses);
  bool uses_ok = true;
  for (long long u = 0; u < uses && uses_ok; ++u)
    uses_ok = use[u].face >= 0 && use[u].face < faces && use[u].corner >= 0 && use[u].corner <= 2;
  if (!file.checked(kEdgeUses, uses_ok)) return file.damaged("edge uses");
  c.edge_uses = file.view<EdgeUse>(kEdgeUses);
  const auto edge_count = static_cast<long long>(c.edges.size());
  const auto per_face = static_cast<std::size_t>(faces);
  if (file.count(kFaceEdges) != per_face || file.count(kFaceNeighbours) != per_face ||
      file.count(kZeroArea) != per_face || file.count(kFaceComponent) != per_face ||
      !file.checked(kFaceEdges, all_within(file.at<int>(kFaceEdges), 3 * per_face, -1, edge_count)) ||
      !file.checked(kFaceNeighbours, all_within(file.at<int>(kFaceNeighbours), 3 * per_face, -1, faces)) ||
      !file.checked(kFaceComponent, all_within(file.at<int>(kFaceComponent), per_face, 0, c.component_count)))
    return file.damaged("connectivity");
  c.face_edges = file.view<Eigen::Vector3i>(kFaceEdges);
  c.face_neighbours = file.view<Eigen::Vector3i>(kFaceNeighbours);
  c.zero_area = file.view<char>(kZeroArea);
  c.face_component = file.view<int>(kFaceComponent);
  return scalars.failed ? file.damaged("the scalars end early") : Status::success();
}

Status read_cells(const SectionTable& file, const PreparedSceneView& scene, CellLayout& cells) {
  cells.cell_of_face = file.copy<int>(kCellOfFace);
  cells.slot_in_cell = file.copy<int>(kSlotInCell);
  cells.island_of_cell = file.copy<int>(kIslandOfCell);
  cells.cell_halvings = file.copy<int>(kCellHalvings);
  cells.island_cell_size = file.copy<double>(kIslandCellSize);
  const std::size_t faces = scene.mesh.triangles.size(), count = cells.island_of_cell.size();
  if (cells.cell_of_face.size() != faces || cells.slot_in_cell.size() != faces || cells.cell_halvings.size() != count ||
      cells.island_cell_size.size() != scene.islands.boxes.size() ||
      !all_within(cells.island_of_cell.data(), count, -1, static_cast<long long>(scene.islands.boxes.size())) ||
      !all_within(cells.cell_of_face.data(), faces, 0, static_cast<long long>(count)))
    return file.damaged("cells");
  cells.faces_of_cell.assign(count, {});
  for (std::size_t f = 0; f < faces; ++f) {
    std::vector<int>& list = cells.faces_of_cell[static_cast<std::size_t>(cells.cell_of_face[f])];
    if (cells.slot_in_cell[f] != static_cast<int>(list.size())) return file.damaged("cells: a face's slot");
    list.push_back(static_cast<int>(f));
  }
  for (const std::vector<int>& list : cells.faces_of_cell)
    if (list.empty()) return file.damaged("cells: an empty cell");
  return Status::success();
}

// The index, viewing the file; every index in it checked against what it
// names.
Status read_index(const SectionTable& file, const PreparedSceneView& scene, LittleEndianReader& scalars,
                  SceneIndexData& index) {
  const auto faces = static_cast<long long>(scene.mesh.triangles.size());
  const auto edges = static_cast<long long>(scene.connectivity.edges.size());
  const std::uint8_t mode = scalars.u8();
  if (mode > static_cast<std::uint8_t>(ValidityMode::exact)) return file.damaged("its conditions");
  index.mode = static_cast<ValidityMode>(mode);
  index.free_space_reach = scalars.f64();
  index.agent_radius = scalars.f64();
  index.max_deviation = scalars.f64();
  const bool exact = index.mode == ValidityMode::exact;
  const std::size_t bars = file.count(kBars);
  const BoundaryBar* bar = file.at<BoundaryBar>(kBars);
  bool bars_ok = true;
  for (std::size_t b = 0; b < bars && bars_ok; ++b)
    bars_ok = bar[b].edge >= 0 && bar[b].edge < edges && bar[b].face >= 0 && bar[b].face < faces;
  if (!file.checked(kBars, bars_ok)) return file.damaged("bars");
  const auto sized = [&](std::uint32_t id, long long n) {
    return file.count(id) == static_cast<std::size_t>(n) || (!exact && file.count(id) == 0);
  };
  if (file.count(kOpenEdgeUse) != static_cast<std::size_t>(edges) ||
      !file.checked(kOpenEdgeUse, all_within(file.at<int>(kOpenEdgeUse), file.count(kOpenEdgeUse), -1,
                                             static_cast<long long>(scene.connectivity.edge_uses.size()))) ||
      file.count(kFaceNormals) != static_cast<std::size_t>(faces) ||
      file.count(kFaceAreas) != static_cast<std::size_t>(faces) || !sized(kFrontReach, faces) ||
      !sized(kOpeningReach, edges) ||
      !file.checked(kFrontSweepFace,
                    all_within(file.at<int>(kFrontSweepFace), file.count(kFrontSweepFace), 0, faces)) ||
      !file.checked(kOpeningSweepEdge,
                    all_within(file.at<int>(kOpeningSweepEdge), file.count(kOpeningSweepEdge), 0, edges)) ||
      !file.checked(kBarOfPiece,
                    all_within(file.at<int>(kBarOfPiece), file.count(kBarOfPiece), 0, static_cast<long long>(bars))))
    return file.damaged("scene index");
  index.open_edge_use = file.view<int>(kOpenEdgeUse);
  index.face_normals = file.view<Eigen::Vector3d>(kFaceNormals);
  index.face_areas = file.view<double>(kFaceAreas);
  index.bars = file.view<BoundaryBar>(kBars);
  index.front_sweep_face = file.view<int>(kFrontSweepFace);
  index.front_reach = file.view<double>(kFrontReach);
  index.opening_sweep_edge = file.view<int>(kOpeningSweepEdge);
  index.opening_reach = file.view<std::array<double, kOpeningFans>>(kOpeningReach);
  index.bar_of_piece = file.view<int>(kBarOfPiece);
  AabbTree* trees[kTreeCount] = {&index.vertex_tree, &index.edge_tree,        &index.face_tree,
                                 &index.bar_tree,    &index.front_sweep_tree, &index.opening_sweep_tree};
  const std::size_t limits[kTreeCount] = {scene.mesh.positions.size(),     static_cast<std::size_t>(edges),
                                          static_cast<std::size_t>(faces), file.count(kBarOfPiece),
                                          file.count(kFrontSweepFace),     file.count(kOpeningSweepEdge)};
  for (int t = 0; t < kTreeCount; ++t) {
    const std::uint32_t id = kFirstTreeSection + kSectionsPerTree * static_cast<std::uint32_t>(t);
    const std::string why =
        AabbTreeStorage::read(file[id].data, file.count(id), file.at<int>(id + 1), file.count(id + 1),
                              file.at<Aabb>(id + 2), file.count(id + 2), limits[t], scalars, *trees[t]);
    file.release(id);
    file.release(id + 1);
    if (!why.empty()) return file.damaged(section_name(id) + ": " + why);
  }
  if (scalars.failed || scalars.at != scalars.size) return file.damaged("scalars");
  return Status::success();
}

} // namespace

Result<MappedPreparedScene> read_prepared_scene(const MappedFile& file, const std::string& name) {
  SectionTable table(file, name);
  MappedPreparedScene out;
  if (Status s = table.read_header(out.options_key); !s.ok()) return s;
  if (Status s = table.check_sums(); !s.ok()) return s;
  LittleEndianReader scalars{table[kScalars].data, table[kScalars].bytes, 0};
  if (Status s = read_scene(table, scalars, out.scene); !s.ok()) return s;
  if (Status s = read_cells(table, out.scene, out.cells); !s.ok()) return s;
  if (Status s = read_index(table, out.scene, scalars, out.index); !s.ok()) return s;
  // What was read to check it is read again only where a cell needs it.
  file.release_pages();
  return out;
}

} // namespace hullcover::detail

// Writing the prepared scene file (prepared_scene_file.h); reading it is in
// prepared_scene_reading.cpp. Both share the section table of
// prepared_scene_sections.h.

#include "cells/prepared_scene_file.h"
#include "cells/prepared_scene_sections.h"

#include "cells/cell_merging.h"
#include "cells/cell_result_bytes.h"

#include "hullcover/geometry/atomic_file.h"
#include "hullcover/geometry/little_endian_bytes.h"
#include "hullcover/geometry/mapped_file.h"

#include <cstring>

namespace hullcover::detail {

void AabbTreeStorage::write(const AabbTree& tree, int which, PreparedSections& out, LittleEndianWriter& scalars) {
  static_assert(sizeof(AabbTree::Node) == kTreeNodeBytes, "a node is stored as laid out in memory");
  const std::uint32_t first = kFirstTreeSection + kSectionsPerTree * static_cast<std::uint32_t>(which);
  out.add(first, tree.nodes_);
  out.add(first + 1, tree.items_);
  out.add(first + 2, tree.leaf_boxes_);
  scalars.i32(tree.root_.index);
  scalars.i32(tree.root_.count);
  for (int axis = 0; axis < 3; ++axis) {
    std::uint32_t low, high;
    std::memcpy(&low, &tree.root_box_.min[axis], 4);
    std::memcpy(&high, &tree.root_box_.max[axis], 4);
    scalars.u32(low);
    scalars.u32(high);
  }
}

std::uint64_t prepared_options_key(const DecompositionStages& stages) {
  const Covering& covering = stages.covering;
  const DecomposeOptions& options = covering.options;
  LittleEndianWriter key;
  key.bytes.assign(kPreparedMagic, sizeof kPreparedMagic);
  key.u32(kPreparedVersion);
  write_merging_options(key, covering);
  key.u8(static_cast<std::uint8_t>(options.conditions));
  key.f64(covering.bar_half_length);
  key.f64(covering.prism_thickness_cap);
  key.f64(covering.free_space_reach);
  key.u8(covering.free_space_capped);
  key.f64(covering.near_merge_distance);
  key.u8(options.prism_thickness_cap.has_value());
  key.u8(options.near_merge_distance.has_value());
  key.u8(options.bar_half_length.has_value());
  key.u8(options.cell_size.has_value());
  key.f64(options.cell_size.value_or(0.0));
  return fnv1a(reinterpret_cast<const unsigned char*>(key.bytes.data()), key.bytes.size());
}

namespace {

// The scene's numbers that are not arrays, and the trees' roots.
void write_scalars(const PreparedSceneView& scene, const DecompositionStages& stages, PreparedSections& out,
                   LittleEndianWriter& s) {
  s.f64(scene.mesh.coordinate_error);
  s.f64(scene.mesh.coordinate_relative_error);
  const Tolerance& t = scene.tolerance;
  s.f64(t.length);
  s.i32(t.places);
  s.f64(t.floor);
  s.f64(t.diagonal);
  s.f64(t.local_extent);
  s.f64(t.largest_island);
  s.i32(t.islands);
  s.u8(t.user_given);
  s.u8(t.raised_to_floor);
  s.i32(scene.vertices_before_weld);
  s.i32(scene.unreferenced_dropped);
  s.i32(scene.connectivity.component_count);
  const SceneIndexData& index = stages.index_data;
  s.u8(static_cast<std::uint8_t>(index.mode));
  s.f64(index.free_space_reach);
  s.f64(index.agent_radius);
  s.f64(index.max_deviation);
  const AabbTree* trees[kTreeCount] = {&index.vertex_tree, &index.edge_tree,        &index.face_tree,
                                       &index.bar_tree,    &index.front_sweep_tree, &index.opening_sweep_tree};
  for (int t_index = 0; t_index < kTreeCount; ++t_index) AabbTreeStorage::write(*trees[t_index], t_index, out, s);
}

std::string material_names_blob(const MeshView& mesh) {
  LittleEndianWriter names;
  names.u32(static_cast<std::uint32_t>(mesh.material_names.size()));
  for (const std::string& name : mesh.material_names) {
    names.u32(static_cast<std::uint32_t>(name.size()));
    names.bytes += name;
  }
  return names.bytes;
}

} // namespace

Status write_prepared_scene(const std::string& path, const PreparedSceneView& scene,
                            const DecompositionStages& stages) {
  if (!host_is_little_endian())
    return {StatusCode::internal_error, "prepared scene files are written on little-endian machines only"};
  PreparedSections out;
  const MeshView& mesh = scene.mesh;
  out.add(kPositions, mesh.positions);
  out.add(kTriangles, mesh.triangles);
  out.add(kMaterialIds, mesh.material_ids);
  out.add_blob(kMaterialNames, material_names_blob(mesh));
  const Tolerance& t = scene.tolerance;
  out.add(kIslandLengths, t.island_lengths);
  out.add(kIslandZones, t.island_zones);
  out.add(kIslandPlace, t.island_place);
  const IslandsView& islands = scene.islands;
  out.add(kIslandOfFace, islands.island_of_face);
  out.add(kIslandBoxes, islands.boxes);
  out.add(kIslandFaceCounts, islands.face_counts);
  const ConnectivityView& c = scene.connectivity;
  // An edge has holes after its kind: stored as five ints.
  std::vector<StoredEdge> edges;
  edges.reserve(c.edges.size());
  for (const MeshEdge& e : c.edges)
    edges.push_back({e.v0, e.v1, e.first_use, e.use_count, static_cast<std::int32_t>(e.kind)});
  out.add(kEdges, edges);
  out.add(kEdgeUses, c.edge_uses);
  out.add(kFaceEdges, c.face_edges);
  out.add(kFaceNeighbours, c.face_neighbours);
  out.add(kZeroArea, c.zero_area);
  out.add(kFaceComponent, c.face_component);
  const CellLayout& cells = stages.cells;
  out.add(kCellOfFace, cells.cell_of_face);
  out.add(kSlotInCell, cells.slot_in_cell);
  out.add(kIslandOfCell, cells.island_of_cell);
  out.add(kCellHalvings, cells.cell_halvings);
  out.add(kIslandCellSize, cells.island_cell_size);
  const SceneIndexData& index = stages.index_data;
  out.add(kOpenEdgeUse, index.open_edge_use);
  out.add(kFaceNormals, index.face_normals);
  out.add(kFaceAreas, index.face_areas);
  out.add(kBars, index.bars);
  out.add(kFrontSweepFace, index.front_sweep_face);
  out.add(kFrontReach, index.front_reach);
  out.add(kOpeningSweepEdge, index.opening_sweep_edge);
  out.add(kOpeningReach, index.opening_reach);
  out.add(kBarOfPiece, index.bar_of_piece);
  LittleEndianWriter scalars;
  write_scalars(scene, stages, out, scalars);
  out.add_blob(kScalars, std::move(scalars.bytes));
  const std::string header = out.header(prepared_options_key(stages));
  Status written = write_file_atomically(path, [&](std::FILE* file) { return out.write(header, file); });
  // Readers on this machine then bring in the pages they read one by one.
  if (written.ok()) drop_cached_pages(path);
  return written;
}

} // namespace hullcover::detail

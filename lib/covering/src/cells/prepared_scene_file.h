#pragma once
// The prepared scene file (docs/worlds.md, "The prepared scene file"): what
// stage 1 made (the welded scene, its cells and the scene index with its
// trees and free-space sweeps) in one binary file that a bake's workers map
// instead of importing and indexing the scene. Internal to the decomposer;
// StagedDecomposition::write_prepared and ::map_prepared are its public face.
//
// Layout (version 1), little-endian:
//   0   magic "HCPREP\r\n"
//   8   u32 version, u32 section count n
//   16  u64 options key (prepared_options_key), u64 0
//   32  n section entries of 32 bytes: u32 id, u32 element size,
//       u64 offset, u64 length, u64 checksum of the section's bytes
//   32 + 32 n: u64 checksum of every byte before it
// Each section starts on a multiple of kSectionAlignment
// (prepared_scene_sections.h; the search trees'
// nodes are read in place, 64-byte aligned). Arrays of plain numbers and
// records are stored as the host lays them out, so the file is refused on a
// big-endian host; records with holes (an edge's kind) are stored field by
// field.

#include "cells/decomposition_stages.h"

#include "hullcover/geometry/mapped_file.h"

#include <cstdint>
#include <memory>
#include <string>

namespace hullcover::detail {

/// What decides the stages besides the scene: the resolved lengths and
/// every option prepare_stages reads, hashed. A worker's options must give
/// the key the file was written with.
std::uint64_t prepared_options_key(const DecompositionStages& stages);

/// Writes the file for `stages`, prepared from `scene` (the mesh as the
/// caller gave it: a worker puts it in its own local frame again), to
/// `path` atomically. The arrays are written from where they lie, not
/// copied. Fails with `unwritable_file`.
Status write_prepared_scene(const std::string& path, const PreparedSceneView& scene, const DecompositionStages& stages);

/// What a worker takes from a mapped file: the scene and the index (read
/// in place from `file`, which must outlive them) and the cells (copied).
struct MappedPreparedScene {
  PreparedSceneView scene;
  CellLayout cells;
  SceneIndexData index;
  std::uint64_t options_key = 0;
};

/// Reads `file`: checks its header, every section's checksum and length,
/// and every index and tree link the decomposer follows (so that no read
/// leaves an array), handing back each section's pages once checked.
/// Fails with `unknown_format` (not a prepared scene, or another version or
/// byte order) or `unreadable_file` (damaged: the message names the
/// section) and a message starting with `name`.
Result<MappedPreparedScene> read_prepared_scene(const MappedFile& file, const std::string& name);

} // namespace hullcover::detail

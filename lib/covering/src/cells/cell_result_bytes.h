#pragma once
// A cell's result as bytes (StagedDecomposition): to move it between
// processes (a distributed bake) and to keep it for a later bake (the cell
// cache). Faces are written by their slot in the cell and vertices by their
// first use in the cell's faces, so the bytes still mean the same patches
// in an edited scene whose faces of this cell are the same (same key).
//
// Layout (integers little-endian, reals IEEE-754 binary64 little-endian):
//   magic "HCCELL\0\0", u32 version, u64 cell key, u32 cell faces,
//   u32 cell vertices, statistics (u32 count, that many i64), u32 patches,
//   per patch: u32 n + n u32 face slots, u32 n + n u32 hull vertices,
//   u32 n + n x 4 f64 face planes, 5 f64 (area, boundary length, area
//   vector), u8 planar, i32 material, i32 version, u8 has solid, and the
//   solid: u32 V + V x 3 f64, u32 F + per facet u32 n + n u32 corners,
//   u32 P + P x 4 f64 planes, u32 (0 or V) + i32 vertex ids (-1: none);
//   then per patch its hull (patch_hulls.h): a solid as above, f64
//   thickness, f64 volume, u8 kept as grown, u32 P + P u8 surface planes;
//   u64 FNV-1a-64 of everything before it.

#include "cells/cell_merging.h"

#include "hullcover/geometry/little_endian_bytes.h"

#include <cstdint>
#include <string>

namespace hullcover::detail {

/// Writes the options every cell's merging reads (not the per-island
/// lengths): part of each cell key, and of the cell cache's record of the
/// last bake (scene_change.h).
void write_merging_options(LittleEndianWriter& out, const Covering& covering);

/// What decides cell `cell`'s merging, hashed (FNV-1a-64): its faces (slot
/// order, corners by first use, materials), their positions' exact bits,
/// the tolerance, and every option and resolved length the merging reads.
/// Two scenes whose cell has the same key merge it alike, up to the
/// validity checks against the rest of the scene (PatchMerger::recheck_patches).
std::uint64_t cell_key(const DecompositionStages& stages, int cell);

/// `result` of cell `cell`, as bytes.
std::string cell_result_bytes(const DecompositionStages& stages, int cell, const CellResult& result);

/// Reads bytes written by cell_result_bytes for a cell of the same key.
/// Fails with `unknown_format` (not a cell result, another version) or
/// `unreadable_file` (truncated, checksum, another key, an index out of
/// range, a face in two patches or a face of non-zero area in none, a
/// non-finite value): bytes from a cache are never trusted.
Result<CellResult> cell_result_from_bytes(const DecompositionStages& stages, int cell, const std::string& bytes);

} // namespace hullcover::detail

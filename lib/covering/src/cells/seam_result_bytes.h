#pragma once
// A seam cell's result (seam_finish.h) as bytes, to move it between the
// processes of one bake (`python3 -m hullcover.bake` runs each seam cell's
// finish as a task). Vertices are named by mesh vertex id: the bytes are
// read by the stages of the same prepared scene, never kept for an edited
// one (the cell cache keeps cells, not seam cells).
//
// Layout (integers little-endian, reals IEEE-754 binary64 little-endian):
//   magic "HCSEAM\0\0", u32 version, u32 seam cell, u32 its faces, u32 the
//   scene's faces, statistics (u32 count, that many i64), i64 seam merges,
//   i32 largest cell, i32 its kept try, u32 hulls, per hull: the solid
//   (hull_record_bytes.h), u32 n + n u32 faces (ascending), u8 planar, f64
//   thickness, i32 material, f64 volume, u32 P + P u8 surface planes; then
//   u64 FNV-1a-64 of everything before it.

#include "cells/seam_finish.h"

#include <string>

namespace hullcover::detail {

/// `result` of seam cell `seam` of `seams` (seam_layout), as bytes.
std::string seam_result_bytes(const DecompositionStages& stages, const CellLayout& seams, int seam,
                              const SeamResult& result);

/// Reads bytes seam_result_bytes wrote for seam cell `seam`. Fails with
/// `unknown_format` (not a seam result, another version) or
/// `unreadable_file` (truncated, checksum, another seam cell or scene, an
/// index out of range, a face outside the seam cell or in two hulls, a
/// non-finite value, a hull that does not hold its faces within the
/// island's tolerance, or a material that is not its faces' smallest).
Result<SeamResult> seam_result_from_bytes(const DecompositionStages& stages, const CellLayout& seams, int seam,
                                          const std::string& bytes);

} // namespace hullcover::detail

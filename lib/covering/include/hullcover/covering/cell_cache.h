#pragma once
/// \file cell_cache.h
/// Re-bakes of only what changed: a folder of cell results keyed by their
/// content (StagedDecomposition::cell_key), one file per cell,
/// `<key as 16 hex digits>.cell`.
///
/// A bake with a cache reuses a cell's stored result when the cell's key is
/// unchanged (same faces, positions to the bit, materials, tolerance and
/// options) AND every hull it keeps passes the validity conditions against
/// the scene as it is now and is made the same now (an edit anywhere can
/// put a face inside a kept hull, or open space one takes: a new doorway far
/// away). Every other cell is merged again and stored. A cell's bytes carry
/// its patches' hulls; the finish makes anew only those the seam pass
/// changes. The covering is valid either way; after an edit it may differ
/// from a full bake's, which could merge more where the edit freed room.
///
/// Each bake also leaves `last-bake.scene`: a hash and box per face and the
/// checksum of each cell's bytes it used (scene_change.h). The next bake
/// with the same options then re-checks, of the cells it finds as the last
/// bake used them, only the patches within reach of a face added or removed
/// since (near it, or meeting a free-space sweep that crosses it); without
/// it (or with an agent radius or max deviation), every patch.
///
/// Files are written atomically (atomic_file.h); a file that does not read
/// back (another version, truncated, changed) is treated as absent and
/// replaced. Entries no bake uses any more are left in place: the folder
/// may serve several scenes; delete it to start over.

#include "hullcover/covering/covering.h"

#include <string>

namespace hullcover {

/// What a bake with a cache did.
struct CellCacheReport {
  int cells = 0;  ///< cells in the scene
  int reused = 0; ///< taken from the cache, re-checked against this scene
  int stale = 0;  ///< found under their key but refused by the re-check (then merged)
  int merged = 0; ///< merged in this bake (stale ones included) and stored
  /// Faces added plus faces removed since the last bake; -1 when not known
  /// (no snapshot, other options, an allowance): then every patch is re-checked.
  int changed_faces = -1;
  long patches_rechecked = 0;      ///< patches of cached cells re-checked (and their hulls made again)
  long patches_kept_unchecked = 0; ///< patches of cached cells no change since the last bake can reach
  double seconds_checking = 0.0;   ///< wall time reading and re-checking cached cells (and finding the change)
  double seconds_merging = 0.0;    ///< wall time merging the other cells
};

/// decompose() with a cell cache in folder `cache_dir` (created if absent,
/// its parent must exist). Cells are checked or merged on
/// DecomposeOptions::threads threads; progress is reported as the cells
/// finish. Fails as decompose() does, and with `unwritable_file` when the
/// folder cannot be made or a cell cannot be stored.
[[nodiscard]] Result<Covering> decompose_with_cell_cache(PreparedMesh prepared, const DecomposeOptions& options,
                                                         const std::string& cache_dir, CellCacheReport& report);

} // namespace hullcover

#pragma once
// The decomposition's stages, internal to the decomposer: what every cell
// shares (resolved lengths, islands, cells, the scene index), one cell's
// merging, and the finish (seam pass and hulls). decompose() runs them in one
// process; StagedDecomposition (staged_decomposition.h) lets cells run
// elsewhere, or come from an earlier bake.

#include "hullcover/covering/covering_types.h"
#include "hullcover/covering/merge_cells.h"
#include "hullcover/geometry/parallel_for.h"
#include "hullcover/mesh/mesh_islands.h"
#include "hullcover/mesh/tolerance.h"

#include "cells/decomposition_stages.h"
#include "merging/patch_hulls.h"
#include "merging/patch_merging.h"
#include "validity/scene_index.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hullcover::detail {

/// What one cell gave: the patches it kept, their hulls and its counts.
struct CellResult {
  std::vector<Patch> patches;   ///< alive ones only
  std::vector<PatchHull> hulls; ///< per patch (same index), made on the cell's view
  CoveringStatistics statistics;
};

/// Cells and a scene index made before (read from a prepared scene file,
/// prepared_scene_file.h), for prepare_stages to take instead of making them.
struct MadeStages {
  CellLayout cells;
  SceneIndexData index;
};

/// Checks the options, resolves lengths, finds islands and cells and builds
/// the scene index; or, given `made`, takes its cells and index (moved out
/// of it). Fails with `invalid_argument` for options out of range.
Result<std::unique_ptr<DecompositionStages>> prepare_stages(const PreparedSceneView& prepared,
                                                            const DecomposeOptions& options,
                                                            MadeStages* made = nullptr);

/// The near-merge distance cell `cell` merges with: the user's, else its
/// island's own (the largest island's for the one cell of --cell-size 0).
double cell_near_merge_distance(const DecompositionStages& stages, int cell);

/// The half-length of the bars on island `island`'s faces (-1: the whole
/// scene's): the user's, else exact mode's multiple of the island's own
/// tolerance, else the paper's (one for the scene).
double island_bar_half_length(const DecompositionStages& stages, int island);

/// Merges one cell (every order try; the try with the fewest hulls is
/// kept) and makes its patches' hulls. `progress(fraction)`, when set,
/// reports the cell's own share.
CellResult merge_cell(const DecompositionStages& stages, int cell, const std::function<void(double)>& progress);

/// Whether `result` (read from a cell's bytes) can stand in for cell `cell`
/// in this scene: every patch `touched` selects (every one when `touched`
/// is empty) passes the checks its merge passed
/// (PatchMerger::recheck_patches) and gets the same hull made now (so the
/// finish, which keeps it, gives what a bake of this scene would). False,
/// with `why` (optional) saying why, otherwise.
bool cell_result_holds(const DecompositionStages& stages, int cell, const CellResult& result,
                       const std::function<bool(const Patch&, const PatchHull&)>& touched, std::string* why);

/// cell_result_holds on `bytes` read back for cell `cell`
/// (StagedDecomposition::still_valid); false, with `why`, when they do not
/// read back for its key.
bool cell_bytes_hold(const DecompositionStages& stages, int cell, const std::string& bytes,
                     const std::function<bool(const Patch&, const PatchHull&)>& touched, std::string* why);

/// The cells' numbers, most faces first (ties by number): the order to run
/// them in, so the last to finish is a small one.
std::vector<int> largest_cells_first(const CellLayout& cells);

/// Merges every cell on `threads` threads, largest cells first; results per
/// cell, whichever thread ran it. Reports DecomposeOptions::progress.
std::vector<CellResult> merge_cells(const DecompositionStages& stages, int threads);

/// The seam pass and the hulls, from every cell's result (index = cell).
/// `seconds_cells`: the cells' merging time, for the statistics.
Covering finish_stages(const DecompositionStages& stages, std::vector<CellResult> results, double seconds_cells);

/// parallel_for (hullcover/geometry/parallel_for.h) taking the i in the
/// given order (empty: ascending).
void run_in_parallel(int count, int threads, const std::vector<int>& order, const std::function<void(int)>& job);

/// Adds a cell's counts to the scene's (timings are measured for the whole).
void add_counts(CoveringStatistics& total, const CoveringStatistics& cell);

} // namespace hullcover::detail

#pragma once
// The finish (stage 3 of staged_decomposition.h) in two steps, so that a
// bake can run the first as tasks:
//  1. per seam cell (an island; the whole scene with --cell-size 0), from
//     its cells' results: the seam pass across its cell borders, then the
//     hulls of its surviving patches (finish_seam);
//  2. for the scene: flat hulls for faces no hull covers (which may lie
//     within tol of another island's hull), every hull in the order of its
//     first face, and back to the scene's frame (assemble_covering).
// No edge joins two islands, so step 1 of one seam cell reads no other's
// patches; its result is a pure function of its cells' results, and the
// covering the same whichever process ran which seam cell.

#include "cells/cell_merging.h"

#include <vector>

namespace hullcover::detail {

/// What step 1 gives for one seam cell.
struct SeamResult {
  /// The hulls of its surviving patches, by patch id (its cells' patches in
  /// cell order, as the seam pass numbers them), in the local frame.
  std::vector<CoveringHull> hulls;
  /// Its cells' counts, its seam pass's and its hull making's;
  /// `seam_merges`: the seam pass's merges.
  CoveringStatistics statistics;
  /// Its first cell of the most faces, and that cell's kept order try (the
  /// scene reports the largest cell's).
  int largest_cell = -1;
  int largest_cell_kept_try = 0;
};

/// The seam cells: one per island (numbered as the islands), or one for
/// the whole scene when the cells are (--cell-size 0).
CellLayout seam_layout(const DecompositionStages& stages);

/// Step 1 for seam cell `seam` of `seams` (seam_layout), from the results
/// of its cells (`cells`, ascending: every cell whose faces lie in it),
/// making hulls on `threads` threads.
SeamResult finish_seam(const DecompositionStages& stages, const CellLayout& seams, int seam,
                       const std::vector<int>& cells, std::vector<CellResult> results, int threads);

/// Step 2, from every seam cell's result (index = seam cell). Timings, for
/// the statistics: the cells' merging, the seam pass, the hull making.
Covering assemble_covering(const DecompositionStages& stages, std::vector<SeamResult> seams, double seconds_cells,
                           double seconds_seams, double seconds_hulls);

} // namespace hullcover::detail

// The seam pass: after every cell has merged on its own (merge_cells.h),
// patches on either side of a cell border that share an edge are tried as
// pairs under the same conditions, so cells cost hulls only where the
// greedy order would have differed, not wherever a floor crosses a border.

#include "merging/patch_merging.h"

#include <utility>

namespace hullcover::detail {

PatchMerger::PatchMerger(const SceneIndex& index, const DecomposeOptions& options, const CellLayout& seams,
                         int seam_cell, std::vector<Patch> patches, std::vector<int> cell_of_patch,
                         CoveringStatistics& statistics)
    : index_(index), options_(options), cells_(seams), cell_(seam_cell), statistics_(statistics),
      near_merge_distance_(0.0), cell_of_patch_(std::move(cell_of_patch)) {
  patches_ = std::move(patches);
  face_patch_.assign(seams.faces_of_cell[seam_cell].size(), -1);
  for (int p = 0; p < static_cast<int>(patches_.size()); ++p)
    for (int f : patches_[p].faces) patch_entry(f) = p;
  // Zero-area faces are in no patch: alone and dead, as the cells left them.
  for (int& entry : face_patch_)
    if (entry < 0) {
      entry = static_cast<int>(patches_.size());
      patches_.emplace_back();
      patches_.back().alive = false;
      cell_of_patch_.push_back(-1);
    }
  recount_shared_edges();
}

void PatchMerger::run_seams() {
  const int starting = static_cast<int>(cell_of_patch_.size());
  for (int p = 0; p < starting; ++p)
    for (const auto& [q, length] : patches_[p].shared_length)
      if (p < q && q < starting && cell_of_patch_[p] != cell_of_patch_[q]) push_pair(p, q);
  run_pairs();
}

} // namespace hullcover::detail

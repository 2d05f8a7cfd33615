// One cell's merging, and every cell's on a pool of threads (merge_cells.h:
// cells share only the read-only scene index, so they run apart).

#include "cells/cell_merging.h"

#include "hullcover/geometry/tolerances.h"

#include "hullcover/geometry/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numeric>

namespace hullcover::detail {

void run_in_parallel(int count, int threads, const std::vector<int>& order, const std::function<void(int)>& job) {
  parallel_for(count, threads, [&](int i) { job(order.empty() ? i : order[i]); });
}

void add_counts(CoveringStatistics& total, const CoveringStatistics& cell) {
  total.zero_area_faces_skipped += cell.zero_area_faces_skipped;
  total.merges += cell.merges;
  total.near_merges += cell.near_merges;
  total.dissolved_patches += cell.dissolved_patches;
  total.candidates_tested += cell.candidates_tested;
  for (size_t i = 0; i < total.rejections.size(); ++i) total.rejections[i] += cell.rejections[i];
  total.qhull_calls += cell.qhull_calls;
  total.incremental_hulls += cell.incremental_hulls;
  total.prisms_made_flat += cell.prisms_made_flat;
  total.solids_kept_as_grown += cell.solids_kept_as_grown;
}

double cell_near_merge_distance(const DecompositionStages& stages, int cell) {
  const Covering& covering = stages.covering;
  const DecomposeOptions& options = covering.options;
  const int island = stages.cells.island_of_cell[cell];
  if (options.near_merge_distance || island < 0) return covering.near_merge_distance;
  // A cell cut from a crowded cube reaches as far as its own side allows
  // (merge_cells.h, cell_halvings): halving is exact.
  return options.conditions == ValidityMode::exact
             ? std::ldexp(kDefaultNearMergeRelative * covering.island_extents[island],
                          -stages.cells.cell_halvings[cell])
             : 0.0;
}

double island_bar_half_length(const DecompositionStages& stages, int island) {
  const Covering& covering = stages.covering;
  const DecomposeOptions& options = covering.options;
  if (options.bar_half_length || options.conditions != ValidityMode::exact) return covering.bar_half_length;
  return kExactBarHalfLengthInTolerances *
         (island < 0 ? stages.prepared.tolerance.length : stages.island_tolerance[island]);
}

CellResult merge_cell(const DecompositionStages& stages, int cell, const std::function<void(double)>& progress) {
  const Covering& covering = stages.covering;
  const DecomposeOptions& options = covering.options;
  const double near_merge_distance = cell_near_merge_distance(stages, cell);
  // Each try keeps its own options and statistics: the merger refers to them.
  struct Try {
    DecomposeOptions options;
    CoveringStatistics statistics;
    std::unique_ptr<PatchMerger> merger;
    int hulls = 0;
  };
  std::unique_ptr<Try> kept;
  for (int attempt = 0; attempt < options.order_tries; ++attempt) {
    auto run = std::make_unique<Try>();
    run->options = options;
    run->options.dissolve = covering.dissolve;
    if (attempt > 0) {
      run->options.order = MergeOrder::random;
      run->options.seed = options.seed + static_cast<std::uint64_t>(attempt - 1);
    }
    run->options.progress = nullptr;
    if (progress)
      run->options.progress = [&progress, attempt, &options](double fraction) {
        progress((attempt + fraction) / options.order_tries);
      };
    run->merger = std::make_unique<PatchMerger>(stages.index_of_cell(cell), run->options, near_merge_distance,
                                                stages.cells, cell, run->statistics);
    run->merger->run();
    for (const Patch& patch : run->merger->patches()) run->hulls += patch.alive;
    if (!kept || run->hulls < kept->hulls) {
      run->statistics.kept_try = attempt;
      kept = std::move(run);
    }
  }
  CellResult result;
  result.statistics = kept->statistics;
  ConvexHullBuilder builder;
  std::vector<int> scratch;
  const std::vector<Patch>& patches = kept->merger->patches();
  for (int id = 0; id < static_cast<int>(patches.size()); ++id)
    if (patches[id].alive) {
      result.patches.push_back(patches[id]);
      result.hulls.push_back(make_patch_hull(stages, stages.index_of_cell(cell), *kept->merger, id, builder, scratch));
    }
  return result;
}

std::vector<int> largest_cells_first(const CellLayout& cells) {
  std::vector<int> order(cells.faces_of_cell.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return cells.faces_of_cell[a].size() > cells.faces_of_cell[b].size(); });
  return order;
}

std::vector<CellResult> merge_cells(const DecompositionStages& stages, int threads) {
  const CellLayout& cells = stages.cells;
  const DecomposeOptions& options = stages.covering.options;
  const int cell_count = static_cast<int>(cells.faces_of_cell.size());
  const std::vector<int> order = largest_cells_first(cells);
  // Progress: each cell's fraction, weighted by its faces; reported one
  // call at a time.
  std::mutex progress_mutex;
  std::vector<double> done(cell_count, 0.0);
  double done_faces = 0.0;
  const double total_faces = std::max<double>(1.0, static_cast<double>(stages.prepared.mesh.triangles.size()));
  const auto report = [&](int cell, double fraction) {
    const std::lock_guard<std::mutex> lock(progress_mutex);
    done_faces += (fraction - done[cell]) * static_cast<double>(cells.faces_of_cell[cell].size());
    done[cell] = fraction;
    options.progress(std::min(1.0, done_faces / total_faces));
  };
  std::vector<CellResult> results(cell_count);
  run_in_parallel(cell_count, threads, order, [&](int cell) {
    std::function<void(double)> progress;
    if (options.progress) progress = [&report, cell](double fraction) { report(cell, fraction); };
    results[cell] = merge_cell(stages, cell, progress);
    if (progress) progress(1.0);
  });
  return results;
}

} // namespace hullcover::detail

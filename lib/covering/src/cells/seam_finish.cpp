#include "cells/seam_finish.h"

#include "cells/local_frame.h"
#include "merging/face_coverage.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <numeric>
#include <tuple>

namespace hullcover::detail {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// One seam cell on its way through step 1.
struct SeamWork {
  int seam = 0;
  // Its cells' patches, the cell each came from, the hull that cell made
  // and the patch's version then (a patch the seam pass leaves unchanged
  // keeps that hull).
  std::vector<Patch> patches;
  std::vector<int> origins;
  std::vector<PatchHull> hulls;
  std::vector<int> versions;
  CoveringStatistics seam_statistics;
  std::unique_ptr<PatchMerger> merger;
  SeamResult result;
};

void take_cell(const DecompositionStages& stages, int cell, CellResult cell_result, SeamWork& work) {
  SeamResult& result = work.result;
  add_counts(result.statistics, cell_result.statistics);
  const std::vector<std::vector<int>>& faces = stages.cells.faces_of_cell;
  if (result.largest_cell < 0 || faces[cell].size() > faces[result.largest_cell].size()) {
    result.largest_cell = cell;
    result.largest_cell_kept_try = cell_result.statistics.kept_try;
  }
  for (size_t p = 0; p < cell_result.patches.size(); ++p) {
    work.versions.push_back(cell_result.patches[p].version);
    work.hulls.push_back(std::move(cell_result.hulls[p]));
    work.patches.push_back(std::move(cell_result.patches[p]));
    work.origins.push_back(cell);
  }
}

void run_seam_pass(const DecompositionStages& stages, const CellLayout& seams, SeamWork& work) {
  DecomposeOptions options = stages.covering.options;
  options.progress = nullptr;
  work.merger =
      std::make_unique<PatchMerger>(stages.index_of_island(seams.island_of_cell[work.seam]), options, seams, work.seam,
                                    std::move(work.patches), std::move(work.origins), work.seam_statistics);
  work.merger->run_seams();
  work.result.statistics.seam_merges += work.seam_statistics.merges;
  add_counts(work.result.statistics, work.seam_statistics);
}

// The hulls of every surviving patch of `works`, on `threads` threads.
void make_hulls(const DecompositionStages& stages, const CellLayout& seams, std::vector<SeamWork>& works, int threads) {
  // (work, patch id, place in the work's hulls), in work and id order.
  std::vector<std::tuple<int, int, int>> alive;
  for (int w = 0; w < static_cast<int>(works.size()); ++w) {
    const std::vector<Patch>& patches = works[w].merger->patches();
    int place = 0;
    for (int id = 0; id < static_cast<int>(patches.size()); ++id)
      if (patches[id].alive) alive.emplace_back(w, id, place++);
    works[w].result.hulls.resize(static_cast<size_t>(place));
  }
  std::vector<CoveringStatistics> made_counts(alive.size());
  // Hulls are made in runs, each with its own Qhull builder and scratch.
  constexpr int kHullsPerRun = 64;
  const int hull_count = static_cast<int>(alive.size());
  run_in_parallel((hull_count + kHullsPerRun - 1) / kHullsPerRun, threads, {}, [&](int run) {
    ConvexHullBuilder builder;
    std::vector<int> scratch;
    for (int i = run * kHullsPerRun; i < std::min(hull_count, (run + 1) * kHullsPerRun); ++i) {
      const auto [w, id, place] = alive[i];
      SeamWork& work = works[w];
      const PatchMerger& merger = *work.merger;
      const bool unchanged =
          id < static_cast<int>(work.versions.size()) && merger.patches()[id].version == work.versions[id];
      PatchHull made = unchanged ? std::move(work.hulls[id])
                                 : make_patch_hull(stages, stages.index_of_island(seams.island_of_cell[work.seam]),
                                                   merger, id, builder, scratch);
      count_hull_making(made_counts[i], made);
      work.result.hulls[place] = std::move(made.hull);
    }
  });
  for (int i = 0; i < hull_count; ++i) add_counts(works[std::get<0>(alive[i])].result.statistics, made_counts[i]);
}

} // namespace

CellLayout seam_layout(const DecompositionStages& stages) {
  const DecomposeOptions& options = stages.covering.options;
  return options.cell_size && *options.cell_size == 0.0 ? lay_out_cells(stages.prepared, stages.prepared.islands, 0.0)
                                                        : lay_out_islands(stages.prepared, stages.prepared.islands);
}

SeamResult finish_seam(const DecompositionStages& stages, const CellLayout& seams, int seam,
                       const std::vector<int>& cells, std::vector<CellResult> results, int threads) {
  std::vector<SeamWork> works(1);
  works[0].seam = seam;
  for (size_t i = 0; i < cells.size(); ++i) take_cell(stages, cells[i], std::move(results[i]), works[0]);
  run_seam_pass(stages, seams, works[0]);
  make_hulls(stages, seams, works, threads);
  return std::move(works[0].result);
}

Covering assemble_covering(const DecompositionStages& stages, std::vector<SeamResult> seams, double seconds_cells,
                           double seconds_seams, double seconds_hulls) {
  const Clock::time_point start = Clock::now();
  Covering covering = stages.covering;
  const DecomposeOptions& options = covering.options;
  CoveringStatistics& stats = covering.statistics;
  const std::vector<std::vector<int>>& faces = stages.cells.faces_of_cell;
  // The scene reports the kept try of its first cell of the most faces.
  int largest = -1;
  size_t hull_count = 0;
  for (const SeamResult& seam : seams) {
    add_counts(stats, seam.statistics);
    stats.seam_merges += seam.statistics.seam_merges;
    hull_count += seam.hulls.size();
    const int c = seam.largest_cell;
    if (c >= 0 && (largest < 0 || faces[c].size() > faces[largest].size() ||
                   (faces[c].size() == faces[largest].size() && c < largest))) {
      largest = c;
      stats.kept_try = seam.largest_cell_kept_try;
    }
  }
  stats.order_tries = options.order_tries;
  stats.seconds_seams = seconds_seams;
  stats.seconds_merging = seconds_cells + seconds_seams;
  covering.hulls.reserve(hull_count);
  for (SeamResult& seam : seams)
    for (CoveringHull& hull : seam.hulls) covering.hulls.push_back(std::move(hull));
  seams.clear();
  const FaceCoverageCount coverage = cover_uncovered_faces(stages, covering, threads_to_use(options.threads));
  stats.faces_given_flat_hulls = coverage.covered;
  stats.thin_faces_given_flat_hulls = coverage.thin_covered;
  stats.faces_left_uncovered = coverage.bare;
  std::sort(covering.hulls.begin(), covering.hulls.end(),
            [](const CoveringHull& x, const CoveringHull& y) { return x.faces.front() < y.faces.front(); });
  for (CoveringHull& hull : covering.hulls) hull.cell = stages.cells.cell_of_face[hull.faces.front()];
  if (!stages.frame_origin.isZero()) to_scene_frame(covering, stages.frame_origin);
  stats.seconds_output = seconds_hulls + seconds_since(start);
  if (options.progress) options.progress(1.0);
  return covering;
}

Covering finish_stages(const DecompositionStages& stages, std::vector<CellResult> results, double seconds_cells) {
  const int threads = threads_to_use(stages.covering.options.threads);
  // The seam pass runs per seam cell (no edge joins two islands), islands
  // in parallel, largest first.
  const CellLayout seams = seam_layout(stages);
  const int seam_count = static_cast<int>(seams.faces_of_cell.size());
  std::vector<SeamWork> works(static_cast<size_t>(seam_count));
  for (int s = 0; s < seam_count; ++s) works[s].seam = s;
  for (int c = 0; c < static_cast<int>(results.size()); ++c)
    take_cell(stages, c, std::move(results[c]), works[seams.cell_of_face[stages.cells.faces_of_cell[c].front()]]);
  results.clear();
  std::vector<int> seam_order(static_cast<size_t>(seam_count));
  std::iota(seam_order.begin(), seam_order.end(), 0);
  std::stable_sort(seam_order.begin(), seam_order.end(),
                   [&](int a, int b) { return seams.faces_of_cell[a].size() > seams.faces_of_cell[b].size(); });
  const Clock::time_point seams_start = Clock::now();
  run_in_parallel(seam_count, threads, seam_order, [&](int s) { run_seam_pass(stages, seams, works[s]); });
  const double seconds_seams = seconds_since(seams_start);
  // Hulls are made across every seam cell at once, so one large island
  // spreads over every thread.
  const Clock::time_point hulls_start = Clock::now();
  make_hulls(stages, seams, works, threads);
  const double seconds_hulls = seconds_since(hulls_start);
  std::vector<SeamResult> finished;
  finished.reserve(works.size());
  for (SeamWork& work : works) finished.push_back(std::move(work.result));
  return assemble_covering(stages, std::move(finished), seconds_cells, seconds_seams, seconds_hulls);
}

} // namespace hullcover::detail

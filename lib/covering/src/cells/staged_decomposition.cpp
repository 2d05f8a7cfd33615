#include "hullcover/covering/staged_decomposition.h"

#include "cells/cell_merging.h"
#include "cells/cell_result_bytes.h"
#include "cells/prepared_scene_file.h"
#include "cells/seam_result_bytes.h"

#include "hullcover/covering/merge_cells.h"
#include "hullcover/geometry/parallel_for.h"

#include "hullcover/geometry/mapped_file.h"

#include <exception>

namespace hullcover {
namespace {

Status failed(const std::exception& e) {
  return {StatusCode::internal_error, std::string("decomposition failed: ") + e.what()};
}

} // namespace

Result<std::unique_ptr<StagedDecomposition>> StagedDecomposition::prepare(PreparedMesh prepared,
                                                                          const DecomposeOptions& options) {
  try {
    std::unique_ptr<StagedDecomposition> staged(new StagedDecomposition());
    staged->prepared_ = std::make_unique<PreparedMesh>(std::move(prepared));
    staged->scene_ = std::make_unique<PreparedSceneView>(view_of(*staged->prepared_));
    Result<std::unique_ptr<detail::DecompositionStages>> stages = detail::prepare_stages(*staged->scene_, options);
    if (!stages.ok()) return stages.status();
    staged->stages_ = std::move(stages).value();
    // Progress belongs to a run, not to stages other threads share.
    staged->stages_->covering.options.progress = nullptr;
    return Result<std::unique_ptr<StagedDecomposition>>(std::move(staged));
  } catch (const std::exception& e) {
    return failed(e);
  }
}

Result<std::unique_ptr<StagedDecomposition>> StagedDecomposition::map_prepared(const std::string& path,
                                                                               const DecomposeOptions& options) {
  try {
    Result<std::unique_ptr<MappedFile>> file = MappedFile::open(path);
    if (!file.ok()) return file.status();
    Result<detail::MappedPreparedScene> read = detail::read_prepared_scene(*file.value(), path);
    if (!read.ok()) return read.status();
    detail::MappedPreparedScene& parts = read.value();
    std::unique_ptr<StagedDecomposition> staged(new StagedDecomposition());
    staged->mapping_ = std::move(file).value();
    staged->scene_ = std::make_unique<PreparedSceneView>(std::move(parts.scene));
    detail::MadeStages made{std::move(parts.cells), std::move(parts.index)};
    Result<std::unique_ptr<detail::DecompositionStages>> stages =
        detail::prepare_stages(*staged->scene_, options, &made);
    if (!stages.ok()) return stages.status();
    staged->stages_ = std::move(stages).value();
    staged->stages_->covering.options.progress = nullptr;
    if (detail::prepared_options_key(*staged->stages_) != parts.options_key)
      return Status{StatusCode::invalid_argument,
                    path + " was prepared with other options than these: prepare it again with them"};
    return Result<std::unique_ptr<StagedDecomposition>>(std::move(staged));
  } catch (const std::exception& e) {
    return failed(e);
  }
}

StagedDecomposition::~StagedDecomposition() = default;

Status StagedDecomposition::write_prepared(const std::string& path) const {
  try {
    return detail::write_prepared_scene(path, *scene_, *stages_);
  } catch (const std::exception& e) {
    return failed(e);
  }
}

void StagedDecomposition::release_mapped_pages() const {
  if (mapping_) mapping_->release_pages();
}

int StagedDecomposition::cell_count() const { return static_cast<int>(stages_->cells.faces_of_cell.size()); }

const std::vector<int>& StagedDecomposition::cell_faces(int cell) const {
  return stages_->cells.faces_of_cell.at(static_cast<size_t>(cell));
}

std::uint64_t StagedDecomposition::cell_key(int cell) const { return detail::cell_key(*stages_, cell); }

Result<std::string> StagedDecomposition::merge_cell(int cell) const {
  if (cell < 0 || cell >= cell_count()) return Status{StatusCode::invalid_argument, "no such cell"};
  try {
    return detail::cell_result_bytes(*stages_, cell, detail::merge_cell(*stages_, cell, nullptr));
  } catch (const std::exception& e) {
    return failed(e);
  }
}

bool StagedDecomposition::still_valid(int cell, const std::string& bytes, std::string* why) const {
  if (cell < 0 || cell >= cell_count()) {
    if (why) *why = "no such cell";
    return false;
  }
  try {
    return detail::cell_bytes_hold(*stages_, cell, bytes, {}, why);
  } catch (const std::exception& e) {
    if (why) *why = e.what();
    return false;
  }
}

namespace {

// The results of `cells` read back from their bytes (same order).
Result<std::vector<detail::CellResult>> read_cells(const detail::DecompositionStages& stages,
                                                   const std::vector<int>& cells,
                                                   const std::vector<std::string>& bytes) {
  std::vector<detail::CellResult> results;
  results.reserve(cells.size());
  for (size_t i = 0; i < cells.size(); ++i) {
    Result<detail::CellResult> result = detail::cell_result_from_bytes(stages, cells[i], bytes[i]);
    if (!result.ok())
      return Status{result.status().code(), "cell " + std::to_string(cells[i]) + ": " + result.status().message()};
    results.push_back(std::move(result).value());
  }
  return results;
}

} // namespace

Result<Covering> StagedDecomposition::finish(const std::vector<std::string>& cells) const {
  if (static_cast<int>(cells.size()) != cell_count())
    return Status{StatusCode::invalid_argument, "finish needs one result per cell (" + std::to_string(cell_count()) +
                                                    "), got " + std::to_string(cells.size())};
  try {
    std::vector<int> every_cell(cells.size());
    for (int c = 0; c < cell_count(); ++c) every_cell[c] = c;
    Result<std::vector<detail::CellResult>> results = read_cells(*stages_, every_cell, cells);
    if (!results.ok()) return results.status();
    return detail::finish_stages(*stages_, std::move(results).value(), 0.0);
  } catch (const std::exception& e) {
    return failed(e);
  }
}

const CellLayout& StagedDecomposition::seams() const {
  std::call_once(seams_laid_out_, [this] {
    seams_ = std::make_unique<CellLayout>(detail::seam_layout(*stages_));
    cells_of_seam_.assign(seams_->faces_of_cell.size(), {});
    for (int c = 0; c < cell_count(); ++c)
      cells_of_seam_[seams_->cell_of_face[stages_->cells.faces_of_cell[c].front()]].push_back(c);
  });
  return *seams_;
}

int StagedDecomposition::seam_count() const { return static_cast<int>(seams().faces_of_cell.size()); }

const std::vector<int>& StagedDecomposition::seam_cells(int seam) const {
  if (seam < 0 || seam >= seam_count()) return no_cells_;
  return cells_of_seam_[static_cast<size_t>(seam)];
}

Result<std::string> StagedDecomposition::finish_seam(int seam, const std::vector<std::string>& cells) const {
  try {
    if (seam < 0 || seam >= seam_count()) return Status{StatusCode::invalid_argument, "no such seam cell"};
    const std::vector<int>& its_cells = seam_cells(seam);
    if (cells.size() != its_cells.size())
      return Status{StatusCode::invalid_argument, "seam cell " + std::to_string(seam) + " has " +
                                                      std::to_string(its_cells.size()) + " cells, got " +
                                                      std::to_string(cells.size()) + " results"};
    Result<std::vector<detail::CellResult>> results = read_cells(*stages_, its_cells, cells);
    if (!results.ok()) return results.status();
    const detail::SeamResult result =
        detail::finish_seam(*stages_, seams(), seam, its_cells, std::move(results).value(),
                            threads_to_use(stages_->covering.options.threads));
    return detail::seam_result_bytes(*stages_, seams(), seam, result);
  } catch (const std::exception& e) {
    return failed(e);
  }
}

Result<Covering> StagedDecomposition::finish_seams(const std::vector<std::string>& seam_bytes) const {
  try {
    if (static_cast<int>(seam_bytes.size()) != seam_count())
      return Status{StatusCode::invalid_argument, "finish_seams needs one result per seam cell (" +
                                                      std::to_string(seam_count()) + "), got " +
                                                      std::to_string(seam_bytes.size())};
    // Read (and checked: every hull against its faces) on every thread;
    // the first failure in seam cell order is the one reported.
    const CellLayout& layout = seams();
    std::vector<detail::SeamResult> results(seam_bytes.size());
    std::vector<Status> failures(seam_bytes.size(), Status::success());
    parallel_for(seam_count(), threads_to_use(stages_->covering.options.threads), [&](int s) {
      Result<detail::SeamResult> result = detail::seam_result_from_bytes(*stages_, layout, s, seam_bytes[s]);
      if (result.ok())
        results[s] = std::move(result).value();
      else
        failures[s] = result.status();
    });
    for (int s = 0; s < seam_count(); ++s)
      if (!failures[s].ok())
        return Status{failures[s].code(), "seam cell " + std::to_string(s) + ": " + failures[s].message()};
    return detail::assemble_covering(*stages_, std::move(results), 0.0, 0.0, 0.0);
  } catch (const std::exception& e) {
    return failed(e);
  }
}

} // namespace hullcover

#pragma once
/// \file staged_decomposition.h
/// decompose() in three stages, for bakes that run cells elsewhere (a Dask
/// cluster: `python3 -m hullcover.bake`) or take cells from an earlier bake
/// (the cell cache: `hullcover decompose --cell-cache DIR`):
///
///  1. prepare(): islands, cells and the scene index. Deterministic: every
///     process that prepares the same mesh with the same options gets the
///     same cells, numbered alike.
///  2. merge_cell(c) for every cell, in any order, on any thread or process:
///     bytes that hold the patches cell c kept (cells merge apart,
///     merge_cells.h).
///  3. finish(): the seam pass and the hulls, from every cell's bytes.
///
/// finish() on bytes from merge_cell() gives exactly what decompose() gives
/// for the same mesh and options: the same hulls in the same order, the same
/// statistics apart from timings. Bytes from an earlier bake of an edited
/// scene may stand in for a cell whose key is unchanged and which
/// still_valid() accepts: the covering is then valid (every kept hull was
/// re-checked against the new scene), though a full bake may merge more.

#include "hullcover/covering/covering.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hullcover {

class MappedFile;
struct CellLayout;
struct PreparedSceneView;
namespace detail {
struct DecompositionStages;
}

/// The stages of one decomposition. merge_cell(), still_valid() and the
/// accessors are const and safe to call from many threads at once.
class StagedDecomposition {
public:
  /// Stage 1 on a prepared mesh, which is kept (moved in). Fails with
  /// `invalid_argument` for options out of range (as decompose() does), or
  /// `internal_error` (out of memory).
  [[nodiscard]] static Result<std::unique_ptr<StagedDecomposition>> prepare(PreparedMesh prepared,
                                                                            const DecomposeOptions& options);
  /// Stage 1 read from a prepared scene file that write_prepared() wrote
  /// (docs/worlds.md, "The prepared scene file"): the scene and its cells
  /// are copied out of it, and the scene index (its search trees and
  /// free-space sweeps, most of stage 1's memory) is read in place from the
  /// file mapped into memory, so a process holds only the pages its cells'
  /// checks read. `options` must be those the file was prepared with.
  /// Fails with `file_not_found`, `unknown_format` (not a prepared scene
  /// file, or another version), `unreadable_file` (damaged: the message
  /// names the part), `invalid_argument` (prepared with other options, or
  /// options out of range) or `internal_error`.
  [[nodiscard]] static Result<std::unique_ptr<StagedDecomposition>> map_prepared(const std::string& path,
                                                                                 const DecomposeOptions& options);
  ~StagedDecomposition();

  /// Writes stage 1 (the scene, its cells and the scene index) to `path`
  /// for map_prepared(), atomically: versioned, little-endian, each part
  /// checksummed. Fails with `unwritable_file` or `internal_error`.
  [[nodiscard]] Status write_prepared(const std::string& path) const;
  /// For stages read by map_prepared(): hands the file's pages read so far
  /// back to the system, so that memory holds only what later cells read
  /// (a bake's worker calls it between cells, and on a timer while a large
  /// one runs). Safe while other threads merge cells or finish seams: the
  /// mapping is read-only, and a page dropped as it is read is read again
  /// from the file. Nothing for other stages.
  void release_mapped_pages() const;
  StagedDecomposition(const StagedDecomposition&) = delete;
  StagedDecomposition& operator=(const StagedDecomposition&) = delete;

  /// How many cells the scene has (numbered 0 .. count - 1).
  int cell_count() const;
  /// The faces of cell `cell`, ascending (mesh face ids).
  const std::vector<int>& cell_faces(int cell) const;
  /// What decides the cell's merging, hashed: its faces and their positions'
  /// exact bits, materials, the tolerance and every option the merging
  /// reads. The same key in two bakes means the same faces merged alike.
  std::uint64_t cell_key(int cell) const;

  /// Stage 2 for one cell: its patches as bytes (a versioned binary form,
  /// lib/covering/src/cells/cell_result_bytes.h). Progress is not reported.
  /// Fails with `invalid_argument` for a cell out of range, or
  /// `internal_error`.
  [[nodiscard]] Result<std::string> merge_cell(int cell) const;

  /// Whether `bytes` (from a bake of this or an earlier version of the
  /// scene) can stand in for cell `cell`: they read back (checksum, ranges),
  /// carry this cell's key, and every hull they keep still passes the
  /// validity conditions against THIS scene (an edit elsewhere can put a
  /// face inside a kept hull, or open space it takes). False, never an
  /// error, for bytes that do not qualify; `why` (optional) says why.
  bool still_valid(int cell, const std::string& bytes, std::string* why = nullptr) const;

  /// Stage 3: the seam pass and the hulls, from one entry per cell (index =
  /// cell). Fails with `invalid_argument` for a wrong count, `unknown_format`
  /// or `unreadable_file` for bytes that do not read back for their cell
  /// (cell_result_bytes.h), or `internal_error`.
  [[nodiscard]] Result<Covering> finish(const std::vector<std::string>& cells) const;

  /// Stage 3 in two steps, for bakes that run the seam pass as tasks. The
  /// seam cells: one per island (no edge joins two), or one for the whole
  /// scene when the cells are (cell_size 0). Counted 0 .. seam_count() - 1.
  int seam_count() const;
  /// The cells of seam cell `seam`, ascending: whose bytes finish_seam
  /// takes (empty for a seam cell out of range).
  const std::vector<int>& seam_cells(int seam) const;
  /// Step 1 for one seam cell: the seam pass across its cells' borders and
  /// its hulls, from its cells' bytes (seam_cells' order), as bytes (a
  /// checked binary form, lib/covering/src/cells/seam_result_bytes.h).
  /// Fails as finish() does, or with `invalid_argument` for a seam cell out
  /// of range.
  [[nodiscard]] Result<std::string> finish_seam(int seam, const std::vector<std::string>& cells) const;
  /// Step 2: the covering from every seam cell's bytes (index = seam cell):
  /// flat hulls for faces no hull covers, every hull in the order of its
  /// first face. finish_seams() on finish_seam()'s bytes equals finish() on
  /// the same cells' bytes. Fails with `invalid_argument` for a wrong count,
  /// `unknown_format` or `unreadable_file` for bytes that do not read back
  /// for their seam cell, or `internal_error`.
  [[nodiscard]] Result<Covering> finish_seams(const std::vector<std::string>& seams) const;

  /// The mesh given to prepare(); null for stages read by map_prepared(),
  /// whose scene stays in the mapped file.
  const PreparedMesh* prepared() const { return prepared_.get(); }

private:
  StagedDecomposition() = default;
  /// The seam cells and the cells of each, laid out on first use (once:
  /// calls may come from many threads).
  const CellLayout& seams() const;
  // Declared first, so destroyed last: the stages read the file in place.
  std::unique_ptr<MappedFile> mapping_;
  std::unique_ptr<PreparedMesh> prepared_;   // none when the scene is mapped
  std::unique_ptr<PreparedSceneView> scene_; // the scene's arrays, in prepared_ or mapping_
  std::unique_ptr<detail::DecompositionStages> stages_;
  mutable std::once_flag seams_laid_out_;
  mutable std::unique_ptr<CellLayout> seams_;
  mutable std::vector<std::vector<int>> cells_of_seam_;
  const std::vector<int> no_cells_{};
};

} // namespace hullcover

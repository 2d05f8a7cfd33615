#include "hullcover/covering/cell_cache.h"

#include "hullcover/geometry/atomic_file.h"
#include "hullcover/geometry/regular_file.h"

#include "hullcover/geometry/little_endian_bytes.h"

#include "cells/cell_merging.h"
#include "cells/cell_result_bytes.h"
#include "cells/scene_change.h"

#include <sys/stat.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <new>

namespace hullcover {
namespace {

using Clock = std::chrono::steady_clock;

// A snapshot takes 56 bytes a face and 16 a cell (scene_change.h). One of a
// scene more than this many times the size of this one is of no use (nearly
// every face changed) and is not read: every kept hull is then re-checked.
constexpr std::uint64_t kLargestUsefulSnapshotRatio = 4;

std::string entry_path(const std::string& dir, std::uint64_t key) {
  char name[32];
  std::snprintf(name, sizeof name, "%016" PRIx64 ".cell", key);
  return dir + "/" + name;
}

Status make_folder(const std::string& dir) {
  if (::mkdir(dir.c_str(), 0777) == 0 || errno == EEXIST) {
    struct stat info {};
    if (::stat(dir.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) return Status::success();
  }
  return {StatusCode::unwritable_file, "cannot use cell cache folder " + dir + ": " +
                                           (errno == EEXIST ? std::string("not a folder") : std::strerror(errno))};
}

} // namespace

namespace {

// The last bake's scene, beside its cells (scene_change.h).
std::string snapshot_path(const std::string& dir) { return dir + "/last-bake.scene"; }

// The change since the last bake, when its snapshot reads back.
detail::SceneChange change_since_last_bake(const detail::DecompositionStages& stages,
                                           const std::vector<std::uint64_t>& face_hashes, const std::string& dir,
                                           detail::SceneSnapshot& snapshot) {
  const std::uint64_t own_size = 56 * std::uint64_t{stages.prepared.mesh.triangles.size()} +
                                 16 * std::uint64_t{stages.cells.faces_of_cell.size()} + 64;
  try {
    Result<std::string> bytes = read_regular_file(snapshot_path(dir), kLargestUsefulSnapshotRatio * own_size);
    if (!bytes.ok()) return {};
    Result<detail::SceneSnapshot> read = detail::read_scene_snapshot(bytes.value());
    if (!read.ok()) return {};
    snapshot = std::move(read).value();
    return detail::scene_change_since(stages, face_hashes, snapshot);
  } catch (const std::bad_alloc&) {
    // Out of memory for the record: re-check everything rather than fail.
    snapshot = {};
    return {};
  }
}

Result<Covering> decompose_with_cache_unchecked(const PreparedSceneView& prepared, const DecomposeOptions& options,
                                                const std::string& cache_dir, CellCacheReport& report) {
  if (Status s = make_folder(cache_dir); !s.ok()) return s;
  Result<std::unique_ptr<detail::DecompositionStages>> prepared_stages = detail::prepare_stages(prepared, options);
  if (!prepared_stages.ok()) return prepared_stages.status();
  detail::DecompositionStages& stages = *prepared_stages.value();
  // Progress is this function's own, cell by cell.
  stages.covering.options.progress = nullptr;
  const int count = static_cast<int>(stages.cells.faces_of_cell.size());
  report.cells = count;
  Clock::time_point start = Clock::now();
  // Each once: this bake's snapshot records them too.
  const std::vector<std::uint64_t> face_hashes = detail::face_hashes_of(stages);
  std::vector<std::uint64_t> keys(count);
  for (int c = 0; c < count; ++c) keys[c] = detail::cell_key(stages, c);
  detail::SceneSnapshot snapshot;
  const detail::SceneChange change = change_since_last_bake(stages, face_hashes, cache_dir, snapshot);
  report.changed_faces = change.everything ? -1 : change.changed_faces;
  // Each cell's bytes (stored, and checksummed in the snapshot) and its
  // result, read or merged once.
  std::vector<std::string> cells(count);
  std::vector<detail::CellResult> results(count);
  std::vector<char> reused(count, 0);
  std::atomic<int> stale{0};
  std::atomic<long> rechecked{0}, unchecked{0};
  Status failure = Status::success();
  std::mutex mutex;
  int done = 0;
  // Counted under the lock, so the reports never go back.
  const auto progress = [&] {
    if (!options.progress) return;
    const std::lock_guard<std::mutex> lock(mutex);
    options.progress(static_cast<double>(++done) / (count + 1));
  };
  const int threads = threads_to_use(options.threads);
  // First every cached cell, checked; then the rest, merged: the two
  // timings tell what a re-bake costs.
  detail::run_in_parallel(count, threads, {}, [&](int c) {
    const std::uint64_t key = keys[c];
    Result<std::string> bytes = read_regular_file(entry_path(cache_dir, key));
    if (!bytes.ok()) return;
    // Bytes the last bake used held against its scene: only the patches an
    // edit since can reach need a look. Any other bytes, every patch.
    const auto known = snapshot.cell_checksums.find(key);
    const bool held_last_time =
        !change.everything && known != snapshot.cell_checksums.end() &&
        known->second == fnv1a(reinterpret_cast<const unsigned char*>(bytes.value().data()), bytes.value().size());
    const auto touched = [&](const detail::Patch& patch, const detail::PatchHull& made) {
      const bool look = !held_last_time || detail::patch_may_be_touched(stages, change, patch, made);
      (look ? rechecked : unchecked) += 1;
      return look;
    };
    Result<detail::CellResult> result = detail::cell_result_from_bytes(stages, c, bytes.value());
    if (result.ok() && detail::cell_result_holds(stages, c, result.value(), touched, nullptr)) {
      results[c] = std::move(result).value();
      cells[c] = std::move(bytes).value();
      reused[c] = 1;
      progress();
    } else {
      ++stale;
    }
  });
  report.seconds_checking = std::chrono::duration<double>(Clock::now() - start).count();
  start = Clock::now();
  detail::run_in_parallel(count, threads, detail::largest_cells_first(stages.cells), [&](int c) {
    if (reused[c]) return;
    detail::CellResult result = detail::merge_cell(stages, c, nullptr);
    std::string bytes = detail::cell_result_bytes(stages, c, result);
    Status stored = write_file_atomically(entry_path(cache_dir, keys[c]), bytes);
    if (!stored.ok()) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (failure.ok()) failure = stored;
      return;
    }
    cells[c] = std::move(bytes);
    results[c] = std::move(result);
    progress();
  });
  report.seconds_merging = std::chrono::duration<double>(Clock::now() - start).count();
  if (!failure.ok()) return failure;
  for (char r : reused) report.reused += r;
  report.stale = stale;
  report.merged = count - report.reused;
  report.patches_rechecked = rechecked;
  report.patches_kept_unchecked = unchecked;
  Covering finished = detail::finish_stages(stages, std::move(results), 0.0);
  finished.statistics.seconds_merging += report.seconds_checking + report.seconds_merging;
  // Only after every cell held or was stored: the next bake trusts what
  // this one records.
  if (Status s = write_file_atomically(snapshot_path(cache_dir),
                                       detail::scene_snapshot_bytes(stages, face_hashes, keys, cells));
      !s.ok())
    return s;
  if (options.progress) options.progress(1.0);
  return finished;
}

} // namespace

Result<Covering> decompose_with_cell_cache(PreparedMesh prepared, const DecomposeOptions& options,
                                           const std::string& cache_dir, CellCacheReport& report) {
  report = {};
  // No exception may leave the library: a worker thread's (out of memory)
  // comes back here.
  try {
    return decompose_with_cache_unchecked(view_of(prepared), options, cache_dir, report);
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("decomposition failed: ") + e.what()};
  }
}

} // namespace hullcover

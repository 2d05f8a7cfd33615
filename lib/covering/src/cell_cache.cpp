#include "hullcover/covering/cell_cache.h"

#include "hullcover/covering/staged_decomposition.h"
#include "hullcover/geometry/atomic_file.h"
#include "hullcover/geometry/regular_file.h"

#include "cell_merging.h"

#include <sys/stat.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <mutex>

namespace hullcover {
namespace {

using Clock = std::chrono::steady_clock;

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

Result<Covering> decompose_with_cache_unchecked(PreparedMesh prepared, const DecomposeOptions& options,
                                                const std::string& cache_dir, CellCacheReport& report) {
  if (Status s = make_folder(cache_dir); !s.ok()) return s;
  Result<std::unique_ptr<StagedDecomposition>> prepared_stages =
      StagedDecomposition::prepare(std::move(prepared), options);
  if (!prepared_stages.ok()) return prepared_stages.status();
  const StagedDecomposition& staged = *prepared_stages.value();
  const int count = staged.cell_count();
  report.cells = count;
  std::vector<std::string> cells(count);
  std::vector<char> reused(count, 0);
  std::atomic<int> stale{0};
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
  Clock::time_point start = Clock::now();
  detail::run_in_parallel(count, threads, {}, [&](int c) {
    Result<std::string> bytes = read_regular_file(entry_path(cache_dir, staged.cell_key(c)));
    if (!bytes.ok()) return;
    if (staged.still_valid(c, bytes.value())) {
      cells[c] = std::move(bytes).value();
      reused[c] = 1;
      progress();
    } else {
      ++stale;
    }
  });
  report.seconds_checking = std::chrono::duration<double>(Clock::now() - start).count();
  start = Clock::now();
  detail::run_in_parallel(count, threads, {}, [&](int c) {
    if (reused[c]) return;
    Result<std::string> bytes = staged.merge_cell(c);
    Status stored = bytes.ok() ? write_file_atomically(entry_path(cache_dir, staged.cell_key(c)), bytes.value())
                               : bytes.status();
    if (!stored.ok()) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (failure.ok()) failure = stored;
      return;
    }
    cells[c] = std::move(bytes).value();
    progress();
  });
  report.seconds_merging = std::chrono::duration<double>(Clock::now() - start).count();
  if (!failure.ok()) return failure;
  for (char r : reused) report.reused += r;
  report.stale = stale;
  report.merged = count - report.reused;
  Result<Covering> covering = staged.finish(cells);
  if (!covering.ok()) return covering;
  Covering finished = std::move(covering).value();
  finished.statistics.seconds_merging += report.seconds_checking + report.seconds_merging;
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
    return decompose_with_cache_unchecked(std::move(prepared), options, cache_dir, report);
  } catch (const std::exception& e) {
    return Status{StatusCode::internal_error, std::string("decomposition failed: ") + e.what()};
  }
}

} // namespace hullcover

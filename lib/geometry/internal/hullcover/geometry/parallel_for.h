#pragma once
/// \file parallel_for.h
/// Independent jobs on std::thread workers: a shared atomic counter hands
/// out indices, each job writes only its own result slot, and the caller
/// combines the slots in index order afterwards, so no figure depends on
/// which thread ran which job. Header-only; a target that includes it links
/// Threads::Threads.

#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace hullcover {

/// The worker count a `threads` option stands for: itself when positive,
/// every core (std::thread::hardware_concurrency, at least 1) for 0 or less.
/// Callers refuse negative counts before asking, where a count is user input.
inline int threads_to_use(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

/// Runs `work` on `threads` threads at once (the calling thread is one of
/// them) and returns once each has returned. A thread that cannot be
/// started leaves its share to the others: `work` must take whatever is
/// left, as a loop over shared jobs does. `work` must not throw.
inline void run_together(int threads, const std::function<void()>& work) {
  std::vector<std::thread> pool;
  try {
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  } catch (const std::system_error&) {}
  work();
  for (std::thread& thread : pool) thread.join();
}

/// Runs `job(i)` for every i in [0, count) on up to `threads` threads (the
/// calling thread is one of them; no thread is started for one job or one
/// thread). Indices are handed out in ascending order. The first exception
/// a job throws is rethrown here once every thread has stopped; the other
/// threads finish their current job and take no new one.
inline void parallel_for(int count, int threads, const std::function<void(int)>& job) {
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        job(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = count;
      }
    }
  };
  run_together(std::min(threads, count), work);
  if (failure) std::rethrow_exception(failure);
}

/// Runs `job(i)` for every i in [0, count) on up to `threads` threads, a
/// batch of `batch` consecutive indices at a time, and after each batch
/// calls `commit(i)` for its indices in ascending order on the calling
/// thread. Results kept per index between the two stay bounded by one batch,
/// and whatever `commit` does (sums, progress reports) happens on one
/// thread, in index order, whatever the thread count. A job's exception is
/// rethrown as parallel_for does, before that batch is committed.
inline void parallel_for_ordered(int count, int threads, int batch, const std::function<void(int)>& job,
                                 const std::function<void(int)>& commit) {
  batch = std::max(1, batch);
  for (int first = 0; first < count; first += batch) {
    const int size = std::min(batch, count - first);
    parallel_for(size, threads, [&](int k) { job(first + k); });
    for (int k = 0; k < size; ++k) commit(first + k);
  }
}

/// Runs `job(i)` for every i in [0, count) as parallel_for does, and when
/// `done` is set, calls `done(fraction)` with the fraction of the jobs
/// finished, rising, at most `steps` times and last with 1: from the
/// calling thread, as it finishes jobs of its own (it is one of the
/// threads), so the others never wait for a report.
inline void parallel_for_reporting(int count, int threads, int steps, const std::function<void(int)>& job,
                                   const std::function<void(double)>& done) {
  if (!done) {
    parallel_for(count, threads, job);
    return;
  }
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> finished{0};
  long long told = 0; // the last step reported; only the caller reads it
  parallel_for(count, threads, [&](int i) {
    job(i);
    const int now = ++finished;
    if (std::this_thread::get_id() != caller) return;
    const long long step = static_cast<long long>(now) * steps / count;
    if (step > told && step < steps) {
      told = step;
      done(static_cast<double>(now) / count);
    }
  });
  done(1.0);
}

} // namespace hullcover

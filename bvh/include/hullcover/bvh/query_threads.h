#pragma once
/// \file query_threads.h
/// Threads for batch queries (HullQueries' *_batch calls): a few workers
/// started once and kept, so a server that asks a batch every tick starts
/// no thread per tick. A batch is cut into small chunks that the threads
/// take in turn (the caller's thread takes part), so uneven queries even
/// out; every query's answer is computed alone, so a batch gives the same
/// answers for any thread count.
///
/// Between batches a thread watches for the next one for a while
/// (`watch`, see start()) before it sleeps: a sleeping thread takes tens of
/// microseconds to wake, as long as a batch of a few hundred rays.

#include "hullcover/geometry/status.h"

#include <chrono>
#include <cstddef>
#include <memory>

namespace hullcover::bvh {

/// A pool of threads for the batch queries (hull_queries.h): started once,
/// shared by any number of batches, one batch at a time.
class QueryThreads {
public:
  /// `threads` in all, the caller's included (>= 1; 0: one per hardware
  /// thread). After a batch, the threads watch for the next for `watch`
  /// (yielding the core to any other work) before they sleep: a server
  /// that asks batches less than `watch` apart never waits for a thread to
  /// wake. Fails with `invalid_argument` for a negative count, more than
  /// kMostThreads, or a watch outside [0, kLongestWatch]; and
  /// `internal_error` if the system starts none.
  static Result<std::shared_ptr<QueryThreads>> start(int threads, std::chrono::microseconds watch = kDefaultWatch);
  /// The most threads start() accepts.
  static constexpr int kMostThreads = 256;
  /// How long threads watch for the next batch unless told: back-to-back
  /// batches within a tick find them awake; between ticks they sleep.
  static constexpr std::chrono::microseconds kDefaultWatch{200};
  /// The longest watch start() accepts (one second).
  static constexpr std::chrono::microseconds kLongestWatch{1'000'000};

  ~QueryThreads();
  QueryThreads(const QueryThreads&) = delete;
  QueryThreads& operator=(const QueryThreads&) = delete;

  /// Threads that run a batch, the caller's included.
  int size() const;

  /// Runs `body(begin, end, context)` over [0, count) in chunks of at most
  /// `chunk` items on every thread and returns when all are done. `body`
  /// must not throw. One batch at a time: a second caller waits its turn.
  void run(size_t count, size_t chunk, void (*body)(size_t begin, size_t end, void* context), void* context);

private:
  QueryThreads();
  struct Shared;
  std::unique_ptr<Shared> shared_;
};

} // namespace hullcover::bvh

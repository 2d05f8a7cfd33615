#pragma once
/// \file query_threads.h
/// Threads for batch queries (HullQueries' *_batch calls): a few workers
/// started once and kept, so a server that asks a batch every tick starts
/// no thread per tick. A batch is cut into small chunks that the threads
/// take in turn (the caller's thread takes part), so uneven queries even
/// out; every query's answer is computed alone, so a batch gives the same
/// answers for any thread count.

#include "hullcover/geometry/status.h"

#include <cstddef>
#include <memory>

namespace hullcover::bvh {

/// A pool of threads for the batch queries (hull_queries.h): started once,
/// shared by any number of batches, one batch at a time.
class QueryThreads {
public:
  /// `threads` in all, the caller's included (>= 1; 0: one per hardware
  /// thread). Fails with `invalid_argument` for a negative count or more
  /// than kMostThreads, and `internal_error` if the system starts none.
  static Result<std::shared_ptr<QueryThreads>> start(int threads);
  /// The most threads start() accepts.
  static constexpr int kMostThreads = 256;

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

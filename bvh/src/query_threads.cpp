#include "hullcover/bvh/query_threads.h"

#include "query_guard.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace hullcover::bvh {

namespace {
// Calls `ready()` until it is true or `how_long` is over; whether it was.
// A thread between batches, or a caller waiting for the last chunks,
// watches before it sleeps: a sleeping thread takes tens of microseconds
// to wake, as long as a whole batch of short rays.
template <typename Ready>
bool watch(std::chrono::microseconds how_long, Ready&& ready) {
  const auto until = std::chrono::steady_clock::now() + how_long;
  for (;;) {
    for (int i = 0; i < 64; ++i) {
      if (ready()) return true;
      std::this_thread::yield();
    }
    if (std::chrono::steady_clock::now() >= until) return ready();
  }
}
} // namespace

struct QueryThreads::Shared {
  std::vector<std::thread> workers;
  std::chrono::microseconds watch_time = kDefaultWatch;
  std::mutex batch_mutex; // one batch at a time
  std::mutex mutex;
  std::condition_variable wake, done;
  // The batch in progress, published under `mutex` with a new generation
  // (read without it only to watch for a change).
  std::atomic<std::uint64_t> generation{0};
  std::atomic<bool> quitting{false};
  size_t count = 0, chunk = 1;
  void (*body)(size_t, size_t, void*) = nullptr;
  void* context = nullptr;
  std::atomic<size_t> next{0};
  std::atomic<int> busy{0}; // workers still in the batch

  // Takes chunks until none is left.
  void take_chunks() {
    for (;;) {
      const size_t begin = next.fetch_add(chunk, std::memory_order_relaxed);
      if (begin >= count) return;
      body(begin, std::min(count, begin + chunk), context);
    }
  }

  void work() {
    std::uint64_t seen = 0;
    for (;;) {
      watch(watch_time, [&] { return quitting.load() || generation.load() != seen; });
      {
        std::unique_lock<std::mutex> lock(mutex);
        wake.wait(lock, [&] { return quitting.load() || generation.load() != seen; });
        if (quitting.load()) return;
        seen = generation.load();
      }
      take_chunks();
      std::lock_guard<std::mutex> lock(mutex);
      if (busy.fetch_sub(1) == 1) done.notify_one();
    }
  }
};

QueryThreads::QueryThreads() : shared_(std::make_unique<Shared>()) {}

QueryThreads::~QueryThreads() {
  {
    std::lock_guard<std::mutex> lock(shared_->mutex);
    shared_->quitting.store(true);
  }
  shared_->wake.notify_all();
  for (std::thread& t : shared_->workers) t.join();
}

Result<std::shared_ptr<QueryThreads>> QueryThreads::start(int threads, std::chrono::microseconds watch) {
  using Started = Result<std::shared_ptr<QueryThreads>>;
  return detail::guarded("starting query threads", [&]() -> Started {
    if (threads < 0 || threads > kMostThreads)
      return Status{StatusCode::invalid_argument, "query threads: " + std::to_string(threads) +
                                                      " is not a thread count from 0 to " +
                                                      std::to_string(kMostThreads)};
    if (watch.count() < 0 || watch > kLongestWatch)
      return Status{StatusCode::invalid_argument, "query threads: a watch of " + std::to_string(watch.count()) +
                                                      " microseconds is not from 0 to " +
                                                      std::to_string(kLongestWatch.count())};
    if (threads == 0) threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, kMostThreads);
    std::shared_ptr<QueryThreads> pool(new QueryThreads());
    pool->shared_->watch_time = watch;
    try {
      for (int i = 1; i < threads; ++i) pool->shared_->workers.emplace_back([s = pool->shared_.get()] { s->work(); });
    } catch (const std::system_error& e) {
      if (pool->shared_->workers.empty())
        return Status{StatusCode::internal_error, std::string("query threads: no thread could start: ") + e.what()};
      // Fewer threads than asked still answer every batch, only slower.
    }
    return pool;
  });
}

int QueryThreads::size() const { return static_cast<int>(shared_->workers.size()) + 1; }

void QueryThreads::run(size_t count, size_t chunk, void (*body)(size_t, size_t, void*), void* context) {
  if (count == 0) return;
  Shared& s = *shared_;
  std::lock_guard<std::mutex> batch(s.batch_mutex);
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    s.count = count;
    s.chunk = std::max<size_t>(chunk, 1);
    s.body = body;
    s.context = context;
    s.next.store(0, std::memory_order_relaxed);
    s.busy.store(static_cast<int>(s.workers.size()));
    s.generation.fetch_add(1);
  }
  s.wake.notify_all();
  s.take_chunks();
  if (watch(s.watch_time, [&] { return s.busy.load() == 0; })) return;
  std::unique_lock<std::mutex> lock(s.mutex);
  s.done.wait(lock, [&] { return s.busy.load() == 0; });
}

} // namespace hullcover::bvh

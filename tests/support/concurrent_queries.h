#pragma once
// Many threads asking one world the same questions at once: what the
// determinism tests compare with the one-thread answers.

#include <cstddef>
#include <thread>
#include <vector>

namespace hullcover::test {

/// Runs `ask(k, answer)` for every k in [0, count) on each of `threads`
/// threads at once, each thread starting at a different k so that they
/// overlap on different questions; returns each thread's answers, by k.
template <typename Answer, typename Ask>
std::vector<std::vector<Answer>> answers_from_threads(int threads, size_t count, Ask&& ask) {
  std::vector<std::vector<Answer>> got(threads, std::vector<Answer>(count));
  std::vector<std::thread> running;
  for (int t = 0; t < threads; ++t)
    running.emplace_back([&, t] {
      for (size_t i = 0; i < count; ++i) {
        const size_t k = (i + 50 * static_cast<size_t>(t)) % count;
        ask(k, got[t][k]);
      }
    });
  for (std::thread& th : running) th.join();
  return got;
}

} // namespace hullcover::test

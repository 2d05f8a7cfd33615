#pragma once
// Runs programs in child processes (fork and exec, no shell: arguments reach
// the program byte for byte) under a wall-clock limit and an address-space
// cap, a few at a time, and reports how each ended and what it cost: exit
// status or signal, seconds, and peak resident memory from wait4's rusage.
// For probing a command with hostile input, where a run may crash, hang or
// grow without bound and must not take the test down with it.

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace hullcover::test {

struct ChildSpec {
  std::vector<std::string> argv; ///< argv[0] is the program's path
  std::string working_dir;
  std::string stdout_path, stderr_path; ///< created or truncated; stdin is /dev/null
  std::vector<std::string> extra_env;   ///< "NAME=value", after the parent's environment
};

struct ChildLimits {
  std::chrono::milliseconds wall{60000};          ///< killed (SIGKILL) after this: a hang
  std::uint64_t address_space_bytes = 4ull << 30; ///< RLIMIT_AS of the child; 0: none
  int parallel = 4;                               ///< children at once (a hung one sleeps, so more than the cores)
};

struct ChildOutcome {
  bool exited = false; ///< ended by exit(); `status` holds its code
  int status = -1;
  int signal = 0; ///< the signal that ended it (SIGKILL when timed out)
  bool timed_out = false;
  double seconds = 0.0;
  double peak_rss_mb = 0.0; ///< ru_maxrss of the child
};

namespace detail {

// Everything the child needs, built before fork: between fork and exec only
// async-signal-safe calls are made (the parent may have threads).
struct PreparedChild {
  std::vector<std::string> env_storage;
  std::vector<char*> argv, envp;
};

inline PreparedChild prepare_child(const ChildSpec& spec) {
  PreparedChild p;
  for (char** e = environ; e != nullptr && *e != nullptr; ++e) p.env_storage.emplace_back(*e);
  for (const std::string& e : spec.extra_env) p.env_storage.push_back(e);
  for (const std::string& a : spec.argv) p.argv.push_back(const_cast<char*>(a.c_str()));
  p.argv.push_back(nullptr);
  for (std::string& e : p.env_storage) p.envp.push_back(e.data());
  p.envp.push_back(nullptr);
  return p;
}

[[noreturn]] inline void exec_child(const ChildSpec& spec, const PreparedChild& p, const ChildLimits& limits) {
  setpgid(0, 0); // its own group, so a kill reaches anything it starts
  if (limits.address_space_bytes > 0) {
    const rlimit address_space{limits.address_space_bytes, limits.address_space_bytes};
    setrlimit(RLIMIT_AS, &address_space);
  }
  const rlimit no_core{0, 0}; // a crash is reported by its signal; no core files in the tree
  setrlimit(RLIMIT_CORE, &no_core);
  const int in = open("/dev/null", O_RDONLY);
  const int out = open(spec.stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err = open(spec.stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (in < 0 || out < 0 || err < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0) _exit(126);
  if (!spec.working_dir.empty() && chdir(spec.working_dir.c_str()) != 0) _exit(126);
  execve(p.argv[0], p.argv.data(), p.envp.data());
  _exit(127);
}

} // namespace detail

/// Runs every spec, `limits.parallel` at a time, and returns their outcomes
/// in the specs' order. A launch failure shows as exit status 126 or 127.
inline std::vector<ChildOutcome> run_children(const std::vector<ChildSpec>& specs, const ChildLimits& limits) {
  using Clock = std::chrono::steady_clock;
  struct Running {
    std::size_t index;
    pid_t pid;
    Clock::time_point start;
    bool killed = false;
  };
  std::vector<ChildOutcome> outcomes(specs.size());
  std::vector<Running> running;
  std::size_t next = 0;
  // Polled rather than blocking in wait4: each child has its own deadline.
  constexpr std::chrono::milliseconds kPoll{2};
  while (next < specs.size() || !running.empty()) {
    while (running.size() < static_cast<std::size_t>(std::max(1, limits.parallel)) && next < specs.size()) {
      const detail::PreparedChild prepared = detail::prepare_child(specs[next]);
      const Clock::time_point start = Clock::now();
      const pid_t pid = fork();
      if (pid == 0) detail::exec_child(specs[next], prepared, limits);
      if (pid < 0) {
        outcomes[next].exited = true;
        outcomes[next].status = 126;
      } else {
        running.push_back({next, pid, start});
      }
      ++next;
    }
    for (std::size_t i = 0; i < running.size();) {
      Running& r = running[i];
      int raw = 0;
      rusage usage{};
      const pid_t got = wait4(r.pid, &raw, WNOHANG, &usage);
      const double seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
      if (got == r.pid) {
        ChildOutcome& o = outcomes[r.index];
        o.exited = WIFEXITED(raw);
        o.status = o.exited ? WEXITSTATUS(raw) : -1;
        o.signal = WIFSIGNALED(raw) ? WTERMSIG(raw) : 0;
        o.timed_out = r.killed;
        o.seconds = seconds;
        o.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0; // Linux reports kilobytes
        running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
        continue;
      }
      if (!r.killed && Clock::now() - r.start > limits.wall) {
        kill(-r.pid, SIGKILL); // the child's own group (setpgid above) ...
        kill(r.pid, SIGKILL);  // ... and the child, should it not have made one yet
        r.killed = true;
      }
      ++i;
    }
    if (!running.empty()) std::this_thread::sleep_for(kPoll);
  }
  return outcomes;
}

} // namespace hullcover::test

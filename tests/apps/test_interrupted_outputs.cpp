// A `hullcover decompose` stopped at any moment (SIGINT, SIGTERM, a full
// disk) leaves each output either as it was or complete: never half written,
// and no temporary file beside it. The files of a small scene are written in
// a millisecond or two, so a kill rarely lands inside a write here; the kill
// inside a write is tested deterministically in
// tests/geometry/test_atomic_file.cpp, and this test proves that every
// output of the command goes through that writer and leaves nothing behind.

#include "command_run.h"
#include "temp_dir.h"

#include "hullcover/bvh/runtime_file.h"
#include "hullcover/validate/hull_set.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <algorithm>
#include <set>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using hullcover::test::CommandRun;
using hullcover::test::slurp;
using hullcover::test::TempDir;

const std::string kOld = "old content\n";

// The outputs of one decompose run, placed in their own folder with old
// content, so a run that stops early shows as old content.
struct Outputs {
  std::string folder, obj, json, world;
  explicit Outputs(const std::string& f) : folder(f), obj(f + "/h.obj"), json(f + "/h.json"), world(f + "/w.hcw") {}
  void write_old() const {
    for (const std::string& path : {obj, json, world}) {
      FILE* out = std::fopen(path.c_str(), "w");
      std::fputs(kOld.c_str(), out);
      std::fclose(out);
    }
  }
  std::string arguments(const std::string& scene) const {
    return "decompose " + scene + " -o " + obj + " --json " + json + " --world " + world + " -q";
  }
};

// Each output holds its old content or a whole file its reader accepts.
void expect_old_or_complete(const Outputs& o, const std::string& when) {
  EXPECT_TRUE(slurp(o.obj) == kOld || hullcover::validate::load_hull_set(o.obj).ok()) << when;
  EXPECT_TRUE(slurp(o.world) == kOld || hullcover::bvh::read_runtime_file(o.world).ok()) << when;
  EXPECT_TRUE(slurp(o.json) == kOld || nlohmann::json::accept(slurp(o.json))) << when;
  EXPECT_EQ(hullcover::test::folder_entries(o.folder), (std::set<std::string>{"h.obj", "h.json", "w.hcw"})) << when;
}

// Starts hullcover with `arguments` (split on spaces), output discarded.
pid_t start_hullcover(const std::string& arguments) {
  std::vector<std::string> words{HULLCOVER_EXECUTABLE};
  for (size_t at = 0; at <= arguments.size();) {
    const size_t space = std::min(arguments.find(' ', at), arguments.size());
    if (space > at) words.push_back(arguments.substr(at, space - at));
    at = space + 1;
  }
  const pid_t child = fork();
  if (child == 0) {
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return child;
}

TEST(InterruptedOutputs, ASignalAtAnyMomentLeavesEachOutputOldOrComplete) {
  TempDir dir;
  ASSERT_EQ(hullcover::test::run_hullcover(dir, "demo --out " + dir.path("demo")).status, 0);
  const std::string scene = dir.path("demo/demo-scene.obj");
  // Kill moments spread from the start of the run to three times its length,
  // measured here (a loaded machine runs slow, and unevenly), so some land in
  // the writing of the files and the last ones after the run has ended.
  const Outputs timed(dir.path("timed"));
  ASSERT_EQ(mkdir(timed.folder.c_str(), 0700), 0);
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(hullcover::test::run_hullcover(dir, timed.arguments(scene)).status, 0);
  const auto run_time = std::chrono::steady_clock::now() - start;
  constexpr int kMoments = 30;
  const auto kStep = run_time * 3 / kMoments;
  int interrupted = 0, finished = 0;
  for (int k = 0; k < kMoments; ++k) {
    const Outputs o(dir.path("run" + std::to_string(k)));
    ASSERT_EQ(mkdir(o.folder.c_str(), 0700), 0);
    o.write_old();
    const pid_t child = start_hullcover(o.arguments(scene));
    std::this_thread::sleep_for(kStep * k);
    kill(child, k % 2 == 0 ? SIGTERM : SIGINT);
    int status = 0;
    waitpid(child, &status, 0);
    if (WIFSIGNALED(status))
      ++interrupted;
    else if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
      ++finished;
    expect_old_or_complete(o, "killed at moment " + std::to_string(k) + " of " + std::to_string(kMoments));
  }
  // Both kinds of ending must occur, or the moments missed the run.
  EXPECT_GT(interrupted, 0);
  EXPECT_GT(finished, 0);
}

TEST(InterruptedOutputs, AFullDiskIsAnErrorAndLeavesTheOldFiles) {
  TempDir dir;
  ASSERT_EQ(hullcover::test::run_hullcover(dir, "demo --out " + dir.path("demo")).status, 0);
  const Outputs o(dir.path("run"));
  ASSERT_EQ(mkdir(o.folder.c_str(), 0700), 0);
  o.write_old();
  // A file-size limit of one block stands in for a full disk: the write
  // fails (SIGXFSZ ignored, as a full disk raises no signal).
  const std::string command = "sh -c 'ulimit -f 1; trap \"\" XFSZ; exec " + std::string(HULLCOVER_EXECUTABLE) + " " +
                              o.arguments(dir.path("demo/demo-scene.obj")) + "' >" + dir.path("stdout") + " 2>" +
                              dir.path("stderr");
  const int raw = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 2);
  const std::string err = slurp(dir.path("stderr"));
  EXPECT_NE(err.find("h.obj: write failed"), std::string::npos) << err;
  EXPECT_EQ(slurp(o.obj), kOld);
  expect_old_or_complete(o, "full disk");
}

} // namespace

// Progress bars: drawn on stderr when it is a terminal, and nothing at all
// on stderr otherwise (logs, pipes, CI).

#include "command_run.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace {

using hullcover::test::run_hullcover;
using hullcover::test::slurp;
using hullcover::test::TempDir;

// Writes the demo scene to `dir`, returning its path.
std::string demo_scene(const TempDir& dir) {
  EXPECT_EQ(run_hullcover(dir, "demo --out " + dir.path("demo")).status, 0);
  return dir.path("demo/demo-scene.obj");
}

TEST(TerminalProgress, NothingOnStderrWhenItIsNotATerminal) {
  TempDir dir;
  const std::string scene = demo_scene(dir);
  const auto run = run_hullcover(dir, "decompose " + scene + " -o " + dir.path("h.obj"));
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.err, "");
}

TEST(TerminalProgress, BarOnATerminalAndNoneWithQuiet) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "script(1) (util-linux) not found";
  TempDir dir;
  const std::string scene = demo_scene(dir);
  // script(1) runs the command on a pseudo-terminal and copies what it shows.
  const auto on_terminal = [&](const std::string& extra) {
    const std::string command = "script -qec '" + std::string(HULLCOVER_EXECUTABLE) + " decompose " + scene + " -o " +
                                dir.path("h.obj") + extra + "' /dev/null >" + dir.path("tty.txt") + " </dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0);
    return slurp(dir.path("tty.txt"));
  };
  const std::string shown = on_terminal("");
  EXPECT_NE(shown.find("100.0% decomposing"), std::string::npos) << shown;
  EXPECT_NE(shown.find("[#####"), std::string::npos) << shown;
  EXPECT_EQ(on_terminal(" -q").find("decomposing"), std::string::npos);
}

} // namespace

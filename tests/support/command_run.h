#pragma once
// Runs the real `hullcover` binary (HULLCOVER_EXECUTABLE, defined by the
// test target) as a user would, capturing its exit status and output.

#include "temp_dir.h"

#include <cstdlib>
#include <string>
#include <sys/wait.h>

namespace hullcover::test {

struct CommandRun {
  int status = -1; ///< exit status; -1 when it did not exit (a signal)
  std::string out, err;
};

/// `hullcover ARGUMENTS`, its output kept in `dir`.
inline CommandRun run_hullcover(const TempDir& dir, const std::string& arguments) {
  const std::string command = std::string(HULLCOVER_EXECUTABLE) + " " + arguments + " >" + dir.path("stdout") + " 2>" +
                              dir.path("stderr") + " </dev/null";
  const int raw = std::system(command.c_str());
  CommandRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(dir.path("stdout"));
  r.err = slurp(dir.path("stderr"));
  return r;
}

} // namespace hullcover::test

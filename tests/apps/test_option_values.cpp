// Every numeric option of every command, taken from the parser's own option
// list (so a new option cannot be left out), refuses nonsense: empty, not a
// number, NaN, infinite, beyond double's range, absurdly large, negative
// (unless it is a coordinate), and fractional for a count. Each refusal is
// exit status 2 with one line naming the option, from the real binary.

#include "command_run.h"
#include "commands.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

using hullcover::test::CommandRun;
using hullcover::test::run_hullcover;
using hullcover::test::TempDir;

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// CLI11 names a number option's type FLOAT, INT or UINT, then ":" and each
// check's description.
bool is_number_option(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  return starts_with(type, "FLOAT") || starts_with(type, "INT") || starts_with(type, "UINT");
}

bool is_count_option(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  return starts_with(type, "INT") || starts_with(type, "UINT");
}

// Coordinates (a query shape's centre, a ray's direction) take any sign;
// their check says so in its description.
bool takes_negative(const CLI::Option& option) {
  return option.get_type_name().find("COORDINATE") != std::string::npos;
}

std::string option_name(const CLI::Option& option) {
  if (!option.get_lnames().empty()) return "--" + option.get_lnames().front();
  return "-" + option.get_snames().front();
}

// The values every number option must refuse.
std::vector<std::string> nonsense_for(const CLI::Option& option) {
  std::vector<std::string> values = {"", "banana", "nan", "inf", "-inf", "1e400", "1e300", "99999999999999999999999"};
  if (!takes_negative(option)) values.push_back("-1");
  if (is_count_option(option)) values.push_back("2.5");
  return values;
}

// The option's text with `bad` in position `at` of its values (a vector
// option such as --sphere x,y,z,r takes several), the others 1.
std::string with_value(const CLI::Option& option, const std::string& bad, int at) {
  const int count = std::max(1, option.get_expected_min());
  std::string text = option_name(option) + "='";
  for (int k = 0; k < count; ++k) text += (k ? "," : "") + (k == at ? bad : std::string("1"));
  return text + "'";
}

TEST(OptionValues, EveryNumberOptionOfEveryCommandRefusesNonsenseNamingTheOption) {
  CLI::App app;
  int exit_status = 0;
  hullcover::app::register_all_commands(app, exit_status);
  TempDir dir;
  const std::string scene = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  // A value wrongly taken runs the command, which may write to the working
  // folder (bench's default --out): that is the test's own folder.
  const std::filesystem::path was = std::filesystem::current_path();
  std::filesystem::current_path(dir.path("."));

  int commands = 0, options = 0, number_options = 0, runs = 0;
  std::vector<std::string> failures;
  for (const CLI::App* command : app.get_subcommands({})) {
    ++commands;
    // Every positional gets the scene's path, every required option a path
    // to write: the option under test is refused before any file is read.
    std::string positionals;
    for (const CLI::Option* option : command->get_options()) {
      if (option->get_positional())
        positionals += " " + scene;
      else if (option->get_required())
        positionals += " " + option_name(*option) + "=" + dir.path("out.obj");
    }
    for (const CLI::Option* option : command->get_options()) {
      if (!option->nonpositional() || option->get_type_size() == 0) continue; // positionals, flags, --help
      ++options;
      if (!is_number_option(*option)) continue;
      ++number_options;
      const std::string name = option_name(*option);
      for (int at = 0; at < std::max(1, option->get_expected_min()); ++at)
        for (const std::string& bad : nonsense_for(*option)) {
          const std::string arguments = command->get_name() + " " + with_value(*option, bad, at) + positionals;
          const CommandRun r = run_hullcover(dir, arguments);
          ++runs;
          std::istringstream lines(r.err);
          std::string first;
          std::getline(lines, first);
          if (r.status != 2 || first.find(name) == std::string::npos)
            failures.push_back("hullcover " + arguments + " -> exit " + std::to_string(r.status) + ": " + first);
        }
    }
  }
  std::filesystem::current_path(was);
  std::printf("%d commands, %d options taking a value, %d of them numbers: %d runs with nonsense\n", commands, options,
              number_options, runs);
  RecordProperty("number_options", number_options);
  RecordProperty("runs", runs);
  EXPECT_GE(number_options, 40);
  std::string listed;
  for (const std::string& failure : failures) listed += failure + "\n";
  EXPECT_TRUE(failures.empty()) << failures.size() << " accepted or refused without naming the option:\n" << listed;
}

// Numbers written as text with a unit or after '@' (bench's sweeps and
// scenes, world's scenes) are parsed by the commands themselves: the same
// bound holds there.
TEST(OptionValues, NumbersInsideTextOptionsKeepTheSameBound) {
  TempDir dir;
  const std::string scene = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const std::string out = " --out " + dir.path("bench");
  for (const std::string& arguments :
       {"bench " + scene + " --agent-radius 1e300" + out, "bench " + scene + " --max-deviation 2e15m" + out,
        "bench " + scene + " --query-radius nan" + out, "bench " + scene + "@1e300" + out,
        "world " + scene + "@1e300 -o " + dir.path("w.obj"), "world " + scene + "@-1 -o " + dir.path("w.obj")}) {
    const CommandRun r = run_hullcover(dir, arguments);
    EXPECT_EQ(r.status, 2) << arguments << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find("hullcover: error:"), std::string::npos) << arguments << "\n" << r.err;
  }
}

} // namespace

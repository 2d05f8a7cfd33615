// Every file of the fuzz corpora (tests/fuzz/corpus/<target>/) and every
// saved crasher (tests/fuzz/regressions/<target>/) run through its target's
// body, in every build: how a crash the fuzzer once found stays fixed. One
// test per file, named after it, so a failure names the input. Files are
// listed when ctest runs (discovery before the tests), so a crasher dropped
// into regressions/ is replayed without a rebuild.

#include "fuzz_targets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

namespace hullcover::fuzz {
namespace {

namespace fs = std::filesystem;

using Body = int (*)(const std::uint8_t*, std::size_t);

struct Target {
  const char* name;
  Body body;
};
const Target kTargets[] = {{kMeshImport, fuzz_one_mesh_import},
                           {kRuntimeFile, fuzz_one_runtime_file},
                           {kHullObj, fuzz_one_hull_obj},
                           {kCellResult, fuzz_one_cell_result},
                           {kSceneSnapshot, fuzz_one_scene_snapshot},
                           {kPreparedScene, fuzz_one_prepared_scene}};

struct Input {
  std::string target;
  std::string kind; // "corpus" or "regressions"
  fs::path file;
};

// gtest prints a failing test's parameter: the file, not its bytes.
void PrintTo(const Input& input, std::ostream* os) { *os << input.file.string(); }

// Files directly in <kind>/<target>/, sorted; dot files (.gitkeep) are not inputs.
std::vector<Input> inputs() {
  std::vector<Input> out;
  for (const char* kind : {"corpus", "regressions"})
    for (const Target& t : kTargets) {
      const fs::path folder = fs::path(HULLCOVER_FUZZ_DIR) / kind / t.name;
      std::error_code error;
      std::vector<fs::path> files;
      for (const fs::directory_entry& e : fs::directory_iterator(folder, error))
        if (e.is_regular_file() && e.path().filename().string().front() != '.') files.push_back(e.path());
      std::sort(files.begin(), files.end());
      for (const fs::path& f : files) out.push_back({t.name, kind, f});
    }
  return out;
}

std::string test_name(const testing::TestParamInfo<Input>& info) {
  std::string name = info.param.target + "_" + info.param.kind + "_" + info.param.file.filename().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class FuzzReplay : public testing::TestWithParam<Input> {};

// Passes when the body returns: a crash, a sanitizer report or an uncaught
// exception is the failure (the suite's own process dies, naming the test).
TEST_P(FuzzReplay, RunsWithoutCrashing) {
  const Input& input = GetParam();
  std::ifstream in(input.file, std::ios::binary);
  ASSERT_TRUE(in) << input.file;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto target =
      std::find_if(std::begin(kTargets), std::end(kTargets), [&](const Target& t) { return input.target == t.name; });
  ASSERT_NE(target, std::end(kTargets));
  EXPECT_EQ(target->body(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
}

INSTANTIATE_TEST_SUITE_P(Files, FuzzReplay, testing::ValuesIn(inputs()), test_name);

// A wrong folder would otherwise replay nothing and pass.
TEST(FuzzCorpus, EveryTargetHasSeeds) {
  for (const Target& t : kTargets) {
    const std::vector<Input> all = inputs();
    EXPECT_TRUE(
        std::any_of(all.begin(), all.end(), [&](const Input& i) { return i.target == t.name && i.kind == "corpus"; }))
        << "no seed in " << HULLCOVER_FUZZ_DIR << "/corpus/" << t.name;
  }
}

} // namespace
} // namespace hullcover::fuzz

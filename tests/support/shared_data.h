#pragma once
// Where the project's shared data (real game scenes, other tools' hulls)
// lives, for tests that read it in place.

#include "hullcover/mesh/prepared_mesh.h"

#include <optional>
#include <string>

namespace hullcover::test {

/// The `data/scenes` directory, or nothing when it is absent (a user's
/// clone without ../shared). The environment variable HULLCOVER_SHARED_DIR
/// overrides the location configured at build time.
std::optional<std::string> shared_scenes_dir();

/// As shared_scenes_dir(), saying on stderr why a benchmark has nothing to
/// measure when the scenes are absent.
std::optional<std::string> shared_scenes_dir_for_benchmark();

/// Imports and prepares `file` from the shared scenes at the default
/// tolerance (for benchmarks; tests assert each step themselves).
Result<PreparedMesh> prepare_shared_scene(const std::string& dir, const std::string& file);

/// A file name as a test name (GoogleTest allows letters, digits and
/// underscores only): every other character becomes '_'.
std::string file_test_name(const std::string& file);

/// The eight shared scenes, by file name.
inline const char* const kSharedScenes[] = {
    "recast-dungeon.obj",      "recast-nav_test.obj",     "recast-undulating.obj",    "sauerbraten-fdm6.obj",
    "sauerbraten-pandora.obj", "stanford-bunny-res2.ply", "thor-art56-gearplate.stl", "threejs-collision-world.glb"};

} // namespace hullcover::test

/// Skips the current test, with a message saying why, when the shared
/// scenes are absent; otherwise binds `dir` to their directory.
#define HULLCOVER_REQUIRE_SHARED_SCENES(dir)                                                 \
  const auto dir##_found = ::hullcover::test::shared_scenes_dir();                           \
  if (!dir##_found)                                                                          \
    GTEST_SKIP() << "../shared/data/scenes not found (a clone without the project's shared " \
                    "folder); set HULLCOVER_SHARED_DIR to run this test";                    \
  const std::string dir = *dir##_found

#pragma once
// Reading and preparing the scene a command works on, with the one-line
// error every command prints for unreadable input.

#include "hullcover/mesh/mesh_import.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace hullcover::app {

struct LoadedScene {
  PreparedMesh prepared;
  ImportReport report;
};

/// Imports `path` within `limits` and prepares it with the tolerance given
/// (or the default). On failure prints "hullcover: error: PATH: problem" to
/// stderr and returns nothing.
std::optional<LoadedScene> load_scene(const std::string& path, std::optional<double> tolerance,
                                      const ImportLimits& limits = {});

/// Adds --max-file-size, --max-node-depth and --max-triangles to `command`,
/// filling `limits` (mesh_import.h documents each and its default).
void add_import_limit_options(CLI::App& command, ImportLimits& limits);

} // namespace hullcover::app

#include "scene_loading.h"
#include "number_checks.h"

#include <CLI/CLI.hpp>

#include <cstdio>

namespace hullcover::app {

std::optional<LoadedScene> load_scene(const std::string& path, std::optional<double> tolerance,
                                      const ImportLimits& limits) {
  Result<ImportedMesh> imported = import_mesh(path, limits);
  if (!imported.ok()) {
    std::fprintf(stderr, "hullcover: error: %s\n", imported.status().message().c_str());
    return std::nullopt;
  }
  Result<PreparedMesh> prepared = prepare_mesh(imported.value().mesh, tolerance);
  if (!prepared.ok()) {
    std::fprintf(stderr, "hullcover: error: %s: %s\n", path.c_str(), prepared.status().message().c_str());
    return std::nullopt;
  }
  return LoadedScene{std::move(prepared).value(), imported.value().report};
}

void add_import_limit_options(CLI::App& command, ImportLimits& limits) {
  command
      .add_option("--max-file-size", limits.max_file_bytes,
                  "Largest scene file, and file it refers to, in bytes (a bound on what a file from anyone may make "
                  "the importer read)")
      ->capture_default_str()
      ->check(count_from(1, kLargestFileLimit));
  command
      .add_option("--max-node-depth", limits.max_node_depth,
                  "Deepest node hierarchy (and glTF JSON nesting) a scene may have")
      ->capture_default_str()
      ->check(count_from(1, kDeepestNodeLimit));
  command
      .add_option("--max-triangles", limits.max_triangles,
                  "Most triangles a scene may place, counting a mesh once per node that places it (default: one per "
                  "8 bytes of the files read, at least 65,536, at most 4,194,304)")
      ->check(count_from(1, kMostTrianglesLimit));
  command.add_option("--max-materials", limits.max_materials, "Most distinct materials an OBJ file may name (usemtl)")
      ->capture_default_str()
      ->check(count_from(1, kMostMaterialsLimit));
}

} // namespace hullcover::app

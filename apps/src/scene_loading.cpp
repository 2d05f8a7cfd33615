#include "scene_loading.h"

#include <cstdio>

namespace hullcover::app {

std::optional<LoadedScene> load_scene(const std::string& path, std::optional<double> tolerance) {
  Result<ImportedMesh> imported = import_mesh(path);
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

} // namespace hullcover::app

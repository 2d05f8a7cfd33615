#include "shared_data.h"

#include "hullcover/mesh/mesh_import.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace hullcover::test {

std::optional<std::string> shared_scenes_dir() {
  const char* from_environment = std::getenv("HULLCOVER_SHARED_DIR");
  const std::filesystem::path root = from_environment ? from_environment : HULLCOVER_SHARED_DIR;
  const std::filesystem::path scenes = root / "data" / "scenes";
  std::error_code error;
  if (!std::filesystem::is_directory(scenes, error)) return std::nullopt;
  return scenes.string();
}

std::optional<std::string> shared_scenes_dir_for_benchmark() {
  std::optional<std::string> dir = shared_scenes_dir();
  if (!dir) std::fprintf(stderr, "../shared/data/scenes not found: nothing to benchmark (set HULLCOVER_SHARED_DIR)\n");
  return dir;
}

Result<PreparedMesh> prepare_shared_scene(const std::string& dir, const std::string& file) {
  Result<ImportedMesh> imported = import_mesh(dir + "/" + file);
  if (!imported.ok()) return imported.status();
  return prepare_mesh(imported.value().mesh, std::nullopt);
}

std::string file_test_name(const std::string& file) {
  std::string name = file;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

} // namespace hullcover::test

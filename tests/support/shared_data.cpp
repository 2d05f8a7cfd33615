#include "shared_data.h"

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

} // namespace hullcover::test

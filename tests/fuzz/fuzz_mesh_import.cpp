// Fuzz target: mesh import (lib/mesh), the reader every command runs on a
// scene from anyone, then prepare_mesh (validation, tolerance, welding,
// connectivity) on what it accepts, as `hullcover info` does.

#include "fuzz_support.h"
#include "fuzz_targets.h"

#include "hullcover/mesh/mesh_import.h"
#include "hullcover/mesh/prepared_mesh.h"

namespace hullcover::fuzz {

int fuzz_one_mesh_import(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // The formats with a pre-check of their own (scene_file_checks.cpp,
  // gltf_file_checks.cpp) and OBJ, the commonest; one byte costs the
  // fuzzer little and lets one corpus hold every format.
  static constexpr const char* kExtensions[] = {".obj", ".ply", ".stl", ".gltf", ".glb"};
  constexpr std::size_t kFormats = sizeof kExtensions / sizeof kExtensions[0];
  const std::string name = std::string("scene") + kExtensions[data[0] % kFormats];
  // The default limits, as every command applies them: the triangle limit
  // scales with the file's size, so no small input imports for long.
  const std::string path = write_scratch_file(name, data + 1, size - 1);
  Result<ImportedMesh> imported = import_mesh(path);
  remove_scratch_file(path);
  if (!imported.ok()) return 0;
  Result<PreparedMesh> prepared = prepare_mesh(imported.value().mesh, std::nullopt);
  static_cast<void>(prepared);
  return 0;
}

} // namespace hullcover::fuzz

#ifdef HULLCOVER_LIBFUZZER_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hullcover::fuzz::fuzz_one_mesh_import(data, size);
}
#endif

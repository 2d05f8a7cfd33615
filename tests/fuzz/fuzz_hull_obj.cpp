// Fuzz target: the hull-file readers (validate's load_hull_set on an `.obj`:
// V-HACD output, hand-made UCX meshes, anyone's hulls to audit; and on a
// `.glb`, an engine export, when the input starts with GLB's magic), then
// queries on the hulls it makes.

#include "fuzz_support.h"
#include "fuzz_targets.h"

#include "hullcover/validate/hull_set.h"

#include <cstring>

namespace hullcover::fuzz {

int fuzz_one_hull_obj(const std::uint8_t* data, std::size_t size) {
  const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::string path = write_scratch_file(glb ? "hulls.glb" : "hulls.obj", data, size);
  Result<validate::HullSet> set = validate::load_hull_set(path);
  remove_scratch_file(path);
  if (set.ok()) query_hulls(std::move(set.value().hulls));
  return 0;
}

} // namespace hullcover::fuzz

#ifdef HULLCOVER_LIBFUZZER_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hullcover::fuzz::fuzz_one_hull_obj(data, size);
}
#endif

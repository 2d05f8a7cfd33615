// Fuzz target: the hull-OBJ reader (validate's load_hull_set on an `.obj`:
// V-HACD output, hand-made UCX meshes, anyone's hulls to audit), then
// queries on the hulls it makes.

#include "fuzz_support.h"
#include "fuzz_targets.h"

#include "hullcover/validate/hull_set.h"

namespace hullcover::fuzz {

int fuzz_one_hull_obj(const std::uint8_t* data, std::size_t size) {
  const std::string path = write_scratch_file("hulls.obj", data, size);
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

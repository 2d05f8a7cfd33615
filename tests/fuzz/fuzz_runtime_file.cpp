// Fuzz target: the runtime file readers (bvh's read_runtime_file: the `.hcw`
// a game server loads, and its section readers), then queries on the hulls
// read_runtime_file accepts: the reader promises hulls checked before use.

#include "fuzz_support.h"
#include "fuzz_targets.h"

#include "hullcover/bvh/runtime_file.h"
#include "hullcover/geometry/little_endian_bytes.h"

#include <cstring>
#include <vector>

namespace hullcover::fuzz {
namespace {

// runtime_file.h's header: magic (8 bytes), u32 version, u32 reserved,
// u64 hull count, u64 payload bytes, u64 FNV-1a-64 of the payload.
constexpr std::size_t kHeaderBytes = 40;
constexpr std::size_t kPayloadBytesAt = 24;
constexpr std::size_t kChecksumAt = 32;

void read_and_query(const std::uint8_t* data, std::size_t size) {
  const std::string path = write_scratch_file("world.hcw", data, size);
  Result<std::vector<bvh::RuntimeHull>> hulls = bvh::read_runtime_file(path);
  // The section readers share the checks but walk the file their own way.
  if (Result<std::vector<bvh::RuntimeSection>> sections = bvh::read_runtime_sections(path); sections.ok())
    for (const bvh::RuntimeSection& s : sections.value()) (void)bvh::read_runtime_section(path, s.id);
  remove_scratch_file(path);
  if (hulls.ok()) query_hulls(std::move(hulls.value()));
}

} // namespace

int fuzz_one_runtime_file(const std::uint8_t* data, std::size_t size) {
  read_and_query(data, size);
  // A mutated payload almost never keeps its checksum: without this second
  // read the fuzzer would stop at "checksum mismatch" and never reach the
  // checks of counts, indices and values behind it.
  static constexpr char kMagic[8] = {'H', 'C', 'W', 'O', 'R', 'L', 'D', '\0'};
  if (size < kHeaderBytes || std::memcmp(data, kMagic, sizeof kMagic) != 0) return 0;
  std::vector<std::uint8_t> fixed(data, data + size);
  put_u64(fixed, kPayloadBytesAt, size - kHeaderBytes);
  put_u64(fixed, kChecksumAt, fnv1a(fixed.data() + kHeaderBytes, size - kHeaderBytes));
  if (std::memcmp(fixed.data(), data, kHeaderBytes) != 0) read_and_query(fixed.data(), fixed.size());
  return 0;
}

} // namespace hullcover::fuzz

#ifdef HULLCOVER_LIBFUZZER_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hullcover::fuzz::fuzz_one_runtime_file(data, size);
}
#endif

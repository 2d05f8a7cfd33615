// Fuzz target: a cell's result as bytes (lib/covering/src/cells/cell_result_bytes.h),
// what a distributed bake's worker sends back and the cell cache reads from
// disk. StagedDecomposition::still_valid and finish must refuse bad bytes with
// a message, never crash, hang or trust them.
//
// A small scene of several cells is prepared for each input; the input is
// read two ways: as cell 0's bytes as they come, and as EDITS to the valid
// bytes of cell 0 (the key and checksum made right afterwards), so the
// fuzzer reaches the checks of counts, indices and values behind them.

#include "fuzz_support.h"
#include "fuzz_targets.h"

#include "hullcover/covering/staged_decomposition.h"
#include "hullcover/geometry/little_endian_bytes.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <cstring>
#include <string>
#include <vector>

namespace hullcover::fuzz {
namespace {

// cell_result_bytes.h's layout: magic (8 bytes), u32 version, u64 cell
// key; ..., u64 FNV-1a-64 of everything before it.
constexpr std::size_t kKeyAt = 12;
// still_valid, then finish with the bytes in place of cell 0.
void read_as_cell_zero(const StagedDecomposition& staged, const std::vector<std::string>& cells,
                       const std::string& bytes) {
  std::string why;
  (void)staged.still_valid(0, bytes, &why);
  std::vector<std::string> with = cells;
  with[0] = bytes;
  (void)staged.finish(with);
}

} // namespace

int fuzz_one_cell_result(const std::uint8_t* data, std::size_t size) {
  Result<PreparedMesh> prepared = prepare_mesh(small_scene_in_cells(), std::nullopt);
  if (!prepared.ok()) return 0;
  DecomposeOptions options;
  options.cell_size = kSmallSceneCellSize;
  options.threads = 1;
  Result<std::unique_ptr<StagedDecomposition>> staged =
      StagedDecomposition::prepare(std::move(prepared).value(), options);
  if (!staged.ok() || staged.value()->cell_count() < 2) return 0;
  const StagedDecomposition& s = *staged.value();
  std::vector<std::string> cells;
  for (int c = 0; c < s.cell_count(); ++c) {
    Result<std::string> bytes = s.merge_cell(c);
    if (!bytes.ok()) return 0;
    cells.push_back(std::move(bytes).value());
  }
  read_as_cell_zero(s, cells, std::string(reinterpret_cast<const char*>(data), size));

  // The valid bytes, edited; an input of a length not a multiple of the
  // edit size ends them there (a truncation to that many bytes modulo the size).
  std::string edited = cells[0];
  apply_byte_edits(edited, data, size);
  if (size % kEditBytes != 0) edited.resize(data[size - 1] % edited.size());
  if (edited.size() >= kKeyAt + 8 + kChecksumBytes) {
    put_u64(edited, kKeyAt, s.cell_key(0));
    put_u64(edited, edited.size() - kChecksumBytes,
            fnv1a(reinterpret_cast<const unsigned char*>(edited.data()), edited.size() - kChecksumBytes));
  }
  read_as_cell_zero(s, cells, edited);
  return 0;
}

} // namespace hullcover::fuzz

#ifdef HULLCOVER_LIBFUZZER_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hullcover::fuzz::fuzz_one_cell_result(data, size);
}
#endif

// Fuzz target: the prepared scene file (StagedDecomposition::map_prepared,
// lib/covering/src/cells/prepared_scene_file.h), what every worker of a
// distributed bake maps. The reader must refuse a bad file with a message,
// never crash, hang, allocate without bound or leave a view that points
// outside the mapping.
//
// For each input a small scene in cells is prepared and its file written;
// the input is mapped two ways: as the file as it comes, and as EDITS to
// the valid file with every checksum made right afterwards, so the fuzzer
// reaches the checks of lengths, indices and tree links behind them. (The
// numbers a file holds, reaches and boxes, are trusted as its writer made
// them, as the cell cache's are; its links are not: that is what is
// fuzzed.)

#include "fuzz_support.h"
#include "fuzz_targets.h"
#include "prepared_scene_edits.h"

#include "hullcover/covering/staged_decomposition.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace hullcover::fuzz {
namespace {

DecomposeOptions small_scene_options() {
  DecomposeOptions options;
  options.cell_size = kSmallSceneCellSize;
  options.threads = 1;
  return options;
}

void map(const std::string& bytes) {
  const std::string path =
      write_scratch_file("scene.hcp", reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  Result<std::unique_ptr<StagedDecomposition>> mapped = StagedDecomposition::map_prepared(path, small_scene_options());
  if (mapped.ok()) mapped.value()->release_mapped_pages();
  remove_scratch_file(path);
}

} // namespace

int fuzz_one_prepared_scene(const std::uint8_t* data, std::size_t size) {
  Result<PreparedMesh> prepared = prepare_mesh(small_scene_in_cells(), std::nullopt);
  if (!prepared.ok()) std::abort();
  Result<std::unique_ptr<StagedDecomposition>> staged =
      StagedDecomposition::prepare(std::move(prepared).value(), small_scene_options());
  if (!staged.ok()) std::abort();
  const std::string good = write_scratch_file("good.hcp", data, 0);
  if (!staged.value()->write_prepared(good).ok()) std::abort();
  std::string valid;
  {
    std::ifstream in(good, std::ios::binary);
    valid.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  remove_scratch_file(good);

  map(std::string(reinterpret_cast<const char*>(data), size));

  // The valid file edited, its checksums made right; an input of a length
  // not a multiple of the edit size cuts it there.
  std::string edited = valid;
  apply_byte_edits(edited, data, size);
  if (size % kEditBytes != 0) edited.resize(data[size - 1] * valid.size() / 256);
  test::reseal_prepared_scene(edited);
  map(edited);
  return 0;
}

} // namespace hullcover::fuzz

#ifdef HULLCOVER_LIBFUZZER_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hullcover::fuzz::fuzz_one_prepared_scene(data, size);
}
#endif

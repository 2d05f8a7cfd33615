// Fuzz target: the cell cache's record of the last bake (`last-bake.scene`,
// lib/covering/src/cells/scene_change.h), read by every bake with a cache. A bake
// must refuse a bad record (and re-check every kept patch), never crash,
// hang, allocate without bound or trust what it cannot read.
//
// For each input a small scene in cells is baked into a fresh cache; then
// the scene, with one face added, is baked again twice from copies of it:
// once with the input as the record, once with the input read as EDITS to
// the valid record (its checksum made right afterwards), so the fuzzer
// reaches the checks of counts and values behind the checksum. A bake that
// fails (rather than falling back to re-checking everything) aborts.

#include "fuzz_support.h"
#include "fuzz_targets.h"

#include "hullcover/covering/cell_cache.h"
#include "hullcover/geometry/little_endian_bytes.h"
#include "hullcover/mesh/prepared_mesh.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace hullcover::fuzz {
namespace {

constexpr const char* kRecordName = "last-bake.scene";

bool bake(const Mesh& mesh, const std::string& cache) {
  Result<PreparedMesh> prepared = prepare_mesh(mesh, std::nullopt);
  if (!prepared.ok()) return false;
  DecomposeOptions options;
  options.cell_size = kSmallSceneCellSize;
  options.threads = 1;
  CellCacheReport report;
  return decompose_with_cell_cache(std::move(prepared).value(), options, cache, report).ok();
}

// A copy of the flat folder `from` as `to`, file by file through streams:
// std::filesystem::copy gives up when a signal interrupts its sendfile
// (libFuzzer's timers raise them), where the streams' reads and writes retry.
void copy_folder_of_files(const std::string& from, const std::string& to) {
  std::filesystem::create_directory(to);
  for (const std::filesystem::directory_entry& entry : std::filesystem::directory_iterator(from)) {
    std::ifstream in(entry.path(), std::ios::binary);
    if (!in) std::abort();
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(std::filesystem::path(to) / entry.path().filename(), std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (in.bad() || !out) std::abort();
  }
}

// A re-bake of `after` from a copy of the filled cache `filled`, with
// `record` as the last bake's record. A bad record is refused and every
// kept patch re-checked: the bake itself must not fail.
void rebake_with_record(const Mesh& after, const std::string& filled, const std::string& cache,
                        const std::string& record) {
  std::error_code ignored;
  std::filesystem::remove_all(cache, ignored);
  copy_folder_of_files(filled, cache);
  std::ofstream(cache + "/" + kRecordName, std::ios::binary | std::ios::trunc) << record;
  if (!bake(after, cache)) std::abort();
}

} // namespace

int fuzz_one_scene_snapshot(const std::uint8_t* data, std::size_t size) {
  const std::string marker = write_scratch_file("scene-snapshot.marker", data, 0);
  const std::filesystem::path folder = std::filesystem::path(marker).parent_path();
  const std::string filled = folder / "scene-snapshot-filled", cache = folder / "scene-snapshot-cache";
  std::error_code ignored;
  std::filesystem::remove_all(filled, ignored);
  const Mesh before = small_scene_in_cells();
  if (!bake(before, filled)) std::abort();
  std::string valid;
  {
    std::ifstream in(filled + "/" + kRecordName, std::ios::binary);
    valid.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  if (valid.size() <= kChecksumBytes) std::abort();
  // One face added beside the block: the re-bake reads the record to find it.
  Mesh after = before;
  const int base = static_cast<int>(after.positions.size());
  after.positions.insert(after.positions.end(), {{2.5, 0.2, 1.0}, {3.0, 0.2, 1.0}, {2.5, 1.0, 1.5}});
  after.triangles.emplace_back(base, base + 1, base + 2);
  after.material_ids.push_back(0);

  rebake_with_record(after, filled, cache, std::string(reinterpret_cast<const char*>(data), size));

  // The valid record edited; an input of a length not a multiple of the
  // edit size ends it there (its last one or two bytes, little-endian,
  // modulo the size: anywhere in the record).
  std::string edited = valid;
  apply_byte_edits(edited, data, size);
  const std::size_t rest = size % kEditBytes;
  if (rest == 1) edited.resize(data[size - 1] % edited.size());
  if (rest == 2) edited.resize((data[size - 2] | (static_cast<std::size_t>(data[size - 1]) << 8)) % edited.size());
  if (edited.size() >= kChecksumBytes)
    put_u64(edited, edited.size() - kChecksumBytes,
            fnv1a(reinterpret_cast<const unsigned char*>(edited.data()), edited.size() - kChecksumBytes));
  rebake_with_record(after, filled, cache, edited);
  std::filesystem::remove_all(cache, ignored);
  std::filesystem::remove_all(filled, ignored);
  remove_scratch_file(marker);
  return 0;
}

} // namespace hullcover::fuzz

#ifdef HULLCOVER_LIBFUZZER_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hullcover::fuzz::fuzz_one_scene_snapshot(data, size);
}
#endif

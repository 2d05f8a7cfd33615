#pragma once
// What the fuzz target bodies share: a scratch folder per process, and a
// few queries on hulls a reader accepted.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/mesh.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hullcover::fuzz {

/// Writes `size` bytes to `name` in this process's scratch folder (made on
/// first use under the system temp folder, removed at exit) and returns the
/// file's path. The folder holds nothing else unless a body leaves it there.
std::string write_scratch_file(const std::string& name, const std::uint8_t* data, std::size_t size);

/// Removes `path` (a file write_scratch_file made), so the next input's
/// folder is empty again.
void remove_scratch_file(const std::string& path);

/// Overwrites the 8 bytes of `bytes` at `at` with `v`, little-endian: how a
/// target makes a mutated file's size or checksum field right again, so the
/// fuzzer reaches the checks behind it (checksums: hullcover::fnv1a,
/// hullcover/geometry/little_endian_bytes.h). `Bytes` is any sequence of
/// byte-sized values; `at + 8` must not pass its end.
template <typename Bytes>
void put_u64(Bytes& bytes, std::size_t at, std::uint64_t v) {
  for (int k = 0; k < 8; ++k) bytes[at + k] = static_cast<typename Bytes::value_type>(v >> (8 * k));
}

/// Bytes of the FNV-1a-64 checksum ending a cell result or a scene record.
inline constexpr std::size_t kChecksumBytes = 8;
/// Bytes of one edit an input makes to a valid file: a u16 position
/// (little-endian, modulo the file's size) and the byte to put there.
inline constexpr std::size_t kEditBytes = 3;

/// Applies the size / kEditBytes whole edits at the start of `data` to
/// `bytes` (not empty); the rest of the input is the caller's.
void apply_byte_edits(std::string& bytes, const std::uint8_t* data, std::size_t size);

/// A cell side (scene units) that cuts small_scene_in_cells into several
/// cells.
inline constexpr double kSmallSceneCellSize = 2.0;

/// A small scene of several cells, each with merged patches (planar and
/// solid): a terrain patch, a block on it and a room beside it. Small, so
/// a fuzzer that bakes it for each input still runs many a second.
Mesh small_scene_in_cells();

/// Builds a HullWorld from `hulls` (when it accepts them) and asks it a
/// touch, a contact, a ray and a distance query near the first hull: a
/// reader's accepted hulls must be safe to query.
void query_hulls(std::vector<bvh::RuntimeHull> hulls);

} // namespace hullcover::fuzz

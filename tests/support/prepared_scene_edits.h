#pragma once
// Makes the checksums of a prepared scene file's bytes right again after a
// test or fuzz input has edited them (layout: lib/covering/src/cells/
// prepared_scene_file.h), so that what it reaches is the reader's checks
// of lengths, indices and links behind the checksums.

#include "cells/prepared_scene_sections.h"

#include <cstdint>
#include <cstring>
#include <string>

namespace hullcover::test {

/// Where section `id`'s table entry says it lies: {offset, length}; {0, 0}
/// when the table does not list it.
inline std::pair<std::uint64_t, std::uint64_t> prepared_section_at(const std::string& bytes, std::uint32_t id) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::uint64_t entry = detail::kPreparedHeadBytes; entry + detail::kSectionEntryBytes <= bytes.size();
       entry += detail::kSectionEntryBytes) {
    LittleEndianReader in{data, bytes.size(), entry};
    if (in.u32() != id) continue;
    in.u32();
    const std::uint64_t offset = in.u64(), length = in.u64();
    return {offset, length};
  }
  return {0, 0};
}

/// Recomputes every section's checksum that lies inside `bytes`, then the
/// header's. Bytes too short for a table are left as they are.
inline void reseal_prepared_scene(std::string& bytes) {
  if (bytes.size() < detail::kPreparedHeadBytes) return;
  auto* data = reinterpret_cast<unsigned char*>(bytes.data());
  LittleEndianReader head{data, bytes.size(), 12};
  const std::uint64_t count = head.u32();
  const std::uint64_t table_end = detail::kPreparedHeadBytes + detail::kSectionEntryBytes * count;
  if (count > bytes.size() || table_end + 8 > bytes.size()) return;
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::uint64_t entry = detail::kPreparedHeadBytes + detail::kSectionEntryBytes * k;
    LittleEndianReader in{data, bytes.size(), entry + 8};
    const std::uint64_t offset = in.u64(), length = in.u64();
    if (offset > bytes.size() || length > bytes.size() - offset) continue;
    const std::uint64_t sum = detail::section_checksum(data + offset, length);
    for (int b = 0; b < 8; ++b) data[entry + 24 + b] = static_cast<unsigned char>(sum >> (8 * b));
  }
  const std::uint64_t sum = fnv1a(data, table_end);
  for (int b = 0; b < 8; ++b) data[table_end + b] = static_cast<unsigned char>(sum >> (8 * b));
}

} // namespace hullcover::test

#include "cells/prepared_scene_sections.h"

#include "validity/scene_index.h"

#include <cstring>

namespace hullcover::detail {

std::uint32_t element_bytes_of(std::uint32_t id) {
  if (id >= kFirstTreeSection && id <= kSectionCount) {
    switch ((id - kFirstTreeSection) % kSectionsPerTree) {
      case 0: return kTreeNodeBytes;
      case 1: return sizeof(int);
      default: return sizeof(Aabb);
    }
  }
  switch (id) {
    case kScalars:
    case kMaterialNames:
    case kZeroArea: return 1;
    case kPositions:
    case kFaceNormals: return sizeof(Eigen::Vector3d);
    case kTriangles:
    case kFaceEdges:
    case kFaceNeighbours: return sizeof(Eigen::Vector3i);
    case kIslandZones:
    case kIslandBoxes: return sizeof(Aabb);
    case kEdges: return sizeof(StoredEdge);
    case kEdgeUses: return sizeof(EdgeUse);
    case kIslandLengths:
    case kIslandCellSize:
    case kFaceAreas:
    case kFrontReach: return sizeof(double);
    case kBars: return sizeof(BoundaryBar);
    case kOpeningReach: return sizeof(std::array<double, kOpeningFans>);
    default: return sizeof(std::int32_t);
  }
}

std::string section_name(std::uint32_t id) {
  static const char* const kNames[] = {"scalars",
                                       "material names",
                                       "positions",
                                       "triangles",
                                       "material ids",
                                       "island tolerances",
                                       "island zones",
                                       "island places",
                                       "island of face",
                                       "island boxes",
                                       "island face counts",
                                       "edges",
                                       "edge uses",
                                       "face edges",
                                       "face neighbours",
                                       "zero-area flags",
                                       "face components",
                                       "cell of face",
                                       "slot in cell",
                                       "island of cell",
                                       "cell halvings",
                                       "island cell sizes",
                                       "open edge uses",
                                       "face normals",
                                       "face areas",
                                       "bars",
                                       "front sweep faces",
                                       "front reaches",
                                       "opening sweep edges",
                                       "opening reaches",
                                       "bar pieces"};
  static const char* const kTrees[] = {"vertex", "edge", "face", "bar", "front sweep", "opening sweep"};
  static const char* const kParts[] = {"nodes", "items", "leaf boxes"};
  if (id >= kScalars && id < kFirstTreeSection) return kNames[id - kScalars];
  if (id >= kFirstTreeSection && id <= kSectionCount) {
    const std::uint32_t k = id - kFirstTreeSection;
    return std::string(kTrees[k / kSectionsPerTree]) + " tree " + kParts[k % kSectionsPerTree];
  }
  return "section " + std::to_string(id);
}

std::uint64_t section_checksum(const unsigned char* data, std::size_t bytes, std::uint64_t hash) {
  std::size_t i = 0;
  for (; i + 8 <= bytes; i += 8) {
    std::uint64_t word;
    std::memcpy(&word, data + i, 8); // the file is little-endian, as is the host (checked)
    hash = (hash ^ word) * 0x100000001b3ull;
  }
  if (i < bytes) {
    std::uint64_t word = 0;
    std::memcpy(&word, data + i, bytes - i);
    hash = (hash ^ word) * 0x100000001b3ull;
  }
  return hash;
}

bool host_is_little_endian() {
  const std::uint32_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

void PreparedSections::add_bytes(std::uint32_t id, std::uint32_t element_bytes, const unsigned char* data,
                                 std::size_t bytes) {
  entries_.push_back({id, element_bytes, data, bytes, 0});
}

void PreparedSections::add_blob(std::uint32_t id, std::string bytes) {
  blobs_.push_back(std::move(bytes));
  add_bytes(id, 1, reinterpret_cast<const unsigned char*>(blobs_.back().data()), blobs_.back().size());
}

namespace {
std::uint64_t aligned(std::uint64_t at) { return (at + kSectionAlignment - 1) / kSectionAlignment * kSectionAlignment; }
} // namespace

std::string PreparedSections::header(std::uint64_t options_key) {
  LittleEndianWriter out;
  out.bytes.assign(kPreparedMagic, sizeof kPreparedMagic);
  out.u32(kPreparedVersion);
  out.u32(static_cast<std::uint32_t>(entries_.size()));
  out.u64(options_key);
  out.u64(0);
  std::uint64_t at = aligned(kPreparedHeadBytes + kSectionEntryBytes * entries_.size() + 8);
  for (Entry& e : entries_) {
    e.offset = at;
    out.u32(e.id);
    out.u32(e.element_bytes);
    out.u64(e.offset);
    out.u64(e.bytes);
    out.u64(section_checksum(e.data, e.bytes));
    at = aligned(at + e.bytes);
  }
  out.u64(fnv1a(reinterpret_cast<const unsigned char*>(out.bytes.data()), out.bytes.size()));
  return out.bytes;
}

bool PreparedSections::write(const std::string& header, std::FILE* file) const {
  static const char kZeros[kSectionAlignment] = {};
  std::uint64_t at = header.size();
  if (std::fwrite(header.data(), 1, header.size(), file) != header.size()) return false;
  for (const Entry& e : entries_) {
    if (std::fwrite(kZeros, 1, e.offset - at, file) != e.offset - at) return false;
    if (e.bytes > 0 && std::fwrite(e.data, 1, e.bytes, file) != e.bytes) return false;
    at = e.offset + e.bytes;
  }
  return true;
}

} // namespace hullcover::detail

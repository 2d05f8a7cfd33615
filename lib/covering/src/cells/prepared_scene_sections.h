#pragma once
// The section table of the prepared scene file (prepared_scene_file.h):
// section ids, the element size each holds, the checksum, and the writer's
// list of sections. Shared by its writer and its reader.

#include "hullcover/covering/merge_cells.h"
#include "hullcover/geometry/aabb_tree.h"
#include "hullcover/geometry/little_endian_bytes.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <string>
#include <type_traits>
#include <vector>

namespace hullcover::detail {

inline constexpr char kPreparedMagic[8] = {'H', 'C', 'P', 'R', 'E', 'P', '\r', '\n'};
inline constexpr std::uint32_t kPreparedVersion = 1;
/// Bytes before the section table; bytes of one table entry.
inline constexpr std::uint64_t kPreparedHeadBytes = 32, kSectionEntryBytes = 32;
/// Every section starts on a multiple of this many bytes.
inline constexpr std::uint64_t kSectionAlignment = 64;
/// The search trees stored: vertex, edge, face, bar, front sweep, opening sweep.
inline constexpr int kTreeCount = 6;
inline constexpr std::uint32_t kSectionsPerTree = 3; // nodes, items, leaf boxes
inline constexpr std::size_t kTreeNodeBytes = 64;

enum PreparedSection : std::uint32_t {
  kScalars = 1,
  kMaterialNames,
  kPositions,
  kTriangles,
  kMaterialIds,
  kIslandLengths,
  kIslandZones,
  kIslandPlace,
  kIslandOfFace,
  kIslandBoxes,
  kIslandFaceCounts,
  kEdges,
  kEdgeUses,
  kFaceEdges,
  kFaceNeighbours,
  kZeroArea,
  kFaceComponent,
  kCellOfFace,
  kSlotInCell,
  kIslandOfCell,
  kCellHalvings,
  kIslandCellSize,
  kOpenEdgeUse,
  kFaceNormals,
  kFaceAreas,
  kBars,
  kFrontSweepFace,
  kFrontReach,
  kOpeningSweepEdge,
  kOpeningReach,
  kBarOfPiece,
  kFirstTreeSection,
  kSectionCount = kFirstTreeSection + kTreeCount * kSectionsPerTree - 1, // ids run 1 .. kSectionCount
};

/// An edge as stored: v0, v1, first use, use count, kind.
using StoredEdge = std::array<std::int32_t, 5>;

/// Bytes per element of section `id`; 1 for the blobs read field by field.
std::uint32_t element_bytes_of(std::uint32_t id);
/// A section's name, for messages.
std::string section_name(std::uint32_t id);

/// FNV-1a-64 taken a 64-bit little-endian word at a time (the last word
/// padded with zeros): a checksum against damage, eight times as fast as
/// FNV-1a byte by byte on files of gigabytes.
/// `hash` continues a checksum over bytes before these (their count a
/// multiple of 8).
std::uint64_t section_checksum(const unsigned char* data, std::size_t bytes,
                               std::uint64_t hash = 0xcbf29ce484222325ull);

bool host_is_little_endian();

/// The sections to write: pointers to the arrays where they lie, or bytes
/// made for the file (the blobs).
class PreparedSections {
public:
  /// The elements of `array` (a std::vector or MappableArray), where they
  /// lie; it must outlive write().
  template <class Array>
  void add(std::uint32_t id, const Array& array) {
    using T = std::remove_cv_t<std::remove_reference_t<decltype(*array.data())>>;
    add_bytes(id, sizeof(T), reinterpret_cast<const unsigned char*>(array.data()), array.size() * sizeof(T));
  }
  void add_blob(std::uint32_t id, std::string bytes);
  /// The magic, version, table and header checksum, sections laid out in
  /// the order they were added.
  std::string header(std::uint64_t options_key);
  /// Writes the header and every section, padded to kSectionAlignment.
  bool write(const std::string& header, std::FILE* file) const;

private:
  struct Entry {
    std::uint32_t id;
    std::uint32_t element_bytes;
    const unsigned char* data;
    std::size_t bytes;
    std::uint64_t offset;
  };
  void add_bytes(std::uint32_t id, std::uint32_t element_bytes, const unsigned char* data, std::size_t bytes);
  std::vector<Entry> entries_;
  std::deque<std::string> blobs_; // a deque: entries point into its strings
};

/// Reads and writes AabbTree's private arrays (a friend of AabbTree).
struct AabbTreeStorage {
  /// Adds tree `which`'s sections and its root to `scalars`.
  static void write(const AabbTree& tree, int which, PreparedSections& out, LittleEndianWriter& scalars);
  /// A tree viewing the mapped arrays, its root read from `scalars`; fails
  /// (empty message: none) when a link leaves the arrays, an item is not
  /// below `item_limit`, or the tree is deeper than a walk's stack holds.
  static std::string read(const unsigned char* nodes, std::size_t node_count, const int* items, std::size_t item_count,
                          const Aabb* leaf_boxes, std::size_t leaf_box_count, std::size_t item_limit,
                          LittleEndianReader& scalars, AabbTree& tree);
};

} // namespace hullcover::detail

#pragma once
/// \file runtime_file.h
/// The runtime file (`.hcw`): a covering's hulls in a versioned,
/// little-endian binary form that loads fast and is checked before use.
///
/// Layout (all integers unsigned little-endian, all reals IEEE-754 binary64
/// little-endian):
///
///     header  magic "HCWORLD\0" (8 bytes), u32 version, u32 reserved (0),
///             u64 hull count, u64 payload bytes, u64 FNV-1a-64 of the payload
///     payload per hull: u32 material, u32 vertex count V, u32 facet count F,
///             u32 plane count P (>= F), u32 facet index count I,
///             6 x f64 bounding box (min xyz, max xyz),
///             V x 3 f64 vertices, P x 4 f64 planes (normal xyz, offset),
///             F x u32 facet sizes, I x u32 facet vertex indices,
///             (version 2) u32 S (0 or P), S x u8 surface flags (1: plane p
///             is the surface's own, RuntimeHull::surface_planes; S = 0:
///             unknown)
///     (version 3) section table after the last hull: u32 section count N,
///             then per section u32 id, u32 hull count C (>= 1), C x u32
///             hull indices; ids strictly ascending, each section's indices
///             strictly ascending, every hull in exactly one section
///
/// Planes after the first F bound flat hulls sideways (see ConvexPolytope).
/// The checksum covers the whole payload, section table included. A file of
/// version 1 or 2 reads as one section 0 holding every hull.
///
/// Sections are the cells a server streams in and out (StreamedWorld,
/// streamed_world.h); hull indices are global: hull i of the file is hull i
/// of every answer, whichever sections are loaded.

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/status.h"

#include <string>
#include <vector>

namespace hullcover::bvh {

/// The version written. Versions 1 (no surface flags: its hulls count every
/// plane as the surface's) and 2 (no section table) are still read.
inline constexpr std::uint32_t kRuntimeFileVersion = 3;
/// The oldest version read.
inline constexpr std::uint32_t kRuntimeFileFirstVersion = 1;

/// Writes `hulls` to `path`; `section_of_hull[i]` (any u32) names hull i's
/// section, null puts every hull in section 0. Fails with `unwritable_file`,
/// or `invalid_argument` when section_of_hull's size is not the hull count.
Status write_runtime_file(const std::vector<RuntimeHull>& hulls, const std::string& path,
                          const std::vector<std::uint32_t>* section_of_hull = nullptr);

/// Reads and checks a runtime file: magic, version, sizes against the file
/// length, checksum, index ranges (facet indices < V, facet sizes >= 3,
/// their sum = I, P >= F), finite values, unit normals. Reads only a
/// regular file (a FIFO or device is refused, not waited on) of at most
/// kDefaultMaxInputFileBytes. Fails with `file_not_found`, `unreadable_file`
/// (with what is wrong and where), `limit_exceeded` (over 1 GiB) or
/// `unknown_format` (not a runtime file, or a newer version).
/// The section table is checked too (see the layout), so a file that reads
/// here reads by sections as well.
Result<std::vector<RuntimeHull>> read_runtime_file(const std::string& path);

/// One section of a runtime file: a cell a server streams in and out.
struct RuntimeSection {
  std::uint32_t id = 0;   ///< as written; distinct within a file
  std::vector<int> hulls; ///< its global hull indices, ascending, never empty
};

/// A section's hulls, ready for StreamedWorld::add_section.
struct SectionHulls {
  std::uint32_t id = 0;
  /// Global index of hulls[i] (its index in the whole file), ascending.
  std::vector<int> indices;
  std::vector<RuntimeHull> hulls;
};

/// The section table, ascending ids (one section 0 for a version 1 or 2
/// file, none for a file without hulls). Reads the whole file and checks
/// what read_runtime_file checks but the hulls' values (they are not
/// parsed); fails as it does.
[[nodiscard]] Result<std::vector<RuntimeSection>> read_runtime_sections(const std::string& path);

/// The hulls of section `id` with their global indices. Reads the whole file
/// (the checksum covers it) and checks its header, sizes and section table
/// and this section's hulls as read_runtime_file does; fails as it does,
/// and with `invalid_argument` when the file has no section `id`.
[[nodiscard]] Result<SectionHulls> read_runtime_section(const std::string& path, std::uint32_t id);

} // namespace hullcover::bvh

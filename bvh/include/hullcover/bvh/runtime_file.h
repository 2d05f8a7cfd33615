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
///
/// Planes after the first F bound flat hulls sideways (see ConvexPolytope).

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/status.h"

#include <string>
#include <vector>

namespace hullcover::bvh {

/// The version written. Version 1 (no surface flags) is still read: its
/// hulls count every plane as the surface's.
inline constexpr std::uint32_t kRuntimeFileVersion = 2;
/// The oldest version read.
inline constexpr std::uint32_t kRuntimeFileFirstVersion = 1;

/// Writes `hulls` to `path`. Fails with `unwritable_file`.
Status write_runtime_file(const std::vector<RuntimeHull>& hulls, const std::string& path);

/// Reads and checks a runtime file: magic, version, sizes against the file
/// length, checksum, index ranges (facet indices < V, facet sizes >= 3,
/// their sum = I, P >= F), finite values, unit normals. Reads only a
/// regular file (a FIFO or device is refused, not waited on) of at most
/// kDefaultMaxInputFileBytes. Fails with `file_not_found`, `unreadable_file`
/// (with what is wrong and where), `limit_exceeded` (over 1 GiB) or
/// `unknown_format` (not a runtime file, or a newer version).
Result<std::vector<RuntimeHull>> read_runtime_file(const std::string& path);

} // namespace hullcover::bvh

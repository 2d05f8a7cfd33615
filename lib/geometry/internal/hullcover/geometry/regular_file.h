#pragma once
/// \file regular_file.h
/// Reading a whole input file that anyone may have made: only a regular
/// file, and only up to a size the caller allows.
///
/// The hull readers (`.hcw` runtime files, hull OBJ groups) read through
/// this; scene files go through the importer's own confined reading
/// (lib/mesh). It lives in the geometry layer because that is the one layer
/// the runtime links.

#include "hullcover/geometry/status.h"

#include <cstdint>
#include <string>

namespace hullcover {

/// The largest file a hull reader reads unless told otherwise, bytes (the
/// scene importer's default `--max-file-size` too).
inline constexpr std::uint64_t kDefaultMaxInputFileBytes = std::uint64_t{1} << 30;

/// The whole content of `path`. Opens without blocking (a FIFO is refused,
/// not waited on) and reads only a regular file of at most `max_bytes`.
///
/// Fails with `file_not_found` (no such path), `unreadable_file` (a folder,
/// FIFO, device or socket; or a read error) or `limit_exceeded` (larger than
/// `max_bytes`, which the message names with the file's size). Never
/// allocates more than the file's size.
[[nodiscard]] Result<std::string> read_regular_file(const std::string& path,
                                                    std::uint64_t max_bytes = kDefaultMaxInputFileBytes);

} // namespace hullcover

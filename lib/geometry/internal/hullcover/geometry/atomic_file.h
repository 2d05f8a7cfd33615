#pragma once
/// \file atomic_file.h
/// Output files that nobody ever sees half written.
///
/// Every file hullcover writes (hull OBJ, JSON reports, `.hcw` runtime files,
/// bench tables and plots) goes through `write_file_atomically`: the bytes go
/// to an unnamed temporary file in the destination's folder, which is flushed
/// to disk and only then named: linked at the destination itself when
/// nothing is there yet, else named and renamed over the destination. A run
/// killed by SIGINT, SIGTERM or SIGKILL, or stopped by a full disk, leaves
/// the destination as it was (absent, or its previous content) or complete
/// and, on Linux file systems with O_TMPFILE (ext4, xfs, btrfs, tmpfs), no
/// temporary file either: an unnamed file vanishes with the process, a new
/// file never has a temporary name, and when one replaces an old file
/// SIGINT, SIGTERM, SIGHUP and SIGQUIT are held back on the writing thread
/// from naming it to the rename (microseconds), then delivered. In those
/// microseconds, SIGKILL or another signal that ends a program, or one of
/// those four taken by another thread of the process, can still leave the
/// name `.NAME.hullcover-PID-N` beside the destination. (The cell cache,
/// written from worker threads, writes new files, unless it replaces an
/// entry that did not read back.)
/// Elsewhere the temporary file is named `.NAME.hullcover-XXXXXX` from the
/// start and a kill during the write can leave it behind (never the
/// destination half written).
///
/// It lives in the geometry layer because that is the one layer every writer
/// (the decomposer, the runtime's `.hcw` writer, the apps) links.

#include "hullcover/geometry/status.h"

#include <cstdio>
#include <functional>
#include <string>

namespace hullcover {

/// Writes the content of a file to the open stream it is given. The stream's
/// error flag is checked after it returns, so a writer may ignore the return
/// values of `fprintf`/`fwrite`; it returns false to abandon the file itself.
using FileContentWriter = std::function<bool(std::FILE*)>;

/// Writes `path` through `write_content` so that `path` holds either its
/// previous content or the complete new content, never a part of it. A symlink
/// at `path` is replaced, not written through. The new file's permissions are
/// 0666 less the umask (those of an existing file are not kept).
///
/// Fails with `unwritable_file`, naming `path` and the system's reason, when
/// the folder does not exist or cannot be written, a write fails (full disk,
/// file-size limit), the content writer returns false, or the rename fails
/// (for example `path` is a folder). On failure `path` is untouched and no
/// temporary file remains.
[[nodiscard]] Status write_file_atomically(const std::string& path, const FileContentWriter& write_content);

/// `write_file_atomically` for content already in memory.
[[nodiscard]] Status write_file_atomically(const std::string& path, const std::string& content);

} // namespace hullcover

#pragma once
// Cairo's output through hullcover's atomic file writer, shared by every
// picture the command line writes (the bench's plot, `render`, the audit's
// HTML report): no picture is ever seen half written.

#include "hullcover/geometry/status.h"

#include <cairo.h>

#include <string>

namespace hullcover::app {

/// Cairo's write callback (cairo_write_func_t) onto an open stdio stream,
/// the closure: a short write reports CAIRO_STATUS_WRITE_ERROR and leaves
/// the stream's error flag set for the atomic writer to report.
cairo_status_t write_cairo_bytes_to_stream(void* stream, const unsigned char* data, unsigned int length);

/// Writes `surface` (an image surface, drawn) as a PNG file at `path`
/// through write_file_atomically. Fails with `unwritable_file` naming `path`
/// when it cannot be written, `internal_error` when cairo cannot encode.
[[nodiscard]] Status write_png_atomically(cairo_surface_t* surface, const std::string& path);

/// The PNG encoding of `surface` (an image surface, drawn), in memory, for
/// embedding. Fails with `internal_error` when cairo cannot encode it.
[[nodiscard]] Result<std::string> png_bytes(cairo_surface_t* surface);

} // namespace hullcover::app

#include "cairo_file_output.h"

#include "hullcover/geometry/atomic_file.h"

#include <cstdio>

namespace hullcover::app {
namespace {

// No exception may unwind through cairo's C frames: a failed allocation is
// cairo's own out-of-memory status.
cairo_status_t append_cairo_bytes(void* text, const unsigned char* data, unsigned int length) {
  try {
    static_cast<std::string*>(text)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  } catch (...) {
    return CAIRO_STATUS_NO_MEMORY;
  }
}

} // namespace

cairo_status_t write_cairo_bytes_to_stream(void* stream, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::FILE*>(stream);
  return std::fwrite(data, 1, length, out) == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

Status write_png_atomically(cairo_surface_t* surface, const std::string& path) {
  cairo_status_t encoded = CAIRO_STATUS_SUCCESS;
  const Status written = write_file_atomically(path, [&](std::FILE* out) {
    encoded = cairo_surface_write_to_png_stream(surface, write_cairo_bytes_to_stream, out);
    return encoded == CAIRO_STATUS_SUCCESS;
  });
  // A failed write is the file's (the atomic writer names the reason); any
  // other cairo failure is the picture's.
  if (!written.ok() && encoded != CAIRO_STATUS_SUCCESS && encoded != CAIRO_STATUS_WRITE_ERROR)
    return {StatusCode::internal_error,
            path + ": cairo could not encode the picture: " + cairo_status_to_string(encoded)};
  return written;
}

Result<std::string> png_bytes(cairo_surface_t* surface) {
  std::string bytes;
  if (const cairo_status_t encoded = cairo_surface_write_to_png_stream(surface, append_cairo_bytes, &bytes);
      encoded != CAIRO_STATUS_SUCCESS)
    return Status{StatusCode::internal_error,
                  std::string("cairo could not encode a picture: ") + cairo_status_to_string(encoded)};
  return bytes;
}

} // namespace hullcover::app

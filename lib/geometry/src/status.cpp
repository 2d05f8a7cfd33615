#include "hullcover/geometry/status.h"

namespace hullcover {

const char* status_code_name(StatusCode code) {
  switch (code) {
    case StatusCode::ok: return "ok";
    case StatusCode::file_not_found: return "file_not_found";
    case StatusCode::unreadable_file: return "unreadable_file";
    case StatusCode::unwritable_file: return "unwritable_file";
    case StatusCode::unknown_format: return "unknown_format";
    case StatusCode::empty_scene: return "empty_scene";
    case StatusCode::non_finite_coordinate: return "non_finite_coordinate";
    case StatusCode::index_out_of_range: return "index_out_of_range";
    case StatusCode::invalid_argument: return "invalid_argument";
    case StatusCode::degenerate_scene: return "degenerate_scene";
    case StatusCode::internal_error: return "internal_error";
    case StatusCode::reference_outside_folder: return "reference_outside_folder";
    case StatusCode::limit_exceeded: return "limit_exceeded";
  }
  return "unknown";
}

} // namespace hullcover

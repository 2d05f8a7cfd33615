#pragma once
// The exception barrier of bvh's public calls (private to bvh/). A game
// server links this library: an exception from FCL, Eigen or an exhausted
// allocator must come back as a Status, not unwind through the caller.

#include "hullcover/geometry/status.h"

#include <exception>
#include <new>
#include <string>

namespace hullcover::bvh::detail {

/// `internal_error` with "<what> failed: <why>". Building the message can
/// itself run out of memory; the code alone then still reaches the caller.
inline Status internal_failure(const char* what, const char* why) noexcept {
  try {
    return {StatusCode::internal_error, std::string(what) + " failed: " + why};
  } catch (...) {
    return {StatusCode::internal_error, std::string()};
  }
}

/// Runs `call` (returning a Status or a Result<T>) and turns anything it
/// throws into `internal_error`, naming `what` was being done.
template <typename Call>
auto guarded(const char* what, Call&& call) noexcept -> decltype(call()) {
  try {
    return call();
  } catch (const std::bad_alloc&) {
    return internal_failure(what, "out of memory");
  } catch (const std::exception& e) {
    return internal_failure(what, e.what());
  } catch (...) {
    return internal_failure(what, "unknown exception");
  }
}

} // namespace hullcover::bvh::detail

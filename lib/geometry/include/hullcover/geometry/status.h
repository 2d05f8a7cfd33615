#pragma once
/// \file status.h
/// The outcome of any hullcover call that can fail on its input.
///
/// hullcover never lets an exception escape its public API (a game server
/// links it): a function that can fail returns a `Status` or a `Result<T>`
/// holding a code a program can branch on and one line a person can read.
/// Asserts are kept for programmer errors only.

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace hullcover {

/// Why a call failed. `ok` is success; every other code comes with a message.
enum class StatusCode {
  ok,
  file_not_found,           ///< the path does not exist or is not a regular file
  unreadable_file,          ///< the file exists but could not be opened or parsed
  unwritable_file,          ///< an output file could not be created or written
  unknown_format,           ///< no importer understands the file's format
  empty_scene,              ///< the input holds no triangle
  non_finite_coordinate,    ///< a position is NaN or infinite
  index_out_of_range,       ///< a triangle names a vertex that does not exist
  invalid_argument,         ///< an option is out of its documented range
  degenerate_scene,         ///< the input has no extent (all points coincide)
  internal_error,           ///< a bug or exhausted memory, caught before it left the library
  reference_outside_folder, ///< a scene file refers to a file outside its own folder
  limit_exceeded,           ///< an input is larger than a documented, overridable limit
};

/// Short stable name of a code ("file_not_found", ...), for logs and JSON.
const char* status_code_name(StatusCode code);

/// Success, or a failure code with a one-line human-readable message.
class [[nodiscard]] Status {
public:
  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}

  static Status success() { return {}; }

  bool ok() const { return code_ == StatusCode::ok; }
  StatusCode code() const { return code_; }
  /// One line naming what failed and why; empty on success.
  const std::string& message() const { return message_; }

private:
  StatusCode code_ = StatusCode::ok;
  std::string message_;
};

/// A value, or the `Status` that explains why there is none.
template <typename T>
class [[nodiscard]] Result {
public:
  Result(T value) : value_(std::move(value)) {}
  Result(Status failure) : status_(std::move(failure)) {}

  bool ok() const { return status_.ok() && value_.has_value(); }
  const Status& status() const { return status_; }

  /// The value. Calling these on a failed result is a programmer error.
  T& value() & {
    assert(value_.has_value());
    return *value_;
  }
  const T& value() const& {
    assert(value_.has_value());
    return *value_;
  }
  /// Moved out of a temporary result: returned by value, so a range-for
  /// over a member of `f().value()` does not dangle.
  T value() && {
    assert(value_.has_value());
    return std::move(*value_);
  }

private:
  Status status_;
  std::optional<T> value_;
};

} // namespace hullcover

#pragma once
// What the project's text scene readers (obj_reader.h, stl_ascii_reader.h,
// ply_reader.h) share: decimal numbers read in double, and failures
// that name the line.

#include "hullcover/geometry/status.h"

#include <charconv>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>

namespace hullcover::detail {

/// A whole word as a double, correctly rounded (std::from_chars); false when
/// it is not a number from end to end. "nan" and "inf" parse (then caught as
/// non-finite); a number beyond double's range reads as infinite, one below
/// its smallest as zero.
inline bool read_decimal(std::string_view word, double& value) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1); // from_chars takes no '+'
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error == std::errc::result_out_of_range && end == word.data() + word.size()) {
    // Beyond double's range either way: strtod gives the infinity (caught
    // as non-finite) or the zero (1e-400 is a coordinate of 0).
    value = std::strtod(std::string(word).c_str(), nullptr);
    return true;
  }
  return error == std::errc() && end == word.data() + word.size() && !word.empty();
}

/// A failure at line `line` of the text.
inline Status at_line(StatusCode code, long line, const std::string& what) {
  return {code, "line " + std::to_string(line) + ": " + what};
}

} // namespace hullcover::detail

#pragma once
// Checks of numeric options that say in one line what was wrong, naming the
// text given (CLI11's own range checks print the whole range of a double,
// 309 digits). A number that fails is bad usage: exit 2.

#include <CLI/CLI.hpp>

#include <cmath>
#include <exception>
#include <string>

namespace hullcover::app {

namespace detail {

// `text` as a finite number, or false.
inline bool finite_number(const std::string& text, double& value) {
  size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && std::isfinite(value);
}

} // namespace detail

/// A finite number >= 0.
inline CLI::Validator non_negative_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (detail::finite_number(text, value) && value >= 0.0) return {};
        return "must be a finite number, 0 or more, not '" + text + "'";
      },
      "NUMBER>=0");
}

/// A finite number > 0.
inline CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (detail::finite_number(text, value) && value > 0.0) return {};
        return "must be a finite number above 0, not '" + text + "'";
      },
      "NUMBER>0");
}

} // namespace hullcover::app

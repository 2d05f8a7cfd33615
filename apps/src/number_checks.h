#pragma once
// Checks of numeric options that say in one line what was wrong, naming the
// text given (CLI11's own range checks print the whole range of a double,
// 309 digits). A number that fails is bad usage: exit 2. Every number
// option of every command carries one of these (tests/apps/
// test_option_values.cpp walks the parser's options to hold it so).

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <string>

namespace hullcover::app {

/// The largest magnitude a number option takes: beyond any scene's lengths
/// (a light-year is 9.5e15 m) and far inside double's range even squared,
/// so no option's value overflows a distance computed from it.
inline constexpr double kLargestOptionValue = 1e15;

namespace detail {

// Characters of the user's text a message repeats.
inline constexpr size_t kEchoedCharacters = 40;

inline std::string echoed(const std::string& text) {
  return text.size() <= kEchoedCharacters ? text : text.substr(0, kEchoedCharacters) + "...";
}

// `text` as a finite number within kLargestOptionValue, or false.
inline bool bounded_number(const std::string& text, double& value) {
  size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && std::isfinite(value) && std::abs(value) <= kLargestOptionValue;
}

inline std::string largest_text() { return "1e15"; }

} // namespace detail

/// A finite number >= 0, at most kLargestOptionValue.
inline CLI::Validator non_negative_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (detail::bounded_number(text, value) && value >= 0.0) return {};
        return "must be a number from 0 to " + detail::largest_text() + ", not '" + detail::echoed(text) + "'";
      },
      "NUMBER>=0");
}

/// A finite number > 0, at most kLargestOptionValue.
inline CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (detail::bounded_number(text, value) && value > 0.0) return {};
        return "must be a number above 0, at most " + detail::largest_text() + ", not '" + detail::echoed(text) + "'";
      },
      "NUMBER>0");
}

/// A finite number from `least` to `most` (NaN, which every comparison
/// lets through CLI::Range, is refused).
inline CLI::Validator number_in(double least, double most) {
  const std::string range = CLI::detail::to_string(least) + " to " + CLI::detail::to_string(most);
  return CLI::Validator(
      [least, most, range](std::string& text) -> std::string {
        double value = 0.0;
        if (detail::bounded_number(text, value) && value >= least && value <= most) return {};
        return "must be a number from " + range + ", not '" + detail::echoed(text) + "'";
      },
      "NUMBER " + range);
}

/// A coordinate or direction component: any sign, finite, magnitude at most
/// kLargestOptionValue.
inline CLI::Validator coordinate() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (detail::bounded_number(text, value)) return {};
        return "must be a number from -" + detail::largest_text() + " to " + detail::largest_text() + ", not '" +
               detail::echoed(text) + "'";
      },
      "COORDINATE");
}

/// A whole number from `least` to `most`, written in decimal digits (no
/// sign: "-1" is refused rather than wrapped to 2^64 - 1 by an unsigned
/// option).
inline CLI::Validator count_from(std::uint64_t least, std::uint64_t most) {
  const std::string range = std::to_string(least) + " to " + std::to_string(most);
  return CLI::Validator(
      [least, most, range](std::string& text) -> std::string {
        bool digits = !text.empty() && text.size() <= 20;
        for (const char c : text) digits = digits && c >= '0' && c <= '9';
        if (digits) {
          try {
            const unsigned long long value = std::stoull(text);
            if (value >= least && value <= most) return {};
          } catch (const std::exception&) {}
        }
        return "must be a whole number from " + range + ", not '" + detail::echoed(text) + "'";
      },
      "COUNT " + range);
}

/// `--threads N`: 0 (every core) or a thread count.
inline CLI::Validator thread_count() { return count_from(0, std::numeric_limits<int>::max()); }

/// `--seed N`: any 64-bit seed, never a negative one wrapped.
inline CLI::Validator seed_number() { return count_from(0, std::numeric_limits<std::uint64_t>::max()); }

// Bounds of the count options. The import limits exist to bound what a file
// from anyone may make the importer do, so raising them stays bounded too.

/// `--max-file-size`: 1 TiB.
inline constexpr std::uint64_t kLargestFileLimit = std::uint64_t{1} << 40;
/// `--max-node-depth`: deeper hierarchies would risk the importer's stack,
/// which the limit protects (8 MiB at about 1 KiB a level).
inline constexpr std::uint64_t kDeepestNodeLimit = 2048;
/// `--max-triangles`: 2^29, so three corners a triangle stay within a
/// signed 32-bit index (and 2^29 triangles take about 240 GB).
inline constexpr std::uint64_t kMostTrianglesLimit = std::uint64_t{1} << 29;
/// `--max-materials`: Assimp's OBJ reader takes about 35 KB per name.
inline constexpr std::uint64_t kMostMaterialsLimit = 65536;
/// `audit --proxies`: 16.7 million poses, hours of work.
inline constexpr std::uint64_t kMostProxies = std::uint64_t{1} << 24;
/// `query --max-contacts`.
inline constexpr std::uint64_t kMostContacts = std::uint64_t{1} << 20;
/// `world --triangles`: the import's own bound.
inline constexpr std::uint64_t kMostWorldTriangles = kMostTrianglesLimit;

} // namespace hullcover::app

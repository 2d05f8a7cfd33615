#pragma once
// What the PLY pre-check's two halves share: ply_file_checks.cpp reads the
// header and walks binary bodies, ply_ascii_checks.cpp walks ASCII ones.
// Both hold the elements the header declares against the body, read a chunk
// at a time, and report in the same words.

#include "scene_file_rules.h"

#include "hullcover/geometry/status.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

namespace hullcover::detail {

// Bytes of the body read at a time: per-byte stream calls would be slow on
// large files, and reading the body whole would hold it in memory.
inline constexpr std::size_t kBodyChunkBytes = std::size_t{64} << 10;
// The fewest bytes an ASCII list item takes: a separator and a digit.
inline constexpr std::uint64_t kAsciiItemBytes = 2;
// The elements Assimp counts and parses; any other it takes to have as many
// instances as its name's leading digits say (usually none) and skips.
inline constexpr const char* kCountedElements[] = {"vertex", "face", "tristrips", "edge", "material"};

enum class Number { signed_integer, unsigned_integer, real };

struct ScalarType {
  int bytes = 0; // 0: a name PLY does not have
  Number number = Number::unsigned_integer;
};

struct Property {
  std::string name;
  bool is_list = false;
  ScalarType length; // a list's length
  ScalarType value;  // the scalar, or each list item
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t least_bytes = 0; // per element
  std::vector<Property> properties;

  bool has_list() const {
    return std::any_of(properties.begin(), properties.end(), [](const Property& p) { return p.is_list; });
  }
  bool counted() const {
    return std::any_of(std::begin(kCountedElements), std::end(kCountedElements),
                       [&](const char* known) { return name == known; });
  }
  // Whether Assimp parses the lists of its instances (the rest it skips).
  bool lists_parsed() const { return counted() && has_list(); }
  // How many instances Assimp reads: strtoul10 of the text after "element"
  // when it does not know the name, as 32 bits.
  std::uint64_t assimp_count() const {
    if (counted()) return count;
    std::uint32_t digits_value = 0;
    for (std::size_t i = 0; i < name.size() && name[i] >= '0' && name[i] <= '9'; ++i)
      digits_value = digits_value * 10 + static_cast<std::uint32_t>(name[i] - '0');
    return digits_value;
  }
};

inline std::string instance(const Element& e, std::uint64_t i) { return e.name + " #" + std::to_string(i); }

inline bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Assimp's line ends (IsLineEnd). Byte tests are lambdas so that the loops
// taking bytes inline them.
inline constexpr auto is_line_end = [](int c) { return c == '\r' || c == '\n' || c == '\f' || c == '\0'; };

// The bytes [offset, offset + bytes) of `in`, read a chunk at a time.
class BodyReader {
public:
  BodyReader(std::ifstream& in, std::uint64_t offset, std::uint64_t bytes)
      : in_(in), unread_(bytes), chunk_(kBodyChunkBytes) {
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(offset));
  }
  std::uint64_t left() const { return unread_ + (end_ - next_); }
  int peek() { return next_ < end_ || fill() ? chunk_[next_] : -1; }
  int get() {
    const int c = peek();
    next_ += c >= 0 ? 1 : 0;
    return c;
  }
  bool read(unsigned char* out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      const int c = get();
      if (c < 0) return false;
      out[i] = static_cast<unsigned char>(c);
    }
    return true;
  }
  // Takes bytes while `keep` accepts them, handing each run of them in the
  // chunk to `seen(data, size)`; returns how many. The loop runs over the
  // chunk in memory, which keeps an ASCII walk near memory speed.
  template <class Keep, class Seen>
  std::uint64_t take_while(Keep keep, Seen seen) {
    std::uint64_t taken = 0;
    while (next_ < end_ || fill()) {
      std::size_t i = next_;
      while (i < end_ && keep(chunk_[i])) ++i;
      seen(chunk_.data() + next_, i - next_);
      taken += i - next_;
      next_ = i;
      if (i < end_) break;
    }
    return taken;
  }
  template <class Keep>
  std::uint64_t take_while(Keep keep) {
    return take_while(keep, [](const unsigned char*, std::size_t) {});
  }
  struct Bytes {
    const unsigned char* data;
    std::size_t size;
  };
  // The bytes read and not yet taken; none only at the end of the data.
  Bytes ahead() {
    if (next_ == end_) fill();
    return {chunk_.data() + next_, end_ - next_};
  }
  void take(std::size_t n) { next_ += n; }
  bool skip(std::uint64_t n) {
    if (n > left()) return false;
    const std::uint64_t buffered = end_ - next_;
    if (n <= buffered) {
      next_ += static_cast<std::size_t>(n);
      return true;
    }
    in_.seekg(static_cast<std::streamoff>(n - buffered), std::ios::cur);
    unread_ -= n - buffered;
    next_ = end_;
    return true;
  }

private:
  bool fill() {
    const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(unread_, chunk_.size()));
    if (want == 0) return false;
    in_.read(reinterpret_cast<char*>(chunk_.data()), static_cast<std::streamsize>(want));
    const std::size_t got = static_cast<std::size_t>(in_.gcount());
    unread_ = got < want ? 0 : unread_ - want; // a file that shrank ends here
    next_ = 0;
    end_ = got;
    return got > 0;
  }

  std::ifstream& in_;
  std::uint64_t unread_;
  std::vector<unsigned char> chunk_;
  std::size_t next_ = 0;
  std::size_t end_ = 0;
};

inline Status too_long(const std::string& where, const Property& p, const std::string& items, std::uint64_t left,
                       std::uint64_t item_bytes) {
  return damaged_file("PLY " + where + " has a " + p.name + " list of " + items + " items; the " +
                      std::to_string(left) + " bytes left hold at most " + std::to_string(left / item_bytes));
}

inline Status ends_inside(const std::string& where, const Element& e) {
  return damaged_file("PLY data ends inside " + where + " of " + std::to_string(e.count));
}

} // namespace hullcover::detail

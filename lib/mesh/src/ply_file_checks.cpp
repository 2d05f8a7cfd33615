#include "ply_file_checks.h"

#include "scene_file_checks.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hullcover::detail {
namespace {

// Bytes of the body read at a time: per-byte stream calls would be slow on
// large files, and reading the body whole would hold it in memory.
constexpr std::size_t kBodyChunkBytes = std::size_t{64} << 10;
// The fewest bytes an ASCII list item takes: a separator and a digit.
constexpr std::uint64_t kAsciiItemBytes = 2;
// Characters of an ASCII token kept: numbers are far shorter, and a longer
// token is refused where it is read as one.
constexpr std::size_t kMaxTokenChars = 64;
// ASCII list lengths saturate here, past any file, so ten times one still
// fits 64 bits.
constexpr std::uint64_t kLengthCeiling = 1'000'000'000'000'000'000;
// Binary real-valued lengths are clamped here before the cast to an integer
// (defined behaviour); any length this long is refused anyway.
constexpr double kRealLengthCeiling = 0x1p62;
// The elements Assimp counts and parses; any other it takes to have as many
// instances as its name's leading digits say (usually none) and skips.
constexpr const char* kCountedElements[] = {"vertex", "face", "tristrips", "edge", "material"};

Status damaged(const std::string& why) { return {StatusCode::unreadable_file, why}; }

enum class Number { signed_integer, unsigned_integer, real };

struct ScalarType {
  int bytes = 0;  // 0: a name PLY does not have
  Number number = Number::unsigned_integer;
};

ScalarType ply_scalar_type(const std::string& type) {
  if (type == "char" || type == "int8") return {1, Number::signed_integer};
  if (type == "uchar" || type == "uint8") return {1, Number::unsigned_integer};
  if (type == "short" || type == "int16") return {2, Number::signed_integer};
  if (type == "ushort" || type == "uint16") return {2, Number::unsigned_integer};
  if (type == "int" || type == "int32") return {4, Number::signed_integer};
  if (type == "uint" || type == "uint32") return {4, Number::unsigned_integer};
  if (type == "float" || type == "float32") return {4, Number::real};
  if (type == "double" || type == "float64") return {8, Number::real};
  return {};
}

struct Property {
  std::string name;
  bool is_list = false;
  ScalarType length;  // a list's length
  ScalarType value;   // the scalar, or each list item
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t least_bytes = 0;  // per element
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

std::string instance(const Element& e, std::uint64_t i) { return e.name + " #" + std::to_string(i); }

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Assimp's line ends (IsLineEnd). Byte tests are lambdas so that the loops
// taking bytes inline them.
constexpr auto is_line_end = [](int c) { return c == '\r' || c == '\n' || c == '\f' || c == '\0'; };

// The next line of `text` from `at` as Assimp's IOStreamBuffer::getNextLine
// reads it: at a line end it first skips through the next '\n'; the line then
// runs to the next line-end byte, which it takes. So a lone '\r' ends a line,
// and a second line end in a row hides the text up to the next '\n'.
std::optional<std::string> assimp_line(const std::string& text, std::size_t& at) {
  if (at < text.size() && is_line_end(text[at])) {
    while (at < text.size() && text[at] != '\n') ++at;
    ++at;
  }
  if (at >= text.size()) return std::nullopt;
  const std::size_t start = at;
  while (at < text.size() && !is_line_end(text[at])) ++at;
  ++at;  // past the byte that ends it (past the text when none does)
  return text.substr(start, at - 1 - start);
}

// A header line's words: Assimp's PLY reader separates them by spaces and
// tabs only.
std::vector<std::string> words_of(const std::string& line) {
  std::vector<std::string> words;
  for (std::size_t at = line.find_first_not_of(" \t"); at != std::string::npos;
       at = line.find_first_not_of(" \t", at)) {
    const std::size_t end = std::min(line.find_first_of(" \t", at), line.size());
    words.push_back(line.substr(at, end - at));
    at = end;
  }
  return words;
}

struct Header {
  bool ascii = false;
  bool big_endian = false;
  std::vector<Element> elements;
  std::uint64_t after_line = 0;  // just past the byte ending the 'end_header' line: Assimp's next line read
  std::uint64_t line_number = 1;  // of the line at after_line
  std::uint64_t data_at = 0;     // binary data, as Assimp reads it
};

Status add_property(const std::vector<std::string>& words, Element& e) {
  const auto word = [&](std::size_t i) { return i < words.size() ? words[i] : std::string(); };
  Property p;
  p.is_list = word(1) == "list";
  if (p.is_list) {
    p.length = ply_scalar_type(word(2));
    p.value = ply_scalar_type(word(3));
    if (p.length.bytes == 0 || p.value.bytes == 0)
      return damaged("PLY list property with types '" + word(2) + "', '" + word(3) + "'");
  } else if ((p.value = ply_scalar_type(word(1))).bytes == 0) {
    return damaged("PLY property of unknown type '" + word(1) + "'");
  }
  p.name = word(p.is_list ? 4 : 2);
  if (p.name.empty()) return damaged("PLY property of '" + e.name + "' has no name (Assimp would drop it)");
  e.properties.push_back(p);
  return Status::success();
}

// Reads the header the way Assimp does (its line ends, its word separators,
// a property only in the unbroken run of lines after its element's), so that
// the elements checked are the ones Assimp will read.
Status read_header(std::ifstream& in, std::uint64_t file_bytes, Header& h) {
  std::string text;
  text.resize(static_cast<std::size_t>(std::min<std::uint64_t>(file_bytes, kMaxPlyHeaderBytes)));
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.compare(0, 3, "ply") != 0) return damaged("not a PLY file (no 'ply' magic)");
  std::size_t at = 0;
  bool have_format = false;
  bool ended = false;
  bool in_element = false;
  while (const std::optional<std::string> line = assimp_line(text, at)) {
    const std::vector<std::string> words = words_of(*line);
    const std::string keyword = words.empty() ? std::string() : words[0];
    if (keyword == "end_header") {
      ended = true;
      break;
    }
    if (keyword == "format") {
      const std::string format = words.size() > 1 ? words[1] : std::string();
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        return damaged("PLY format '" + format + "' is none of ascii, binary_little_endian, binary_big_endian");
      if (have_format) return damaged("PLY header has two format lines");
      h.ascii = format == "ascii";
      h.big_endian = format == "binary_big_endian";
      have_format = true;
    } else if (keyword == "element") {
      Element e;
      e.name = words.size() > 1 ? words[1] : std::string();
      const std::string count = words.size() > 2 ? words[2] : std::string();
      if (count.size() > 19 || !all_digits(count))
        return damaged("PLY element '" + e.name + "' has count '" + count + "', not a number");
      e.count = std::stoull(count);
      h.elements.push_back(e);
      in_element = true;
      continue;
    } else if (keyword == "property") {
      if (h.elements.empty()) return damaged("PLY property before any element");
      if (!in_element)
        return damaged("PLY property line '" + *line + "' follows a line that ends " + h.elements.back().name +
                       "'s properties (Assimp would drop it)");
      if (Status added = add_property(words, h.elements.back()); !added.ok()) return added;
      continue;
    }
    in_element = in_element && keyword == "comment";
  }
  if (!ended)
    return damaged("PLY header has no 'end_header' within the first " + std::to_string(text.size()) + " bytes");
  if (!have_format) return damaged("PLY header has no format line");
  // The byte after the line decides where binary data starts, so it must be read too.
  if (at >= text.size() && text.size() < file_bytes) return damaged("PLY 'end_header' line has no end");
  at = std::min(at, text.size());
  h.after_line = at;
  h.line_number += static_cast<std::uint64_t>(std::count(text.data(), text.data() + at, '\n'));
  // Assimp starts binary data one byte later when that byte is '\n', meant
  // as the second half of a "\r\n" line end; after a plain '\n' it is data.
  const bool newline_next = at < text.size() && text[at] == '\n';
  if (!h.ascii && newline_next && text[at - 1] == '\n')
    return damaged("binary PLY data starts with byte 0x0A, which Assimp would skip as part of the 'end_header' "
                   "line's end, reading every value one byte off");
  h.data_at = at + (newline_next ? 1 : 0);
  return Status::success();
}

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
    unread_ = got < want ? 0 : unread_ - want;  // a file that shrank ends here
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

Status too_long(const std::string& where, const Property& p, const std::string& items, std::uint64_t left,
                std::uint64_t item_bytes) {
  return damaged("PLY " + where + " has a " + p.name + " list of " + items + " items; the " + std::to_string(left) +
                 " bytes left hold at most " + std::to_string(left / item_bytes));
}

Status ends_inside(const std::string& where, const Element& e) {
  return damaged("PLY data ends inside " + where + " of " + std::to_string(e.count));
}

// A binary list length as Assimp reads it: its type, in the file's byte
// order (a real one truncated). Nothing for a NaN.
std::optional<std::int64_t> binary_length(const unsigned char* raw, ScalarType type, bool big_endian) {
  std::uint64_t bits = 0;
  for (int i = 0; i < type.bytes; ++i) bits = bits << 8 | raw[big_endian ? i : type.bytes - 1 - i];
  if (type.number == Number::unsigned_integer) return static_cast<std::int64_t>(bits);  // at most 32 bits
  if (type.number == Number::signed_integer) {
    const std::uint64_t sign = std::uint64_t{1} << (8 * type.bytes - 1);
    return static_cast<std::int64_t>(bits ^ sign) - static_cast<std::int64_t>(sign);
  }
  double length = 0;
  if (type.bytes == sizeof(float)) {
    const auto narrow = static_cast<std::uint32_t>(bits);
    float f = 0;
    std::memcpy(&f, &narrow, sizeof f);
    length = f;
  } else {
    std::memcpy(&length, &bits, sizeof length);
  }
  if (std::isnan(length)) return std::nullopt;
  return static_cast<std::int64_t>(std::clamp(length, -kRealLengthCeiling, kRealLengthCeiling));
}

Status walk_binary(BodyReader& body, const std::vector<Element>& elements, bool big_endian) {
  for (const Element& e : elements) {
    if (!e.has_list()) {
      // Fixed-size instances: one skip however many (the size check keeps
      // count x bytes within 64 bits).
      if (!body.skip(e.count * e.least_bytes)) return damaged("PLY data ends inside the " + e.name + " elements");
      continue;
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (const Property& p : e.properties) {
        if (!p.is_list) {
          if (!body.skip(static_cast<std::uint64_t>(p.value.bytes))) return ends_inside(instance(e, i), e);
          continue;
        }
        unsigned char raw[sizeof(double)] = {};
        if (!body.read(raw, static_cast<std::size_t>(p.length.bytes))) return ends_inside(instance(e, i), e);
        const std::optional<std::int64_t> items = binary_length(raw, p.length, big_endian);
        if (!items)
          return damaged("PLY " + instance(e, i) + " has a " + p.name + " list whose length is not a number");
        if (*items < 0)
          return damaged("PLY " + instance(e, i) + " has a " + p.name + " list of " + std::to_string(*items) +
                         " items (a negative length)");
        const auto item_bytes = static_cast<std::uint64_t>(p.value.bytes);
        // Compared by division: items x bytes may not fit 64 bits.
        if (static_cast<std::uint64_t>(*items) > body.left() / item_bytes)
          return too_long(instance(e, i), p, std::to_string(*items), body.left(), item_bytes);
        body.skip(static_cast<std::uint64_t>(*items) * item_bytes);
      }
    }
  }
  return Status::success();
}

struct Token {
  std::string text;  // its first kMaxTokenChars characters
  std::uint64_t length = 0;
  std::uint64_t left = 0;  // bytes after it
};

// The token's text for a message: one line, printable.
std::string shown(const Token& t) {
  std::string text = t.text;
  for (char& c : text)
    if (c < ' ' || c > '~') c = '?';
  return "'" + text + (t.length > t.text.size() ? "...'" : "'");
}

// Reads a token: the bytes up to the next one `ends` accepts (not taken).
template <class Ends>
void read_token(BodyReader& body, Token& t, Ends ends) {
  t.text.clear();
  t.length = body.take_while([&](unsigned char c) { return !ends(c); },
                             [&](const unsigned char* data, std::size_t size) {
                               const std::size_t room = kMaxTokenChars - t.text.size();
                               t.text.append(reinterpret_cast<const char*>(data), std::min(size, room));
                             });
  t.left = body.left();
}

// The PLY format's separators: space, '\t', '\n', '\v', '\f', '\r'.
constexpr auto is_space = [](int c) { return c == ' ' || (c >= '\t' && c <= '\r'); };

// A token as a list length: digits only (Assimp reads a sign or a fraction as
// something else), saturating at kLengthCeiling.
std::optional<std::uint64_t> whole_number(const Token& t) {
  if (t.length > t.text.size() || !all_digits(t.text)) return std::nullopt;
  std::uint64_t n = 0;
  for (char c : t.text) n = std::min(n * 10 + static_cast<std::uint64_t>(c - '0'), kLengthCeiling);
  return n;
}

Status not_a_length(const std::string& where, const Property& p, const Token& t) {
  return damaged("PLY " + where + " has a " + p.name + " list of length " + shown(t) + ", not a whole number");
}

// Whether Assimp's reader of `number` (strtoul10, strtol10,
// fast_atoreal_move) takes all of `t`: only then does its next value start
// at the next token, where this check reads it.
bool read_whole(const Token& t, Number number) {
  std::string_view s = t.text;
  if (t.length > s.size()) return false;
  if (number != Number::unsigned_integer && !s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  if (number != Number::real) return all_digits(s);
  std::string lower(s);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "nan" || lower == "inf" || lower == "infinity") return true;
  const std::size_t e = s.find_first_of("eE");
  if (e != std::string_view::npos) {
    std::string_view exponent = s.substr(e + 1);
    if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) exponent.remove_prefix(1);
    if (!all_digits(exponent)) return false;
  }
  const std::string_view mantissa = s.substr(0, e);
  const std::size_t dot = mantissa.find('.');
  if (dot == std::string_view::npos) return all_digits(mantissa);
  const std::string_view whole = mantissa.substr(0, dot), fraction = mantissa.substr(dot + 1);
  return (all_digits(whole) && (fraction.empty() || all_digits(fraction))) || (whole.empty() && all_digits(fraction));
}

// Skips `tokens` tokens, counting where tokens start a chunk at a time with
// no branch a byte (vertex arrays are most of an ASCII file); false when the
// data ends first. Starts at the data's start or just after a token.
bool skip_tokens(BodyReader& body, std::uint64_t tokens) {
  bool after_space = true;
  while (tokens > 0) {
    const BodyReader::Bytes ahead = body.ahead();
    if (ahead.size == 0) return false;
    std::uint64_t starts = 0;
    bool before = after_space;
    for (std::size_t i = 0; i < ahead.size; ++i) {
      const bool space = is_space(ahead.data[i]);
      starts += before && !space ? 1 : 0;
      before = space;
    }
    if (starts < tokens) {
      tokens -= starts;
      after_space = before;
      body.take(ahead.size);
      continue;
    }
    // The last token starts in this chunk: go to it, then take it whole.
    std::size_t i = 0;
    for (before = after_space;; ++i) {
      const bool space = is_space(ahead.data[i]);
      if (before && !space && --tokens == 0) break;
      before = space;
    }
    body.take(i);
    body.take_while([](unsigned char c) { return !is_space(c); });
  }
  return true;
}

// The PLY format's reading of an ASCII body: whitespace-separated tokens,
// elements in any layout of lines.
Status walk_ascii_tokens(BodyReader& body, const std::vector<Element>& elements) {
  Token t;
  // Only a list's length is kept as text; other tokens are only counted.
  const auto next = [&](bool keep_text) {
    body.take_while(is_space);
    if (body.peek() < 0) return false;
    if (keep_text)
      read_token(body, t, is_space);
    else
      body.take_while([](unsigned char c) { return !is_space(c); });
    return true;
  };
  for (const Element& e : elements) {
    if (!e.has_list()) {
      // The size check keeps count x properties within 64 bits.
      if (!skip_tokens(body, e.count * e.properties.size()))
        return damaged("PLY data ends inside the " + e.name + " elements");
      continue;
    }
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (const Property& p : e.properties) {
        if (!next(p.is_list)) return ends_inside(instance(e, i), e);
        if (!p.is_list) continue;
        const std::optional<std::uint64_t> items = whole_number(t);
        if (!items) return not_a_length(instance(e, i), p, t);
        if (*items > t.left / kAsciiItemBytes) return too_long(instance(e, i), p, t.text, t.left, kAsciiItemBytes);
        for (std::uint64_t k = 0; k < *items; ++k)
          if (!next(false)) return ends_inside(instance(e, i), e);
      }
  }
  return Status::success();
}

// Assimp's reading of an ASCII body: each instance is one line (as
// assimp_line), its values separated by spaces and tabs; values the line
// lacks are left at defaults, and what follows its properties is ignored.
// Assimp sizes each list by its length before reading the items.
class AssimpLines {
 public:
  AssimpLines(BodyReader& body, std::uint64_t line_number) : body_(body), line_(line_number) {}

  bool next_line() {
    finish_line();
    if (is_line_end(body_.peek()))
      for (int c = take(); c >= 0 && c != '\n';) c = take();
    if (body_.peek() < 0) return false;
    in_line_ = true;
    number_ = line_;
    return true;
  }
  bool next_value(Token& t) {
    if (!in_line_) return false;
    body_.take_while([](unsigned char c) { return c == ' ' || c == '\t'; });
    if (body_.peek() < 0 || is_line_end(body_.peek())) {
      finish_line();
      return false;
    }
    read_token(body_, t, [](int c) { return c == ' ' || c == '\t' || is_line_end(c); });
    return true;
  }
  std::uint64_t number() const { return number_; }

 private:
  // Takes the rest of the line and the byte that ends it.
  void finish_line() {
    if (!in_line_) return;
    body_.take_while([](unsigned char c) { return !is_line_end(c); });
    take();
    in_line_ = false;
  }
  int take() {
    const int c = body_.get();
    line_ += c == '\n' ? 1 : 0;
    return c;
  }

  BodyReader& body_;
  std::uint64_t line_;
  std::uint64_t number_ = 0;
  bool in_line_ = false;
};

Status check_line(AssimpLines& lines, const Element& e, std::uint64_t i, std::uint64_t& listed,
                  std::uint64_t data_bytes) {
  const auto where = [&] {
    return instance(e, i) + " (line " + std::to_string(lines.number()) + ", one element a line as Assimp reads it)";
  };
  const auto not_read_whole = [&](const Property& p, const Token& t) {
    return damaged("PLY " + where() + " has " + shown(t) + " for " + p.name +
                   ", not a number Assimp reads whole (it would read the rest as the next value)");
  };
  Token t;
  for (const Property& p : e.properties) {
    if (!lines.next_value(t)) return Status::success();
    if (!p.is_list) {
      if (!read_whole(t, p.value.number)) return not_read_whole(p, t);
      continue;
    }
    const std::optional<std::uint64_t> items = whole_number(t);
    if (!items) return not_a_length(where(), p, t);
    if (*items > t.left / kAsciiItemBytes) return too_long(where(), p, t.text, t.left, kAsciiItemBytes);
    // Assimp keeps the lists of edge and material elements all at once.
    listed += *items;
    if (listed > data_bytes / kAsciiItemBytes)
      return damaged("PLY lists up to " + where() + " have " + std::to_string(listed) + " items in all; the " +
                     std::to_string(data_bytes) + " bytes of data hold at most " +
                     std::to_string(data_bytes / kAsciiItemBytes));
    for (std::uint64_t k = 0; k < *items; ++k) {
      if (!lines.next_value(t)) return Status::success();
      if (!read_whole(t, p.value.number)) return not_read_whole(p, t);
    }
  }
  return Status::success();
}

Status walk_assimp_lines(BodyReader& body, const std::vector<Element>& elements, std::uint64_t line_number,
                         std::uint64_t data_bytes) {
  AssimpLines lines(body, line_number);
  std::uint64_t listed = 0;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const Element& e = elements[k];
    const bool parsed = e.lists_parsed();
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if (!lines.next_line()) {
        // Past the last line Assimp parses that line again for each instance.
        if (std::any_of(elements.begin() + static_cast<std::ptrdiff_t>(k), elements.end(),
                        [](const Element& later) { return later.lists_parsed(); }))
          return damaged("PLY data has no line for " + instance(e, i) + " (Assimp reads one element a line)");
        return Status::success();
      }
      if (!parsed) continue;
      if (Status line = check_line(lines, e, i, listed, data_bytes); !line.ok()) return line;
    }
  }
  return Status::success();
}

} // namespace

Status check_ply(std::ifstream& in, std::uint64_t file_bytes) {
  Header h;
  if (Status header = read_header(in, file_bytes, h); !header.ok()) return header;
  const std::uint64_t data_at = h.ascii ? h.after_line : h.data_at;
  const std::uint64_t body = file_bytes - std::min(file_bytes, data_at);

  // Every element takes at least its scalars' bytes and each list's length
  // (binary), or two characters a property (ASCII: a digit and a separator).
  std::uint64_t needed = 0;
  for (Element& e : h.elements) {
    for (const Property& p : e.properties) {
      const int binary_bytes = p.is_list ? p.length.bytes : p.value.bytes;
      e.least_bytes += h.ascii ? kAsciiItemBytes : static_cast<std::uint64_t>(binary_bytes);
    }
    if (e.least_bytes == 0 && e.count > 0)
      return damaged("PLY element '" + e.name + "' has no properties but a count of " + std::to_string(e.count));
    // Compared by division: count x bytes may not fit 64 bits.
    if (e.least_bytes > 0 && e.count > (body + 1) / e.least_bytes)
      return damaged("PLY declares " + std::to_string(e.count) + " " + e.name + " elements, more than its " +
                     std::to_string(body) + " bytes of data can hold");
    needed += e.count * e.least_bytes;
    if (needed > body + 1)
      return damaged("PLY elements need at least " + std::to_string(needed) + " bytes; the data has " +
                     std::to_string(body));
  }
  // An element Assimp does not count shifts where it reads every later one.
  for (auto e = h.elements.begin(); e != h.elements.end(); ++e) {
    const bool later_data = std::any_of(e + 1, h.elements.end(), [](const Element& l) { return l.count > 0; });
    if (e->assimp_count() > e->count || (e->assimp_count() != e->count && later_data))
      return damaged("PLY element '" + e->name + "' (" + std::to_string(e->count) +
                     ") is not one Assimp counts (vertex, face, tristrips, edge, material): it would read " +
                     std::to_string(e->assimp_count()) + " of it and the elements after it from the wrong place");
  }

  if (std::none_of(h.elements.begin(), h.elements.end(), [](const Element& e) { return e.has_list(); }))
    return Status::success();
  if (!h.ascii) {
    BodyReader data(in, data_at, body);
    return walk_binary(data, h.elements, h.big_endian);
  }
  {
    BodyReader data(in, data_at, body);
    if (Status tokens = walk_ascii_tokens(data, h.elements); !tokens.ok()) return tokens;
  }
  BodyReader data(in, data_at, body);
  return walk_assimp_lines(data, h.elements, h.line_number, body);
}

} // namespace hullcover::detail

#include "ply_ascii_checks.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>

namespace hullcover::detail {
namespace {

// Characters of an ASCII token kept: numbers are far shorter, and a longer
// token is refused where it is read as one.
constexpr std::size_t kMaxTokenChars = 64;
// ASCII list lengths saturate here, past any file, so ten times one still
// fits 64 bits.
constexpr std::uint64_t kLengthCeiling = 1'000'000'000'000'000'000;

struct Token {
  std::string text; // its first kMaxTokenChars characters
  std::uint64_t length = 0;
  std::uint64_t left = 0; // bytes after it
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
  return damaged_file("PLY " + where + " has a " + p.name + " list of length " + shown(t) + ", not a whole number");
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
    return damaged_file("PLY " + where() + " has " + shown(t) + " for " + p.name +
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
      return damaged_file("PLY lists up to " + where() + " have " + std::to_string(listed) + " items in all; the " +
                          std::to_string(data_bytes) + " bytes of data hold at most " +
                          std::to_string(data_bytes / kAsciiItemBytes));
    for (std::uint64_t k = 0; k < *items; ++k) {
      if (!lines.next_value(t)) return Status::success();
      if (!read_whole(t, p.value.number)) return not_read_whole(p, t);
    }
  }
  return Status::success();
}

} // namespace

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
        return damaged_file("PLY data ends inside the " + e.name + " elements");
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
          return damaged_file("PLY data has no line for " + instance(e, i) + " (Assimp reads one element a line)");
        return Status::success();
      }
      if (!parsed) continue;
      if (Status line = check_line(lines, e, i, listed, data_bytes); !line.ok()) return line;
    }
  }
  return Status::success();
}

} // namespace hullcover::detail

#include "ply_file_checks.h"

#include "ply_ascii_checks.h"
#include "scene_file_rules.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace hullcover::detail {
namespace {

// Binary real-valued lengths are clamped here before the cast to an integer
// (defined behaviour); any length this long is refused anyway.
constexpr double kRealLengthCeiling = 0x1p62;

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
  ++at; // past the byte that ends it (past the text when none does)
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
  std::uint64_t line_number = 1; // of the line at after_line
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
      return damaged_file("PLY list property with types '" + word(2) + "', '" + word(3) + "'");
  } else if ((p.value = ply_scalar_type(word(1))).bytes == 0) {
    return damaged_file("PLY property of unknown type '" + word(1) + "'");
  }
  p.name = word(p.is_list ? 4 : 2);
  if (p.name.empty()) return damaged_file("PLY property of '" + e.name + "' has no name (Assimp would drop it)");
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
  if (text.compare(0, 3, "ply") != 0) return damaged_file("not a PLY file (no 'ply' magic)");
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
        return damaged_file("PLY format '" + format + "' is none of ascii, binary_little_endian, binary_big_endian");
      if (have_format) return damaged_file("PLY header has two format lines");
      h.ascii = format == "ascii";
      h.big_endian = format == "binary_big_endian";
      have_format = true;
    } else if (keyword == "element") {
      Element e;
      e.name = words.size() > 1 ? words[1] : std::string();
      const std::string count = words.size() > 2 ? words[2] : std::string();
      if (count.size() > 19 || !all_digits(count))
        return damaged_file("PLY element '" + e.name + "' has count '" + count + "', not a number");
      e.count = std::stoull(count);
      h.elements.push_back(e);
      in_element = true;
      continue;
    } else if (keyword == "property") {
      if (h.elements.empty()) return damaged_file("PLY property before any element");
      if (!in_element)
        return damaged_file("PLY property line '" + *line + "' follows a line that ends " + h.elements.back().name +
                            "'s properties (Assimp would drop it)");
      if (Status added = add_property(words, h.elements.back()); !added.ok()) return added;
      continue;
    }
    in_element = in_element && keyword == "comment";
  }
  if (!ended)
    return damaged_file("PLY header has no 'end_header' within the first " + std::to_string(text.size()) + " bytes");
  if (!have_format) return damaged_file("PLY header has no format line");
  // The byte after the line decides where binary data starts, so it must be read too.
  if (at >= text.size() && text.size() < file_bytes) return damaged_file("PLY 'end_header' line has no end");
  at = std::min(at, text.size());
  h.after_line = at;
  h.line_number += static_cast<std::uint64_t>(std::count(text.data(), text.data() + at, '\n'));
  // Assimp starts binary data one byte later when that byte is '\n', meant
  // as the second half of a "\r\n" line end; after a plain '\n' it is data.
  const bool newline_next = at < text.size() && text[at] == '\n';
  if (!h.ascii && newline_next && text[at - 1] == '\n')
    return damaged_file(
        "binary PLY data starts with byte 0x0A, which Assimp would skip as part of the 'end_header' "
        "line's end, reading every value one byte off");
  h.data_at = at + (newline_next ? 1 : 0);
  return Status::success();
}

// A binary list length as Assimp reads it: its type, in the file's byte
// order (a real one truncated). Nothing for a NaN.
std::optional<std::int64_t> binary_length(const unsigned char* raw, ScalarType type, bool big_endian) {
  std::uint64_t bits = 0;
  for (int i = 0; i < type.bytes; ++i) bits = bits << 8 | raw[big_endian ? i : type.bytes - 1 - i];
  if (type.number == Number::unsigned_integer) return static_cast<std::int64_t>(bits); // at most 32 bits
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
      if (!body.skip(e.count * e.least_bytes)) return damaged_file("PLY data ends inside the " + e.name + " elements");
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
          return damaged_file("PLY " + instance(e, i) + " has a " + p.name + " list whose length is not a number");
        if (*items < 0)
          return damaged_file("PLY " + instance(e, i) + " has a " + p.name + " list of " + std::to_string(*items) +
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
      return damaged_file("PLY element '" + e.name + "' has no properties but a count of " + std::to_string(e.count));
    // Compared by division: count x bytes may not fit 64 bits.
    if (e.least_bytes > 0 && e.count > (body + 1) / e.least_bytes)
      return damaged_file("PLY declares " + std::to_string(e.count) + " " + e.name + " elements, more than its " +
                          std::to_string(body) + " bytes of data can hold");
    needed += e.count * e.least_bytes;
    if (needed > body + 1)
      return damaged_file("PLY elements need at least " + std::to_string(needed) + " bytes; the data has " +
                          std::to_string(body));
  }
  // An element Assimp does not count shifts where it reads every later one.
  for (auto e = h.elements.begin(); e != h.elements.end(); ++e) {
    const bool later_data = std::any_of(e + 1, h.elements.end(), [](const Element& l) { return l.count > 0; });
    if (e->assimp_count() > e->count || (e->assimp_count() != e->count && later_data))
      return damaged_file("PLY element '" + e->name + "' (" + std::to_string(e->count) +
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

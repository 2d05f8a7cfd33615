#include "ply_header.h"

#include "scene_file_rules.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace hullcover::detail {
namespace {

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
} // namespace

Status read_ply_header(std::istream& in, std::uint64_t file_bytes, PlyHeader& h) {
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
  // Binary data starts after the line's end: a '\n', or the '\n' of a
  // "\r\n" (the line read ends at its '\r'). A first data byte of 0x0A after
  // a '\n' is data (Assimp skipped it, reading every value a byte off; the
  // project's reader reads PLY now).
  const bool crlf = at < text.size() && text[at] == '\n' && text[at - 1] == '\r';
  h.data_at = at + (crlf ? 1 : 0);
  return Status::success();
}

} // namespace hullcover::detail

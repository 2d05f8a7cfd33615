#pragma once
// OBJ text as lines and statements, shared by the OBJ checks
// (obj_file_checks.h) and the OBJ reader (obj_reader.h).

#include <istream>
#include <string>
#include <utility>

namespace hullcover::detail {

/// The line's statement keyword and the text after it, leading and
/// trailing blanks gone.
inline std::pair<std::string, std::string> statement(const std::string& line) {
  const size_t start = line.find_first_not_of(" \t");
  if (start == std::string::npos) return {};
  const size_t end = line.find_first_of(" \t\r", start);
  if (end == std::string::npos) return {line.substr(start), ""};
  const size_t rest = line.find_first_not_of(" \t", end);
  std::string text = rest == std::string::npos ? std::string() : line.substr(rest);
  while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t')) text.pop_back();
  return {line.substr(start, end - start), text};
}

/// The next line of OBJ text, split as Assimp's OBJ reader splits them, so
/// the checks and the reader see the same lines: a line ends at '\n', '\r',
/// '\f' or NUL, and one ending in '\' goes on in the next. Splitting only
/// at '\n' would let "usemtl a\rusemtl b\r..." past as one line.
inline bool next_obj_line(std::istream& in, std::string& line) {
  line.clear();
  char c = 0;
  bool any = false;
  while (in.get(c)) {
    any = true;
    if (c == '\n' || c == '\r' || c == '\f' || c == '\0') {
      if (c == '\r' && in.peek() == '\n') in.get(c); // CRLF: one line end, for the line numbers
      if (!line.empty() && line.back() == '\\') {
        line.pop_back();
        continue;
      }
      return true;
    }
    line += c;
  }
  return any;
}

} // namespace hullcover::detail

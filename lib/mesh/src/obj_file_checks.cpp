#include "obj_file_checks.h"

#include "scene_file_rules.h"

#include <sstream>
#include <string>
#include <unordered_set>

namespace hullcover::detail {
namespace {

// The line's statement keyword and the text after it, leading blanks gone.
std::pair<std::string, std::string> statement(const std::string& line) {
  const size_t start = line.find_first_not_of(" \t");
  if (start == std::string::npos) return {};
  const size_t end = line.find_first_of(" \t\r", start);
  if (end == std::string::npos) return {line.substr(start), ""};
  const size_t rest = line.find_first_not_of(" \t", end);
  std::string text = rest == std::string::npos ? std::string() : line.substr(rest);
  while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t')) text.pop_back();
  return {line.substr(start, end - start), text};
}

// The next line as Assimp's OBJ reader splits them: a line ends at '\n',
// '\r', '\f' or NUL, and one ending in '\' goes on in the next. Splitting
// only at '\n' would let "usemtl a\rusemtl b\r..." past as one line.
bool next_assimp_line(std::istream& in, std::string& line) {
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

} // namespace

Status check_obj(std::istream& in, const ImportLimits& limits) {
  if (limits.max_materials < 0) return {StatusCode::invalid_argument, "--max-materials must not be negative"};
  std::unordered_set<std::string> materials;
  std::string line;
  long number = 0;
  while (next_assimp_line(in, line)) {
    ++number;
    const auto [keyword, text] = statement(line);
    if (keyword == "mtllib") {
      std::istringstream names(text);
      std::string name;
      while (names >> name)
        if (reference_text_leaves_folder(name))
          return {StatusCode::reference_outside_folder,
                  "line " + std::to_string(number) + " refers to material library '" + name +
                      "', outside the scene file's folder (references are read only inside it: no absolute paths, "
                      "no '..', no URLs)"};
    } else if (keyword == "usemtl") {
      materials.insert(text);
      if (materials.size() > static_cast<size_t>(limits.max_materials))
        return {StatusCode::limit_exceeded, "line " + std::to_string(number) + " names material number " +
                                                std::to_string(materials.size()) + ", more than the limit of " +
                                                std::to_string(limits.max_materials) +
                                                " (raise it with --max-materials)"};
    }
  }
  return Status::success();
}

} // namespace hullcover::detail

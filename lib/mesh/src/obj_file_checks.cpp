#include "obj_file_checks.h"

#include "obj_lines.h"
#include "scene_file_rules.h"

#include <sstream>
#include <string>
#include <unordered_set>

namespace hullcover::detail {

Status check_obj(std::istream& in, const ImportLimits& limits) {
  if (limits.max_materials < 0) return {StatusCode::invalid_argument, "--max-materials must not be negative"};
  std::unordered_set<std::string> materials;
  std::string line;
  long number = 0;
  while (next_obj_line(in, line)) {
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

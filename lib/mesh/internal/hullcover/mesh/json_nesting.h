#pragma once
/// \file json_nesting.h
/// How deep a JSON text nests, counted without parsing it: nlohmann's
/// parser and a parsed value's destructor recurse once per level, so a
/// hostile file of a million '[' would overflow the stack before any
/// parse could refuse it. Readers of glTF from anyone check this first.

#include <algorithm>
#include <string>

namespace hullcover {

/// The deepest nesting of objects and arrays in `text` (brackets inside
/// strings do not count). Not a validation: malformed text still gets a
/// number.
inline int json_nesting_depth(const std::string& text) {
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"')
      in_string = true;
    else if (c == '{' || c == '[')
      deepest = std::max(deepest, ++depth);
    else if (c == '}' || c == ']')
      --depth;
  }
  return deepest;
}

} // namespace hullcover

#include "stl_ascii_reader.h"

#include "scene_text.h"
#include "obj_lines.h"
#include "scene_file_rules.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <unordered_map>
#include <vector>

namespace hullcover::detail {
namespace {

// Words a statement may have: "facet normal x y z" has five, and a line is
// split no further (a 1 GiB line of words is not held as views).
constexpr size_t kMostWordsRead = 6;

std::vector<std::string_view> blank_separated_words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t at = 0;
  while (at < line.size() && words.size() < kMostWordsRead) {
    while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at]))) ++at;
    const size_t start = at;
    while (at < line.size() && !std::isspace(static_cast<unsigned char>(line[at]))) ++at;
    if (at > start) words.push_back(line.substr(start, at - start));
  }
  return words;
}

// A word for a message: its first 40 characters.
std::string shown(std::string_view word) { return std::string(word.substr(0, 40)); }

bool is_keyword(std::string_view word, const char* keyword) {
  const size_t n = std::strlen(keyword);
  if (word.size() != n) return false;
  for (size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(word[i])) != keyword[i]) return false;
  return true;
}

// Positions keyed by their bits (-0 as 0), so bit-identical corners join.
struct PositionKey {
  std::array<std::uint64_t, 3> bits;
  bool operator==(const PositionKey& other) const { return bits == other.bits; }
};
struct PositionHash {
  size_t operator()(const PositionKey& key) const {
    size_t h = 0;
    for (const std::uint64_t b : key.bits) h = h * 1000003u ^ std::hash<std::uint64_t>()(b);
    return h;
  }
};

PositionKey key_of(const Eigen::Vector3d& p) {
  PositionKey key{};
  for (int k = 0; k < 3; ++k) {
    const double value = p[k] == 0.0 ? 0.0 : p[k];
    std::memcpy(&key.bits[k], &value, sizeof value);
  }
  return key;
}

} // namespace

bool is_ascii_stl(const std::string& path, std::uint64_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t declared = 0;
  return stl_layout(in, file_bytes, declared) == StlLayout::ascii;
}

Result<Mesh> read_ascii_stl(std::istream& in, std::uint64_t triangle_limit) {
  Mesh mesh;
  std::unordered_map<PositionKey, int, PositionHash> position_of;
  std::string line;
  long line_number = 0;
  bool in_facet = false;
  int corners = 0;
  Eigen::Vector3i facet = Eigen::Vector3i::Zero();
  while (next_obj_line(in, line)) {
    ++line_number;
    const std::vector<std::string_view> words = blank_separated_words(line);
    if (words.empty()) continue;
    const std::string_view keyword = words.front();
    if (is_keyword(keyword, "solid") || is_keyword(keyword, "endsolid")) {
      if (in_facet) return at_line(StatusCode::unreadable_file, line_number, "a solid starts or ends inside a facet");
    } else if (is_keyword(keyword, "facet")) {
      if (in_facet) return at_line(StatusCode::unreadable_file, line_number, "a facet starts inside a facet");
      if (mesh.triangles.size() >= triangle_limit)
        return at_line(StatusCode::limit_exceeded, line_number,
                       "more than " + std::to_string(triangle_limit) + " facets (raise it with --max-triangles)");
      in_facet = true;
      corners = 0;
    } else if (is_keyword(keyword, "outer") || is_keyword(keyword, "endloop")) {
      if (!in_facet) return at_line(StatusCode::unreadable_file, line_number, "a loop outside a facet");
    } else if (is_keyword(keyword, "vertex")) {
      if (!in_facet) return at_line(StatusCode::unreadable_file, line_number, "a vertex outside a facet");
      if (corners == 3)
        return at_line(StatusCode::unreadable_file, line_number, "a facet with more than three vertices");
      if (words.size() != 4)
        return at_line(StatusCode::unreadable_file, line_number, "a vertex needs three coordinates");
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) {
        if (!read_decimal(words[k + 1], p[k]))
          return at_line(StatusCode::unreadable_file, line_number,
                         "coordinate '" + shown(words[k + 1]) + "' is not a number");
        if (!std::isfinite(p[k]))
          return at_line(StatusCode::non_finite_coordinate, line_number,
                         "coordinate '" + shown(words[k + 1]) + "' is not a finite number");
      }
      const auto [found, added] = position_of.try_emplace(key_of(p), static_cast<int>(mesh.positions.size()));
      if (added) mesh.positions.push_back(p);
      facet[corners++] = found->second;
    } else if (is_keyword(keyword, "endfacet")) {
      if (!in_facet || corners != 3)
        return at_line(StatusCode::unreadable_file, line_number, "a facet ends without three vertices");
      mesh.triangles.push_back(facet);
      in_facet = false;
    } else {
      return at_line(StatusCode::unreadable_file, line_number, "'" + shown(keyword) + "' is no ASCII STL statement");
    }
  }
  if (in_facet) return at_line(StatusCode::unreadable_file, line_number, "the text ends inside a facet");
  if (mesh.triangles.empty()) return Status{StatusCode::empty_scene, "no facet"};
  mesh.material_ids.assign(mesh.triangles.size(), 0);
  return mesh;
}

} // namespace hullcover::detail

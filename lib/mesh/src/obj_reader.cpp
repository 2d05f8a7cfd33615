#include "obj_reader.h"

#include "scene_text.h"
#include "obj_lines.h"
#include "polygon_triangulation.h"

#include <charconv>
#include <cstdlib>
#include <limits>
#include <cmath>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace hullcover::detail {
namespace {

// The next blank-separated word of `text` from `at`, or empty at the end.
std::string_view next_word(std::string_view text, size_t& at) {
  while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
  const size_t start = at;
  while (at < text.size() && text[at] != ' ' && text[at] != '\t') ++at;
  return text.substr(start, at - start);
}

// A face corner's position index (the part before any '/'), resolved to a
// 0-based index among `count` positions; false when it names none.
bool read_corner(std::string_view word, size_t count, long long& index) {
  word = word.substr(0, word.find('/'));
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), index);
  if (error != std::errc() || end != word.data() + word.size() || word.empty()) return false;
  if (index < 0)
    index += static_cast<long long>(count); // -1: the last position so far
  else
    --index; // OBJ counts from 1
  return index >= 0 && index < static_cast<long long>(count);
}

class ObjBuilder {
public:
  explicit ObjBuilder(std::uint64_t triangle_limit) : triangle_limit_(triangle_limit) {
    mesh_.material_names.push_back("default"); // faces before any usemtl (and `usemtl default`)
    material_ids_.emplace("default", 0);
  }

  Status position(std::string_view text, long line) {
    // Corners are ints: a file of more positions than an int counts could
    // not be indexed (and would be over 16 GiB of text).
    if (mesh_.positions.size() >= static_cast<size_t>(std::numeric_limits<int>::max()))
      return at_line(StatusCode::limit_exceeded, line, "more positions than an index can name");
    size_t at = 0;
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) {
      const std::string_view word = next_word(text, at);
      double value = 0.0;
      if (word.empty()) return at_line(StatusCode::unreadable_file, line, "a position needs three coordinates");
      if (!read_decimal(word, value))
        return at_line(StatusCode::unreadable_file, line, "'" + std::string(word) + "' is not a number");
      if (!std::isfinite(value))
        return at_line(StatusCode::non_finite_coordinate, line,
                       "coordinate '" + std::string(word) + "' is not a finite number");
      p[k] = value;
    }
    mesh_.positions.push_back(p);
    return Status::success();
  }

  Status face(std::string_view text, long line) {
    corners_.clear();
    indices_.clear();
    size_t at = 0;
    for (std::string_view word = next_word(text, at); !word.empty(); word = next_word(text, at)) {
      long long index = 0;
      if (!read_corner(word, mesh_.positions.size(), index))
        return at_line(word.find_first_not_of("+-0123456789/") == std::string_view::npos
                           ? StatusCode::index_out_of_range
                           : StatusCode::unreadable_file,
                       line, "face corner '" + std::string(word) + "' names no position");
      indices_.push_back(static_cast<int>(index));
      corners_.push_back(mesh_.positions[index]);
      // A polygon of n corners makes n - 2 triangles: stop at the limit
      // before one line's corners can outgrow it.
      if (mesh_.triangles.size() + indices_.size() > triangle_limit_ + 2) return over_limit(line);
    }
    if (indices_.size() < 3) {
      ++skipped_;
      return Status::success();
    }
    triangles_.clear();
    if (triangulate_polygon(corners_, triangles_) == Triangulation::too_large)
      return at_line(StatusCode::limit_exceeded, line,
                     "a concave polygon of " + std::to_string(indices_.size()) + " corners, more than the " +
                         std::to_string(kMostConcaveCorners) + " the reader triangulates (triangulate it on export)");
    if (mesh_.triangles.size() + triangles_.size() > triangle_limit_) return over_limit(line);
    for (const Eigen::Vector3i& t : triangles_) {
      mesh_.triangles.emplace_back(indices_[t[0]], indices_[t[1]], indices_[t[2]]);
      mesh_.material_ids.push_back(material_);
    }
    return Status::success();
  }

  void use_material(const std::string& name) {
    const auto [it, added] = material_ids_.emplace(name, static_cast<int>(mesh_.material_names.size()));
    if (added) mesh_.material_names.push_back(name);
    material_ = it->second;
  }

  void skip_primitive() { ++skipped_; }
  int skipped() const { return skipped_; }

  Result<Mesh> finish() {
    if (mesh_.triangles.empty()) return Status{StatusCode::empty_scene, "the file holds no triangles"};
    // "default" stays only when a face has it.
    if (mesh_.material_names.size() > 1 && !uses_default()) {
      mesh_.material_names.erase(mesh_.material_names.begin());
      for (int& m : mesh_.material_ids) --m;
    }
    return std::move(mesh_);
  }

private:
  Status over_limit(long line) const {
    return at_line(
        StatusCode::limit_exceeded, line,
        "more than the limit of " + std::to_string(triangle_limit_) + " triangles (raise it with --max-triangles)");
  }

  bool uses_default() const {
    for (int m : mesh_.material_ids)
      if (m == 0) return true;
    return false;
  }

  std::uint64_t triangle_limit_;
  int skipped_ = 0;
  Mesh mesh_;
  std::unordered_map<std::string, int> material_ids_;
  int material_ = 0;
  std::vector<int> indices_;
  std::vector<Eigen::Vector3d> corners_;
  std::vector<Eigen::Vector3i> triangles_;
};

} // namespace

Result<Mesh> read_obj(std::istream& in, std::uint64_t triangle_limit, ObjSideFacts& facts) {
  ObjBuilder builder(triangle_limit);
  std::string line;
  long number = 0;
  while (next_obj_line(in, line)) {
    ++number;
    const auto [keyword, text] = statement(line);
    Status read = Status::success();
    if (keyword == "v")
      read = builder.position(text, number);
    else if (keyword == "f" || keyword == "fo")
      read = builder.face(text, number);
    else if (keyword == "usemtl")
      builder.use_material(text);
    else if (keyword == "l" || keyword == "p")
      builder.skip_primitive();
    else if (keyword == "mtllib") {
      std::istringstream names(text);
      for (std::string name; names >> name;) facts.material_libraries.push_back(name);
    }
    if (!read.ok()) return read;
  }
  facts.skipped_primitives = builder.skipped();
  return builder.finish();
}

} // namespace hullcover::detail

#include "ply_ascii_reader.h"

#include "ply_header.h"
#include "polygon_triangulation.h"
#include "scene_text.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <vector>

namespace hullcover::detail {
namespace {

Status at_instance(StatusCode code, const Element& e, std::uint64_t i, const std::string& what) {
  return {code, "PLY " + instance(e, i) + ": " + what};
}

// A whole number token (a list length or a corner's index), or false.
bool read_whole(const std::string& token, long long& value) {
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size() && !token.empty();
}

// The index of the property named one of `names` in `e`, or -1.
int property_named(const Element& e, std::initializer_list<const char*> names, bool list) {
  for (size_t k = 0; k < e.properties.size(); ++k)
    for (const char* name : names)
      if (e.properties[k].name == name && e.properties[k].is_list == list) return static_cast<int>(k);
  return -1;
}

} // namespace

bool is_ascii_ply(const std::string& path, std::uint64_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  PlyHeader h;
  return in && read_ply_header(in, file_bytes, h).ok() && h.ascii;
}

Result<Mesh> read_ascii_ply(std::istream& in, std::uint64_t file_bytes, std::uint64_t triangle_limit, int& skipped) {
  PlyHeader h;
  if (Status header = read_ply_header(in, file_bytes, h); !header.ok()) return header;
  if (!h.ascii) return Status{StatusCode::unreadable_file, "PLY body is binary, not ASCII"};
  in.clear();
  in.seekg(static_cast<std::streamoff>(h.after_line));
  Mesh mesh;
  std::vector<std::vector<long long>> faces; // corners, judged once every vertex is read
  std::string token;
  for (const Element& e : h.elements) {
    const bool vertices = e.name == "vertex", polygons = e.name == "face";
    const int x = property_named(e, {"x"}, false), y = property_named(e, {"y"}, false),
              z = property_named(e, {"z"}, false);
    const int corners = property_named(e, {"vertex_indices", "vertex_index"}, true);
    if (vertices && (x < 0 || y < 0 || z < 0) && e.count > 0)
      return Status{StatusCode::unreadable_file, "PLY vertex element has no x, y and z"};
    for (std::uint64_t i = 0; i < e.count; ++i) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      std::vector<long long> face;
      for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
        const Property& property = e.properties[k];
        if (!(in >> token)) return at_instance(StatusCode::unreadable_file, e, i, "the data ends inside it");
        if (!property.is_list) {
          const int axis = !vertices ? -1 : k == x ? 0 : k == y ? 1 : k == z ? 2 : -1;
          if (axis < 0) continue;
          if (!read_decimal(token, p[axis]))
            return at_instance(StatusCode::unreadable_file, e, i, "'" + token.substr(0, 40) + "' is not a number");
          if (!std::isfinite(p[axis]))
            return at_instance(StatusCode::non_finite_coordinate, e, i,
                               "coordinate '" + token.substr(0, 40) + "' is not a finite number");
          continue;
        }
        long long length = 0;
        if (!read_whole(token, length) || length < 0)
          return at_instance(StatusCode::unreadable_file, e, i,
                             "list length '" + token.substr(0, 40) + "' is not a whole number");
        for (long long item = 0; item < length; ++item) {
          if (!(in >> token)) return at_instance(StatusCode::unreadable_file, e, i, "the data ends inside a list");
          if (!(polygons && k == corners)) continue;
          long long index = 0;
          if (!read_whole(token, index))
            return at_instance(StatusCode::unreadable_file, e, i, "corner '" + token.substr(0, 40) + "' is no index");
          face.push_back(index);
        }
      }
      if (vertices) mesh.positions.push_back(p);
      if (polygons) faces.push_back(std::move(face));
    }
  }
  const Element face_element{"face"};
  std::vector<Eigen::Vector3d> polygon;
  std::vector<Eigen::Vector3i> triangles;
  for (size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() < 3) {
      ++skipped;
      continue;
    }
    polygon.clear();
    for (const long long index : faces[f]) {
      if (index < 0 || index >= static_cast<long long>(mesh.positions.size()))
        return at_instance(StatusCode::index_out_of_range, face_element, f,
                           "corner " + std::to_string(index) + " names no vertex");
      polygon.push_back(mesh.positions[index]);
    }
    triangles.clear();
    if (triangulate_polygon(polygon, triangles) == Triangulation::too_large)
      return at_instance(StatusCode::limit_exceeded, face_element, f,
                         "a concave polygon of " + std::to_string(polygon.size()) + " corners, more than the " +
                             std::to_string(kMostConcaveCorners) + " the reader triangulates");
    if (mesh.triangles.size() + triangles.size() > triangle_limit)
      return at_instance(StatusCode::limit_exceeded, face_element, f,
                         "more than " + std::to_string(triangle_limit) + " triangles (raise it with --max-triangles)");
    for (const Eigen::Vector3i& t : triangles)
      mesh.triangles.emplace_back(faces[f][t[0]], faces[f][t[1]], faces[f][t[2]]);
  }
  if (mesh.triangles.empty()) return Status{StatusCode::empty_scene, "no face"};
  mesh.material_ids.assign(mesh.triangles.size(), 0);
  return mesh;
}

} // namespace hullcover::detail

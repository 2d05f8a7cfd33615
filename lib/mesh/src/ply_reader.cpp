#include "ply_reader.h"

#include "polygon_triangulation.h"
#include "scene_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

namespace hullcover::detail {
namespace {

// Corners a triangle takes: the vertices a file may hold per allowed
// triangle.
constexpr std::uint64_t kCornersPerTriangle = 3;
// The index that ends a triangle strip and starts the next.
constexpr long long kStripRestart = -1;

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

// An ASCII body's values: whitespace-separated tokens, whatever the
// property's type.
class AsciiValues {
public:
  explicit AsciiValues(std::istream& in) : in_(in) {}
  /// Reads the next value; false at the end of the data.
  bool next(const ScalarType&) { return static_cast<bool>(in_ >> token_); }
  bool real(double& value) const { return read_decimal(token_, value); }
  bool whole(long long& value) const { return read_whole(token_, value); }
  /// The value as a message quotes it.
  std::string shown() const { return "'" + token_.substr(0, 40) + "'"; }

private:
  std::istream& in_;
  std::string token_;
};

// A binary body's values: each of its property's type (PLY's integers of
// 1, 2 or 4 bytes, floats of 4 and 8) in the header's byte order.
class BinaryValues {
public:
  BinaryValues(BodyReader& body, bool big_endian) : body_(body), big_endian_(big_endian) {}
  bool next(const ScalarType& type) {
    unsigned char bytes[sizeof(std::uint64_t)];
    const int size = std::clamp(type.bytes, 1, static_cast<int>(sizeof bytes));
    if (!body_.read(bytes, static_cast<std::size_t>(size))) return false;
    std::uint64_t bits = 0;
    for (int i = 0; i < size; ++i) bits |= std::uint64_t{bytes[big_endian_ ? size - 1 - i : i]} << (8 * i);
    integer_ = type.number != Number::real;
    if (type.number == Number::real && size == sizeof(float)) {
      float narrow = 0.0f;
      const std::uint32_t narrow_bits = static_cast<std::uint32_t>(bits);
      std::memcpy(&narrow, &narrow_bits, sizeof narrow);
      real_ = narrow;
    } else if (type.number == Number::real) {
      std::memcpy(&real_, &bits, sizeof real_);
    } else {
      // Two's complement of `size` bytes: the sign bit's weight taken away.
      const std::uint64_t sign = type.number == Number::signed_integer ? std::uint64_t{1} << (8 * size - 1) : 0;
      whole_ = static_cast<long long>(bits ^ sign) - static_cast<long long>(sign);
      real_ = static_cast<double>(whole_);
    }
    return true;
  }
  bool real(double& value) const {
    value = real_;
    return true;
  }
  /// A float stored where a whole number belongs counts when it is one.
  bool whole(long long& value) const {
    if (integer_) {
      value = whole_;
      return true;
    }
    constexpr double kWholeRange = 0x1p62;
    if (!(std::abs(real_) < kWholeRange) || real_ != std::floor(real_)) return false;
    value = static_cast<long long>(real_);
    return true;
  }
  std::string shown() const {
    if (integer_) return std::to_string(whole_);
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", real_);
    return text;
  }

private:
  BodyReader& body_;
  bool big_endian_;
  bool integer_ = true;
  long long whole_ = 0;
  double real_ = 0.0;
};

template <class Values>
Result<Mesh> read_elements(Values& values, const PlyHeader& h, std::uint64_t triangle_limit, int& skipped) {
  // Every vertex a triangle could use, three a triangle: more would be
  // memory the triangle limit does not bound.
  const std::uint64_t vertex_limit = kCornersPerTriangle * triangle_limit;
  Mesh mesh;
  // Corners of every face and strip, one flat array: judged once every
  // vertex is read (a face element may come first). Faces count their
  // triangles as they are read, so the limit bounds what is kept.
  std::vector<long long> corners;
  struct Run {
    size_t begin = 0, end = 0;
    bool strip = false;
    std::uint64_t number = 0;
  };
  std::vector<Run> runs;
  std::uint64_t triangles = 0;
  for (const Element& e : h.elements) {
    const bool vertices = e.name == "vertex", polygons = e.name == "face", strips = e.name == "tristrips";
    const int x = property_named(e, {"x"}, false), y = property_named(e, {"y"}, false),
              z = property_named(e, {"z"}, false);
    const int corner_list = property_named(e, {"vertex_indices", "vertex_index"}, true);
    if (vertices && (x < 0 || y < 0 || z < 0) && e.count > 0)
      return Status{StatusCode::unreadable_file, "PLY vertex element has no x, y and z"};
    if (vertices && mesh.positions.size() + e.count > vertex_limit)
      return Status{StatusCode::limit_exceeded,
                    "PLY declares " + std::to_string(e.count) + " vertices, more than three for each of the " +
                        std::to_string(triangle_limit) + " triangles allowed (raise it with --max-triangles)"};
    for (std::uint64_t i = 0; i < e.count; ++i) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      Run run{corners.size(), corners.size(), strips, i};
      for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
        const Property& property = e.properties[k];
        if (!values.next(property.is_list ? property.length : property.value))
          return at_instance(StatusCode::unreadable_file, e, i, "the data ends inside it");
        if (!property.is_list) {
          const int axis = !vertices ? -1 : k == x ? 0 : k == y ? 1 : k == z ? 2 : -1;
          if (axis < 0) continue;
          if (!values.real(p[axis]))
            return at_instance(StatusCode::unreadable_file, e, i, values.shown() + " is not a number");
          if (!std::isfinite(p[axis]))
            return at_instance(StatusCode::non_finite_coordinate, e, i,
                               "coordinate " + values.shown() + " is not a finite number");
          continue;
        }
        long long length = 0;
        if (!values.whole(length) || length < 0)
          return at_instance(StatusCode::unreadable_file, e, i,
                             "list length " + values.shown() + " is not a whole number");
        // A polygon of n corners makes n - 2 triangles, a strip at most
        // that: counted before its corners are kept, and a list too short
        // for a triangle keeps none, so the limit bounds what is kept.
        const bool kept = (polygons || strips) && k == corner_list && length >= 3;
        if (kept) triangles += static_cast<std::uint64_t>(length) - 2;
        if (triangles > triangle_limit)
          return at_instance(
              StatusCode::limit_exceeded, e, i,
              "more than " + std::to_string(triangle_limit) + " triangles (raise it with --max-triangles)");
        for (long long item = 0; item < length; ++item) {
          if (!values.next(property.value))
            return at_instance(StatusCode::unreadable_file, e, i, "the data ends inside a list");
          if (!kept) continue;
          long long index = 0;
          if (!values.whole(index))
            return at_instance(StatusCode::unreadable_file, e, i, "corner " + values.shown() + " is no index");
          corners.push_back(index);
        }
      }
      if (vertices) mesh.positions.push_back(p);
      run.end = corners.size();
      if (run.end > run.begin)
        runs.push_back(run);
      else if (polygons && skipped < std::numeric_limits<int>::max())
        ++skipped; // fewer than three corners
    }
  }
  Element face_element, strip_element;
  face_element.name = "face";
  strip_element.name = "tristrips";
  std::vector<Eigen::Vector3d> polygon;
  std::vector<Eigen::Vector3i> cut;
  for (const Run& run : runs) {
    const Element& element = run.strip ? strip_element : face_element;
    for (size_t c = run.begin; c < run.end; ++c)
      if (!(run.strip && corners[c] == kStripRestart) &&
          (corners[c] < 0 || corners[c] >= static_cast<long long>(mesh.positions.size())))
        return at_instance(StatusCode::index_out_of_range, element, run.number,
                           "corner " + std::to_string(corners[c]) + " names no vertex");
    if (run.strip) {
      // A strip's triangles turn their winding each step; -1 starts anew.
      int step = 0;
      for (size_t c = run.begin; c < run.end; ++c) {
        if (corners[c] == kStripRestart) {
          step = 0;
          continue;
        }
        if (++step < 3) continue;
        const int a = static_cast<int>(corners[c - 2]), b = static_cast<int>(corners[c - 1]),
                  d = static_cast<int>(corners[c]);
        if (step % 2 == 1)
          mesh.triangles.emplace_back(a, b, d);
        else
          mesh.triangles.emplace_back(b, a, d);
      }
      continue;
    }
    polygon.clear();
    for (size_t c = run.begin; c < run.end; ++c) polygon.push_back(mesh.positions[corners[c]]);
    cut.clear();
    if (triangulate_polygon(polygon, cut) == Triangulation::too_large)
      return at_instance(StatusCode::limit_exceeded, element, run.number,
                         "a concave polygon of " + std::to_string(polygon.size()) + " corners, more than the " +
                             std::to_string(kMostConcaveCorners) + " the reader triangulates");
    for (const Eigen::Vector3i& t : cut)
      mesh.triangles.emplace_back(static_cast<int>(corners[run.begin + t[0]]),
                                  static_cast<int>(corners[run.begin + t[1]]),
                                  static_cast<int>(corners[run.begin + t[2]]));
  }
  if (mesh.triangles.empty()) return Status{StatusCode::empty_scene, "no face"};
  mesh.material_ids.assign(mesh.triangles.size(), 0);
  return mesh;
}

} // namespace

Result<Mesh> read_ply_body(std::ifstream& in, const PlyHeader& h, std::uint64_t file_bytes,
                           std::uint64_t triangle_limit, int& skipped) {
  if (h.ascii) {
    in.clear();
    in.seekg(static_cast<std::streamoff>(h.after_line));
    AsciiValues values(in);
    return read_elements(values, h, triangle_limit, skipped);
  }
  BodyReader body(in, h.data_at, file_bytes - std::min(file_bytes, h.data_at));
  BinaryValues values(body, h.big_endian);
  return read_elements(values, h, triangle_limit, skipped);
}

} // namespace hullcover::detail

#include "scene_file_checks.h"

#include "gltf_file_checks.h"
#include "obj_file_checks.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <vector>

namespace hullcover::detail {
namespace {

std::string lower_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? std::string() : path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

Status damaged(const std::string& why) { return {StatusCode::unreadable_file, why}; }

// Bytes one value of a PLY scalar type takes; 0 for a name PLY does not have.
int ply_scalar_bytes(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

// The header's elements must fit the bytes after it: every element takes at
// least its scalars' bytes and each list's count (binary), or two characters
// per property (ASCII: a digit and a separator).
Status check_ply(std::ifstream& in, std::uint64_t file_bytes) {
  std::string header;
  header.resize(static_cast<std::size_t>(std::min<std::uint64_t>(file_bytes, kMaxPlyHeaderBytes)));
  in.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<std::size_t>(in.gcount()));
  if (header.compare(0, 3, "ply") != 0) return damaged("not a PLY file (no 'ply' magic)");
  const std::size_t end = header.find("end_header");
  if (end == std::string::npos)
    return damaged("PLY header has no 'end_header' within the first " + std::to_string(header.size()) + " bytes");
  const std::size_t body_start = header.find('\n', end);
  if (body_start == std::string::npos && end + 10 < file_bytes) return damaged("PLY 'end_header' line has no end");
  const std::uint64_t body = file_bytes - std::min<std::uint64_t>(file_bytes, body_start == std::string::npos ? file_bytes : body_start + 1);

  std::istringstream lines(header.substr(0, end));
  std::string line;
  bool ascii = false;
  bool have_format = false;
  struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::uint64_t least_bytes = 0;  // per element
  };
  std::vector<Element> elements;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      std::string format;
      words >> format;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        return damaged("PLY format '" + format + "' is none of ascii, binary_little_endian, binary_big_endian");
      ascii = format == "ascii";
      have_format = true;
    } else if (keyword == "element") {
      Element e;
      std::string count;
      words >> e.name >> count;
      if (count.empty() || count.size() > 19 || !std::all_of(count.begin(), count.end(), ::isdigit))
        return damaged("PLY element '" + e.name + "' has count '" + count + "', not a number");
      e.count = std::stoull(count);
      elements.push_back(e);
    } else if (keyword == "property") {
      if (elements.empty()) return damaged("PLY property before any element");
      std::string type;
      words >> type;
      std::uint64_t bytes = 0;
      if (type == "list") {
        std::string count_type, item_type;
        words >> count_type >> item_type;
        if (ply_scalar_bytes(count_type) == 0 || ply_scalar_bytes(item_type) == 0)
          return damaged("PLY list property with types '" + count_type + "', '" + item_type + "'");
        bytes = ascii ? 2 : static_cast<std::uint64_t>(ply_scalar_bytes(count_type));
      } else {
        if (ply_scalar_bytes(type) == 0) return damaged("PLY property of unknown type '" + type + "'");
        bytes = ascii ? 2 : static_cast<std::uint64_t>(ply_scalar_bytes(type));
      }
      elements.back().least_bytes += bytes;
    }
  }
  if (!have_format) return damaged("PLY header has no format line");
  std::uint64_t needed = 0;
  for (const Element& e : elements) {
    if (e.least_bytes == 0 && e.count > 0)
      return damaged("PLY element '" + e.name + "' has no properties but a count of " + std::to_string(e.count));
    // Compared by division: count x bytes may not fit 64 bits.
    if (e.least_bytes > 0 && e.count > (body + 1) / e.least_bytes)
      return damaged("PLY declares " + std::to_string(e.count) + " " + e.name + " elements, more than its " +
                     std::to_string(body) + " bytes of data can hold");
    needed += e.count * e.least_bytes;
    if (needed > body + 1)
      return damaged("PLY elements need at least " + std::to_string(needed) + " bytes; the data has " +
                     std::to_string(body));
  }
  return Status::success();
}

// A binary STL is an 80-byte header, a count and 50 bytes per triangle; an
// ASCII one starts with "solid" (a binary header may too, so the size
// decides first).
Status check_stl(std::ifstream& in, std::uint64_t file_bytes) {
  char head[84] = {};
  in.read(head, sizeof head);
  const std::uint64_t got = static_cast<std::uint64_t>(in.gcount());
  std::string start(head, static_cast<std::size_t>(std::min<std::uint64_t>(got, 80)));
  start.erase(0, start.find_first_not_of(" \t\r\n"));
  if (got == 84) {
    const std::uint64_t count = little_endian_u32(reinterpret_cast<const unsigned char*>(head + 80));
    if (84 + 50 * count == file_bytes) return Status::success();
    if (start.compare(0, 5, "solid") == 0) return Status::success();
    return damaged("binary STL declares " + std::to_string(count) + " triangles, which take " +
                   std::to_string(84 + 50 * count) + " bytes; the file has " + std::to_string(file_bytes));
  }
  if (start.compare(0, 5, "solid") == 0) return Status::success();
  return damaged("STL shorter than a binary header (84 bytes) and not ASCII ('solid')");
}

} // namespace

Status check_scene_file(const std::string& path, const ImportLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {StatusCode::unreadable_file, "cannot open"};
  in.seekg(0, std::ios::end);
  const std::uint64_t file_bytes = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  const std::string ext = lower_extension(path);
  if (ext == ".ply") return check_ply(in, file_bytes);
  if (ext == ".stl") return check_stl(in, file_bytes);
  if (ext == ".gltf" || ext == ".glb") return check_gltf(path, in, file_bytes, ext == ".glb", limits);
  if (ext == ".obj") return check_obj(in, limits);
  return Status::success();
}

} // namespace hullcover::detail

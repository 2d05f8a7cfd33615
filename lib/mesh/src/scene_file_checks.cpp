#include "scene_file_checks.h"
#include "scene_file_rules.h"

#include "gltf_file_checks.h"
#include "obj_file_checks.h"
#include "ply_file_checks.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>

namespace hullcover::detail {
namespace {

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
    return damaged_file("binary STL declares " + std::to_string(count) + " triangles, which take " +
                        std::to_string(84 + 50 * count) + " bytes; the file has " + std::to_string(file_bytes));
  }
  if (start.compare(0, 5, "solid") == 0) return Status::success();
  return damaged_file("STL shorter than a binary header (84 bytes) and not ASCII ('solid')");
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
